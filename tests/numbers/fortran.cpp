// FORTRAN's fields (workspace/numbers/fortran.h). Iw and Fw.d against fmt, which converts the
// exact binary value with halves to even: tens of millions of values of every magnitude, the exact
// halves, the edges of WRITE's ten columns, the tiny, the signed zeros; Ew.d against printf; the
// forms that keep the whole value; the readers, and what the writers write read back.
#include <doctest/doctest.h>

#include <bit>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include <fmt/format.h>

#include "tests/numbers/values.h"
#include "workspace/numbers/decimal.h"
#include "workspace/numbers/fortran.h"

using namespace igds;
using namespace igds::fortran;

namespace {

// Fw.d as fmt writes it (the point kept when d is 0), with w asterisks when it takes more than w
// columns; NaN and the infinities as gfortran writes them.
std::string by_fmt(double v, int w, int d) {
  const std::string stars(std::size_t(w), '*');
  if (!std::isfinite(v)) {
    const std::string word = std::isnan(v) ? "NaN"
                             : v > 0       ? (w >= 8 ? "Infinity" : "Inf")
                                           : (w >= 9 ? "-Infinity" : "-Inf");
    return int(word.size()) > w ? stars : fmt::format("{:>{}}", word, w);
  }
  char text[400];
  auto r = d == 0 ? fmt::format_to_n(text, sizeof text, "{:#{}.0f}", v, w)
                  : fmt::format_to_n(text, sizeof text, "{:{}.{}f}", v, w, d);
  if (r.size > std::size_t(w)) return stars;
  return std::string(text, r.size);
}

// Compares put_f with fmt in Fw.d (F10.3, WRITE's, unless said) on every value checked, counting
// the disagreements and remembering the first.
struct Comparison {
  int w = 10, d = 3;
  std::size_t values = 0, wrong = 0;
  double first_wrong = 0;
  std::string ours, theirs;

  void check(double v) {
    ++values;
    char ours_text[64];
    bool fits = put_f(ours_text, v, w, d);
    std::string expected = by_fmt(v, w, d);
    bool expected_fits = expected != std::string(std::size_t(w), '*');
    if (std::memcmp(ours_text, expected.data(), std::size_t(w)) == 0 && fits == expected_fits)
      return;
    if (wrong++ == 0) first_wrong = v, ours.assign(ours_text, std::size_t(w)), theirs = expected;
  }
  void report() const {
    INFO("values compared: ", values);
    INFO("first disagreement: ",
         fmt::format("{:.17g} ours '{}' fmt '{}'", first_wrong, ours, theirs));
    CHECK(wrong == 0);
  }
};

double from_bits(std::uint64_t b) {
  return std::bit_cast<double>(b);
}

// `count` doubles on either side of v, one ulp apart, v included.
template <class F>
void around(double v, int count, F&& f) {
  double up = v, down = v;
  f(v);
  for (int i = 0; i < count; ++i) {
    up = std::nextafter(up, INFINITY);
    down = std::nextafter(down, -INFINITY);
    f(up);
    f(down);
  }
}

}  // namespace

