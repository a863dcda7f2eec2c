// RESTORE [name] (manual 4.3): NAME IGDSDATA, written by SAVE, becomes the current surface.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "workspace/error.h"

namespace igds {

namespace {

const Prompt file_prompt{"FILE NAME?",
                         "The name of a file saved with SAVE: 1 to 8 letters, digits or "
                         "$ # @ + - _ (type IGDSDATA)."};

void run_restore(Context& ctx, const Choice*) {
  const std::string name = ask_file_name(ctx, file_prompt);
  Workspace& ws = ctx.workspace();
  restore_surface(ctx.disk(), name, ws);
  ctx.say(
      fmt::format("NOCUR {} NOSTR {} INTCU {} INTST {}", ws.nocur, ws.nostr, ws.intcu, ws.intst));
}

constexpr const Prompt* questions[] = {&file_prompt};

}  // namespace

extern const Command restore_command{
    .name = "RESTORE",
    .options = {},
    .follows = "[name]",
    .option_prompt = {},
    .summary = "makes NAME.IGDSDATA the current surface",
    .long_help =
        "RESTORE reads the file NAME.IGDSDATA from the disk, written earlier by SAVE, and makes "
        "the surface in it the current surface: the input points and tangents, NOCUR, NOSTR, "
        "INTCU, INTST, the patches and the interpolated grid. The current image, the stored "
        "copies and the HELP setting are not changed. Afterwards IGDS shows the numbers of curves "
        "and stringers and the grid.\n"
        "\n"
        "The name may follow the command; otherwise IGDS asks for it. A name is 1 to 8 letters, "
        "digits or $ # @ + - _ (HULL and hull are the same file).\n"
        "\n"
        "  INCORRECT PARAMETER   the name is not such a name\n"
        "  FILE NOT FOUND        there is no NAME.IGDSDATA on the disk\n"
        "  FILE DAMAGED: ...     the file is not a good IGDSDATA file; the current surface is "
        "kept\n"
        "\n"
        "Example:\n"
        "  RESTORE HULL\n"
        "  NOCUR 4 NOSTR 5 INTCU 3 INTST 3",
    .questions = questions,
    .run = run_restore,
};

}  // namespace igds
