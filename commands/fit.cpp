// FIT [name] (Marks 1970, CADA/REM/SUBROUTS; docs/marks.md): NAME.CADADATA, Marks's fitting
// deck, becomes the current surface with Marks's tangents and twists, and NAME.CADALIST its
// listing.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/entries.h"
#include "commands/reports.h"
#include "commands/surface.h"
#include "workspace/disk/disk.h"
#include "workspace/error.h"
#include "workspace/exchange/marks_deck.h"
#include "workspace/exchange/marks_listing.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/limits.h"
#include "workspace/kernels/surface.h"

namespace igds {

namespace {

using exchange::DeckError;

constexpr std::string_view kept = "CURRENT SURFACE KEPT";

// A deck holds at most max_input_points points: a key and two cards of 80 columns (and their
// line ends) for each, with room for sequence numbers and blank cards.
constexpr std::size_t max_deck_bytes = 4096 + 256 * max_input_points;

const Prompt file_prompt{"FILE NAME?",
                         "The name of a fitting deck: 1 to 8 letters, digits or $ # @ + - _ "
                         "(type CADADATA; the listing goes to NAME.CADALIST)."};

// What is wrong with a deck, in the words of the report.
std::string deck_reason(const DeckError& e) {
  switch (e.problem) {
    case DeckError::Problem::bad_number:
      return fmt::format("LINE {} COLUMN {}: NOT A NUMBER", e.line, e.column);
    case DeckError::Problem::bad_key:
      return fmt::format("LINE {} COLUMN {}: THE KEY OF POINT {} IS NOT 0 TO 15", e.line, e.column,
                         e.point);
    case DeckError::Problem::missing_point:
      return fmt::format("POINT {} HAS NO POSITION, KEY ON LINE {}; IGDS NEEDS EVERY POINT",
                         e.point, e.line);
    case DeckError::Problem::ends_early:
      return fmt::format("IT ENDS BEFORE LINE {}: NUMBERS MISSING", e.line);
    case DeckError::Problem::extra_cards:
      return fmt::format("LINE {}: A CARD AFTER THE LAST POINT", e.line);
    case DeckError::Problem::too_small:
      return fmt::format("{} ROWS AND {} COLUMNS: AT LEAST 2 OF EACH", e.rows, e.columns);
    case DeckError::Problem::too_large:
      return fmt::format("{} ROWS AND {} COLUMNS: MORE THAN {} POINTS", e.rows, e.columns,
                         max_input_points);
  }
  return "FORMAT";
}

void run_fit(Context& ctx, const Choice*) {
  const std::string name = ask_file_name(ctx, file_prompt);
  const std::string text = read_user_file(ctx.disk(), name, "CADADATA", max_deck_bytes, kept);
  exchange::MarksDeck deck;
  try {
    deck = exchange::read_deck(text);
  } catch (const DeckError& e) {
    throw Report(fmt::format("DECK REFUSED: {}.CADADATA ({}); {}", name, deck_reason(e), kept));
  }
  exchange::MarksFit fit;
  try {
    fit = exchange::fit_deck(deck);
  } catch (const DataError& e) {
    throw worded(e, kept);
  }
  const int nocur = deck.rows, nostr = deck.columns;
  const Density density = ask_density(ctx, nocur, nostr);

  // INTPN from Marks's patches: the interior tangents are his (F-mesh), not IGDS's splines.
  // Numbers near the largest make results that overflow: each is checked before it is kept.
  Surface surface;
  try {
    const SurfaceInput input{nocur,        nostr,      density.intcu, density.intst,
                             &deck.points, &fit.inptg, true};
    // PATCHES are checked whole before FIT, INTPN as FIT makes it.
    if (auto overflow = refit_into(input, fit.patches, surface.intpn)) throw *overflow;
    const std::size_t rows = fit.inptg.size() / 4;
    for (std::size_t r = 0; r < rows; ++r) {
      if (first_not_finite(fit.inptg.data() + 4 * r, 3) == 3) continue;
      DataError e(DataError::Problem::tangent_not_finite);
      e.number = static_cast<std::size_t>(fit.inptg.ravel[4 * r + 3]);
      throw e;
    }
  } catch (const DataError& e) {
    throw worded(e, "THE SURFACE IS NOT CHANGED");
  }
  surface.patches = fit.patches;

  // The listing first: when the disk refuses it, nothing has changed.
  std::size_t overflow = 0;
  write_user_file(ctx.disk(), name, "CADALIST", exchange::cada_listing(deck, fit, &overflow), true,
                  kept);

  std::size_t given = 0;
  for (int key : deck.keys)
    given += (key & exchange::key_horizontal ? 1 : 0) + (key & exchange::key_vertical ? 1 : 0) +
             (key & exchange::key_twist ? 1 : 0);
  // PATCHES are Marks's, not the interpolation of INPPN and INPTG: the session keeps them.
  make_current(ctx.workspace(), nocur, nostr, density, std::move(deck.points), fit.inptg,
               std::move(surface), {.marks_twists = true, .auto_tangents = true}, false);
  ctx.say(fmt::format("NOCUR {} NOSTR {} INTCU {} INTST {}", nocur, nostr, density.intcu,
                      density.intst));
  ctx.say(fmt::format("{}.CADALIST: {} POINTS, {} PATCHES, {} GIVEN VECTORS", name,
                      std::size_t(nocur) * std::size_t(nostr),
                      std::size_t(nocur - 1) * std::size_t(nostr - 1), given));
  if (overflow > 0)
    ctx.say(fmt::format("{} {} NOT FIT THE LISTING'S FIELDS: WRITTEN AS ASTERISKS", overflow,
                        overflow == 1 ? "VALUE DOES" : "VALUES DO"));
}

constexpr const Prompt* questions[] = {&file_prompt, &density_prompt};

}  // namespace

extern const Command fit_command{
    .name = "FIT",
    .options = {},
    .follows = "[name]",
    .option_prompt = {},
    .summary = "fits Marks's deck NAME.CADADATA: a new surface, and NAME.CADALIST",
    .long_help =
        "FIT reads NAME.CADADATA, the input deck of Marks's fitting program (Cambridge CAD Group, "
        "1970, CADA/REM/SUBROUTS), and makes it the current surface, replacing the old one. The "
        "deck is card images:\n"
        "\n"
        "  (2I4)    MR NC, the rows and columns of the grid: NOCUR and NOSTR\n"
        "  (18F4.0) the key of every point, row by row: 1 (position given), +2 tangent along the "
        "row given, +4 along the column, +8 twist given\n"
        "  (9F7.1)  for each point, row by row, a new card: x y z, then the given vectors (along "
        "the row, along the column, twist)\n"
        "\n"
        "Every point needs its position (a key of 0 is refused, the point named). Where the deck "
        "gives no vector, Marks's rule gives it: the F-mesh tangent (direction of the central "
        "difference, length of the shorter chord), the ends of a line made parabolas, and the "
        "twists of Birkhoff and de Boor. The surface has MARKS twists and AUTO border tangents. "
        "FIT then asks INTERPOLATED CURVES AND STRINGERS? as BUILD does, and writes "
        "NAME.CADALIST, the listing of the program: the 13 numbers of every point, then the "
        "matrix B of every patch.\n"
        "\n"
        "The interior tangents are Marks's, not IGDS's splines: CHANGE GRID keeps them; CHANGE "
        "POINTS, TANGENTS or TWISTS interpolates the points again with IGDS's splines.\n"
        "\n"
        "  FILE NOT FOUND        there is no NAME.CADADATA on the disk\n"
        "  DECK REFUSED: ...     the deck cannot be read (line, column or point named); the "
        "current surface is kept\n"
        "\n"
        "Example:\n"
        "  FIT SPHERE\n"
        "  INTERPOLATED CURVES AND STRINGERS? 2 2\n"
        "  NOCUR 5 NOSTR 5 INTCU 2 INTST 2\n"
        "  SPHERE.CADALIST: 25 POINTS, 16 PATCHES, 0 GIVEN VECTORS",
    .questions = questions,
    .run = run_fit,
};

}  // namespace igds
