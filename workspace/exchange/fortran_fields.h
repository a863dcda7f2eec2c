// FORTRAN fixed-field card images, as the decks and listings of the Cambridge programs of 1970
// used them (spec marks.md): reading Iw and Fw.d fields, writing Fw.d as gfortran writes it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace igds::exchange {

// The lines of a text as cards: a line ends at LF (a CR before it is dropped); a last line without
// LF is a card too.
class Cards {
 public:
  explicit Cards(std::string_view text) : text_(text) {}
  // The next card into `card`; false at the end of the text.
  bool next(std::string_view& card);
  // The line number of the card last returned (1-based; 0 before the first).
  std::size_t line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0, line_ = 0;
};

// The value of an input field of `width` columns starting at column `first` (0-based) of `card`,
// read as FORTRAN does with BLANK='NULL' (gfortran's default): columns past the card's end are
// blanks, blanks are ignored, a blank field is zero. nullopt when the field is not a number.
// Iw: an optional sign and digits.
std::optional<long long> read_i(std::string_view card, std::size_t first, std::size_t width);
// Fw.d: an optional sign, digits with at most one decimal point (without one, the last `decimals`
// digits are the fraction), an optional exponent (E, D or a sign, then digits); nullopt also when
// the value is not a finite double.
std::optional<double> read_f(std::string_view card, std::size_t first, std::size_t width,
                             int decimals);

// Fw.d output: the value rounded to `decimals` places, right-aligned in `width` columns, a decimal
// point even when `decimals` is 0 (F4.0 writes 1 as "  1."), a minus sign on negative values
// that round to zero; `width` asterisks when it does not fit or is not finite.
std::string format_f(double value, int width, int decimals);

}  // namespace igds::exchange
