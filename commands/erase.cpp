// ERASE: a clean screen, as the PAGE key of the 4013 gave (DISPLAY never erases).
#include "commands/answers.h"
#include "commands/command.h"

namespace igds {

namespace {

void run_erase(Context& ctx, const Choice*) {
  expect_no_more_words(ctx);
  ctx.erase();
}

}  // namespace

extern const Command erase_command{
    .name = "ERASE",
    .options = {},
    .follows = {},
    .option_prompt = {},
    .summary = "a clean screen (a page)",
    .long_help =
        "ERASE clears the Tektronix screen, as the PAGE key of the 4013 did. DISPLAY never "
        "erases: like the storage tube, the screen keeps the images drawn on it, one over the "
        "other, so that they can be compared. ERASE is the way to start again from a clean "
        "screen. Nothing in the session changes. With images shown nowhere (--term none) ERASE "
        "does nothing.\n"
        "\n"
        "Example:\n"
        "  DISPLAY SURFACE ORTHOGONAL XY\n"
        "  DISPLAY SURFACE ORTHOGONAL XZ\n"
        "  ERASE\n"
        "  DISPLAY SURFACE ASSONOMETRIC 110 130 120",
    .questions = {},
    .run = run_erase,
};

}  // namespace igds
