// APL characters without an APL keyboard: a prefix key, then an ordinary key, gives a glyph, as
// in RIDE and ngn/apl (Dyalog's backtick layout: `r is ⍴, `i is ⍳, `- is ×, `[ is ←, ...).
// Only the glyphs of igds's APL are mapped. And a name for each APL glyph, for devices that
// cannot draw it (the Tek window has no APL characters).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace igds::apl {

inline constexpr char prefix_key = '`';

struct PrefixKey {
  char key;                // typed after the prefix key
  std::string_view glyph;  // UTF-8
};

// The map, in keyboard order (the number row, then the rows of letters; shifted keys last).
std::span<const PrefixKey> prefix_keys();

// The glyph of `key after the prefix key, or empty when the key has none.
std::string_view prefix_glyph(char key);

// The help listing of the map: lines such as "`r ⍴ RHO     `i ⍳ IOTA ...".
std::vector<std::string> keyboard_help();

// The name of an APL glyph that is not ASCII (⍴ RHO, ⍳ IOTA, ← LEFTARROW, ¯ OVERBAR, ...), or
// empty for any other character.
std::string_view glyph_name(char32_t glyph);

}  // namespace igds::apl
