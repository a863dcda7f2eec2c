#include "workspace/numbers/fortran.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

#include "workspace/numbers/decimal.h"
#include "workspace/numbers/digits.h"

namespace igds::fortran {

using numbers::digits_before;
using numbers::exact_power;
using numbers::power_of_ten;
using numbers::two_digits;

namespace {

std::size_t columns(int width) {
  return static_cast<std::size_t>(width < 0 ? 0 : width);
}

void stars(char* out, std::size_t width) {
  std::memset(out, '*', width);
}

// `length` characters of `text` right-justified in `width` columns at `out`, or after one blank
// when they do not fit; returns the end.
char* whole_field(char* out, const char* text, std::size_t length, int width) {
  const std::size_t w = columns(width);
  if (length > w) {
    *out++ = ' ';
  } else {
    std::memset(out, ' ', w - length);
    out += w - length;
  }
  std::memcpy(out, text, length);
  return out + length;
}

// What put(w) writes at w appended to `out`: a field of `width` columns, or at most `room`
// characters when its text does not fit them.
template <class Put>
void append_field(std::string& out, int width, std::size_t room, const Put& put) {
  const std::size_t size = out.size();
  out.resize(size + std::max(columns(width), room));
  out.resize(static_cast<std::size_t>(put(out.data() + size) - out.data()));
}

// NaN and the infinities at `buffer` as gfortran writes them in a field of `width` columns
// ("Infinity" needs 8 columns, 9 with its minus; "Inf" 3, 4 with its minus); 0 when nothing fits.
std::size_t not_finite_text(char* buffer, double value, std::size_t width) {
  const char* text = std::isnan(value) ? "NaN"
                     : value > 0       ? (width >= 8 ? "Infinity" : "Inf")
                                       : (width >= 9 ? "-Infinity" : "-Inf");
  const std::size_t n = std::strlen(text);
  if (n > width) return 0;
  std::memcpy(buffer, text, n);
  return n;
}

// |value| x 10^decimals rounded to an integer, exact halves to even, by integer arithmetic: for
// decimals 0 to 3 and |value| below 2^52, where the product of the 53-bit significand and
// 10^decimals fits 64 bits and the binary exponent is a shift. False otherwise.
bool scaled(double value, int decimals, std::uint64_t& q) {
  // The value is m x 2^e exactly (IEEE 754 binary64): m the 53-bit significand.
  const auto bits = std::bit_cast<std::uint64_t>(value);
  const int biased = static_cast<int>((bits >> 52) & 0x7FF);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  const std::uint64_t m = biased == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
  const int e = biased == 0 ? -1074 : biased - 1075;
  if (decimals < 0 || decimals > 3 || e >= 0) return false;
  const std::uint64_t x = m * power_of_ten[decimals];  // below 2^63
  const int s = -e;
  if (s >= 64) {
    q = 0;  // x < 2^63 <= half of 2^s
    return true;
  }
  q = x >> s;
  const std::uint64_t rest = x & ((std::uint64_t{1} << s) - 1), half = std::uint64_t{1} << (s - 1);
  if (rest > half || (rest == half && (q & 1))) ++q;
  return true;
}

// "[-]ddd.ddd", q in units of 10^-decimals (0 to 3), ending at `end`; returns where it starts.
char* fixed_before(char* end, std::uint64_t q, int decimals, bool negative) {
  // The decimals by constant divisors, the last two from the table of pairs.
  if (decimals == 3) {
    const auto f = static_cast<unsigned>(q % 1000);
    q /= 1000;
    end -= 3;
    end[0] = static_cast<char>('0' + f / 100);
    std::memcpy(end + 1, two_digits + 2 * (f % 100), 2);
  } else if (decimals == 2) {
    end -= 2;
    std::memcpy(end, two_digits + 2 * (q % 100), 2);
    q /= 100;
  } else if (decimals == 1) {
    *--end = static_cast<char>('0' + q % 10);
    q /= 10;
  }
  *--end = '.';
  end = digits_before(end, q);
  if (negative) *--end = '-';
  return end;
}

// Room for the library's Fw.d: 309 digits before the point of the largest double, a sign, the
// point and up to 60 decimals.
constexpr std::size_t fixed_room = 384;

// Fw.d of a finite value by the library (exact too: the digits of the binary value, halves to
// even) at `buffer` (fixed_room characters); 0 when `decimals` is out of its range.
std::size_t library_fixed(char* buffer, double value, int decimals) {
  if (decimals < 0 || decimals > 60) return 0;
  const auto r =
      std::to_chars(buffer, buffer + fixed_room - 1, value, std::chars_format::fixed, decimals);
  if (r.ec != std::errc()) return 0;
  auto n = static_cast<std::size_t>(r.ptr - buffer);
  if (decimals == 0) buffer[n++] = '.';
  return n;
}

}  // namespace

bool put_i(char* out, std::int64_t value, int width) {
  const std::size_t w = columns(width);
  const bool negative = value < 0;
  // The magnitude as unsigned, so that the most negative value has one too.
  const std::uint64_t magnitude =
      negative ? 0 - static_cast<std::uint64_t>(value) : static_cast<std::uint64_t>(value);
  char text[24];
  char* end = text + sizeof text;
  char* first = digits_before(end, magnitude);
  if (negative) *--first = '-';
  const auto n = static_cast<std::size_t>(end - first);
  if (n > w) {
    stars(out, w);
    return false;
  }
  std::memset(out, ' ', w - n);
  std::memcpy(out + w - n, first, n);
  return true;
}

namespace {

// put_f where integer arithmetic does not reach: NaN and the infinities, more than 3 decimals,
// values of 2^52 and more.
bool put_f_otherwise(char* out, double value, int width, int decimals) {
  const std::size_t w = columns(width);
  char text[fixed_room];
  const std::size_t n =
      std::isfinite(value) ? library_fixed(text, value, decimals) : not_finite_text(text, value, w);
  if (n == 0 || n > w) {
    stars(out, w);
    return false;
  }
  std::memset(out, ' ', w - n);
  std::memcpy(out + w - n, text, n);
  return true;
}

}  // namespace

bool put_f(char* out, double value, int width, int decimals) {
  std::uint64_t q = 0;
  if (!scaled(value, decimals, q)) return put_f_otherwise(out, value, width, decimals);
  // Written where it goes: the columns for digits, besides the point and the sign, must hold q
  // and the digit before the point.
  const bool negative = std::signbit(value);
  const int digits = width - 1 - (negative ? 1 : 0);
  if (digits < decimals + 1 || (digits < 20 && q >= power_of_ten[digits])) {
    stars(out, columns(width));
    return false;
  }
  char* first = fixed_before(out + width, q, decimals, negative);
  std::memset(out, ' ', static_cast<std::size_t>(first - out));
  return true;
}

char* put_i_whole(char* out, std::int64_t value, int width) {
  char buffer[24];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return whole_field(out, buffer, static_cast<std::size_t>(end - buffer), width);
}

void put_i_whole(std::string& out, std::int64_t value, int width) {
  append_field(out, width, 21, [&](char* w) { return put_i_whole(w, value, width); });
}

char* put_f_whole(char* out, double value, int width, int decimals) {
  if (value == 0) value = 0;  // no "-0.0000"
  char buffer[fixed_room];
  if (!std::isfinite(value)) {
    return whole_field(out, buffer, not_finite_text(buffer, value, 9), width);
  }
  if (std::uint64_t q; scaled(value, decimals, q)) {
    char* end = buffer + sizeof buffer;
    char* first = fixed_before(end, q, decimals, value < 0);
    return whole_field(out, first, static_cast<std::size_t>(end - first), width);
  }
  std::size_t n = library_fixed(buffer, value, decimals);
  // Beyond 24 characters the exact shortest form, 1.875E200, which list-directed readers take.
  if (n == 0 || n > 24) n = format_real(buffer, value);
  return whole_field(out, buffer, n, width);
}

void put_f_whole(std::string& out, double value, int width, int decimals) {
  append_field(out, width, 26, [&](char* w) { return put_f_whole(w, value, width, decimals); });
}

namespace {

// |value| * 10^n in one correctly rounded operation, or 0 when 10^|n| is not exact.
double scaled_by_ten(double magnitude, int n) {
  if (n >= 0) return n <= 22 ? magnitude * exact_power[n] : 0;
  return n >= -22 ? magnitude / exact_power[-n] : 0;
}

// The exponent of Ew.d at p: E+ee, or +eee without the E; returns the end.
char* put_e_exponent(char* p, int exponent) {
  const int magnitude = std::abs(exponent);
  if (magnitude < 100) *p++ = 'E';
  *p++ = exponent < 0 ? '-' : '+';
  if (magnitude >= 100) *p++ = static_cast<char>('0' + magnitude / 100);
  std::memcpy(p, two_digits + 2 * (magnitude % 100), 2);
  return p + 2;
}

// The significand r (`digits` digits) and exponent e of Ew.d (|value| is 0.r x 10^e) by double
// arithmetic, for the values (nearly all) where that is provably what the exact value rounds
// to: |value| * 10^(digits - e) is made by one rounded multiplication or division by an exact
// power of ten, so it is within 2^-52 of itself, relatively; when it is farther than that from a
// half-integer and from the ends of [10^(digits-1), 10^digits), its nearest integer is the
// correctly rounded significand. Otherwise (and for digits above 9, zero, subnormals, huge or
// tiny values, NaN and the infinities) false: the library does it.
bool fast_significand(double value, int digits, std::uint64_t& r, int& e) {
  if (digits < 1 || digits > 9) return false;
  const double magnitude = std::abs(value);
  const auto bits = std::bit_cast<std::uint64_t>(magnitude);
  const int binary = static_cast<int>(bits >> 52) - 1023;  // magnitude in [2^b, 2^(b+1))
  if (binary < -60 || binary > 90) return false;
  // 0.d1d2... x 10^e: e = floor(log10(magnitude)) + 1, estimated within one from the binary
  // exponent (78913 / 2^18 is log10(2) to 1e-6).
  e = ((binary * 78913) >> 18) + 1;
  const double low = exact_power[digits - 1], high = exact_power[digits];
  double s = scaled_by_ten(magnitude, digits - e);
  if (s >= high)
    s = scaled_by_ten(magnitude, digits - ++e);
  else if (s < low)
    s = scaled_by_ten(magnitude, digits - --e);
  const double margin = high * 1e-15;  // above the rounding error of s (2^-52 s)
  if (!(s - low > margin && high - s > margin)) return false;
  r = static_cast<std::uint64_t>(s);  // s > 0: its integer part
  const double fraction = s - static_cast<double>(r);
  if (std::abs(fraction - 0.5) < margin) return false;
  r += fraction > 0.5 ? 1 : 0;  // (no branch: it goes either way at random)
  if (r == static_cast<std::uint64_t>(high)) {
    r = static_cast<std::uint64_t>(low);
    ++e;
  }
  return true;
}

// Ew.d into `buffer` (at least 40 characters, for digits up to 16), unpadded, where
// fast_significand does not reach; returns the length.
std::size_t exponent_text(char* buffer, double value, int digits) {
  char* p = buffer;
  if (!std::isfinite(value)) return not_finite_text(buffer, value, 9);
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
  p = put_e_exponent(p, (negative ? -exponent : exponent) + 1);
  return static_cast<std::size_t>(p - buffer);
}

}  // namespace

char* put_e_whole(char* out, double value, int width, int digits) {
  std::uint64_t r = 0;
  int e = 0;
  if (!fast_significand(value, digits, r, e)) {
    char buffer[64];
    return whole_field(out, buffer, exponent_text(buffer, value, digits), width);
  }
  // Written where it goes (the bulk of a DUCT picture): [-]0.r then E+ee (|e| < 100 here),
  // right-justified, or after one blank when wider than the field.
  const bool negative = value < 0;
  const int bare = 2 + digits + 4;  // the text without its sign
  if (width > bare) {
    // Blanks, then the sign's column: a minus or a blank (no branch: signs come at random).
    for (int k = bare + 1; k < width; ++k) *out++ = ' ';
    *out++ = negative ? '-' : ' ';
  } else {
    if (negative || bare > width) *out++ = ' ';
    if (negative) *out++ = '-';
  }
  out[0] = '0';
  out[1] = '.';
  return put_e_exponent(numbers::put_digits(out + 2, r, digits), e);
}

std::string input_text(double value, int digits) {
  if (value == 0) value = 0;  // no "-0."
  char buffer[64];
  const auto end =
      digits == 0
          ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific).ptr
          : std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific,
                          digits - 1)
                .ptr;
  // [-]d[.ddd]e[+-]xx: the digits, without trailing zeros, and the exponent of the first.
  const std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
  const bool negative = text[0] == '-';
  const std::size_t e = text.find('e');
  std::string mantissa;
  for (char c : text.substr(negative ? 1 : 0, e - (negative ? 1 : 0)))
    if (c >= '0' && c <= '9') mantissa += c;
  while (mantissa.size() > 1 && mantissa.back() == '0') mantissa.pop_back();
  int exponent = 0;
  std::from_chars(text.data() + e + (text[e + 1] == '+' ? 2 : 1), text.data() + text.size(),
                  exponent);
  const std::string sign = negative ? "-" : "";
  std::string plain = sign;
  if (exponent >= 0) {
    const std::size_t whole = static_cast<std::size_t>(exponent) + 1;
    plain += mantissa.substr(0, whole);
    if (mantissa.size() < whole) plain.append(whole - mantissa.size(), '0');
    plain += '.';
    if (mantissa.size() > whole) plain += mantissa.substr(whole);
  } else {
    plain += "0.";
    plain.append(static_cast<std::size_t>(-exponent - 1), '0');
    plain += mantissa;
  }
  std::string scientific =
      sign + mantissa.substr(0, 1) + '.' + mantissa.substr(1) + 'E' + std::to_string(exponent);
  return plain.size() < scientific.size() ? plain : scientific;
}

