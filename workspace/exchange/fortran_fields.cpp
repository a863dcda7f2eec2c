#include "workspace/exchange/fortran_fields.h"

#include <charconv>
#include <cmath>
#include <system_error>

#include <fmt/format.h>

namespace igds::exchange {

namespace {

bool digit(char c) {
  return c >= '0' && c <= '9';
}

// The field's characters without its blanks (BLANK='NULL'); columns past the card are blanks.
std::string squeezed(std::string_view card, std::size_t first, std::size_t width) {
  std::string s;
  for (std::size_t k = first; k < first + width && k < card.size(); ++k)
    if (card[k] != ' ') s += card[k];
  return s;
}

}  // namespace

bool Cards::next(std::string_view& card) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  card = text_.substr(pos_, end - pos_);
  if (!card.empty() && card.back() == '\r') card.remove_suffix(1);
  pos_ = end + 1;
  ++line_;
  return true;
}

std::optional<long long> read_i(std::string_view card, std::size_t first, std::size_t width) {
  const std::string s = squeezed(card, first, width);
  if (s.empty()) return 0;
  std::size_t k = s[0] == '+' || s[0] == '-' ? 1 : 0;
  if (k == s.size()) return std::nullopt;
  for (std::size_t d = k; d < s.size(); ++d)
    if (!digit(s[d])) return std::nullopt;
  long long value = 0;
  const auto [end, error] = std::from_chars(s.data() + k, s.data() + s.size(), value);
  if (error != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return s[0] == '-' ? -value : value;
}

std::optional<double> read_f(std::string_view card, std::size_t first, std::size_t width,
                             int decimals) {
  const std::string s = squeezed(card, first, width);
  if (s.empty()) return 0.0;
  std::size_t k = 0;
  const bool negative = s[k] == '-';
  if (s[k] == '+' || s[k] == '-') ++k;
  std::string whole, fraction;
  bool point = false;
  for (; k < s.size() && (digit(s[k]) || (s[k] == '.' && !point)); ++k) {
    if (s[k] == '.')
      point = true;
    else
      (point ? fraction : whole) += s[k];
  }
  if (whole.empty() && fraction.empty()) return std::nullopt;
  // The exponent: E or D and an optional sign, or a sign alone, then digits.
  std::string exponent;
  if (k < s.size()) {
    const char c = s[k];
    const bool letter = c == 'E' || c == 'e' || c == 'D' || c == 'd';
    if (!letter && c != '+' && c != '-') return std::nullopt;
    if (letter) ++k;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) exponent += s[k++];
    const std::size_t digits_from = k;
    for (; k < s.size(); ++k) {
      if (!digit(s[k])) return std::nullopt;
      exponent += s[k];
    }
    if (k == digits_from) return std::nullopt;
  }
  if (!point) {
    // Fw.d without a decimal point: the last d digits are the fraction.
    const std::size_t d = decimals > 0 ? std::size_t(decimals) : 0;
    if (whole.size() < d) whole.insert(0, d - whole.size(), '0');
    fraction = whole.substr(whole.size() - d);
    whole.resize(whole.size() - d);
  }
  std::string text = (whole.empty() ? "0" : whole) + "." + fraction + "0";
  if (!exponent.empty()) text += "e" + exponent;
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return negative ? -value : value;
}

std::string format_f(double value, int width, int decimals) {
  const std::size_t w = width > 0 ? std::size_t(width) : 0;
  if (!std::isfinite(value)) return std::string(w, '*');
  // fmt rounds the exact binary value, halves to even, as gfortran does (disk/cards.h).
  std::string s = decimals == 0 ? fmt::format("{:#{}.0f}", value, width)
                                : fmt::format("{:{}.{}f}", value, width, decimals);
  if (s.size() > w) return std::string(w, '*');
  return s;
}

}  // namespace igds::exchange
