// Numbers as typed and as APL statements hold them (workspace/numbers/typed.h): one reader for
// both, the signs each takes, where a number ends, the edges of double, and what is shown reads
// back.
#include "workspace/numbers/typed.h"

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

namespace igds::test {

namespace {

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// The scan of a text of ASCII and high minuses, as UTF-8 and as code points: both must agree.
ScannedNumber scanned(std::u32string_view text, NumberSigns signs) {
  std::string utf8;
  for (char32_t c : text) utf8 += c == U'¯' ? std::string("¯") : std::string(1, char(c));
  const ScannedNumber wide = scan_number(text, signs), narrow = scan_number(utf8, signs);
  // The same number: the same value, and as many characters (a high minus is 2 bytes of UTF-8).
  std::size_t characters = 0;
  for (std::size_t k = 0; k < narrow.length; ++k)
    characters += (static_cast<unsigned char>(utf8[k]) & 0xC0) != 0x80;
  CHECK(characters == wide.length);
  CHECK(same_bits(narrow.value, wide.value));
  return wide;
}

}  // namespace

TEST_CASE("a number starts a text: where it ends, the signs of APL and of typed entries") {
  using enum NumberSigns;
  auto length = [](std::u32string_view text, NumberSigns signs) {
    return scanned(text, signs).length;
  };
  CHECK(length(U"¯3.5 1", apl) == 4);
  CHECK(length(U"1E¯3+2", apl) == 4);
  CHECK(length(U".5", apl) == 2);
  CHECK(length(U"2.", apl) == 2);
  CHECK(length(U"1.2.3", apl) == 3);
  CHECK(length(U"3A", apl) == 1);
  CHECK(length(U"2E", apl) == 1);    // an E without an exponent is not the number's
  CHECK(length(U"1e-3", apl) == 1);  // APL's minus is a function, not a sign
  CHECK(length(U"1E¯+2", apl) == 1);
  CHECK(length(U"-3", apl) == 0);
  CHECK(length(U"+3", apl) == 0);
  CHECK(length(U"¯", apl) == 0);
  CHECK(length(U".", apl) == 0);
  CHECK(length(U"E5", apl) == 0);
  CHECK(length(U"", apl) == 0);
  CHECK(length(U"-3", typed) == 2);
  CHECK(length(U"+2.5e-2,", typed) == 7);
  CHECK(length(U"1E+2", typed) == 4);
  CHECK(length(U"+-2", typed) == 0);
  CHECK(length(U"¯¯2", typed) == 0);
  CHECK(scanned(U"¯3.5", apl).value == -3.5);
  CHECK(scanned(U"1E¯3", apl).value == 0.001);
  CHECK(scanned(U"2.5e-2", typed).value == 0.025);
}

TEST_CASE("a typed word is one number and nothing else") {
  CHECK(parse_typed_number("12") == 12);
  CHECK(parse_typed_number("¯3.5") == -3.5);
  CHECK(parse_typed_number("-1.5E+03") == -1500);
  CHECK(parse_typed_number("2.5E¯2") == 0.025);
  for (const char* bad : {"", "1E", "3x", "¯", "+-2", "1.2.3", "INF", "1 2", "1,2", "¯ 1"})
    CHECK_FALSE(parse_typed_number(bad));
}

TEST_CASE("numbers beyond double: an infinity above, a zero below, each with its sign") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(parse_typed_number("1E400") == inf);
  CHECK(parse_typed_number("¯1E400") == -inf);
  CHECK(same_bits(*parse_typed_number("1E¯400"), 0.0));
  CHECK(same_bits(*parse_typed_number("¯1E¯400"), -0.0));
  CHECK(parse_typed_number("1" + std::string(400, '0')) == inf);
  CHECK(parse_typed_number("0." + std::string(400, '0') + "1") == 0);
  CHECK(parse_typed_number("1" + std::string(400, '0') + "E¯390") == 1e10);
  CHECK(parse_typed_number("1" + std::string(400, '0') + "E¯80") == inf);
  CHECK(parse_typed_number("4.9E¯324") == std::numeric_limits<double>::denorm_min());
  CHECK(parse_typed_number("1E99999999999999999999") == inf);
  CHECK(same_bits(*parse_typed_number("1E¯99999999999999999999"), 0.0));
  CHECK(same_bits(scanned(U"¯0", NumberSigns::apl).value, -0.0));
}

TEST_CASE("what APL shows reads back to its ten digits") {
  std::mt19937_64 random(10);
  for (int k = 0; k < 200000; ++k) {
    const double v = std::bit_cast<double>(random());
    if (!std::isfinite(v)) continue;
    const std::string shown = format_typed_number(v);
    const auto back = parse_typed_number(shown);
    REQUIRE(back);
    CHECK(std::abs(*back - v) <= std::abs(v) * 5e-10);
  }
  CHECK(format_typed_number(-3.5) == "¯3.5");
  CHECK(format_typed_number(1.5e-7) == "1.5E¯7");
  CHECK(format_typed_number(1e20) == "1E20");
  CHECK(format_typed_number(0.0) == "0");
  CHECK(format_typed_number(-std::numeric_limits<double>::infinity()) == "¯INF");
}

}  // namespace igds::test
