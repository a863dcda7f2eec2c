// FORTRAN's edit descriptors Iw, Fw.d and Ew.d, read and written as igds's card images and files
// use them (docs/exchange.md, "Numbers"): WRITE's cards (docs/disk.md), DUCT pictures, the fixed
// columns of IGES, the Marks deck, listing and tape text (docs/marks.md). Writers round the exact
// binary value of a double to their digits, exact halves to even, as gfortran does; readers take
// what gfortran's READ takes. Fw.d's `decimals` are 0 to 60.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace igds::fortran {

// ---------------------------------------------------------------------------------------------
// Writing as FORTRAN does: exactly `width` characters at `out`, right-justified; `width`
// asterisks, and false, when the value does not fit.

// Iw.
bool put_i(char* out, std::int64_t value, int width);

// Fw.d: the digit before the point always written ("0.500"), the point too when `decimals` is 0
// (F4.0 of 1 is "  1."), a minus sign on every negative value, zero and those that round to zero
// included ("-0.000"). NaN and the infinities as gfortran writes them: "NaN", "Infinity" or
// "Inf", "-Infinity" or "-Inf", whichever fits (true), else asterisks.
bool put_f(char* out, double value, int width, int decimals);

// ---------------------------------------------------------------------------------------------
// Writing a field that never loses its value (DUCT's records and IGES's columns): right-justified
// in `width` columns, or, when the text is wider, the whole text after one blank (list-directed
// readers read it; FORTRAN would write asterisks). A zero has no sign. The char* forms return
// the end; the string forms append.

// Iw. Room at `out`: max(width, 21) characters.
char* put_i_whole(char* out, std::int64_t value, int width);
void put_i_whole(std::string& out, std::int64_t value, int width);

// Fw.d as put_f writes it, but a text beyond 24 characters in the shortest exact form with an
// exponent (1.875E200, decimal.h's format_real). Room at `out`: max(width, 26) characters.
char* put_f_whole(char* out, double value, int width, int decimals);
void put_f_whole(std::string& out, double value, int width, int decimals);

// Ew.d: sign, "0.", `digits` digits (1 to 16), then E+ee, or +eee without the E when the exponent
// has three digits (FORTRAN's form): E14.7 of 12.5 is " 0.1250000E+02", of 1e100
// " 0.1000000+101". Room at `out`: max(width, 40) characters.
char* put_e_whole(char* out, double value, int width, int digits);

// ---------------------------------------------------------------------------------------------
// Writing a real that an Fw.d input field reads whatever its magnitude (DUCT's R1..R7 and T U):
// on input Fw.d takes a point anywhere and an exponent, so a value Fw.d cannot write is still
// written in the field's columns.

// `value` (finite) rounded to `digits` significant digits (1 to 17, halves of the exact binary
// value to even), or its shortest exact digits when `digits` is 0, as the shorter of the plain
// form ("123456.8", "0.0125") and the exponent form ("1.25E-3", "9.876543E8"), the plain one
// only when shorter; a point in both, no '+', no trailing zeros ("1.E6", "0.").
std::string input_text(double value, int digits);

// `width` columns at `out`, right-justified, that read_f(.., width, decimals) reads: Fw.d as
// put_f writes it when it reads back as `value`; else the shortest exact input_text when it fits;
// else the nearest value the columns hold: input_text with as many digits as fit, or Fw.d when
// it holds as many. False, and
// asterisks, only when nothing fits (NaN, the infinities, a width under 8).
bool put_f_input(char* out, double value, int width, int decimals);

// ---------------------------------------------------------------------------------------------
// Reading.

// An input field of `width` columns from column `first` (0-based) of `card`, as FORTRAN's
// formatted READ takes it with BLANK='NULL' (gfortran's default): columns past the card's end
// are blanks, blanks are ignored, a blank field is zero. nullopt when it is not a number.
// Iw: an optional sign and digits, within 64 bits.
std::optional<std::int64_t> read_i(std::string_view card, std::size_t first, std::size_t width);
// Fw.d, and Ew.d, which reads the same: an optional sign, digits with at most one point (without
// one, the last `decimals` digits are the fraction: F7.1 reads "    125" as 12.5), an optional
// exponent (E or D in either case then an optional sign, or a sign alone, then digits); nullopt
// also for a value that is not a finite double.
std::optional<double> read_f(std::string_view card, std::size_t first, std::size_t width,
                             int decimals);

// A value of list-directed input (a field that has a point or an exponent where it has them):
// as read_f reads a field without blanks and with no implied decimals; nullopt for anything
// else, an empty text and texts of more than 125 characters included.
std::optional<double> read_real(std::string_view text);
// An optional sign and digits, within 64 bits.
std::optional<std::int64_t> read_integer(std::string_view text);

// The values of a line of list-directed input, separated by blanks, tabs or commas (several
// together count as one): the first `limit` at `out`; returns how many there are in all.
std::size_t split_values(std::string_view line, std::string_view* out, std::size_t limit);

}  // namespace igds::fortran
