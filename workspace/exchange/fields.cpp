#include "workspace/exchange/fields.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

namespace igds {

namespace {

// `text` right-justified in `width` columns, or after one blank when it does not fit.
char* put_field(char* out, const char* text, std::size_t length, int width) {
  const std::size_t w = static_cast<std::size_t>(width < 0 ? 0 : width);
  if (length > w) {
    *out++ = ' ';
  } else {
    std::memset(out, ' ', w - length);
    out += w - length;
  }
  std::memcpy(out, text, length);
  return out + length;
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// What put(w) writes at w appended to `out`: a field of `width` columns, or at most `room`
// characters when its text does not fit them.
template <class Put>
void append_field(std::string& out, int width, std::size_t room, const Put& put) {
  const std::size_t size = out.size();
  out.resize(size + std::max(static_cast<std::size_t>(width < 0 ? 0 : width), room));
  out.resize(static_cast<std::size_t>(put(out.data() + size) - out.data()));
}

}  // namespace

void put_integer(std::string& out, std::int64_t value, int width) {
  append_field(out, width, 21, [&](char* w) { return put_integer(w, value, width); });
}

char* put_integer(char* out, std::int64_t value, int width) {
  char buffer[24];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return put_field(out, buffer, static_cast<std::size_t>(end - buffer), width);
}

namespace {

// Fw.d into `buffer` (400 characters), unpadded; returns the length.
std::size_t format_fixed(char* buffer, double value, int decimals) {
  if (value == 0) value = 0;  // no "-0.0000"
  const auto result =
      std::to_chars(buffer, buffer + 400, value, std::chars_format::fixed, decimals);
  std::size_t length = static_cast<std::size_t>(result.ptr - buffer);
  // Beyond 24 characters the exact shortest form, 1.875E200, which list-directed readers take.
  if (length > 24) length = format_real(buffer, value);
  return length;
}

}  // namespace

void put_fixed(std::string& out, double value, int width, int decimals) {
  append_field(out, width, 26, [&](char* w) { return put_fixed(w, value, width, decimals); });
}

char* put_fixed(char* out, double value, int width, int decimals) {
  char buffer[400];
  return put_field(out, buffer, format_fixed(buffer, value, decimals), width);
}

namespace {

// 10^k, k = 0..22: the powers of ten that doubles hold exactly.
constexpr double exact_power[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// "00" to "99".
constexpr char two_digits[] =
    "0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546"
    "4748495051525354555657585960616263646566676869707172737475767778798081828384858687888990919293"
    "949596979899";

// |value| * 10^n in one correctly rounded operation, or 0 when 10^|n| is not exact.
double scaled(double magnitude, int n) {
  if (n >= 0) return n <= 22 ? magnitude * exact_power[n] : 0;
  return n >= -22 ? magnitude / exact_power[-n] : 0;
}

// The digits and exponent of format_exponent by double arithmetic, for the values (nearly all)
// where that is provably what the exact value rounds to: |value| * 10^(digits - E) is made by
// one rounded multiplication or division by an exact power of ten, so it is within
// 2^-52 of itself, relatively; when it is farther than that from a half-integer and from the
// ends of [10^(digits-1), 10^digits), its nearest integer is the correctly rounded significand.
// Otherwise (and for digits above 9, subnormals, huge or tiny values) false: the library does it.
bool fast_exponent(char*& p, double value, int digits) {
  if (digits < 1 || digits > 9) return false;
  const double magnitude = std::abs(value);
  const auto bits = std::bit_cast<std::uint64_t>(magnitude);
  const int binary = static_cast<int>(bits >> 52) - 1023;  // magnitude in [2^b, 2^(b+1))
  if (binary < -60 || binary > 90) return false;
  // 0.d1d2... x 10^e: e = floor(log10(magnitude)) + 1, estimated within one from the binary
  // exponent (78913 / 2^18 is log10(2) to 1e-6).
  int e = ((binary * 78913) >> 18) + 1;
  const double low = exact_power[digits - 1], high = exact_power[digits];
  double s = scaled(magnitude, digits - e);
  if (s >= high)
    s = scaled(magnitude, digits - ++e);
  else if (s < low)
    s = scaled(magnitude, digits - --e);
  const double margin = high * 1e-15;  // above the rounding error of s (2^-52 s)
  if (!(s - low > margin && high - s > margin)) return false;
  auto r = static_cast<std::uint64_t>(s);  // s > 0: its integer part
  const double fraction = s - static_cast<double>(r);
  if (std::abs(fraction - 0.5) < margin) return false;
  if (fraction > 0.5) ++r;
  if (r == static_cast<std::uint64_t>(high)) {
    r = static_cast<std::uint64_t>(low);
    ++e;
  }
  if (value < 0) *p++ = '-';
  *p++ = '0';
  *p++ = '.';
  int k = digits;
  for (; k >= 2; k -= 2, r /= 100) std::memcpy(p + k - 2, two_digits + 2 * (r % 100), 2);
  if (k == 1) p[0] = static_cast<char>('0' + r);
  p += digits;
  const int magnitude_e = std::abs(e);
  if (magnitude_e < 100) *p++ = 'E';
  *p++ = e < 0 ? '-' : '+';
  if (magnitude_e >= 100) *p++ = static_cast<char>('0' + magnitude_e / 100);
  std::memcpy(p, two_digits + 2 * (magnitude_e % 100), 2);
  p += 2;
  return true;
}

}  // namespace

std::size_t format_exponent(char* buffer, double value, int digits) {
  char* p = buffer;
  if (std::isfinite(value) && value != 0 && fast_exponent(p, value, digits))
    return static_cast<std::size_t>(p - buffer);
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
  append_field(out, width, 41, [&](char* w) { return put_exponent(w, value, width, digits); });
}

char* put_exponent(char* out, double value, int width, int digits) {
  char buffer[64];
  return put_field(out, buffer, format_exponent(buffer, value, digits), width);
}

namespace {

// 10^k, k = 0..19: the powers of ten in 64 bits.
constexpr std::uint64_t power_of_ten[20] = {1u,
                                            10u,
                                            100u,
                                            1000u,
                                            10000u,
                                            100000u,
                                            1000000u,
                                            10000000u,
                                            100000000u,
                                            1000000000u,
                                            10000000000u,
                                            100000000000u,
                                            1000000000000u,
                                            10000000000000u,
                                            100000000000000u,
                                            1000000000000000u,
                                            10000000000000000u,
                                            100000000000000000u,
                                            1000000000000000000u,
                                            10000000000000000000u};

// The number of decimal digits of v (v > 0).
int digit_count(std::uint64_t v) {
  const int t = (std::bit_width(v) * 1233) >> 12;  // floor(log10(v)) or one more
  return t + 1 - (v < power_of_ten[t] ? 1 : 0);
}

// The eight digits of v (v < 10^8) at w, zeros first: four pairs made independently.
void put_eight(char* w, std::uint32_t v) {
  const std::uint32_t high = v / 10000, low = v % 10000;
  std::memcpy(w, two_digits + 2 * (high / 100), 2);
  std::memcpy(w + 2, two_digits + 2 * (high % 100), 2);
  std::memcpy(w + 4, two_digits + 2 * (low / 100), 2);
  std::memcpy(w + 6, two_digits + 2 * (low % 100), 2);
}

// The `count` digits of v (v < 10^count) at w, zeros first; returns w + count.
char* put_digits(char* w, std::uint64_t v, int count) {
  char* p = w + count;
  for (; p - w >= 8; v /= 100000000) {
    p -= 8;
    put_eight(p, static_cast<std::uint32_t>(v % 100000000));
  }
  auto rest = static_cast<std::uint32_t>(v);
  for (; p - w >= 2; rest /= 100) {
    p -= 2;
    std::memcpy(p, two_digits + 2 * (rest % 100), 2);
  }
  if (p > w) *--p = static_cast<char>('0' + rest);
  return w + count;
}

// `count` zeros at w; returns w + count.
char* put_zeros(char* w, int count) {
  for (int k = 0; k < count; ++k) w[k] = '0';
  return w + count;
}

// format_real of a finite non-zero value below 2^53 in magnitude, from its shortest digits
// (fmt's Dragonbox, the digits std::to_chars chooses too, about three times as fast), laid out as
// std::to_chars lays them out: fixed or scientific, whichever is shorter, fixed on a tie. The
// digits are written where they go, two at a time.
std::size_t format_real_fast(char* out, double value) {
  const auto decimal = fmt::detail::dragonbox::to_decimal(std::abs(value));
  const std::uint64_t s = decimal.significand;
  const int n = digit_count(s), x = decimal.exponent;  // value = s x 10^x, s of n digits
  const int exponent = x + n - 1;                      // d.ddd x 10^exponent
  const int e_digits = std::abs(exponent) >= 100 ? 3 : 2;
  const int scientific = n + (n > 1 ? 1 : 0) + 2 + e_digits;
  const int fixed = x >= 0 ? n + x : (n > -x ? n + 1 : 2 - x);
  char* o = out;
  if (value < 0) *o++ = '-';
  if (fixed <= scientific) {
    if (x >= 0) {
      // An integer: its digits, its zeros, and the point.
      o = put_digits(o, s, n);
      o = put_zeros(o, x);
      *o++ = '.';
    } else if (n > -x) {
      const std::uint64_t scale = power_of_ten[-x];
      o = put_digits(o, s / scale, n + x);
      *o++ = '.';
      o = put_digits(o, s % scale, -x);
    } else {
      *o++ = '0';
      *o++ = '.';
      o = put_zeros(o, -x - n);
      o = put_digits(o, s, n);
    }
  } else {
    const std::uint64_t scale = power_of_ten[n - 1];
    *o++ = static_cast<char>('0' + s / scale);
    *o++ = '.';
    o = put_digits(o, s % scale, n - 1);
    *o++ = 'E';
    if (exponent < 0) *o++ = '-';
    const int m = std::abs(exponent);
    o = put_digits(o, std::uint64_t(m), m >= 100 ? 3 : m >= 10 ? 2 : 1);
  }
  return static_cast<std::size_t>(o - out);
}

}  // namespace

std::size_t format_real(char* out, double value) {
  if (value == 0) value = 0;  // no "-0."
  if (value != 0 && std::abs(value) < 0x1p53) return format_real_fast(out, value);
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

IntegerReals::IntegerReals(std::size_t n) : text_((n + 1) * slot), length_(n + 1) {
  for (std::size_t k = 0; k <= n; ++k)
    length_[k] = static_cast<std::uint8_t>(format_real(&text_[k * slot], double(k)));
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
