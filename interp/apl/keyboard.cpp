#include "interp/apl/keyboard.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "interp/apl/text.h"

namespace igds::apl {

namespace {

// Dyalog's prefix layout (the one RIDE and ngn/apl use), restricted to igds's glyphs.
constexpr std::array<PrefixKey, 46> keys{{
    {'2', "¯"}, {'3', "<"}, {'4', "≤"}, {'5', "="}, {'6', "≥"}, {'7', ">"},  {'8', "≠"}, {'9', "∨"},
    {'0', "∧"}, {'-', "×"}, {'=', "÷"}, {'q', "?"}, {'e', "∊"}, {'r', "⍴"},  {'t', "~"}, {'y', "↑"},
    {'u', "↓"}, {'i', "⍳"}, {'o', "○"}, {'p', "*"}, {'[', "←"}, {']', "→"},  {'s', "⌈"}, {'d', "⌊"},
    {'g', "∇"}, {'h', "∆"}, {'j', "∘"}, {'l', "⎕"}, {';', "⍎"}, {'\'', "⍕"}, {'b', "⊥"}, {'n', "⊤"},
    {'m', "|"}, {',', "⍝"}, {'.', "⍀"}, {'/', "⌿"}, {'#', "⍒"}, {'$', "⍋"},  {'%', "⌽"}, {'^', "⍉"},
    {'&', "⊖"}, {'*', "⍟"}, {'(', "⍱"}, {')', "⍲"}, {'_', "!"}, {'+', "⌹"},
}};

struct GlyphName {
  char32_t glyph;
  std::string_view name;
};

// The glyphs' names as the APL\360 manuals call their shapes.
constexpr std::array<GlyphName, 42> names{{
    {U'¯', "OVERBAR"},    {U'×', "TIMES"},      {U'÷', "DIVIDE"},        {U'⌈', "UPSTILE"},
    {U'⌊', "DOWNSTILE"},  {U'⍟', "CIRCLESTAR"}, {U'○', "CIRCLE"},        {U'≤', "NOTGREATER"},
    {U'≥', "NOTLESS"},    {U'≠', "NOTEQUAL"},   {U'∧', "AND"},           {U'∨', "OR"},
    {U'⍲', "NAND"},       {U'⍱', "NOR"},        {U'⍴', "RHO"},           {U'⍳', "IOTA"},
    {U'↑', "UPARROW"},    {U'↓', "DOWNARROW"},  {U'⌽', "CIRCLESTILE"},   {U'⊖', "CIRCLEBAR"},
    {U'⍉', "TRANSPOSE"},  {U'∊', "EPSILON"},    {U'⍋', "GRADEUP"},       {U'⍒', "GRADEDOWN"},
    {U'⊥', "BASE"},       {U'⊤', "REPRESENT"},  {U'⌹', "DOMINO"},        {U'⍎', "EXECUTE"},
    {U'⍕', "FORMAT"},     {U'⌿', "SLASHBAR"},   {U'⍀', "BACKSLASHBAR"},  {U'←', "LEFTARROW"},
    {U'→', "RIGHTARROW"}, {U'∘', "JOT"},        {U'⎕', "QUAD"},          {U'⍞', "QUOTEQUAD"},
    {U'∇', "DEL"},        {U'∆', "DELTA"},      {U'⍙', "DELTAUNDERBAR"}, {U'⍝', "LAMP"},
    {U'∣', "STILE"},      {U'⋆', "STAR"},
}};

}  // namespace

std::span<const PrefixKey> prefix_keys() {
  return keys;
}

std::string_view prefix_glyph(char key) {
  for (const auto& k : keys)
    if (k.key == key) return k.glyph;
  return {};
}

std::string_view glyph_name(char32_t glyph) {
  for (const auto& n : names)
    if (n.glyph == glyph) return n.name;
  return {};
}

std::vector<std::string> keyboard_help() {
  std::vector<std::string> lines{
      "APL characters: type ` and then the key shown (`` for a ` itself)."};
  constexpr std::size_t width = 20, per_line = 4;
  std::string line;
  std::size_t shown = 0, column = 0;
  for (const auto& k : keys) {
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
