// Words, comments and APL numbers as the interpreter reads them.
#include "interp/words.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <limits>
#include <string>

#include "workspace/apl.h"

namespace igds::test {

using Words = std::vector<std::string>;

TEST_CASE("blanks, tabs and commas separate words") {
  CHECK(split_words("D SU A 110 130 120") == Words{"D", "SU", "A", "110", "130", "120"});
  CHECK(split_words("  1,0 ,\t0,,2  ") == Words{"1", "0", "0", "2"});
  CHECK(split_words("") == Words{});
  CHECK(split_words("   \r") == Words{});
  CHECK(split_words("build\r") == Words{"build"});
}

TEST_CASE("comments: * or ⍝ first, or anything after ⍝") {
  CHECK(is_comment_line("* a CMS comment"));
  CHECK(is_comment_line("   *indented"));
  CHECK(is_comment_line("⍝ an APL lamp"));
  CHECK(is_comment_line("\t⍝"));
  CHECK_FALSE(is_comment_line(""));
  CHECK_FALSE(is_comment_line("1 2 3 * 4"));
  CHECK(split_words("* BUILD") == Words{});
  CHECK(split_words("4 10 0 2 ⍝ the second curve") == Words{"4", "10", "0", "2"});
  CHECK(split_words("4 10 0 2⍝x") == Words{"4", "10", "0", "2"});
  CHECK(split_words("   ⍝ only a comment") == Words{});
}

TEST_CASE("capitals") {
  CHECK(upper("d su") == "D SU");
  CHECK(upper("¯3.5e¯2") == "¯3.5E¯2");
}

TEST_CASE("APL numbers as typed") {
  CHECK(parse_apl_number("12") == 12);
  CHECK(parse_apl_number("¯3.5") == -3.5);
  CHECK(parse_apl_number("-3.5") == -3.5);
  CHECK(parse_apl_number("1E3") == 1000);
  CHECK(parse_apl_number("2.5E¯2") == 0.025);
  CHECK(parse_apl_number("2.5e-2") == 0.025);
  CHECK(parse_apl_number("-1.5E+03") == -1500);
  CHECK(parse_apl_number(".5") == 0.5);
  CHECK_FALSE(parse_apl_number("1E"));
  CHECK_FALSE(parse_apl_number("3x"));
  CHECK_FALSE(parse_apl_number("¯"));
  CHECK_FALSE(parse_apl_number(""));
  CHECK(format_apl_number(-3.5) == "¯3.5");
  CHECK(format_apl_number(110) == "110");
}

TEST_CASE("APL numbers: the value strtod gives the same text, at the edges of double too") {
  CHECK(parse_apl_number("+2.5") == 2.5);
  CHECK(parse_apl_number("2.") == 2);
  CHECK(parse_apl_number("1E+2") == 100);
  CHECK_FALSE(parse_apl_number("+-2"));
  CHECK_FALSE(parse_apl_number("¯¯2"));
  CHECK_FALSE(parse_apl_number("1E¯+2"));
  CHECK_FALSE(parse_apl_number("."));
  CHECK_FALSE(parse_apl_number("1.2.3"));
  CHECK_FALSE(parse_apl_number("INF"));
  // Overflow is an infinity (refused by the commands with the point number), underflow zero or a
  // subnormal number, as strtod gives them.
  CHECK(parse_apl_number("1E400") == std::numeric_limits<double>::infinity());
  CHECK(parse_apl_number("¯1E400") == -std::numeric_limits<double>::infinity());
  CHECK(parse_apl_number("1E¯400") == 0);
  CHECK(parse_apl_number("4.9E¯324") == std::strtod("4.9E-324", nullptr));
  CHECK(parse_apl_number("2.2250738585072011E¯308") ==
        std::strtod("2.2250738585072011E-308", nullptr));
  // A word longer than any buffer: every digit counts.
  const std::string digits = "0." + std::string(200, '0') + "15";
  CHECK(parse_apl_number(digits) == 1.5E-201);
  CHECK(parse_apl_number(std::string(100, '9')) ==
        std::strtod(std::string(100, '9').c_str(), nullptr));
  // Correct rounding on halfway cases: the nearest double, as strtod.
  for (const char* text : {"9007199254740993", "0.1", "2.675", "1.7976931348623157E308",
                           "123456789012345678901234567890", "3.14159265358979323846"})
    CHECK(parse_apl_number(text) == std::strtod(text, nullptr));
}

}  // namespace igds::test
