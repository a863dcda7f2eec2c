// NAME.MPDPTAPE: the 8-track paper tape CADA/REM/BINARY punched for the PDP-7 Multi-Patch Design
// Program (docs/marks.md, "The tape").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/kernels/array.h"

namespace igds::exchange {

// One frame a byte. An 18-bit number is three frames, most significant six bits first, each with
// the two leftmost holes punched: 0o300 | six bits. Negative numbers in 18-bit two's complement.
inline constexpr unsigned char tape_holes = 0300;
inline constexpr std::size_t frames_per_number = 3;
inline constexpr std::size_t numbers_per_patch = 54;
inline constexpr std::int32_t tape_min = -131072, tape_max = 131071;
inline constexpr std::uint32_t tape_end = 0777777;  // the last number of a tape

// Why a tape cannot be written or read. Places are 1-based.
struct TapeError : std::exception {
  enum class Problem {
    shape,             // PATCHES is not (rows) x (columns) x 3 x 4 x 4
    out_of_range,      // `patch`: a number (rounded) outside -131072..131071, or not finite
    no_holes,          // `frame`: a frame without the two leftmost holes
    truncated_number,  // `frame`: the tape ends inside the number starting at this frame
    truncated_patch,   // `patch`: the tape ends inside this patch's 54 numbers
    no_end_mark,       // the tape ends after `patch` patches without 777777 (octal)
    after_end,         // `frame`: a frame other than blank tape after the end mark
  };

  Problem problem;
  std::size_t patch = 0, frame = 0;
  double value = 0;  // out_of_range: the value

  explicit TapeError(Problem p) : problem(p) {}
  // A developer's account of the problem, in English (not a report).
  const char* what() const noexcept override;

 private:
  mutable std::string text_;
};

// The frames of PATCHES ((NOCUR-1) x (NOSTR-1) x 3 x 4 x 4): for every patch row by row, 54
// numbers: the patch number (1, 2, ...), the internal lines and display options (0: all off),
// four zeros (neighbours, cyclicity, continuity), then the 16 x components of B row by row, the
// 16 y, the 16 z, each rounded to the nearest integer (halves away from zero, as FORTRAN's NINT),
// with MPDP's signs: S_V, SE_V, E_H and SE_H (M[0][3], M[1][3], M[3][0], M[3][1]) reversed; then
// the end mark. No leader or trailer. Throws TapeError (shape, out_of_range naming the first patch
// with a number that does not fit 18 bits); the size is 162 frames a patch and 3 more.
std::string write_tape(const Array& patches);

// One patch as the tape holds it, signs as punched.
struct TapePatch {
  std::int32_t number = 0;
  std::int32_t internal_lines = 0;
  std::array<std::int32_t, 4> links{};  // neighbours, cyclicity, continuity
  std::array<std::int32_t, 48> b{};     // x components of B row by row, then y, then z
  friend bool operator==(const TapePatch&, const TapePatch&) = default;
};

// Decodes a tape: blank frames (no holes at all: a punch's leader and trailer) before the first
// number and after the end mark are passed over; the end mark is looked for where a patch would
// start. Throws TapeError for anything else (no_holes, truncated_number, truncated_patch,
// no_end_mark, after_end); never reads past `frames`, and its work is linear in their number.
std::vector<TapePatch> read_tape(std::string_view frames);

// A decoded tape as text, for people and for comparing: per patch a line "PATCH n LINES l LINKS
// a b c d", then the four rows of B with the x, y and z matrices side by side (12 numbers a
// line, as the listing), then a blank line; "END" last.
std::string tape_text(const std::vector<TapePatch>& patches);

}  // namespace igds::exchange
