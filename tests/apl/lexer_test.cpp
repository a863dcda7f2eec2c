// The tokens of a line (APL\360 User's Manual, chapter 1: numbers, literals, names, symbols).
#include "interp/apl/lexer.h"

#include <doctest/doctest.h>

#include "interp/apl/error.h"

namespace igds::apl::test {

namespace {

std::vector<double> numbers_of(const Token& t) {
  auto x = t.literal.numbers();
  return {x.begin(), x.end()};
}

// The error kind and column of a line that does not tokenize.
std::pair<ErrorKind, std::size_t> failure(std::u32string_view line) {
  try {
    tokenize(line);
  } catch (const Error& e) {
    return {e.kind(), e.has_column() ? e.column() : 999};
  }
  return {ErrorKind::interrupt, 999};
}

}  // namespace

TEST_CASE("numbers side by side are one constant vector") {
  auto t = tokenize(U"¯3.5 1E¯3 1.5E3 .5 2");
  REQUIRE(t.size() == 1);
  CHECK(t[0].kind == TokenKind::number);
  CHECK(t[0].column == 0);
  CHECK(numbers_of(t[0]) == std::vector<double>{-3.5, 0.001, 1500, 0.5, 2});
  CHECK(t[0].literal.shape() == Shape{5});
  auto one = tokenize(U"42");
  CHECK(one[0].literal.rank() == 0);  // a single number is a scalar
  CHECK(numbers_of(tokenize(U"2.")[0]) == std::vector<double>{2});
  CHECK(numbers_of(tokenize(U"1e¯2")[0]) == std::vector<double>{0.01});
}

TEST_CASE("numbers beyond double: DOMAIN ERROR above the largest, zero below the smallest") {
  const std::u32string many_digits(400, U'9');
  CHECK(failure(U"1E400") == std::pair{ErrorKind::domain, std::size_t{0}});
  CHECK(failure(U"2+¯1E309") == std::pair{ErrorKind::domain, std::size_t{2}});
  CHECK(failure(many_digits).first == ErrorKind::domain);
  CHECK(numbers_of(tokenize(U"1E¯400 ¯1E¯400 4.9E¯324")[0]) == std::vector<double>{0, 0, 4.9e-324});
  CHECK(numbers_of(tokenize(U"0." + std::u32string(400, U'0') + U"1")[0]) ==
        std::vector<double>{0});
  CHECK(numbers_of(tokenize(many_digits + U"E¯399")[0])[0] == doctest::Approx(10));
}

TEST_CASE("minus is the function, high minus the sign") {
  auto t = tokenize(U"-3");
  REQUIRE(t.size() == 2);
  CHECK(t[0].kind == TokenKind::function);
  CHECK(t[0].glyph == U'-');
  CHECK(numbers_of(t[1]) == std::vector<double>{3});
  // 1e-3 is not a number with an exponent in APL: the E must be followed by digits.
  CHECK(failure(U"1e-3").first == ErrorKind::syntax);
  auto u = tokenize(U"1 ¯2−3");
  REQUIRE(u.size() == 3);
  CHECK(numbers_of(u[0]) == std::vector<double>{1, -2});
  CHECK(u[1].glyph == U'-');  // − (U+2212) is read as -
}

TEST_CASE("character constants: quotes doubled inside, one character is a scalar") {
  auto t = tokenize(U"'IT''S' '' 'A'");
  REQUIRE(t.size() == 3);
  CHECK(t[0].literal.utf8() == "IT'S");
  CHECK(t[0].literal.shape() == Shape{4});
  CHECK(t[1].literal.shape() == Shape{0});
  CHECK(t[1].literal.is_character());
  CHECK(t[2].literal.rank() == 0);
  CHECK(t[2].literal.characters()[0] == U'A');
  CHECK(tokenize(U"'⍝ not a comment'").size() == 1);
}

TEST_CASE("names are folded to capitals; system names keep their quad") {
  auto t = tokenize(U"abc∆1 ⎕io ⎕ ⍞");
  REQUIRE(t.size() == 4);
  CHECK(t[0].kind == TokenKind::name);
  CHECK(t[0].text == "ABC∆1");
  CHECK(t[1].kind == TokenKind::system_name);
  CHECK(t[1].text == "⎕IO");
  CHECK(t[2].kind == TokenKind::quad);
  CHECK(t[3].kind == TokenKind::quote_quad);
}

TEST_CASE("symbols, brackets, the products' jot and dot, and comments") {
  auto t = tokenize(U"X[1;]←+/∘.×A+.×B ⍝ a comment");
  std::vector<TokenKind> kinds;
  for (const auto& k : t) kinds.push_back(k.kind);
  CHECK(kinds == std::vector<TokenKind>{TokenKind::name, TokenKind::left_bracket, TokenKind::number,
                                        TokenKind::semicolon, TokenKind::right_bracket,
                                        TokenKind::assign, TokenKind::function, TokenKind::function,
                                        TokenKind::jot, TokenKind::dot, TokenKind::function,
                                        TokenKind::name, TokenKind::function, TokenKind::dot,
                                        TokenKind::function, TokenKind::name});
  CHECK(t[12].column == 12);
  CHECK(tokenize(U"⍝ only a comment").empty());
  CHECK(tokenize(U"L: →L").at(1).kind == TokenKind::colon);
  CHECK(tokenize(U"1+2\r").size() == 3);
}

TEST_CASE("malformed lines: SYNTAX ERROR at the offending character") {
  CHECK(failure(U"'ABC") == std::pair{ErrorKind::syntax, std::size_t{0}});
  CHECK(failure(U"1+'AB") == std::pair{ErrorKind::syntax, std::size_t{2}});
  CHECK(failure(U"1.2.3").first == ErrorKind::syntax);
  CHECK(failure(U"3A").first == ErrorKind::syntax);
  CHECK(failure(U"2+$") == std::pair{ErrorKind::syntax, std::size_t{2}});
  CHECK(failure(U"¯").first == ErrorKind::syntax);
  CHECK(failure(U"1E400").first == ErrorKind::domain);
  CHECK(strip_comment(U"A←'⍝' ⍝ note") == U"A←'⍝' ");
}

}  // namespace igds::apl::test
