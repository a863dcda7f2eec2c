// The exchange files' numbers (workspace/exchange/fields.h) made by fast paths: each checked
// against an independent exact formatting (the C library's printf, std::to_chars) on millions of
// values of every kind: random bits, decimals of few digits, exact ties, the edges of a decade.
#include "workspace/exchange/fields.h"

#include <doctest/doctest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace igds::test::exchange {

namespace {

// E14.7's text by printf's exact rounding: -d.dddddde+XX rearranged as -0.ddddddd with the
// exponent one higher, E+ee, or +eee without the E.
std::string exponent_by_printf(double v, int digits) {
  if (v == 0) return "0." + std::string(std::size_t(digits), '0') + "E+00";
  char text[64];
  std::snprintf(text, sizeof text, "%.*e", digits - 1, v);
  std::string s = text;
  std::string out;
  std::size_t k = 0;
  if (s[k] == '-') out += s[k++];
  out += "0.";
  out += s[k++];
  if (s[k] == '.') ++k;
  while (s[k] != 'e') out += s[k++];
  const int e = std::stoi(s.substr(k + 1)) + 1;
  const int m = std::abs(e);
  if (m < 100) out += 'E';
  out += e < 0 ? '-' : '+';
  if (m >= 100) out += char('0' + m / 100);
  out += char('0' + m / 10 % 10);
  out += char('0' + m % 10);
  return out;
}

std::string exponent_of(double v, int digits) {
  char buffer[64];
  return std::string(buffer, format_exponent(buffer, v, digits));
}

// The values to check: random bits, random decimals of few digits (the coordinates people
// type), exact binary ties of 7 digits, and the neighbours of powers of ten.
std::vector<double> values(std::size_t count) {
  std::mt19937_64 random(1975);
  std::vector<double> v;
  for (std::size_t k = 0; k < count; ++k) {
    v.push_back(std::bit_cast<double>(random()));
    const int exponent = int(random() % 40) - 20;
    v.push_back(double(std::int64_t(random() % 20000001) - 10000000) * std::pow(10.0, exponent));
    v.push_back(double(random() % 100000000) / 1000.0);
    v.push_back((double(random() % 9000000) + 1000000.5) * std::pow(2.0, int(random() % 20) - 10));
  }
  for (int e = -30; e <= 30; ++e) {
    double p = std::pow(10.0, e);
    for (int k = 0; k < 8; ++k) {
      v.push_back(p);
      v.push_back(-p);
      v.push_back(p * (1 - 5e-8));
      v.push_back(p * (1 - 4.9999999e-8));
      p = std::nextafter(p, 0.0);
    }
  }
  return v;
}

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
  for (double v : values(400000))
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
}

TEST_CASE("E14.7 and the other Ew.d: exactly the digits printf rounds to" *
          doctest::test_suite("slow")) {
  std::size_t checked = 0;
  for (double v : values(100000)) {
    if (!std::isfinite(v)) continue;
    for (int digits : {7, 1, 9, 12}) {
      const std::string expected = exponent_by_printf(v, digits);
      const std::string got = exponent_of(v, digits);
      if (got != expected) {
        CHECK_MESSAGE(got == expected, std::bit_cast<std::uint64_t>(v), " digits ", digits);
        return;
      }
      ++checked;
    }
  }
  CHECK(checked > 1500000);
  CHECK(exponent_of(1234567.5, 7) == "0.1234568E+07");  // a tie: to even
  CHECK(exponent_of(1234568.5, 7) == "0.1234568E+07");
  CHECK(exponent_of(9999999.5, 7) == "0.1000000E+08");
  CHECK(exponent_of(0.09999996, 7) == "0.9999996E-01");
}

}  // namespace igds::test::exchange
