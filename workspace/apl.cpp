#include "workspace/apl.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <system_error>

namespace igds {

namespace {
constexpr std::string_view high_minus = "\xC2\xAF";  // U+00AF in UTF-8
}

std::optional<double> parse_apl_number(std::string_view word) {
  // Rewritten into from_chars's form as it is checked: high minus becomes '-', only one sign per
  // mantissa and exponent, digits and at most one point before the exponent. A '+' of the
  // mantissa is dropped (from_chars takes none); the longest valid word is its digits.
  char small[64];
  std::string large;
  char* text = small;
  if (word.size() > sizeof small) {
    large.resize(word.size());
    text = large.data();
  }
  std::size_t n = 0, i = 0;
  auto sign = [&](bool keep_plus) {
    if (word.substr(i).starts_with(high_minus)) {
      text[n++] = '-';
      i += high_minus.size();
    } else if (i < word.size() && (word[i] == '-' || word[i] == '+')) {
      if (word[i] == '-' || keep_plus) text[n++] = word[i];
      ++i;
    }
  };
  auto digits = [&] {
    const std::size_t start = i;
    while (i < word.size() && word[i] >= '0' && word[i] <= '9') text[n++] = word[i++];
    return i - start;
  };
  sign(false);
  std::size_t mantissa = digits();
  if (i < word.size() && word[i] == '.') {
    text[n++] = word[i++];
    mantissa += digits();
  }
  if (mantissa == 0) return std::nullopt;
  if (i < word.size() && (word[i] == 'E' || word[i] == 'e')) {
    text[n++] = word[i++];
    sign(true);
    if (digits() == 0) return std::nullopt;
  }
  if (i != word.size()) return std::nullopt;
  double value = 0;
  const auto [end, error] = std::from_chars(text, text + n, value);
  if (error == std::errc{} && end == text + n) return value;
  // Out of range: strtod's infinity or underflow, as before (an overflow is refused by the
  // caller with the point number).
  const std::string copy(text, n);
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
