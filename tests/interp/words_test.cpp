// Words, comments and APL numbers as the interpreter reads them.
#include "interp/words.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/numbers/typed.h"

namespace igds::test {

using Words = std::vector<std::string>;

TEST_CASE("blanks, tabs and commas separate words") {
  CHECK(split_words("D SU A 110 130 120") == Words{"D", "SU", "A", "110", "130", "120"});
  CHECK(split_words("  1,0 ,\t0,,2  ") == Words{"1", "0", "0", "2"});
  CHECK(split_words("") == Words{});
  CHECK(split_words("   \r") == Words{});
  CHECK(split_words("build\r") == Words{"build"});
}

TEST_CASE("the words as views of the line, into a vector kept from line to line") {
  const std::string line = " 1,0.5\t¯2  x ⍝ a comment";
  std::vector<std::string_view> views{"left", "from", "before"};
  split_words(line, views);
  REQUIRE(views == std::vector<std::string_view>{"1", "0.5", "¯2", "x"});
  // Views of the line itself, not copies of its words.
  CHECK(views[1].data() == line.data() + 3);
  CHECK(views[3].data() == line.data() + line.find('x'));
  split_words("* a comment line", views);
  CHECK(views.empty());
  split_words("7", views);
  CHECK(views == std::vector<std::string_view>{"7"});
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
  CHECK(parse_typed_number("12") == 12);
  CHECK(parse_typed_number("¯3.5") == -3.5);
  CHECK(parse_typed_number("-3.5") == -3.5);
  CHECK(parse_typed_number("1E3") == 1000);
  CHECK(parse_typed_number("2.5E¯2") == 0.025);
  CHECK(parse_typed_number("2.5e-2") == 0.025);
  CHECK(parse_typed_number("-1.5E+03") == -1500);
  CHECK(parse_typed_number(".5") == 0.5);
  CHECK_FALSE(parse_typed_number("1E"));
  CHECK_FALSE(parse_typed_number("3x"));
  CHECK_FALSE(parse_typed_number("¯"));
  CHECK_FALSE(parse_typed_number(""));
  CHECK(format_typed_number(-3.5) == "¯3.5");
  CHECK(format_typed_number(110) == "110");
}

TEST_CASE("APL numbers: the value strtod gives the same text, at the edges of double too") {
  CHECK(parse_typed_number("+2.5") == 2.5);
  CHECK(parse_typed_number("2.") == 2);
  CHECK(parse_typed_number("1E+2") == 100);
  CHECK_FALSE(parse_typed_number("+-2"));
  CHECK_FALSE(parse_typed_number("¯¯2"));
  CHECK_FALSE(parse_typed_number("1E¯+2"));
  CHECK_FALSE(parse_typed_number("."));
  CHECK_FALSE(parse_typed_number("1.2.3"));
  CHECK_FALSE(parse_typed_number("INF"));
  // Overflow is an infinity (refused by the commands with the point number), underflow zero or a
  // subnormal number, as strtod gives them.
  CHECK(parse_typed_number("1E400") == std::numeric_limits<double>::infinity());
  CHECK(parse_typed_number("¯1E400") == -std::numeric_limits<double>::infinity());
  CHECK(parse_typed_number("1E¯400") == 0);
  CHECK(parse_typed_number("4.9E¯324") == std::strtod("4.9E-324", nullptr));
  CHECK(parse_typed_number("2.2250738585072011E¯308") ==
        std::strtod("2.2250738585072011E-308", nullptr));
  // A word longer than any buffer: every digit counts.
  const std::string digits = "0." + std::string(200, '0') + "15";
  CHECK(parse_typed_number(digits) == 1.5E-201);
  CHECK(parse_typed_number(std::string(100, '9')) ==
        std::strtod(std::string(100, '9').c_str(), nullptr));
  // Correct rounding on halfway cases: the nearest double, as strtod.
  for (const char* text : {"9007199254740993", "0.1", "2.675", "1.7976931348623157E308",
                           "123456789012345678901234567890", "3.14159265358979323846"})
    CHECK(parse_typed_number(text) == std::strtod(text, nullptr));
}

TEST_CASE("APL numbers: the quick way for short numbers gives strtod's double, bit for bit") {
  // Every shape a designer types: 1 to 20 digits, a point anywhere or none, a sign, an exponent
  // near the quick way's limits (10^22, 2^53) and beyond, leading and trailing zeros.
  auto same_bits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  std::uint64_t state = 12345;
  auto next = [&state](int below) {
    state = state * 6364136223846793005u + 1442695040888963407u;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(below));
  };
  int checked = 0;
  for (int r = 0; r < 20000; ++r) {
    std::string c, apl;  // as strtod reads it, as typed in APL
    const int sign = next(3);
    c += sign == 1 ? "-" : "";
    apl += sign == 1 ? "¯" : sign == 2 ? "-" : "";
    if (sign == 2) c += "-";
    const int count = 1 + next(20), point = next(count + 2);
    std::string digits;
    for (int d = 0; d <= count; ++d) {
      if (d == point) digits += '.';
      if (d < count) digits += static_cast<char>('0' + (d == 0 && next(4) == 0 ? 0 : next(10)));
    }
    if (digits == ".") digits = "0.";
    c += digits;
    apl += digits;
    if (next(3) == 0) {
      const int exponent = next(61) - 30;
      c += fmt::format("E{}", exponent);
      apl +=
          fmt::format("{}{}{}", next(2) ? "e" : "E", exponent < 0 ? "¯" : "", std::abs(exponent));
    }
    const auto v = parse_typed_number(apl);
    REQUIRE_MESSAGE(v, apl);
    const double expected = std::strtod(c.c_str(), nullptr);
    CHECK_MESSAGE(same_bits(*v, expected), apl, " ", c);
    ++checked;
  }
  CHECK(checked == 20000);
  CHECK(same_bits(*parse_typed_number("¯0"), -0.0));
  CHECK(same_bits(*parse_typed_number("-0.000"), -0.0));
  CHECK(same_bits(*parse_typed_number("9007199254740992"), 9007199254740992.0));
  CHECK(same_bits(*parse_typed_number("9007199254740993"), 9007199254740992.0));
  CHECK(same_bits(*parse_typed_number("1E22"), 1e22));
  CHECK(same_bits(*parse_typed_number("1E23"), std::strtod("1E23", nullptr)));
  CHECK(same_bits(*parse_typed_number("123456789E¯22"), std::strtod("123456789E-22", nullptr)));
}

TEST_CASE("a line of many points: every word, in order") {
  std::string line = " 1";
  Words expected{"1"};
  for (int j = 0; j < 3000; ++j) {
    const std::string word = fmt::format("{}{}", j * 37 % 1000, j % 3 ? ".5" : "");
    line += fmt::format("{}{}", j % 7 ? " " : " ,\t", word);
    expected.push_back(word);
  }
  CHECK(split_words(line + "  ") == expected);
  CHECK(split_words(line + " ⍝ the end") == expected);
}

}  // namespace igds::test
