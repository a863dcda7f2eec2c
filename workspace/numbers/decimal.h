// Numbers as decimal text where no FORTRAN format says how: the reals of IGES and STEP, the
// shortest that read back as the same double, and the integer coordinates of HP-GL and SVG.
#pragma once

#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace igds {

// The shortest decimal that reads back as the same double, laid out as std::to_chars lays it out
// (fixed or scientific, whichever is shorter, fixed on a tie), with a decimal point always (IGES
// and STEP reals must have one) and the exponent without its plus and leading zeros: 1 -> "1.",
// 0.1 -> "0.1", 1e+20 -> "1.E20", -2.5e-07 -> "-2.5E-7". A zero has no sign.
// Into `buffer` (at least 32 characters, any of which may be written whatever the text's own
// length); returns the length.
std::size_t format_real(char* buffer, double value);
void put_real(std::string& out, double value);

// format_real of the integers 0 .. n, each made once: the knots and parameters of patches,
// written again and again. Each text starts a slot of 32 readable bytes.
class IntegerReals {
 public:
  explicit IntegerReals(std::size_t n);
  std::string_view operator[](std::size_t k) const {
    return {&text_[k * slot], std::size_t(length_[k])};
  }

 private:
  static constexpr std::size_t slot = 32;
  std::vector<char> text_;
  std::vector<std::uint8_t> length_;
};

// The texts of -99 .. 99, each in the first bytes of four (the rest zero), and their lengths.
struct SmallIntegers {
  std::array<std::array<char, 4>, 199> text{};
  std::array<std::uint8_t, 199> length{};
  constexpr SmallIntegers() {
    for (int v = -99; v <= 99; ++v) {
      const unsigned u = static_cast<unsigned>(v < 0 ? -v : v);
      auto& t = text[static_cast<std::size_t>(v + 99)];
      std::size_t n = 0;
      if (v < 0) t[n++] = '-';
      if (u >= 10) t[n++] = static_cast<char>('0' + u / 10);
      t[n++] = static_cast<char>('0' + u % 10);
      length[static_cast<std::size_t>(v + 99)] = static_cast<std::uint8_t>(n);
    }
  }
};
inline constexpr SmallIntegers small_integers;

// `v` at `out` (at most 11 characters, and room for 11), as std::to_chars writes it; returns the
// end. The coordinates of a vector are most of a plot or an SVG document: the small ones, the
// commonest, copied from a table (four bytes, whatever the length: no branch on the digits).
inline char* put_int(char* out, int v) {
  const auto k = static_cast<unsigned>(v) + 99u;
  if (k < 199u) [[likely]] {
    std::memcpy(out, small_integers.text[k].data(), 4);
    return out + small_integers.length[k];
  }
  unsigned u = static_cast<unsigned>(v);
  if (v < 0) {
    *out++ = '-';
    u = 0u - u;
  }
  return std::to_chars(out, out + 10, u).ptr;
}
// "x,y" at `out` (at most 23 characters); returns the end.
inline char* put_pair(char* out, int x, int y) {
  out = put_int(out, x);
  *out++ = ',';
  return put_int(out, y);
}

}  // namespace igds