bool put_f_input(char* out, double value, int width, int decimals) {
  if (value == 0) value = 0;
  const std::size_t w = columns(width);
  if (!std::isfinite(value)) {
    stars(out, w);
    return false;
  }
  if (value == 0 && put_f(out, value, width, decimals)) return true;  // the usual T U
  char fixed[fixed_room];
  const bool fits = w < sizeof fixed && put_f(fixed, value, width, decimals);
  auto put = [&](std::string_view text) {
    std::memset(out, ' ', w - text.size());
    std::memcpy(out + w - text.size(), text.data(), text.size());
    return true;
  };
  if (fits && read_f({fixed, w}, 0, w, decimals) == value) return put({fixed, w});
  if (const std::string exact = input_text(value, 0); exact.size() <= w) return put(exact);
  for (int digits = 17; digits >= 1; --digits) {
    const std::string text = input_text(value, digits);
    if (text.size() > w) continue;
    // Fw.d when it holds as many significant digits.
    if (fits) {
      const std::string_view f = std::string_view(fixed, w);
      const std::size_t first = f.find_first_of("123456789");
      std::size_t held = 0;
      for (std::size_t k = first; k < w && first != f.npos; ++k)
        held += f[k] >= '0' && f[k] <= '9' ? 1 : 0;
      if (held >= static_cast<std::size_t>(digits)) return put(f);
    }
    return put(text);
  }
  stars(out, w);
  return false;
}

namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// The most characters, blanks left out, of a number the readers take.
constexpr std::size_t longest = 125;

// A number in FORTRAN's forms (read_f's, without blanks), `decimals` implied when it has no
// point, normalised for from_chars as [-]digits[.digits][e[-]digits].
std::optional<double> parse_real(std::string_view token, int decimals) {
  char buffer[longest + 64];  // a sign, zeros before the digits, a point
  if (token.empty() || token.size() > longest) return std::nullopt;
  std::size_t i = 0, n = 0;
  if (token[i] == '+' || token[i] == '-') {
    if (token[i] == '-') buffer[n++] = '-';
    ++i;
  }
  const std::size_t mantissa = n;
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
  if (!point && decimals > 0) {
    // The last `decimals` digits are the fraction: zeros before the digits when they are fewer.
    if (decimals > 60) return std::nullopt;
    const auto d = static_cast<std::size_t>(decimals);
    const std::size_t pad = d >= digits ? d - digits + 1 : 0;
    std::memmove(buffer + mantissa + pad, buffer + mantissa, digits);
    std::memset(buffer + mantissa, '0', pad);
    n += pad;
    std::memmove(buffer + n - d + 1, buffer + n - d, d);
    buffer[n - d] = '.';
    ++n;
  }
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

// The field's characters without its blanks (BLANK='NULL'); columns past the card are blanks.
// False when they are more than read_real takes.
bool squeezed(std::string_view card, std::size_t first, std::size_t width, char* out,
              std::size_t& n) {
  n = 0;
  for (std::size_t k = first; k < card.size() && k - first < width; ++k) {
    if (card[k] == ' ') continue;
    if (n == longest + 1) return false;
    out[n++] = card[k];
  }
  return true;
}

}  // namespace

