#include "workspace/numbers/typed.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <system_error>
#include <type_traits>

#include <fmt/format.h>

#include "workspace/numbers/digits.h"

namespace igds {

namespace {

using numbers::exact_power;

constexpr std::string_view high_minus = "\xC2\xAF";  // U+00AF in UTF-8

// The code units of a high minus at p (0: none there).
std::size_t high_minus_at(const char* p, const char* end) {
  return end - p >= 2 && p[0] == high_minus[0] && p[1] == high_minus[1] ? 2 : 0;
}
std::size_t high_minus_at(const char32_t* p, const char32_t* end) {
  return p != end && *p == U'\u00AF' ? 1 : 0;
}

template <class Char>
std::uint32_t code(Char c) {
  return static_cast<std::uint32_t>(static_cast<std::make_unsigned_t<Char>>(c));
}

template <class Char>
ScannedNumber scan(const Char* const begin, const Char* const end, NumberSigns signs) {
  const Char* p = begin;
  // A high minus, or a '+' before the digits: from_chars takes neither.
  bool rewrite = !std::is_same_v<Char, char>;
  auto sign = [&] {  // true for a minus
    if (const std::size_t w = high_minus_at(p, end)) {
      p += w;
      rewrite = true;
      return true;
    }
    if (signs == NumberSigns::typed && p != end && (*p == '-' || *p == '+')) {
      rewrite = rewrite || (p == begin && *p == '+');
      return *p++ == '-';
    }
    return false;
  };
  auto digit = [&](const Char* q) { return q != end && code(*q) - '0' < 10; };
  // The digits are gathered for the quick way: the value is significand x 10^(exponent - scale).
  std::uint64_t significand = 0;
  int significant = 0;  // digits in `significand`, its leading zeros not counted
  int scale = 0;
  const bool negative = sign();
  // The digits and the point in one loop: a loop ends with a mispredicted branch, and most
  // numbers have a point.
  std::size_t mantissa = 0;
  bool point = false;
  for (; p != end; ++p) {
    const auto d = code(*p) - '0';
    if (d < 10) {
      ++mantissa;
      if (significant < 19) {
        significand = 10 * significand + d;
        significant += significand != 0;
        scale += point;
      } else {
        significant = 20;  // more digits than the quick way takes
      }
    } else if (*p == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  if (mantissa == 0) return {};
  std::int64_t exponent = 0;
  if (p != end && (*p == 'E' || *p == 'e')) {
    const Char* e = p++;
    const bool down = sign();
    if (!digit(p)) {
      p = e;  // not an exponent: the number ends before the E
    } else {
      for (; digit(p); ++p)
        if (exponent < 100'000'000) exponent = 10 * exponent + (code(*p) - '0');
      if (down) exponent = -exponent;
    }
  }
  ScannedNumber out;
  out.length = static_cast<std::size_t>(p - begin);
  // The quick way (the usual case: a few digits, a small exponent): a whole significand up to
  // 2^53 and a power of ten up to 10^22 are both exact doubles, so one multiplication or
  // division rounds once, to the same double as from_chars.
  const std::int64_t power = exponent - scale;
  if (significant <= 19 && significand <= (std::uint64_t{1} << 53) && power >= -22 && power <= 22) {
    const double value = static_cast<double>(significand);
    out.value = power < 0 ? value / exact_power[-power] : value * exact_power[power];
    if (negative) out.value = -out.value;
    return out;
  }
  // Otherwise from_chars reads it: in place when it can, else a copy with the high minus as '-'
  // and without a leading '+'.
  std::string copy;
  std::string_view text;
  if constexpr (std::is_same_v<Char, char>) text = std::string_view(begin, out.length);
  if (rewrite) {
    copy.reserve(out.length);
    for (const Char* q = begin; q != p;) {
      if (const std::size_t w = high_minus_at(q, p)) {
        copy += '-';
        q += w;
      } else {
        if (!(q == begin && *q == '+')) copy += static_cast<char>(*q);
        ++q;
      }
    }
    text = copy;
  }
  const auto error = std::from_chars(text.data(), text.data() + text.size(), out.value).ec;
  if (error == std::errc::result_out_of_range) {
    // Beyond the doubles: an infinity when the first digit that is not zero stands at 10^0 or
    // above, a zero when below. Its place: the digits from it to the point, or the zeros after the
    // point before it.
    std::int64_t whole = 0, zeros = 0;
    bool point = false, nonzero = false;
    for (const char c : text.substr(negative ? 1 : 0)) {
      if (c == 'e' || c == 'E') break;
      if (c == '.') {
        point = true;
        continue;
      }
      nonzero = nonzero || c != '0';
      if (!point && nonzero) ++whole;
      if (point && !nonzero) ++zeros;
    }
    const std::int64_t magnitude = exponent + (whole > 0 ? whole - 1 : -zeros - 1);
    out.value = magnitude >= 0 ? std::numeric_limits<double>::infinity() : 0.0;
    if (negative) out.value = -out.value;
  }
  return out;
}

}  // namespace

ScannedNumber scan_number(std::string_view utf8, NumberSigns signs) {
  return scan(utf8.data(), utf8.data() + utf8.size(), signs);
}

ScannedNumber scan_number(std::u32string_view text, NumberSigns signs) {
  return scan(text.data(), text.data() + text.size(), signs);
}

std::string format_typed_number(double value) {
  if (std::isnan(value)) return "NAN";
  if (std::isinf(value)) return value > 0 ? "INF" : std::string(high_minus) + "INF";
  if (value == 0) return "0";
  std::string text = fmt::format("{:.10G}", std::fabs(value));
  // fmt writes 1.5E-07: APL writes 1.5E¯7.
  if (auto e = text.find('E'); e != std::string::npos) {
    std::string mantissa = text.substr(0, e);
    int exponent = std::atoi(text.c_str() + e + 1);
    text = mantissa + "E" + (exponent < 0 ? std::string(high_minus) : "") +
           std::to_string(std::abs(exponent));
  }
  return value < 0 ? std::string(high_minus) + text : text;
}

}  // namespace igds
