// NAME.CADADATA, the fitting deck of CADA/REM/SUBROUTS (docs/marks.md, "The fitting deck"), and
// the fit it asks for: Marks's tangents and twists wherever the deck gives none, and PATCHES.
#pragma once

#include <cstddef>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/kernels/array.h"
#include "workspace/kernels/coons.h"

namespace igds::exchange {

// A point's key is the sum of what the deck gives for it (docs/marks.md: bits 1, 2, 4, 8).
inline constexpr int key_position = 1;
inline constexpr int key_horizontal = 2;  // the tangent along the row (an igds curve)
inline constexpr int key_vertical = 4;    // the tangent along the column (an igds stringer)
inline constexpr int key_twist = 8;

// Marks's ARRAY (MR x NC x 13) as the deck gives it. Rows of Marks's grid are igds curves, columns
// igds stringers; points in igds's point-number order (row by row).
struct MarksDeck {
  int rows = 0, columns = 0;  // MR, NC: NOCUR, NOSTR
  std::vector<int> keys;      // MR*NC keys, 1 to 15, bit key_position always set
  Array points;               // (MR*NC) x 3
  // The given vectors, per unit of patch parameter, (MR*NC) x 3 each, zero where not given.
  Array horizontal, vertical, twists;
};

// Why a deck cannot be read. Places are 1-based; the commands layer words the report.
struct DeckError : std::exception {
  enum class Problem {
    bad_number,     // `line`, `column`: a field that is not a FORTRAN number (or is not finite)
    bad_key,        // `line`, `column`, `point`: a key that is not a whole number from 0 to 15
    missing_point,  // `point` (row by row), `line` of its key: the key gives no position
    ends_early,     // `line`: the deck ends (before this line) while numbers are still wanted
    extra_cards,    // `line`: a card that is not blank after the last point
    too_small,      // `rows`, `columns`: MR or NC below 2
    too_large,      // `rows`, `columns`: MR x NC above max_input_points (limits.h)
  };

  Problem problem;
  std::size_t line = 0, column = 0, point = 0;
  long long rows = 0, columns = 0;

  explicit DeckError(Problem p) : problem(p) {}
  // A developer's account of the problem, in English (not a report).
  const char* what() const noexcept override;

 private:
  mutable std::string text_;
};

// Reads the card images of a deck: (2I4) MR NC; (18F4.0) the MR*NC keys row by row, 18 a card;
// then for each point row by row, starting a new card, (9F7.1) x y z and its given vectors in the
// order horizontal, vertical, twist, nine fields a card. FORTRAN's reading of fixed fields: a
// short card is padded with blanks, blanks inside a field are ignored, a blank field is zero, a
// field without a decimal point has an implied one before its last digit (F7.1: "    125" is
// 12.5), columns after the format's last field are not read. Throws DeckError.
MarksDeck read_deck(std::string_view text);

// CADA/REM/SUBROUTS's computation on a deck.
struct MarksFit {
  GridTangents tangents;  // per_parameter: the given vectors, Marks's (marks.h) elsewhere
  Array twists;           // (MR*NC) x 3: the given ones, Marks's elsewhere
  Array patches;          // PATCHES, (MR-1) x (NC-1) x 3 x 4 x 4, from the two above
  Array inptg;            // the border tangents per unit of chord (workspace/state.h order)
};
MarksFit fit_deck(const MarksDeck& deck);

}  // namespace igds::exchange
