// WRITE [name] (manual 4.7): the current surface as character card images in NAME IGDSCHAR.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "workspace/error.h"

namespace igds {

namespace {

const Prompt file_prompt{"FILE NAME?",
                         "A name for the character file: 1 to 8 letters, digits or $ # @ + - _ "
                         "(type IGDSCHAR; a file of that name is replaced)."};

void run_write(Context& ctx, const Choice*) {
  const Workspace& ws = ctx.workspace();
  if (!ws.has_input()) throw Report(reports::input_not_found);
  const std::string name = ask_file_name(ctx, file_prompt);
  const bool existed = ctx.disk().exists(name, "IGDSCHAR");
  std::size_t overflow = write_char(ctx.disk(), name, ws);
  if (existed) ctx.say(fmt::format("{}.IGDSCHAR REPLACED", name));
  if (overflow == 1) ctx.say("1 VALUE DOES NOT FIT F10.3: WRITTEN AS **********");
  if (overflow > 1)
    ctx.say(fmt::format("{} VALUES DO NOT FIT F10.3: WRITTEN AS **********", overflow));
}

constexpr const Prompt* questions[] = {&file_prompt};

}  // namespace

extern const Command write_command{
    .name = "WRITE",
    .options = {},
    .follows = "[name]",
    .option_prompt = {},
    .summary = "writes the current surface as card images into NAME.IGDSCHAR",
    .long_help =
        "WRITE writes the current surface to the character file NAME.IGDSCHAR on the disk, in "
        "card images that a FORTRAN program (or any other) can read with these formats, one group "
        "after the other:\n"
        "\n"
        "  (10I5)    STATUS\n"
        "  (4I5)     NOCUR NOSTR INTCU INTST\n"
        "  (2I5)     the shape of INPPN,   then (8F10.3) INPPN, 8 numbers a card\n"
        "  (2I5)     the shape of INPTG,   then (8F10.3) INPTG\n"
        "  (3I5)     the shape of INTPN,   then (8F10.3) INTPN\n"
        "  (5I5)     the shape of PATCHES, then (8F10.3) PATCHES\n"
        "\n"
        "Values are rounded to 3 decimals. A value that needs more than 10 columns (1000000 or "
        "more, -100000 or less) is written as ten asterisks, as FORTRAN does, and WRITE says how "
        "many there are; SAVE keeps every value exactly. A file of the same name is replaced, and "
        "WRITE says so (HULL.IGDSCHAR REPLACED).\n"
        "\n"
        "The name may follow the command; otherwise IGDS asks for it. A name is 1 to 8 letters, "
        "digits or $ # @ + - _ (HULL and hull are the same file).\n"
        "\n"
        "  INPUT NOT FOUND       there is no current surface\n"
        "  INCORRECT PARAMETER   the name is not such a name\n"
        "\n"
        "Example:\n"
        "  WRITE HULL",
    .questions = questions,
    .run = run_write,
};

}  // namespace igds
