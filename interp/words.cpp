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

std::vector<std::string> split_words(std::string_view line) {
  std::vector<std::string> words;
  if (is_comment_line(line)) return words;
  if (auto at = line.find(lamp); at != std::string_view::npos) line = line.substr(0, at);
  // Blanks and commas separate words.
  static constexpr auto separator = [] {
    std::array<bool, 256> table{};
    for (std::size_t c = 0; c < table.size(); ++c)
      table[c] = is_blank(static_cast<char>(c)) || c == ',';
    return table;
  }();
  // Where words start and end, found without a branch per character (a line of a thousand
  // points has three thousand words of a few characters each), then the words made.
  std::vector<std::size_t> bounds(line.size() + 1);
  std::size_t count = 0;
  bool before = true;  // a separator, or the start
  for (std::size_t i = 0; i < line.size(); ++i) {
    const bool now = separator[static_cast<unsigned char>(line[i])];
    bounds[count] = i;
    count += before != now;
    before = now;
  }
  bounds[count] = line.size();
  count += !before;
  words.reserve(count / 2);
  for (std::size_t k = 0; k + 1 < count; k += 2)
    words.emplace_back(line.substr(bounds[k], bounds[k + 1] - bounds[k]));
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
