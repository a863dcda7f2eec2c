#include "tests/support/golden.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "tests/support/process.h"

namespace igds::test {

namespace {

// Where a record ends: a line end; a ';' (HP-GL); before a Tek mode byte (GS, US, ESC, FS).
std::vector<std::string_view> records(std::string_view s) {
  std::vector<std::string_view> out;
  const bool text = s.find('\n') != std::string_view::npos;
  std::size_t start = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const bool ends_here = text ? c == '\n' : c == ';';
    const bool starts_here =
        !text && i > start && (c == 0x1D || c == 0x1F || c == 0x1B || c == 0x1C);
    if (starts_here) {
      out.push_back(s.substr(start, i - start));
      start = i;
    }
    if (ends_here) {
      out.push_back(s.substr(start, i + 1 - start));
      start = i + 1;
    }
  }
  if (start < s.size()) out.push_back(s.substr(start));
  return out;
}

std::string shown(std::string_view record) {
  std::string out;
  for (char c : record) {
    const auto b = static_cast<unsigned char>(c);
    if (b >= 0x20 && b < 0x7F)
      out += c;
    else
      out += fmt::format("\\x{:02X}", b);
  }
  return out;
}

}  // namespace

std::string first_difference(std::string_view expected, std::string_view actual) {
  if (expected == actual) return "";
  const auto want = records(expected), got = records(actual);
  std::size_t i = 0;
  while (i < want.size() && i < got.size() && want[i] == got[i]) ++i;
  return fmt::format(
      "first difference in record {} of {} (actual has {}):\n  expected: {}\n  actual:   {}", i + 1,
      want.size(), got.size(), i < want.size() ? shown(want[i]) : "<end>",
      i < got.size() ? shown(got[i]) : "<end>");
}

void check_golden(const std::string& name, const std::string& bytes) {
  const std::filesystem::path path = std::filesystem::path(IGDS_GOLDEN_DIR) / name;
  const char* update = std::getenv("IGDS_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    const std::string was = std::filesystem::exists(path) ? read_file(path) : "";
    write_file(path, bytes);
    const std::string change = first_difference(was, bytes);
    MESSAGE(fmt::format("golden {}: {}", name, change.empty() ? "unchanged" : change));
    return;
  }
  INFO("golden file " << path.string() << " (IGDS_UPDATE_GOLDEN=1 rewrites it)");
  REQUIRE(std::filesystem::exists(path));
  const std::string expected = read_file(path);
  const std::string difference = first_difference(expected, bytes);
  CHECK_MESSAGE(difference.empty(), difference);
}

}  // namespace igds::test
