// NAME.CADALIST: the output of CADA/REM/SUBROUTS (docs/marks.md, "The listing"):
// the 13 elements of every point row by row, then the boundary condition matrix B of every patch.
#pragma once

#include <cstddef>
#include <string>

#include "workspace/exchange/marks_deck.h"

namespace igds::exchange {

// The listing of a deck and its fit, lines ended by LF, FORTRAN fixed fields (F4.0, F7.1, F10.1;
// a value that does not fit is asterisks, counted in `*overflow` when it is given):
//   one line per point, row by row: the key (F4.0), x y z (3F7.1), then the horizontal, vertical
//   and twist vectors, each as (F10.1, 2F7.1): 97 columns, the groups three blanks apart;
//   a blank line;
//   per patch, row by row: the four rows of B in Marks's layout (the places of PATCHES's M),
//   each line row r of the x, y and z matrices side by side, (4F7.1, F10.1, 3F7.1, F10.1,
//   3F7.1), 90 columns: the fields CADA/REM/BINARY reads with 4(4F7.0, F10.0, 3F7.0, F10.0,
//   3F7.0/); then a blank line, the record that format's last slash passes over.
std::string cada_listing(const MarksDeck& deck, const MarksFit& fit,
                         std::size_t* overflow = nullptr);

}  // namespace igds::exchange
