#include "workspace/numbers/decimal.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace igds {

namespace {

// The exponent of format_real at w: E, a minus, the digits without leading zeros; returns the end.
char* put_exponent(char* w, int x) {
  *w++ = 'E';
  if (x < 0) *w++ = '-';
  const int m = std::abs(x);
  if (m >= 100) *w++ = static_cast<char>('0' + m / 100);
  if (m >= 10) *w++ = static_cast<char>('0' + m / 10 % 10);
  *w++ = static_cast<char>('0' + m % 10);
  return w;
}

// format_real of a finite non-zero value below 2^53 in magnitude. std::to_chars gives its shortest
// digits in scientific form, d.ddde+XX (the cheapest of the library's ways to them), and they are
// laid out here as its general form lays them out: fixed or scientific, whichever is shorter, fixed
// on a tie. Each part (at most 16 digits, or 5 zeros) is moved by a copy of 8 or 16 bytes, a vector
// move or two where a copy of the part's own length is a call to the library's; what a copy puts
// past its part is written over by the next, and none reaches past the 32 bytes at `out`.
std::size_t format_below_2_53(char* out, double value) {
  char text[48];  // the scientific form, and bytes read past its end
  const char* const end = std::to_chars(text, text + 32, value, std::chars_format::scientific).ptr;
  const char* p = text;
  char* o = out;
  if (*p == '-') *o++ = *p++;
  // The exponent: two digits, or three.
  const char* e = end[-4] == 'e' ? end - 4 : end - 5;
  int x = 0;
  for (const char* d = e + 2; d < end; ++d) x = 10 * x + (*d - '0');
  if (e[1] == '-') x = -x;
  // value = d.fff x 10^x: n digits, the first and the `nf` after the point.
  const char first = p[0];
  const char* fraction = p + 2;
  const int nf = p[1] == '.' ? int(e - fraction) : 0, n = nf + 1;
  const int scientific = n + (n > 1 ? 1 : 0) + 2 + (std::abs(x) >= 100 ? 3 : 2);
  const int fixed = x < 0 ? n + 1 - x : (n > x + 1 ? n + 1 : x + 1);
  auto copy = [&](const char* from, int count) {
    if (count <= 8)
      std::memcpy(o, from, 8);
    else
      std::memcpy(o, from, 16);
    o += count;
  };
  auto zeros = [&](int count) {
    std::memset(o, '0', 8);
    o += count;
  };
  if (fixed > scientific) {
    *o++ = first;
    *o++ = '.';
    copy(fraction, nf);
    return static_cast<std::size_t>(put_exponent(o, x) - out);
  }
  // A fixed form is chosen only when no longer than the scientific one: at most 5 zeros.
  if (x < 0) {
    *o++ = '0';
    *o++ = '.';
    zeros(-x - 1);
    *o++ = first;
    copy(fraction, nf);
  } else if (nf <= x) {
    // An integer: its digits, its zeros, and the point.
    *o++ = first;
    copy(fraction, nf);
    zeros(x - nf);
    *o++ = '.';
  } else {
    *o++ = first;
    copy(fraction, x);
    *o++ = '.';
    copy(fraction + x, nf - x);
  }
  return static_cast<std::size_t>(o - out);
}

}  // namespace

std::size_t format_real(char* out, double value) {
  if (value == 0) value = 0;  // no "-0."
  if (value != 0 && std::abs(value) < 0x1p53) return format_below_2_53(out, value);
  // Zero, larger values (whose fixed form std::to_chars writes with all the digits of the integer
  // they are) and the values that are no reals of IGES or STEP ("inf."): the library's general
  // form, the point added, e+20 as E20, e-07 as E-7.
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
    int x = 0;
    for (const char* d = e + 2; d < end; ++d) x = 10 * x + (*d - '0');
    o = put_exponent(o, e[1] == '-' ? -x : x);
  }
  return static_cast<std::size_t>(o - out);
}

void put_real(std::string& out, double value) {
  char buffer[32];
  out.append(buffer, format_real(buffer, value));
}

IntegerReals::IntegerReals(std::size_t n) : text_((n + 1) * slot), length_(n + 1) {
  for (std::size_t k = 0; k <= n; ++k)
    length_[k] = static_cast<std::uint8_t>(format_real(&text_[k * slot], double(k)));
}

}  // namespace igds
