// REDO: forward again through the states of the workspace that UNDO went back from
// (workspace/journal.h).
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/picture.h"
#include "commands/reports.h"

namespace igds {

namespace {

void run_redo(Context& ctx, const Choice*) {
  expect_no_more_words(ctx);
  const ImageRef before = ctx.workspace().image;
  std::optional<std::string> redone;
  try {
    redone = ctx.journal().redo(ctx.workspace());
  } catch (const DataError& e) {
    throw worded(e, "NOTHING REDONE");
  }
  if (!redone) throw Report("NOTHING TO REDO");
  show_current_image(ctx, before);
  ctx.say(fmt::format("REDONE: {}", *redone));
}

}  // namespace

extern const Command redo_command{
    .name = "REDO",
    .options = {},
    .follows = {},
    .option_prompt = {},
    .summary = "makes again what UNDO undid",
    .long_help =
        "REDO makes again the change of the last command that UNDO undid, and says which (REDONE: "
        "CHANGE POINTS). Typed again, it goes one more command forward. A command that changes "
        "the workspace after UNDO ends what REDO can make again: NOTHING TO REDO. RED is its "
        "shortest form (R and RE are RESTORE).\n"
        "\n"
        "Example:\n"
        "  UNDO\n"
        "UNDONE: CHANGE POINTS\n"
        "  REDO\n"
        "REDONE: CHANGE POINTS",
    .questions = {},
    .run = run_redo,
};

}  // namespace igds
