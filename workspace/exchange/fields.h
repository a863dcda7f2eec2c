// Numbers and dates as the exchange files write them: FORTRAN's edit descriptors for DUCT (Iw,
// Fw.d, Ew.d), the shortest exact decimal for IGES and STEP. Each appends to a string through a
// buffer on the stack: no allocation per number beyond the string's own growth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace igds {

// Iw: right-justified in `width` columns. A value too wide for its field is written in full after
// one blank (FORTRAN would write asterisks; a list-directed reader reads this).
void put_integer(std::string& out, std::int64_t value, int width);
// The same at `out` (room for max(width, 21) characters); returns the end.
char* put_integer(char* out, std::int64_t value, int width);

// Fw.d: `decimals` digits after the point, right-justified in `width` columns; too wide: as
// put_integer says, and beyond 24 characters in put_real's exact exponent form (1.875E200).
void put_fixed(std::string& out, double value, int width, int decimals);
// The same at `out` (room for max(width, 26) characters); returns the end.
char* put_fixed(char* out, double value, int width, int decimals);

// Ew.d: sign, "0.", `digits` digits, then E+ee, or +eee without the E when the exponent has three
// digits (FORTRAN's form), right-justified in `width` columns: E14.7 of 12.5 is
// " 0.1250000E+02". Zero (of either sign) is 0.0000000E+00.
void put_exponent(std::string& out, double value, int width, int digits);
// The same at `out` (room for max(width, 40) characters); returns the end.
char* put_exponent(char* out, double value, int width, int digits);

// The same into `buffer` (at least 40 characters, for digits up to 16), unpadded; returns the
// length.
std::size_t format_exponent(char* buffer, double value, int digits);

// The shortest decimal that reads back as the same double, with a decimal point always (IGES
// and STEP reals must have one): 1 -> "1.", 0.1 -> "0.1", 1e+20 -> "1.E20", -2.5e-07 ->
// "-2.5E-7".
void put_real(std::string& out, double value);
// The same into `buffer` (at least 32 characters); returns the length.
std::size_t format_real(char* buffer, double value);

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

// A number read in FORTRAN's ways: an optional sign, digits with or without a point, and an
// exponent written E, D (either case) or as a bare sign (0.1234567+100). nullopt for anything
// else, including numbers that are not finite.
std::optional<double> parse_fortran_real(std::string_view token);
// An optional sign and digits, within 64 bits.
std::optional<std::int64_t> parse_fortran_integer(std::string_view token);

// A moment, as the caller's clock gives it (the writers never read the clock themselves, so
// their files can be compared byte for byte).
struct Timestamp {
  int year = 1975, month = 1, day = 1, hour = 0, minute = 0, second = 0;
};
// "22 SEP 1987 09:55:50", the form of DUCT's header line.
std::string duct_date(const Timestamp& t);
// "19870922.095550", IGES's global section.
std::string iges_date(const Timestamp& t);
// "1987-09-22T09:55:50", STEP's FILE_NAME.
std::string iso_date(const Timestamp& t);

}  // namespace igds
