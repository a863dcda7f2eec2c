#include "interp/apl/keyboard.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "interp/apl/glyphs.h"
#include "interp/apl/text.h"

namespace igds::apl {

namespace {

// The keys of the glyph table (interp/apl/glyphs.h), with their glyphs in UTF-8, made once.
struct Keys {
  std::vector<std::string> utf8;
  std::vector<PrefixKey> keys;
  Keys() {
    for (const Glyph& g : glyph_table())
      if (g.key != 0) utf8.push_back(encode_utf8(std::u32string(1, g.glyph)));
    std::size_t i = 0;
    for (const Glyph& g : glyph_table())
      if (g.key != 0) keys.push_back({g.key, utf8[i++]});
  }
};

const Keys& all_keys() {
  static const Keys keys;
  return keys;
}

}  // namespace

std::span<const PrefixKey> prefix_keys() {
  return all_keys().keys;
}

std::string_view prefix_glyph(char key) {
  for (const auto& k : all_keys().keys)
    if (k.key == key) return k.glyph;
  return {};
}

std::vector<std::string> keyboard_help() {
  std::vector<std::string> lines{
      "APL characters: type ` and then the key shown (`` for a ` itself)."};
  constexpr std::size_t width = 20, per_line = 4;
  std::string line;
  std::size_t shown = 0, column = 0;
  for (const auto& k : all_keys().keys) {
    const std::u32string g = decode_utf8(k.glyph);
    const std::string_view name = glyph_name(g.empty() ? U' ' : g[0]);
    std::string entry = fmt::format("{}{} {}", prefix_key, k.key, k.glyph);
    if (!name.empty()) entry += fmt::format(" {}", name);
    if (column > 0) {  // columns of `width` characters (a glyph is one, whatever its UTF-8)
      line.append(width * column > shown ? width * column - shown : 1, ' ');
      shown = std::max(shown, width * column);
    }
    line += entry;
    shown += decode_utf8(entry).size();
    if (++column == per_line) {
      lines.push_back(line);
      line.clear();
      shown = column = 0;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace igds::apl
