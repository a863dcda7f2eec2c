#include "interp/words.h"

#include <array>

namespace igds {

namespace {

constexpr std::string_view lamp = "\xE2\x8D\x9D";  // ⍝ U+235D in UTF-8

constexpr bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

bool reading_apl = false;  // the conversation runs on one thread

}  // namespace

ReadingFor::ReadingFor(bool apl) : was_(reading_apl) {
  reading_apl = apl;
}

ReadingFor::~ReadingFor() {
  reading_apl = was_;
}

bool is_comment_line(std::string_view line) {
  if (reading_apl) return false;
  std::size_t i = 0;
  while (i < line.size() && is_blank(line[i])) ++i;
  line.remove_prefix(i);
  return line.starts_with('*') || line.starts_with(lamp);
}

void split_words(std::string_view line, std::vector<std::string_view>& words) {
  words.clear();
  if (is_comment_line(line)) return;
  if (auto at = line.find(lamp); at != std::string_view::npos) line = line.substr(0, at);
  // Blanks and commas separate words.
  static constexpr auto separator = [] {
    std::array<bool, 256> table{};
    for (std::size_t c = 0; c < table.size(); ++c)
      table[c] = is_blank(static_cast<char>(c)) || c == ',';
    return table;
  }();
  auto apart = [&](std::size_t i) { return separator[static_cast<unsigned char>(line[i])]; };
  const std::size_t n = line.size();
  for (std::size_t i = 0;;) {
    while (i < n && apart(i)) ++i;
    if (i == n) return;
    const std::size_t first = i;
    while (i < n && !apart(i)) ++i;
    words.push_back(line.substr(first, i - first));
  }
}

std::vector<std::string> split_words(std::string_view line) {
  std::vector<std::string_view> views;
  split_words(line, views);
  return {views.begin(), views.end()};
}

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return out;
}

}  // namespace igds
