#include "tests/e2e/examples_support.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "tests/support/process.h"

namespace igds::test {

namespace {

std::filesystem::path expected_dir() {
  return source_dir() / "tests" / "e2e" / "expected";
}

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    lines.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// "* picture: page 3 ..." in an example's header: the Tek page its picture shows.
int picture_page_of(std::string_view text) {
  constexpr std::string_view key = "picture: page ";
  for (const auto& line : split_lines(text)) {
    auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] != '*') break;  // the header has ended
    auto at = line.find(key);
    if (at != std::string::npos) return std::atoi(line.c_str() + at + key.size());
  }
  return -1;
}

}  // namespace

std::vector<Example> examples() {
  std::vector<Example> list;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "scripts/examples")) {
    if (entry.path().extension() != ".igds") continue;
    Example e;
    e.name = entry.path().stem().string();
    e.file = entry.path();
    e.picture_page = picture_page_of(read_file(entry.path()));
    auto inputs = entry.path();
    inputs.replace_extension(".disk");
    if (std::filesystem::is_directory(inputs)) e.inputs = inputs;
    list.push_back(std::move(e));
  }
  std::sort(list.begin(), list.end(),
            [](const Example& a, const Example& b) { return a.name < b.name; });
  return list;
}

void put_inputs(const Example& example, const std::filesystem::path& disk) {
  if (example.inputs.empty()) return;
  for (const auto& entry : std::filesystem::directory_iterator(example.inputs))
    std::filesystem::copy_file(entry.path(), disk / entry.path().filename());
}

std::vector<std::string> command_lines(std::string_view file_text) {
  constexpr std::string_view lamp = "\u235D";  // ⍝, APL's comment
  std::vector<std::string> lines;
  for (auto line : split_lines(file_text)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos &&
        (line[first] == '*' || line.compare(first, lamp.size(), lamp) == 0))
      continue;
    if (auto at = line.find(lamp); at != std::string::npos) line.erase(at);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::string compare_expected(const std::string& file, const std::string& actual) {
  auto path = expected_dir() / file;
  const char* update = std::getenv("IGDS_UPDATE_GOLDEN");
  if (update && std::string_view(update) == "1") {
    std::string old = std::filesystem::exists(path) ? read_file(path) : std::string();
    if (old == actual) return "";
    std::filesystem::create_directories(path.parent_path());
    TempDir scratch;
    write_file(scratch.path() / "old", old);
    write_file(path, actual);
    auto diff = run({"diff", "-u", (scratch.path() / "old").string(), path.string()});
    int added = 0, removed = 0;
    for (const auto& line : split_lines(diff.out)) {
      if (line.rfind("+++", 0) == 0 || line.rfind("---", 0) == 0) continue;
      if (line.rfind('+', 0) == 0) ++added;
      if (line.rfind('-', 0) == 0) ++removed;
    }
    fmt::print("updated {}: {} lines added, {} removed\n", path.string(), added, removed);
    auto lines = split_lines(diff.out);
    for (std::size_t i = 0; i < lines.size() && i < 40; ++i) fmt::print("  {}\n", lines[i]);
    if (lines.size() > 40) fmt::print("  ... ({} more diff lines)\n", lines.size() - 40);
    return "";
  }
  if (!std::filesystem::exists(path))
    return fmt::format("{} is missing (make it with IGDS_UPDATE_GOLDEN=1)", path.string());
  std::string expected = read_file(path);
  if (expected == actual) return "";
  auto want = split_lines(expected), got = split_lines(actual);
  std::size_t i = 0;
  while (i < want.size() && i < got.size() && want[i] == got[i]) ++i;
  return fmt::format(
      "{} differs at line {}:\n  expected: {}\n  actual:   {}\n(IGDS_UPDATE_GOLDEN=1 "
      "rewrites it and prints the diff)",
      path.string(), i + 1, i < want.size() ? want[i] : "<end>", i < got.size() ? got[i] : "<end>");
}

std::string without_disk(std::string text, const std::filesystem::path& disk) {
  for (std::string from : {disk.string(), std::filesystem::canonical(disk).string()}) {
    if (from.empty()) continue;
    for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos;) {
      text.replace(at, from.size(), "<DISK>");
      at += 6;
    }
  }
  return text;
}

}  // namespace igds::test
