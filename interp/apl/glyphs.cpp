#include "interp/apl/glyphs.h"

#include <array>

namespace igds::apl {

namespace {

constexpr std::uint16_t sm = Role::scalar_monadic, sd = Role::scalar_dyadic,
                        mm = Role::mixed_monadic, md = Role::mixed_dyadic, am = Role::axis_monadic,
                        ad = Role::axis_dyadic, op = Role::slash_operator, sx = Role::syntax,
                        nc = Role::name_character;

// The names are those the APL\360 manuals give the shapes.
constexpr std::array table{
    // The prefix keys, in keyboard order.
    Glyph{U'¯', "OVERBAR", '2', sx},
    Glyph{U'<', "", '3', sd},
    Glyph{U'≤', "NOTGREATER", '4', sd},
    Glyph{U'=', "", '5', sd},
    Glyph{U'≥', "NOTLESS", '6', sd},
    Glyph{U'>', "", '7', sd},
    Glyph{U'≠', "NOTEQUAL", '8', sd},
    Glyph{U'∨', "OR", '9', sd},
    Glyph{U'∧', "AND", '0', sd},
    Glyph{U'×', "TIMES", '-', sm | sd},
    Glyph{U'÷', "DIVIDE", '=', sm | sd},
    Glyph{U'?', "", 'q', sm | md},
    Glyph{U'∊', "EPSILON", 'e', md},
    Glyph{U'⍴', "RHO", 'r', mm | md},
    Glyph{U'~', "", 't', sm | md},
    Glyph{U'↑', "UPARROW", 'y', md | ad},
    Glyph{U'↓', "DOWNARROW", 'u', md | ad},
    Glyph{U'⍳', "IOTA", 'i', mm | md},
    Glyph{U'○', "CIRCLE", 'o', sm | sd},
    Glyph{U'*', "", 'p', sm | sd},
    Glyph{U'←', "LEFTARROW", '[', sx},
    Glyph{U'→', "RIGHTARROW", ']', sx},
    Glyph{U'⌈', "UPSTILE", 's', sm | sd},
    Glyph{U'⌊', "DOWNSTILE", 'd', sm | sd},
    Glyph{U'∇', "DEL", 'g', sx},
    Glyph{U'∆', "DELTA", 'h', nc},
    Glyph{U'∘', "JOT", 'j', sx},
    Glyph{U'⎕', "QUAD", 'l', sx},
    Glyph{U'⍎', "EXECUTE", ';', mm},
    Glyph{U'⍕', "FORMAT", '\'', mm | md},
    Glyph{U'⊥', "BASE", 'b', md},
    Glyph{U'⊤', "REPRESENT", 'n', md},
    Glyph{U'|', "", 'm', sm | sd},
    Glyph{U'⍝', "LAMP", ',', sx},
    Glyph{U'⍀', "BACKSLASHBAR", '.', md | ad | op},
    Glyph{U'⌿', "SLASHBAR", '/', md | ad | op},
    Glyph{U'⍒', "GRADEDOWN", '#', mm | md},
    Glyph{U'⍋', "GRADEUP", '$', mm | md},
    Glyph{U'⌽', "CIRCLESTILE", '%', mm | md | am | ad},
    Glyph{U'⍉', "TRANSPOSE", '^', mm | md},
    Glyph{U'⊖', "CIRCLEBAR", '&', mm | md | am | ad},
    Glyph{U'⍟', "CIRCLESTAR", '*', sm | sd},
    Glyph{U'⍱', "NOR", '(', sd},
    Glyph{U'⍲', "NAND", ')', sd},
    Glyph{U'!', "", '_', sm | sd},
    Glyph{U'⌹', "DOMINO", '+', mm | md},
    // The others.
    Glyph{U'+', "", 0, sm | sd},
    Glyph{U'-', "", 0, sm | sd},
    Glyph{U',', "", 0, mm | md | am | ad},
    Glyph{U'/', "", 0, md | ad | op},
    Glyph{U'\\', "", 0, md | ad | op},
    Glyph{U'⍞', "QUOTEQUAD", 0, sx},
    Glyph{U'⍙', "DELTAUNDERBAR", 0, nc},
};

struct Alternative {
  char32_t typed, glyph;
  std::string_view name;
};

constexpr std::array alternatives{
    Alternative{U'−', U'-', "MINUS"},   Alternative{U'⋆', U'*', "STAR"},
    Alternative{U'∣', U'|', "STILE"},   Alternative{U'∼', U'~', "TILDE"},
    Alternative{U'∈', U'∊', "EPSILON"}, Alternative{U'^', U'∧', ""},
};

}  // namespace

std::span<const Glyph> glyph_table() {
  return table;
}

char32_t canonical_glyph(char32_t c) {
  for (const auto& a : alternatives)
    if (a.typed == c) return a.glyph;
  return c;
}

const Glyph* find_glyph(char32_t c) {
  // Looked up for every character of every statement: an index of the table, made once, for
  // the characters below U+2600 (every glyph is one).
  constexpr char32_t limit = 0x2600;
  static const auto index = [] {
    std::array<std::uint8_t, limit> at{};
    for (std::size_t i = 0; i < table.size(); ++i)
      at[table[i].glyph] = static_cast<std::uint8_t>(i + 1);
    for (const auto& a : alternatives) at[a.typed] = at[a.glyph];
    return at;
  }();
  if (c >= limit || index[c] == 0) return nullptr;
  return &table[index[c] - 1];
}

std::string_view glyph_name(char32_t c) {
  for (const auto& a : alternatives)
    if (a.typed == c) return a.name;
  for (const auto& g : table)
    if (g.glyph == c) return g.name;
  return {};
}

}  // namespace igds::apl
