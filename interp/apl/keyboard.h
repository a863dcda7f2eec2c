// APL characters without an APL keyboard: a prefix key, then an ordinary key, gives a glyph, as
// in RIDE and ngn/apl (Dyalog's backtick layout: `r is ⍴, `i is ⍳, `- is ×, `[ is ←, ...).
// The keys are those of the glyph table (interp/apl/glyphs.h, which also names the glyphs).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "interp/apl/glyphs.h"

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

}  // namespace igds::apl
