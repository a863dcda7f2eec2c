// Words, comments and APL numbers as the interpreter reads them.
#include "interp/words.h"

#include <doctest/doctest.h>

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

}  // namespace igds::test
