// The IGDSCHAR card format (spec igds.md section 5): FORTRAN I5 and F10.3 fields, written the
// way gfortran writes them, so that a FORTRAN READ with the same formats gets the values back.
#pragma once

#include <cstddef>
#include <string>

#include "workspace/state.h"

namespace igds::disk {

// Iw: right-aligned in `width` columns; w asterisks when the number does not fit.
std::string format_i(long long value, int width);

// F10.3: the exact binary value rounded to 3 decimals, halves to even (as gfortran does), a
// minus sign on negative values that round to zero, right-aligned in 10 columns; ten asterisks
// when it does not fit (sets *fits = false). NaN and infinities as gfortran: "NaN",
// "Infinity", "-Infinity".
std::string format_f10_3(double value, bool* fits);

// The same fields written at `out`: exactly `width` (put_i) or 10 (put_f10_3) characters, by
// integer arithmetic. They return false, having written asterisks, when the number does not fit.
bool put_i(char* out, long long value, int width);
bool put_f10_3(char* out, double value);

// The whole IGDSCHAR text of `ws`, cards ended by LF; `*overflow` counts F10.3 asterisks.
std::string char_cards(const Workspace& ws, std::size_t* overflow);

}  // namespace igds::disk
