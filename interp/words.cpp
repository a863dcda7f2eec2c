#include "interp/words.h"

namespace igds {

namespace {

constexpr std::string_view lamp = "\xE2\x8D\x9D";  // ⍝ U+235D in UTF-8

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

}  // namespace

bool is_comment_line(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() && is_blank(line[i])) ++i;
  line.remove_prefix(i);
  return line.starts_with('*') || line.starts_with(lamp);
}

std::vector<std::string> split_words(std::string_view line) {
  std::vector<std::string> words;
  if (is_comment_line(line)) return words;
  if (auto at = line.find(lamp); at != std::string_view::npos) line = line.substr(0, at);
  auto separates = [](char c) { return is_blank(c) || c == ','; };
  for (std::size_t i = 0; i < line.size();) {
    while (i < line.size() && separates(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !separates(line[i])) ++i;
    if (i > start) words.emplace_back(line.substr(start, i - start));
  }
  return words;
}

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return out;
}

}  // namespace igds
