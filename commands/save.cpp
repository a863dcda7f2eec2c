// SAVE [name] (manual 4.6): the current surface in the binary file NAME IGDSDATA.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "workspace/error.h"

namespace igds {

namespace {

const Prompt file_prompt{"FILE NAME?",
                         "A name for the surface file: 1 to 8 letters, digits or $ # @ + - _ "
                         "(type IGDSDATA; a file of that name is replaced)."};

void run_save(Context& ctx, const Choice*) {
  const Workspace& ws = ctx.workspace();
  if (!ws.has_input()) throw Report(reports::input_not_found);
  const std::string name = ask_file_name(ctx, file_prompt);
  const bool existed = ctx.disk().exists(name, "IGDSDATA");
  save_surface(ctx.disk(), name, ws);
  if (existed) ctx.say(fmt::format("{}.IGDSDATA REPLACED", name));
}

constexpr const Prompt* questions[] = {&file_prompt};

}  // namespace

extern const Command save_command{
    .name = "SAVE",
    .options = {},
    .follows = "[name]",
    .option_prompt = {},
    .summary = "writes the current surface into NAME.IGDSDATA",
    .long_help =
        "SAVE writes the current surface to the file NAME.IGDSDATA on the disk: the input points "
        "and tangents, NOCUR, NOSTR, INTCU, INTST, the patches and the interpolated grid, exactly "
        "(RESTORE gives back the very same numbers). A file of the same name is replaced, and "
        "SAVE says so (HULL.IGDSDATA REPLACED); the file is written whole or not at all. These "
        "files are an archive of surfaces; RESTORE makes one current again.\n"
        "\n"
        "The name may follow the command; otherwise IGDS asks for it. A name is 1 to 8 letters, "
        "digits or $ # @ + - _ (HULL and hull are the same file).\n"
        "\n"
        "  INPUT NOT FOUND       there is no current surface (BUILD or RESTORE first)\n"
        "  INCORRECT PARAMETER   the name is not such a name\n"
        "  CANNOT WRITE ...      the disk refused (full, say); nothing was changed\n"
        "\n"
        "Example (SA is the shortest abbreviation: S is STORE):\n"
        "  SA HULL",
    .questions = questions,
    .run = run_save,
};

}  // namespace igds
