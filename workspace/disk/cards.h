// The IGDSCHAR card format of WRITE (docs/disk.md): FORTRAN I5 and F10.3 fields
// (workspace/numbers/fortran.h), written the way gfortran writes them, so that a FORTRAN READ
// with the same formats gets the values back.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <utility>

#include "workspace/state.h"

namespace igds::disk {

// The IGDSCHAR text of `ws`, cards ended by LF, made piece by piece as WRITE writes the file:
// `ws` must stay unchanged until the last piece is made.
class CardMaker {
 public:
  static constexpr std::size_t longest_card = 8 * 10 + 1;  // (8F10.3) and its LF

  explicit CardMaker(const Workspace& ws);
  // The whole text's length.
  std::size_t size() const;
  // The next whole cards, at most `room` bytes (at least longest_card) at `out`; 0 at the end.
  std::size_t fill(char* out, std::size_t room);
  // The F10.3 values written so far as asterisks.
  std::size_t overflow() const { return overflow_; }

 private:
  const Workspace& ws_;
  std::array<std::pair<const Array*, std::size_t>, 4> arrays_;  // INPPN INPTG INTPN PATCHES, rank
  bool headed_ = false;    // the (10I5) and (4I5) cards are made
  std::size_t array_ = 0;  // the array whose cards come next
  bool shaped_ = false;    // its shape card is made
  std::size_t next_ = 0;   // its next value
  std::size_t overflow_ = 0;
};

// The whole IGDSCHAR text of `ws`, cards ended by LF; `*overflow` counts F10.3 asterisks.
std::string char_cards(const Workspace& ws, std::size_t* overflow);

}  // namespace igds::disk
