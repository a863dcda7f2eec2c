// REDO (issue 14): forward again through the states of the workspace that UNDO went back from
// (workspace/journal.h).
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/reports.h"

namespace igds {

namespace {

void run_redo(Context& ctx, const Choice*) {
  expect_no_more_words(ctx);
  std::optional<std::string> redone;
  try {
    redone = ctx.journal().redo(ctx.workspace());
  } catch (const DataError& e) {
    throw worded(e, "NOTHING REDONE");
  }
  if (!redone) throw Report("NOTHING TO REDO");
  ctx.say(fmt::format("REDONE: {}", *redone));
}

}  // namespace

extern const Command redo_command{
    .name = "REDO",
    .options = {},
    .follows = {},
    .option_prompt = {},
    .summary = "makes again what UNDO undid",
    .long_help = R"(REDO makes again the change of the last command that UNDO undid, and
says which (REDONE: CHANGE POINTS). Typed again, it goes one more
command forward. A command that changes the workspace after UNDO ends
what REDO can make again: NOTHING TO REDO. RED is its shortest form
(R and RE are RESTORE).

Example:
  UNDO
UNDONE: CHANGE POINTS
  REDO
REDONE: CHANGE POINTS)",
    .questions = {},
    .run = run_redo,
};

}  // namespace igds
