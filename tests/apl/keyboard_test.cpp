// The prefix keys (Dyalog's backtick layout, as RIDE and ngn/apl use it) and the glyphs' names.
#include "interp/apl/keyboard.h"

#include <doctest/doctest.h>

#include <set>

#include "interp/apl/lexer.h"
#include "interp/apl/text.h"

namespace igds::apl::test {

TEST_CASE("the prefix keys of the common layout") {
  CHECK(prefix_glyph('r') == "⍴");
  CHECK(prefix_glyph('i') == "⍳");
  CHECK(prefix_glyph('-') == "×");
  CHECK(prefix_glyph('=') == "÷");
  CHECK(prefix_glyph('[') == "←");
  CHECK(prefix_glyph(']') == "→");
  CHECK(prefix_glyph('2') == "¯");
  CHECK(prefix_glyph('l') == "⎕");
  CHECK(prefix_glyph(',') == "⍝");
  CHECK(prefix_glyph('$') == "⍋");
  CHECK(prefix_glyph('+') == "⌹");
  CHECK(prefix_glyph('z').empty());  // ⊂ is not in igds's APL
}

TEST_CASE("each key once; each glyph one igds's APL reads; each non-ASCII glyph named") {
  std::set<char> keys;
  for (const auto& k : prefix_keys()) {
    CHECK(keys.insert(k.key).second);
    const std::u32string g = decode_utf8(k.glyph);
    REQUIRE(g.size() == 1);
    const bool symbol = std::u32string_view(U"¯←→∘⎕⍝∇∆").find(g[0]) != std::u32string_view::npos;
    CHECK((symbol || is_primitive_glyph(g[0])));
    if (g[0] >= 0x80) CHECK(!glyph_name(g[0]).empty());
  }
  CHECK(glyph_name(U'⍴') == "RHO");
  CHECK(glyph_name(U'⍳') == "IOTA");
  CHECK(glyph_name(U'←') == "LEFTARROW");
  CHECK(glyph_name(U'+').empty());
}

TEST_CASE("the help listing shows every key") {
  auto lines = keyboard_help();
  REQUIRE(lines.size() > 2);
  std::string all;
  for (const auto& l : lines) all += l + "\n";
  for (const auto& k : prefix_keys())
    CHECK(all.find(std::string(1, prefix_key) + k.key + " " + std::string(k.glyph)) !=
          std::string::npos);
  CHECK(all.find("`r ⍴ RHO") != std::string::npos);
}

}  // namespace igds::apl::test
