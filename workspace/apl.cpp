#include "workspace/apl.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <system_error>

namespace igds {

namespace {
constexpr std::string_view high_minus = "\xC2\xAF";  // U+00AF in UTF-8
}

std::optional<double> parse_apl_number(std::string_view word) {
  // Checked first: only one sign per mantissa and exponent (high minus, '-' or '+'), digits and
  // at most one point before the exponent. The digits are gathered meanwhile for the quick way.
  const char* p = word.data();
  const char* const end = p + word.size();
  bool rewrite = false;  // a high minus, or a '+' before the mantissa (from_chars takes neither)
  auto sign = [&](bool exponent) {  // true for a minus
    if (end - p >= 2 && p[0] == high_minus[0] && p[1] == high_minus[1]) {
      p += 2;
      rewrite = true;
      return true;
    }
    if (p != end && (*p == '-' || *p == '+')) {
      rewrite = rewrite || (*p == '+' && !exponent);
      return *p++ == '-';
    }
    return false;
  };
  auto digit = [&] { return p != end && static_cast<unsigned char>(*p - '0') < 10; };
  std::uint64_t significand = 0;
  int significant = 0;  // digits in `significand`, its leading zeros not counted
  int scale = 0;        // the value is significand x 10^(exponent - scale)
  auto digits = [&](bool fraction) {
    const char* start = p;
    for (; digit(); ++p) {
      if (significant < 19) {
        significand = 10 * significand + static_cast<unsigned>(*p - '0');
        significant += significand != 0;
        scale += fraction;
      } else {
        significant = 20;  // more digits than the quick way takes
      }
    }
    return p - start;
  };
  const bool negative = sign(false);
  auto mantissa = digits(false);
  if (p != end && *p == '.') {
    ++p;
    mantissa += digits(true);
  }
  if (mantissa == 0) return std::nullopt;
  int exponent = 0;
  if (p != end && (*p == 'E' || *p == 'e')) {
    ++p;
    const bool down = sign(true);
    if (!digit()) return std::nullopt;
    for (; digit(); ++p)
      if (exponent < 10000) exponent = 10 * exponent + (*p - '0');
    if (down) exponent = -exponent;
  }
  if (p != end) return std::nullopt;
  // The quick way (the usual case: a few digits, a small exponent): a whole significand up to
  // 2^53 and a power of ten up to 10^22 are both exact doubles, so one multiplication or
  // division rounds once, to the same double as from_chars.
  static constexpr double powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const int power = exponent - scale;
  if (significant <= 19 && significand <= (std::uint64_t{1} << 53) && power >= -22 && power <= 22) {
    double value = static_cast<double>(significand);
    value = power < 0 ? value / powers[-power] : value * powers[power];
    return negative ? -value : value;
  }
  // Otherwise as other programs write it, read in place; else in from_chars's form.
  std::string text;
  if (rewrite) {
    text.reserve(word.size());
    for (std::size_t k = 0; k < word.size();) {
      if (word.substr(k).starts_with(high_minus)) {
        text += '-';
        k += high_minus.size();
      } else {
        if (!(k == 0 && word[k] == '+')) text += word[k];
        ++k;
      }
    }
    word = text;
  }
  double value = 0;
  const auto [last, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error == std::errc{} && last == word.data() + word.size()) return value;
  // Out of range: strtod's infinity or underflow, as before (an overflow is refused by the
  // caller with the point number).
  const std::string copy(word);
  return std::strtod(copy.c_str(), nullptr);
}

std::string format_apl_number(double value) {
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
