#include "workspace/apl.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace igds {

namespace {
constexpr std::string_view high_minus = "\xC2\xAF";  // U+00AF in UTF-8
}

std::optional<double> parse_apl_number(std::string_view word) {
  // Rewrite into the C locale's form: high minus becomes '-', only one sign per mantissa and
  // exponent, digits and at most one point before the exponent.
  std::string text;
  text.reserve(word.size());
  for (std::size_t i = 0; i < word.size();) {
    if (word.substr(i).starts_with(high_minus)) {
      text += '-';
      i += high_minus.size();
    } else {
      text += word[i++];
    }
  }
  std::size_t i = 0;
  auto sign = [&] {
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
  };
  auto digits = [&] {
    std::size_t start = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    return i - start;
  };
  sign();
  std::size_t mantissa = digits();
  if (i < text.size() && text[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return std::nullopt;
  if (i < text.size() && (text[i] == 'E' || text[i] == 'e')) {
    ++i;
    sign();
    if (digits() == 0) return std::nullopt;
  }
  if (i != text.size()) return std::nullopt;
  errno = 0;
  double value = std::strtod(text.c_str(), nullptr);
  return value;  // an overflow is an infinity, refused by the caller with the point number
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
