// Decimal text without a FORTRAN format (workspace/numbers/decimal.h): the shortest reals of IGES
// and STEP checked against std::to_chars on millions of values of every kind, and the integers of
// HP-GL and SVG.
#include "workspace/numbers/decimal.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <random>
#include <string>

#include "tests/numbers/values.h"

namespace igds::test {

namespace {

// IGES and STEP's real by std::to_chars's shortest form: the point added, e+20 as E20, e-07 as
// E-7.
std::string real_by_to_chars(double v) {
  if (v == 0) v = 0;
  char text[64];
  const char* end = std::to_chars(text, text + sizeof text, v).ptr;
  std::string s(static_cast<const char*>(text), end), out;
  const std::size_t e = s.find('e');
  out = s.substr(0, e);
  if (out.find('.') == std::string::npos) out += '.';
  if (e != std::string::npos) {
    out += 'E';
    std::size_t k = e + 1;
    if (s[k] == '-') out += '-';
    if (s[k] == '-' || s[k] == '+') ++k;
    while (k + 1 < s.size() && s[k] == '0') ++k;
    out += s.substr(k);
  }
  return out;
}

std::string real_of(double v) {
  char buffer[64];
  return std::string(buffer, format_real(buffer, v));
}

}  // namespace

TEST_CASE("The shortest reals of IGES and STEP: exactly std::to_chars's digits and layout" *
          doctest::test_suite("slow")) {
  std::size_t checked = 0;
  auto check = [&](double v) {
    if (!std::isfinite(v)) return true;
    ++checked;
    const std::string expected = real_by_to_chars(v), got = real_of(v);
    CHECK_MESSAGE(got == expected, std::bit_cast<std::uint64_t>(v));
    return got == expected;
  };
  for (double v : varied_values(400000))
    if (!check(v)) return;
  // Integers and their neighbours, where fixed and scientific forms are near in length.
  for (int e = 0; e < 22; ++e)
    for (double m : {1.0, 1.5, 12.0, 123.0, 1234567.0, 123456789012345.0}) {
      const double v = m * std::pow(10.0, e);
      for (double w : {v, -v, std::nextafter(v, 0.0), std::nextafter(v, 1e300)})
        if (!check(w)) return;
    }
  CHECK(checked > 1600000);
  CHECK(real_of(1e20) == "1.E20");
  CHECK(real_of(-2.5e-7) == "-2.5E-7");
  CHECK(real_of(123456.0) == "123456.");
  CHECK(real_of(0.001) == "0.001");
  CHECK(real_of(-0.0) == "0.");
  CHECK(real_of(5e-324) == "5.E-324");
  CHECK(real_of(-1.7976931348623157e308) == "-1.7976931348623157E308");
  CHECK(real_of(9007199254740993.0) == "9007199254740992.");  // beyond 2^53: the integer's digits
}

// A text of each form of the layout: the longest, the largest double, a point among the digits,
// zeros after the point, an exponent, sixteen digits before the point, an integer and its zeros
// (the most, five), a short fraction and an integer.
TEST_CASE("format_real writes no further than its 32 characters") {
  const double values[] = {-1.2345678901234567e-308,
                           -1.7976931348623157e308,
                           123.45678901234567,
                           -0.0001234567890123456,
                           1e21,
                           4503599627370495.5,
                           -1234567890100000.0,
                           0.1,
                           -7.0};
  for (double v : values) {
    char buffer[64];
    std::fill(std::begin(buffer), std::end(buffer), '#');
    const std::size_t n = format_real(buffer, v);
    CHECK(std::string(buffer, n) == real_by_to_chars(v));
    CHECK(n <= 24);
    CHECK(std::string(buffer + 32, 32) == std::string(32, '#'));
  }
}

TEST_CASE("the integers' reals are made once and are format_real's") {
  const IntegerReals reals(1000);
  for (std::size_t k = 0; k <= 1000; ++k) CHECK(reals[k] == real_of(double(k)));
  CHECK(reals[0] == "0.");
  CHECK(reals[1000] == "1000.");
}

TEST_CASE("the integers of HP-GL and SVG as std::to_chars writes them") {
  auto pair = [](int x, int y) {
    char text[32];
    return std::string(text, put_pair(text, x, y));
  };
  auto expected = [](int x, int y) { return std::to_string(x) + "," + std::to_string(y); };
  for (int v = -1100; v <= 1100; ++v) CHECK(pair(v, -v) == expected(v, -v));
  std::mt19937 random(2);
  for (int k = 0; k < 100000; ++k) {
    const auto x = static_cast<int>(random()), y = static_cast<int>(random()) >> (k % 31);
    CHECK(pair(x, y) == expected(x, y));
  }
  CHECK(pair(INT_MIN, INT_MAX) == "-2147483648,2147483647");
}

}  // namespace igds::test
