// UNDO: back through the states of the workspace after each command that changed
// it, as the journal keeps them (workspace/journal.h), across sessions; REDO is commands/redo.cpp.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/picture.h"
#include "commands/reports.h"

namespace igds {

namespace {

void run_undo(Context& ctx, const Choice*) {
  expect_no_more_words(ctx);
  const ImageRef before = ctx.workspace().image;
  std::optional<std::string> undone;
  try {
    undone = ctx.journal().undo(ctx.workspace());
  } catch (const DataError& e) {
    throw worded(e, "NOTHING UNDONE");
  }
  if (!undone) throw Report("NOTHING TO UNDO");
  show_current_image(ctx, before);
  ctx.say(fmt::format("UNDONE: {}", *undone));
}

}  // namespace

extern const Command undo_command{
    .name = "UNDO",
    .options = {},
    .follows = {},
    .option_prompt = {},
    .summary = "takes back the last change of the workspace",
    .long_help =
        "UNDO puts the workspace back as it was before the last command that changed it, and says "
        "which command it undid (UNDONE: CHANGE POINTS). Typed again, it goes one more command "
        "back. What comes back: NOCUR NOSTR INTCU INTST, the points and tangents, the current "
        "image, FIRST and SECOND, STATUS; PATCHES and INTPN are interpolated again. Files on the "
        "disk (SAVE, STORE FILE, WRITE, PLOT) are not taken back. REDO makes again what UNDO "
        "undid; a command that changes the workspace after UNDO ends what REDO could make again. "
        "The last 200 commands are kept (fewer when they changed very large surfaces whole), and "
        "they stay on the disk with the session: UNDO works after END and a new start (back to a "
        "BUILD or RESTORE of more than about 45 x 45 points: those only the run that made them "
        "can undo). NOTHING TO UNDO: no earlier state is kept (a new disk, or all undone).\n"
        "\n"
        "Example:\n"
        "  CHANGE POINTS\n"
        "  ...\n"
        "  UNDO\n"
        "UNDONE: CHANGE POINTS",
    .questions = {},
    .run = run_undo,
};

}  // namespace igds
