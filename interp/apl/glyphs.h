// The APL characters of igds's APL, in one table: what each is in the language, the name a device
// that cannot draw it writes instead, and the key that types it after the prefix key (Dyalog's
// backtick layout, as RIDE and ngn/apl use it). The tokenizer, the parser, the evaluator, the
// keyboard and ⎕AV all read this table; nothing else lists glyphs.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace igds::apl {

// What a glyph is, as bits of Glyph::roles (Role::scalar_dyadic | Role::mixed_monadic ...).
struct Role {
  enum : std::uint16_t {
    scalar_monadic = 1 << 0,  // f B, element by element
    scalar_dyadic = 1 << 1,   // A f B, element by element (the operands of the operators)
    mixed_monadic = 1 << 2,   // a monadic primitive that is not scalar
    mixed_dyadic = 1 << 3,    // a dyadic primitive that is not scalar
    axis_monadic = 1 << 4,    // f[k] B
    axis_dyadic = 1 << 5,     // A f[k] B
    slash_operator = 1 << 6,  // f/ f⌿ (reduction), f\ f⍀ (scan)
    syntax = 1 << 7,  // ← → ⎕ ⍞ ∇ ∘ ⍝ ¯ ...: part of the language, no function
    name_character = 1 << 8,  // ∆ ⍙: letters of names
  };
};

struct Glyph {
  char32_t glyph;
  std::string_view name;  // OVERBAR, RHO, ...; empty for an ASCII character
  char key;               // typed after the prefix key; 0 for none
  std::uint16_t roles;
};

// The table: the glyphs with a prefix key in keyboard order (the number row, then the rows of
// letters; shifted keys last), then the others.
std::span<const Glyph> glyph_table();

// The entry of a glyph (after canonical_glyph), or null for a character that is no APL symbol.
const Glyph* find_glyph(char32_t c);

// A glyph with one of the roles.
inline bool has_role(char32_t c, std::uint16_t roles) {
  const Glyph* g = find_glyph(c);
  return g && (g->roles & roles) != 0;
}

// The usual spelling of a glyph typed in another way (− ⋆ ∣ ∼ ∈ ^ are - * | ~ ∊ ∧).
char32_t canonical_glyph(char32_t c);

// The name of a non-ASCII APL glyph (⍴ RHO, ← LEFTARROW, ∣ STILE, ...), or empty.
std::string_view glyph_name(char32_t c);

}  // namespace igds::apl