TEST_CASE("F10.3 by integer arithmetic: random doubles of every magnitude agree with fmt" *
          doctest::test_suite("slow")) {
  Comparison c;
  std::mt19937_64 rng(1975);
  // Every bit pattern alike: NaNs, infinities, subnormals, the huge and the tiny.
  for (int i = 0; i < 300'000; ++i) c.check(from_bits(rng()));
  // Magnitudes where the digits show, 2^-40 to 2^21, each sign and mantissa at random.
  std::uniform_int_distribution<int> exponent(1023 - 40, 1023 + 21);
  for (int i = 0; i < 10'000'000; ++i) {
    std::uint64_t b =
        (rng() & 0x800F'FFFF'FFFF'FFFFull) | (static_cast<std::uint64_t>(exponent(rng)) << 52);
    c.check(from_bits(b));
  }
  // Decimal-looking values: k / 10^d as parsed, and one ulp either side.
  std::uniform_int_distribution<long long> k(-999'999'999'999, 999'999'999'999);
  std::uniform_int_distribution<int> d(0, 9);
  static constexpr double tens[] = {1, 10, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  for (int i = 0; i < 2'000'000; ++i)
    around(static_cast<double>(k(rng)) / tens[d(rng)], 1, [&](double v) { c.check(v); });
  c.report();
}

TEST_CASE("F10.3 by integer arithmetic: exact halves and values beside them agree with fmt" *
          doctest::test_suite("slow")) {
  Comparison c;
  // A double is an exact half of a thousandth only as an odd multiple of 1/16 (1000 = 2^3 125):
  // every such value from -100000 to 100000, and some up to 1000000 with their neighbours.
  for (long long k = -1'600'000; k <= 1'600'000; ++k) c.check(static_cast<double>(k) / 16);
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<long long> sixteenths(-1'600'016, 16'000'016);
  for (int i = 0; i < 1'000'000; ++i)
    around(static_cast<double>(sixteenths(rng)) / 16, 2, [&](double v) { c.check(v); });
  // k + 0.0005 style values: the nearest double to each half, and one and two ulps off.
  std::uniform_int_distribution<long long> thousandths(-100'000'000, 1'000'000'000);
  for (int i = 0; i < 1'000'000; ++i)
    around((static_cast<double>(thousandths(rng)) + 0.5) / 1000, 2, [&](double v) { c.check(v); });
  // Multiples of 2^-n: the values whose last bits decide a rounding.
  std::uniform_int_distribution<int> n(1, 70);
  std::uniform_int_distribution<long long> j(-(1ll << 53), 1ll << 53);
  for (int i = 0; i < 2'000'000; ++i) c.check(std::ldexp(static_cast<double>(j(rng)), -n(rng)));
  c.report();
}

TEST_CASE("F10.3 by integer arithmetic: the edges of ten columns, tiny values, signed zeros" *
          doctest::test_suite("slow")) {
  Comparison c;
  // Where the asterisks begin: 1000000.000 and up, -100000.000 and down after rounding.
  for (double edge : {999999.9995, 1e6, 999999.999, -99999.9995, -1e5, -99999.999})
    around(edge, 200'000, [&](double v) { c.check(v); });
  // Around the roundings to 0.001 and to zero, and the subnormals.
  for (double edge : {0.0005, -0.0005, 0.0015, -0.0015, 0.001, -0.001})
    around(edge, 100'000, [&](double v) { c.check(v); });
  for (std::uint64_t b = 0; b < 200'000; ++b) {
    c.check(from_bits(b));
    c.check(from_bits(b | (std::uint64_t{1} << 63)));
  }
  for (int e = -1074; e <= 1023; ++e)
    around(std::ldexp(1.0, e), 3, [&](double v) {
      c.check(v);
      c.check(-v);
    });
  c.check(0.0);
  c.check(-0.0);
  c.check(std::numeric_limits<double>::max());
  c.check(std::numeric_limits<double>::lowest());
  c.check(INFINITY);
  c.check(-INFINITY);
  c.check(std::nan(""));
  c.check(-std::nan(""));
  c.report();

  char field[10];
  CHECK(put_f(field, -0.0, 10, 3));
  CHECK(std::string(field, 10) == "    -0.000");
  CHECK(!put_f(field, -99999.9996, 10, 3));
  CHECK(std::string(field, 10) == "**********");
}

TEST_CASE("Fw.d of other widths and decimals agrees with fmt, by the library beyond 3 decimals" *
          doctest::test_suite("slow")) {
  std::mt19937_64 rng(10);
  for (const auto& [w, d] : {std::pair{4, 0},
                             {7, 1},
                             {10, 1},
                             {8, 2},
                             {12, 3},
                             {10, 4},
                             {14, 6},
                             {30, 3},
                             {25, 0},
                             {3, 1},
                             {2, 0}}) {
    Comparison c;
    c.w = w;
    c.d = d;
    for (int i = 0; i < 50'000; ++i) c.check(from_bits(rng()));
    std::uniform_int_distribution<int> exponent(1023 - 20, 1023 + 60);
    for (int i = 0; i < 100'000; ++i)
      c.check(from_bits((rng() & 0x800F'FFFF'FFFF'FFFFull) |
                        (static_cast<std::uint64_t>(exponent(rng)) << 52)));
    for (long long k = -20'000; k <= 20'000; ++k) c.check(static_cast<double>(k) / 16);
    for (double v : {0.0, -0.0, 0.5, -0.5, 1e15, 4503599627370496.0, 9007199254740993.0, 1e22})
      c.check(v);
    CAPTURE(c.w);
    CAPTURE(c.d);
    c.report();
  }
}

TEST_CASE("Fw.d as gfortran writes it: the point, the zero before it, signs, halves, asterisks") {
  auto f = [](double v, int w, int d) {
    char text[64];
    put_f(text, v, w, d);
    return std::string(text, std::size_t(w));
  };
  CHECK(f(1, 4, 0) == "  1.");
  CHECK(f(15, 4, 0) == " 15.");
  CHECK(f(0.4, 4, 0) == "  0.");
  CHECK(f(-0.4, 4, 0) == " -0.");
  CHECK(f(12.25, 7, 1) == "   12.2");  // the exact binary value, halves to even
  CHECK(f(12.75, 7, 1) == "   12.8");
  CHECK(f(0.0625, 10, 3) == "     0.062");
  CHECK(f(-0.04, 7, 1) == "   -0.0");  // rounds to zero, keeps its sign
  CHECK(f(-0.0, 7, 1) == "   -0.0");
  CHECK(f(0.5, 7, 1) == "    0.5");
  CHECK(f(0.5, 3, 1) == "0.5");
  CHECK(f(0.5, 2, 1) == "**");  // no room for the zero before the point: asterisks
  CHECK(f(-99999.9, 7, 1) == "*******");
  CHECK(f(999999.9, 10, 1) == "  999999.9");
  CHECK(f(1e300, 10, 3) == "**********");
  CHECK(f(1e20, 25, 3) == "100000000000000000000.000");
  CHECK(f(1e20, 24, 3) == std::string(24, '*'));
  CHECK(f(5e-324, 10, 3) == "     0.000");
  CHECK(f(1.0, 0, 0).empty());
  // NaN and the infinities: "Infinity" in 8 columns (9 with its minus), else "Inf"; "NaN" in 3.
  CHECK(f(std::nan(""), 7, 1) == "    NaN");
  CHECK(f(std::nan(""), 3, 1) == "NaN");
  CHECK(f(std::nan(""), 2, 1) == "**");
  CHECK(f(INFINITY, 8, 1) == "Infinity");
  CHECK(f(INFINITY, 7, 1) == "    Inf");
  CHECK(f(-INFINITY, 9, 1) == "-Infinity");
  CHECK(f(-INFINITY, 8, 1) == "    -Inf");
  CHECK(f(-INFINITY, 3, 1) == "***");
  char field[8];
  CHECK(put_f(field, INFINITY, 3, 0));
  CHECK_FALSE(put_f(field, INFINITY, 2, 0));
}

TEST_CASE("I5 by integer arithmetic agrees with fmt") {
  std::size_t wrong = 0;
  auto check = [&](long long v, int width) {
    char field[32];
    bool fits = put_i(field, v, width);
    std::string expected = fmt::format("{:>{}}", v, width);
    bool expected_fits = static_cast<int>(expected.size()) <= width;
    if (!expected_fits) expected = std::string(static_cast<std::size_t>(width), '*');
    if (fits != expected_fits || std::string(field, static_cast<std::size_t>(width)) != expected) {
      if (wrong++ == 0) FAIL_CHECK(fmt::format("{} in {} columns", v, width));
    }
  };
  for (long long v = -200'000; v <= 200'000; ++v) check(v, 5);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 1'000'000; ++i)
    check(static_cast<long long>(rng()) >> (rng() % 64), static_cast<int>(rng() % 22));
  for (long long v : {LLONG_MIN, LLONG_MIN + 1, LLONG_MAX, 0ll, -1ll, 99999ll, -9999ll, -10000ll})
    for (int width = 0; width <= 21; ++width) check(v, width);
  CHECK(wrong == 0);
  char field[20];
  CHECK_FALSE(put_i(field, -12345, 5));
  CHECK(std::string(field, 5) == "*****");
  CHECK(put_i(field, LLONG_MIN, 20));
  CHECK(std::string(field, 20) == "-9223372036854775808");
}

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

// What a whole-value writer puts in a field of one column: the text itself, after its blank when
// it is wider.
template <class Put>
std::string bare(const Put& put) {
  char buffer[512];
  std::string s(buffer, std::size_t(put(buffer) - buffer));
  return s.size() > 1 && s[0] == ' ' ? s.substr(1) : s;
}

std::string exponent_of(double v, int digits) {
  return bare([&](char* w) { return put_e_whole(w, v, 1, digits); });
}

}  // namespace

TEST_CASE("Ew.d: exactly the digits printf rounds to" * doctest::test_suite("slow")) {
  std::size_t checked = 0;
  for (double v : test::varied_values(100000)) {
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

TEST_CASE("Ew.d in fields of any width: right-justified, or the whole text after a blank") {
  // The text written in place (its sign's column a blank or a minus) is the bare text padded.
  std::size_t checked = 0;
  const std::vector<double> values = test::varied_values(5000);
  for (double v : values) {
    for (int digits : {1, 4, 7, 9, 12}) {
      const std::string text = exponent_of(v, digits);
      for (int width : {1, 8, 12, 13, 14, 15, 20}) {
        const std::string expected =
            int(text.size()) > width ? " " + text : std::string(width - text.size(), ' ') + text;
        char buffer[64];
        const std::string got(buffer, put_e_whole(buffer, v, width, digits));
        if (got != expected) {
          CHECK_MESSAGE(got == expected, std::bit_cast<std::uint64_t>(v), " E", width, ".", digits);
          return;
        }
        ++checked;
      }
    }
  }
  CHECK(checked == values.size() * 5 * 7);
}

TEST_CASE("fields that keep the whole value: widths, exponents, overflow") {
  std::string s;
  char buffer[64];
  auto e = [&](double v) { s.append(buffer, put_e_whole(buffer, v, 14, 7)); };
  for (double v : {12.5, -0.001234567, 0.0, -0.0, 1e100, -2.5e-200, 9.99999996}) e(v);
  CHECK(s ==
        " 0.1250000E+02-0.1234567E-02 0.0000000E+00 0.0000000E+00 0.1000000+101-0.2500000-199"
        " 0.1000000E+02");
  s.clear();
  put_f_whole(s, -2.07107, 10, 4);
  put_f_whole(s, 123456.75, 10, 4);  // too wide: in full after a blank
  put_f_whole(s, -0.00001, 10, 4);   // rounds to zero, keeps its sign
  put_f_whole(s, -0.0, 10, 4);       // a zero has none
  put_i_whole(s, -12345, 6);
  put_i_whole(s, 1234567, 6);
  CHECK(s == "   -2.0711 123456.7500   -0.0000    0.0000-12345 1234567");
  s.clear();
  // Beyond 24 characters, Fw.d is the shortest exact form.
  put_f_whole(s, 1.875e200, 10, 4);
  put_f_whole(s, -1e30, 10, 3);
  put_f_whole(s, 123456789012345678.0, 10, 3);
  CHECK(s == " 1.875E200    -1.E30 123456789012345680.000");
  s.clear();
  put_f_whole(s, std::nan(""), 10, 4);
  put_f_whole(s, -INFINITY, 10, 4);
  s.append(buffer, put_e_whole(buffer, INFINITY, 14, 7));
  CHECK(s == "       NaN -Infinity      Infinity");
  CHECK(bare([](char* w) { return put_i_whole(w, 5, 1); }) == "5");
  CHECK(bare([](char* w) { return put_f_whole(w, 5, 1, 1); }) == "5.0");
}

TEST_CASE("Fw.d that keeps the whole value: by integer arithmetic to 3 decimals, as the library") {
  // The whole form's text is the library's (std::to_chars, exact) whatever the path.
  std::size_t checked = 0;
  for (double v : test::varied_values(50000)) {
    if (!std::isfinite(v) || v == 0) continue;
    for (int d : {1, 2, 3, 4}) {
      char text[400];
      const auto r = std::to_chars(text, text + sizeof text, v, std::chars_format::fixed, d);
      std::string expected(text, r.ptr);
      if (expected.size() > 24) continue;
      const std::string got = bare([&](char* w) { return put_f_whole(w, v, 1, d); });
      if (got != expected) {
        CHECK_MESSAGE(got == expected, std::bit_cast<std::uint64_t>(v), " decimals ", d);
        return;
      }
      ++checked;
    }
  }
  CHECK(checked > 300000);
}

TEST_CASE("input fields: blanks, implied decimal point, exponents") {
  CHECK(read_i("   7  12", 0, 4) == 7);
  CHECK(read_i("   7  12", 4, 4) == 12);
  CHECK(read_i("  -3", 0, 4) == -3);
  CHECK(read_i("", 0, 4) == 0);       // a short card is padded with blanks
  CHECK(read_i("1 2 ", 0, 4) == 12);  // blanks ignored (BLANK='NULL')
  CHECK(read_i(" + 7", 0, 4) == 7);
  CHECK_FALSE(read_i("  1.", 0, 4));
  CHECK_FALSE(read_i("   -", 0, 4));
  CHECK_FALSE(read_i(" +-5", 0, 4));
  CHECK(read_f("   12.5", 0, 7, 1) == 12.5);
  CHECK(read_f("    125", 0, 7, 1) == 12.5);  // no point: the last digit is the fraction
  CHECK(read_f("      5", 0, 7, 1) == 0.5);
  CHECK(read_f("     -5", 0, 7, 1) == -0.5);
  CHECK(read_f("      5", 0, 7, 3) == 0.005);
  CHECK(read_f("  1 2 5", 0, 7, 1) == 12.5);  // blanks inside ignored
  CHECK(read_f("    1. ", 0, 7, 1) == 1.0);
  CHECK(read_f("  1.5E2", 0, 7, 1) == 150.0);
  CHECK(read_f("  1.5+2", 0, 7, 1) == 150.0);
  CHECK(read_f("   15+2", 0, 7, 1) == 150.0);  // the implied point, then the exponent
  CHECK(read_f(" 25D-1 ", 0, 7, 1) == 0.25);   // 2.5 x 10^-1
  CHECK(read_f(" 1.5d02", 0, 7, 1) == 150.0);
  CHECK(read_f("  1.", 0, 4, 0) == 1.0);
  CHECK(read_f("   3", 0, 4, 0) == 3.0);
  CHECK(read_f("       ", 0, 7, 1) == 0.0);
  CHECK(read_f("xx", 5, 7, 1) == 0.0);  // past the card's end
  CHECK(read_f("1234567890", 7, 7, 1) == 89.0);
  CHECK(std::signbit(*read_f("   -0.", 0, 6, 1)));
  for (const char* bad : {"  1.2.3", "    abc", "      +", "      .", "  1E999", "  1.5E ",
                          "  1\t5  ", "  1-2-3", " 1.5E+ "}) {
    CAPTURE(bad);
    CHECK_FALSE(read_f(bad, 0, 7, 1));
  }
}

TEST_CASE("list-directed values: separators, FORTRAN's exponents, integers") {
  for (const auto& [text, value] :
       std::vector<std::pair<const char*, double>>{{"0.1250000E+02", 12.5},
                                                   {"0.1D+02", 10},
                                                   {"0.1d-02", 0.001},
                                                   {"0.1000000+101", 1e100},
                                                   {"0.25-3", 0.00025},
                                                   {"+.5", 0.5},
                                                   {"5.", 5},
                                                   {"-7", -7},
                                                   {"1E5", 1e5},
                                                   {"1.E20", 1e20},
                                                   {"4.9E-324", 5e-324}})
    CHECK(read_real(text) == value);
  for (const char* bad : {"", "1e", "e5", "1.2.3", "nan", "inf", "--1", "+-1", "1e999", "0x10",
                          "1 2", "1,2", ".", "-", "1E+", "12a", " 1"})
    CHECK_FALSE(read_real(bad));
  CHECK(read_real(std::string(125, '1')));
  CHECK_FALSE(read_real(std::string(126, '1')));
  CHECK(read_integer("+42") == 42);
  CHECK(read_integer("-2048") == -2048);
  CHECK(read_integer("-9223372036854775808") == LLONG_MIN);
  for (const char* bad : {"", "+", "-", "4.0", "1e3", "99999999999999999999", "+-3", "12 "})
    CHECK_FALSE(read_integer(bad));
  std::string_view values[3];
  CHECK(split_values(" 1, 2\t,,3  4 ", values, 3) == 4);
  CHECK(values[0] == "1");
  CHECK(values[1] == "2");
  CHECK(values[2] == "3");
  CHECK(split_values(" ,\t ", values, 3) == 0);
}

TEST_CASE("reals in Fw.d's input columns at any magnitude: the form, the digits, read back") {
  CHECK(input_text(123456.789, 0) == "123456.789");
  CHECK(input_text(0.0125, 0) == "0.0125");
  CHECK(input_text(0.00125, 0) == "1.25E-3");
  CHECK(input_text(1e-5, 0) == "1.E-5");
  CHECK(input_text(-1.2345678e-6, 6) == "-1.23457E-6");
  CHECK(input_text(987654321.0, 7) == "9.876543E8");
  CHECK(input_text(1e6, 0) == "1.E6");
  CHECK(input_text(-0.0, 0) == "0.");
  CHECK(input_text(0.5, 0) == "0.5");
  char field[10];
  auto put = [&](double v) {
    REQUIRE(put_f_input(field, v, 10, 4));
    return std::string(field, 10);
  };
  CHECK(put(25.2207) == "   25.2207");        // F10.4 when it reads back as the value
  CHECK(put(1234.56789012) == "1234.56789");  // or the most digits that fit
  CHECK(put(0.7071067811865476) == "0.70710678");
  CHECK(put(123456.789) == "123456.789");
  CHECK(put(-98765.4321) == "-98765.432");
  CHECK(put(1.25e-7) == "   1.25E-7");
  CHECK(put(-1.2345678e300) == "-1.235E300");
  CHECK(put(-0.0) == "    0.0000");
  CHECK(!put_f_input(field, NAN, 10, 4));
  CHECK(std::string(field, 10) == "**********");
  // Whatever the value, read_f reads the field as the nearest value of at least 3 significant
  // digits (a negative value with a 3-digit exponent), 5 from 1e-6 to 1e9.
  std::mt19937_64 random(37);
  auto check = [&](double v, double within) {
    const std::string text = put(v);
    const auto back = read_f(text, 0, 10, 4);
    REQUIRE(back);
    CAPTURE(text);
    CHECK(std::abs(*back - v) <= within * std::abs(v));
  };
  for (int n = 0; n < 200000; ++n) {
    const double v = std::bit_cast<double>(random());
    if (std::isfinite(v) && v != 0) check(v, 5e-3);
    const double m = std::pow(10.0, std::uniform_real_distribution<double>(-6, 9)(random));
    check(n % 2 ? m : -m, 5e-5);
  }
}

TEST_CASE("what the writers write reads back") {
  std::size_t checked = 0;
  for (double v : test::varied_values(50000)) {
    if (!std::isfinite(v)) continue;
    // The shortest exact real is the same double to a list-directed reader.
    char text[64];
    const std::size_t n = format_real(text, v);
    const auto back = read_real({text, n});
    REQUIRE(back);
    CHECK(std::bit_cast<std::uint64_t>(*back) == std::bit_cast<std::uint64_t>(v == 0 ? 0.0 : v));
    // E14.7 and F10.3 read back as their own text does: the value to their digits.
    const std::string e = exponent_of(v, 7);
    const auto e_back = read_f(e, 0, e.size(), 0);
    REQUIRE(e_back);
    CHECK(std::abs(*e_back - v) <= std::abs(v) * 5.0001e-7);
    char field[10];
    if (put_f(field, v, 10, 3)) {
      const auto f_back = read_f({field, 10}, 0, 10, 3);
      REQUIRE(f_back);
      CHECK(std::abs(*f_back - v) <= 0.0005 + std::abs(v) * 1e-15);
    }
    ++checked;
  }
  CHECK(checked > 200000);
  // Thousandths written in F10.3 read back as the same double.
  for (long long k = -99'999'999; k <= 999'999'999; k += 9'973) {
    const double v = double(k) / 1000;
    char field[10];
    REQUIRE(put_f(field, v, 10, 3));
    CHECK(read_f({field, 10}, 0, 10, 3) == v);
  }
}