std::optional<std::int64_t> read_i(std::string_view card, std::size_t first, std::size_t width) {
  char text[longest + 1];
  std::size_t n = 0;
  if (!squeezed(card, first, width, text, n)) return std::nullopt;
  if (n == 0) return 0;
  return read_integer({text, n});
}

std::optional<double> read_f(std::string_view card, std::size_t first, std::size_t width,
                             int decimals) {
  char text[longest + 1];
  std::size_t n = 0;
  if (!squeezed(card, first, width, text, n)) return std::nullopt;
  if (n == 0) return 0.0;
  return parse_real({text, n}, decimals);
}

std::optional<double> read_real(std::string_view text) {
  return parse_real(text, 0);
}

std::optional<std::int64_t> read_integer(std::string_view text) {
  std::size_t i = 0;
  if (!text.empty() && text[0] == '+') i = 1;
  if (i == text.size() || (text[i] == '-' && i + 1 == text.size())) return std::nullopt;
  std::int64_t value = 0;
  const char* first = text.data() + i;
  const char* last = text.data() + text.size();
  if (i == 1 && *first == '-') return std::nullopt;  // "+-5"
  const auto result = std::from_chars(first, last, value);
  if (result.ec != std::errc() || result.ptr != last) return std::nullopt;
  return value;
}

std::size_t split_values(std::string_view line, std::string_view* out, std::size_t limit) {
  auto separator = [](char c) { return c == ' ' || c == '\t' || c == ','; };
  std::size_t n = 0, i = 0;
  while (i < line.size()) {
    while (i < line.size() && separator(line[i])) ++i;
    if (i == line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && !separator(line[i])) ++i;
    if (n < limit)
      out[n++] = line.substr(start, i - start);
    else
      ++n;
  }
  return n;
}

}  // namespace igds::fortran
