// ERASE: a clean screen, as the PAGE key of the 4013 gave (DISPLAY never erases).
#include "commands/command.h"
#include "commands/entries.h"

namespace igds {

namespace {

void run_erase(Context& ctx, int) {
  expect_no_more_words(ctx);
  ctx.erase();
}

}  // namespace

extern const Command erase_command{
    .name = "ERASE",
    .options = {},
    .option_prompt = {},
    .short_help = "ERASE: clear the screen (DISPLAY draws over what is there).",
    .long_help = R"(ERASE clears the Tektronix screen, as the PAGE key of the 4013 did. DISPLAY
never erases: like the storage tube, the screen keeps everything drawn on it,
so that images can be compared one over the other. ERASE is the way to start
again from a clean screen. Nothing in the session changes. With images shown
nowhere (--term none) ERASE does nothing.

Example:
  DISPLAY SURFACE ORTHOGONAL XY
  DISPLAY SURFACE ORTHOGONAL XZ
  ERASE
  DISPLAY SURFACE ASSONOMETRIC 110 130 120)",
    .run = run_erase,
};

}  // namespace igds
