#include "workspace/exchange/fields.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace igds {

namespace {

// `text` right-justified in `width` columns, or after one blank when it does not fit.
void put_field(std::string& out, const char* text, std::size_t length, int width) {
  const std::size_t w = static_cast<std::size_t>(width < 0 ? 0 : width);
  if (length > w)
    out.push_back(' ');
  else
    out.append(w - length, ' ');
  out.append(text, length);
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

void put_integer(std::string& out, std::int64_t value, int width) {
  char buffer[24];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  put_field(out, buffer, static_cast<std::size_t>(end - buffer), width);
}

void put_fixed(std::string& out, double value, int width, int decimals) {
  char buffer[400];
  if (value == 0) value = 0;  // no "-0.0000"
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  std::size_t length = static_cast<std::size_t>(result.ptr - buffer);
  // Beyond 24 characters the exact shortest form, 1.875E200, which list-directed readers take.
  if (length > 24) length = format_real(buffer, value);
  put_field(out, buffer, length, width);
}

std::size_t format_exponent(char* buffer, double value, int digits) {
  char* p = buffer;
  if (!std::isfinite(value))
    return std::size_t(std::to_chars(buffer, buffer + 32, value).ptr - buffer);
  if (value == 0) {
    *p++ = '0';
    *p++ = '.';
    for (int k = 0; k < digits; ++k) *p++ = '0';
    for (char c : {'E', '+', '0', '0'}) *p++ = c;
    return static_cast<std::size_t>(p - buffer);
  }
  // d.dddddde+XX from the library (correctly rounded), rearranged as 0.ddddddd with the exponent
  // one higher.
  char sci[64];
  const auto end =
      std::to_chars(sci, sci + sizeof sci, value, std::chars_format::scientific, digits - 1).ptr;
  const char* s = sci;
  if (*s == '-') *p++ = *s++;
  *p++ = '0';
  *p++ = '.';
  *p++ = *s++;  // the leading digit
  if (*s == '.') ++s;
  while (s < end && *s != 'e') *p++ = *s++;
  // s points at 'e': the library's exponent (not NUL-terminated), one higher for 0.ddddddd.
  int exponent = 0;
  const bool negative = s + 1 < end && s[1] == '-';
  for (const char* d = s + 2; d < end; ++d) exponent = 10 * exponent + (*d - '0');
  exponent = (negative ? -exponent : exponent) + 1;
  const int magnitude = std::abs(exponent);
  if (magnitude < 100) *p++ = 'E';
  *p++ = exponent < 0 ? '-' : '+';
  if (magnitude >= 100) *p++ = static_cast<char>('0' + magnitude / 100);
  *p++ = static_cast<char>('0' + magnitude / 10 % 10);
  *p++ = static_cast<char>('0' + magnitude % 10);
  return static_cast<std::size_t>(p - buffer);
}

void put_exponent(std::string& out, double value, int width, int digits) {
  char buffer[64];
  put_field(out, buffer, format_exponent(buffer, value, digits), width);
}

std::size_t format_real(char* out, double value) {
  if (value == 0) value = 0;  // no "-0."
  char buffer[32];
  const char* end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  const char* e = buffer;
  while (e < end && *e != 'e') ++e;
  char* o = out;
  bool point = false;
  for (const char* p = buffer; p < e; ++p) {
    point = point || *p == '.';
    *o++ = *p;
  }
  if (!point) *o++ = '.';
  if (e < end) {
    // e+20 -> E20, e-07 -> E-7.
    *o++ = 'E';
    const char* d = e + 1;
    if (*d == '-') *o++ = '-';
    if (*d == '-' || *d == '+') ++d;
    while (d + 1 < end && *d == '0') ++d;
    while (d < end) *o++ = *d++;
  }
  return static_cast<std::size_t>(o - out);
}

void put_real(std::string& out, double value) {
  char buffer[32];
  out.append(buffer, format_real(buffer, value));
}

std::optional<double> parse_fortran_real(std::string_view token) {
  // Normalised into a buffer as [-]mantissa[e[-]digits] for from_chars.
  char buffer[128];
  if (token.empty() || token.size() >= sizeof buffer - 2) return std::nullopt;
  std::size_t i = 0, n = 0;
  if (token[i] == '+' || token[i] == '-') {
    if (token[i] == '-') buffer[n++] = '-';
    ++i;
  }
  std::size_t digits = 0;
  bool point = false;
  for (; i < token.size(); ++i) {
    const char c = token[i];
    if (is_digit(c)) {
      ++digits;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      break;
    }
    buffer[n++] = c;
  }
  if (digits == 0) return std::nullopt;
  if (i < token.size()) {
    char c = token[i];
    if (c == 'E' || c == 'e' || c == 'D' || c == 'd') {
      if (++i == token.size()) return std::nullopt;
      c = token[i];
    } else if (c != '+' && c != '-') {
      return std::nullopt;
    }
    buffer[n++] = 'e';
    if (c == '+' || c == '-') {
      if (c == '-') buffer[n++] = '-';
      ++i;
    }
    std::size_t exponent_digits = 0;
    for (; i < token.size() && is_digit(token[i]); ++i, ++exponent_digits) buffer[n++] = token[i];
    if (exponent_digits == 0 || i != token.size()) return std::nullopt;
  }
  double value = 0;
  const auto result = std::from_chars(buffer, buffer + n, value);
  if (result.ec != std::errc() || result.ptr != buffer + n || !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_fortran_integer(std::string_view token) {
  std::size_t i = 0;
  if (!token.empty() && token[0] == '+') i = 1;
  if (i == token.size() || (token[i] == '-' && i + 1 == token.size())) return std::nullopt;
  std::int64_t value = 0;
  const char* first = token.data() + i;
  const char* last = token.data() + token.size();
  if (i == 1 && *first == '-') return std::nullopt;  // "+-5"
  const auto result = std::from_chars(first, last, value);
  if (result.ec != std::errc() || result.ptr != last) return std::nullopt;
  return value;
}

namespace {
constexpr const char* month_names[] = {"JAN", "FEB", "MAR", "APR", "MAY", "JUN",
                                       "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"};
}

std::string duct_date(const Timestamp& t) {
  const char* month = t.month >= 1 && t.month <= 12 ? month_names[t.month - 1] : "???";
  return fmt::format("{:02} {} {:04} {:02}:{:02}:{:02}", t.day, month, t.year, t.hour, t.minute,
                     t.second);
}

std::string iges_date(const Timestamp& t) {
  return fmt::format("{:04}{:02}{:02}.{:02}{:02}{:02}", t.year, t.month, t.day, t.hour, t.minute,
                     t.second);
}

std::string iso_date(const Timestamp& t) {
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}", t.year, t.month, t.day, t.hour,
                     t.minute, t.second);
}

}  // namespace igds
