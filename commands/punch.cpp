// PUNCH [name] (Marks 1970, CADA/REM/BINARY; docs/marks.md, "The tape"): PATCHES on the 8-track
// paper tape of the PDP-7 Multi-Patch Design Program, NAME.MPDPTAPE.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "workspace/disk/disk.h"
#include "workspace/error.h"
#include "workspace/exchange/mpdp_tape.h"

namespace igds {

namespace {

using exchange::TapeError;

// The PDP-7 held about ten patches at a time (docs/marks.md).
constexpr std::size_t mpdp_patches = 10;

const Prompt file_prompt{"FILE NAME?",
                         "A name for the tape: 1 to 8 letters, digits or $ # @ + - _ (type "
                         "MPDPTAPE; a file of that name is replaced)."};

void run_punch(Context& ctx, const Choice*) {
  const Workspace& ws = ctx.workspace();
  if (!ws.has_input()) throw Report(reports::input_not_found);
  if (ws.nocur < 2 || ws.nostr < 2)
    throw Report("A SINGLE CURVE OR STRINGER HAS NO PATCHES TO PUNCH");
  // The tape numbers its patches in 18 bits, the number as any other.
  const std::size_t count = std::size_t(ws.nocur - 1) * std::size_t(ws.nostr - 1);
  if (count > std::size_t(exchange::tape_max))
    throw Report(fmt::format("{} PATCHES: THE TAPE NUMBERS AT MOST {}; NO FILE WRITTEN", count,
                             exchange::tape_max));
  const std::string name = ask_file_name(ctx, file_prompt);
  std::string tape;
  try {
    Array made;
    tape = exchange::write_tape(patches_of(ws, made));
  } catch (const TapeError& e) {
    if (e.problem == TapeError::Problem::out_of_range)
      throw Report(fmt::format(
          "PATCH {} HOLDS {}, OUTSIDE THE TAPE'S 18 BITS (-131072 TO 131071); NO FILE WRITTEN",
          e.patch, fmt::format("{:.6g}", e.value)));
    throw Report("PATCHES IS NOT NOCUR-1 BY NOSTR-1 BY 3 BY 4 BY 4; NO FILE WRITTEN");
  }
  write_user_file(ctx.disk(), name, "MPDPTAPE", tape);
  ctx.say(fmt::format("{}.MPDPTAPE: {} {}, {} FRAMES", name, count,
                      count == 1 ? "PATCH" : "PATCHES", tape.size()));
  if (count > mpdp_patches)
    ctx.say(fmt::format("MPDP HOLDS ABOUT {} PATCHES AT A TIME", mpdp_patches));
}

constexpr const Prompt* questions[] = {&file_prompt};

}  // namespace

extern const Command punch_command{
    .name = "PUNCH",
    .options = {},
    .follows = "[name]",
    .option_prompt = {},
    .summary = "punches PATCHES on the MPDP paper tape NAME.MPDPTAPE",
    .long_help =
        "PUNCH writes the patches of the current surface to NAME.MPDPTAPE, the 8-track paper tape "
        "that Marks's CADA/REM/BINARY punched for the PDP-7 Multi-Patch Design Program (MPDP), "
        "one frame a byte:\n"
        "\n"
        "  - every number is 18 bits in three frames, most significant six bits first, each frame "
        "with its two leftmost holes: 300 octal + 6 bits; negative numbers in two's complement; "
        "values rounded to integers\n"
        "  - per patch, row by row, 54 numbers: the patch number, the internal lines (0), four "
        "zeros, then B (Marks's layout of the patch matrix) for x, y and z, 16 numbers each, row "
        "by row, with MPDP's signs: S_V, SE_V, E_H and SE_H change sign\n"
        "  - the tape ends with 777777 octal\n"
        "\n"
        "A number outside -131072 to 131071 cannot be punched: PUNCH names the patch and writes "
        "nothing (scale the surface down first). The PDP-7 held about ten patches at a time: "
        "PUNCH says so when there are more. A single curve or stringer has no patches. A file of "
        "the same name is replaced.\n"
        "\n"
        "  INPUT NOT FOUND       there is no current surface\n"
        "  INCORRECT PARAMETER   the name is not such a name\n"
        "\n"
        "Example (PU is PUNCH; P stays PLOT):\n"
        "  PU SPHERE\n"
        "  SPHERE.MPDPTAPE: 16 PATCHES, 2595 FRAMES\n"
        "  MPDP HOLDS ABOUT 10 PATCHES AT A TIME",
    .questions = questions,
    .run = run_punch,
};

}  // namespace igds
