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
  // Checked first: only one sign per mantissa and exponent (high minus, '-' or '+'), digits and
  // at most one point before the exponent.
  std::size_t i = 0;
  bool rewrite = false;  // a high minus, or a '+' before the mantissa (from_chars takes neither)
  auto sign = [&](bool exponent) {
    if (word.substr(i).starts_with(high_minus)) {
      i += high_minus.size();
      rewrite = true;
    } else if (i < word.size() && (word[i] == '-' || word[i] == '+')) {
      rewrite = rewrite || (word[i] == '+' && !exponent);
      ++i;
    }
  };
  auto digits = [&] {
    const std::size_t start = i;
    while (i < word.size() && word[i] >= '0' && word[i] <= '9') ++i;
    return i - start;
  };
  sign(false);
  std::size_t mantissa = digits();
  if (i < word.size() && word[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return std::nullopt;
  if (i < word.size() && (word[i] == 'E' || word[i] == 'e')) {
    ++i;
    sign(true);
    if (digits() == 0) return std::nullopt;
  }
  if (i != word.size()) return std::nullopt;
  // As other programs write it (the usual case), read in place; else in from_chars's form.
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
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error == std::errc{} && end == word.data() + word.size()) return value;
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
