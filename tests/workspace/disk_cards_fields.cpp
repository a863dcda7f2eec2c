// WRITE's I5 and F10.3 fields (workspace/disk/cards.h), written by integer arithmetic, against
// fmt, which converts the exact binary value with halves to even: tens of millions of values of
// every magnitude, the exact halves, the edges of the ten columns, the tiny, the signed zeros.
#include <doctest/doctest.h>

#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include <fmt/format.h>

#include "workspace/disk/cards.h"

using namespace igds;

namespace {

// F10.3 as fmt writes it, with ten asterisks when it takes more than ten columns.
std::string by_fmt(double v) {
  if (std::isnan(v)) return fmt::format("{:>10}", "NaN");
  if (std::isinf(v)) return fmt::format("{:>10}", v < 0 ? "-Infinity" : "Infinity");
  char text[400];
  auto r = fmt::format_to_n(text, sizeof text, "{:10.3f}", v);
  if (r.size > 10) return std::string(10, '*');
  return std::string(text, r.size);
}

// Compares put_f10_3 with fmt on every value `next` gives, counting the disagreements and
// remembering the first.
struct Comparison {
  std::size_t values = 0, wrong = 0;
  double first_wrong = 0;
  std::string ours, theirs;

  void check(double v) {
    ++values;
    char ours_text[10];
    bool fits = disk::put_f10_3(ours_text, v);
    std::string expected = by_fmt(v);
    bool expected_fits = expected != std::string(10, '*');
    if (std::memcmp(ours_text, expected.data(), 10) == 0 && fits == expected_fits) return;
    if (wrong++ == 0) first_wrong = v, ours.assign(ours_text, 10), theirs = expected;
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
  CHECK(disk::put_f10_3(field, -0.0));
  CHECK(std::string(field, 10) == "    -0.000");
  CHECK(!disk::put_f10_3(field, -99999.9996));
  CHECK(std::string(field, 10) == "**********");
}

TEST_CASE("I5 by integer arithmetic agrees with fmt") {
  std::size_t wrong = 0;
  auto check = [&](long long v, int width) {
    char field[32];
    bool fits = disk::put_i(field, v, width);
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
  CHECK(disk::format_i(-12345, 5) == "*****");
  CHECK(disk::format_i(LLONG_MIN, 20) == "-9223372036854775808");
}
