// The IGDSCHAR card format of WRITE (docs/disk.md): FORTRAN I5 and F10.3 fields
// (workspace/numbers/fortran.h), written the way gfortran writes them, so that a FORTRAN READ
// with the same formats gets the values back.
#pragma once

#include <cstddef>
#include <string>

#include "workspace/state.h"
#include "workspace/text_out.h"

namespace igds::disk {

// The cards' longest line: (8F10.3) and its LF.
inline constexpr std::size_t longest_card = 8 * 10 + 1;

// The IGDSCHAR text of `ws` into `out`, cards ended by LF, made as it is written: the value
// cards of a large array on all cores (text_out.h's put_each), each card where it goes. `ws` must
// stay unchanged meanwhile. Returns the F10.3 values written as asterisks.
std::size_t put_char_cards(const Workspace& ws, TextOut& out);

// The whole IGDSCHAR text of `ws`, cards ended by LF; `*overflow` counts F10.3 asterisks.
std::string char_cards(const Workspace& ws, std::size_t* overflow);

}  // namespace igds::disk
