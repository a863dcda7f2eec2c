// STORE FIRST | SECOND | FILE (manual 4.8): a copy of the current image, in memory or on disk.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "workspace/error.h"

namespace igds {

namespace {

enum Option { first, second, file };

constexpr Choice options[] = {
    {"FIRST", first, {}, "the first copy in memory"},
    {"SECOND", second, {}, "the second copy in memory"},
    {"FILE", file, "[name]", "the file NAME.IGDSIMAG on the disk"},
};

const Prompt file_prompt{"FILE NAME?",
                         "A name for the image file: 1 to 8 letters, digits or $ # @ + - _ "
                         "(type IGDSIMAG; a file of that name is replaced)."};

void run_store(Context& ctx, const Choice* option) {
  Workspace& ws = ctx.workspace();
  if (!ws.image) throw Report(reports::image_not_found);
  if (option->code == file) {
    const std::string name = ask_file_name(ctx, file_prompt);
    const bool existed = ctx.disk().exists(name, "IGDSIMAG");
    store_image(ctx.disk(), name, *ws.image);
    if (existed) ctx.say(fmt::format("{}.IGDSIMAG REPLACED", name));
    return;
  }
  expect_no_more_words(ctx);
  (option->code == first ? ws.temp1 : ws.temp2) = ws.image;
}

constexpr const Prompt* questions[] = {&file_prompt};

}  // namespace

extern const Command store_command{
    .name = "STORE",
    .options = options,
    .follows = {},
    .option_prompt = {"FIRST, SECOND OR FILE?",
                      "FIRST or SECOND: keep the current image in memory; FILE: keep it in a "
                      "file on the disk.",
                      options},
    .summary = "keeps a copy of the current image in memory or in NAME.IGDSIMAG",
    .long_help =
        "STORE keeps a copy of the current image (the one last displayed), so that DISPLAY can "
        "show it again later without projecting anything.\n"
        "\n"
        "  STORE FIRST        the first copy in memory (DISPLAY FIRST shows it)\n"
        "  STORE SECOND       the second copy in memory (DISPLAY SECOND shows it)\n"
        "  STORE FILE [name]  the file NAME.IGDSIMAG on the disk (DISPLAY FILE name shows it); a "
        "file of the same name is replaced, and STORE says so.\n"
        "\n"
        "The copies in memory are part of the session: they are still there next time. With no "
        "current image STORE says IMAGE NOT FOUND; a name that is not 1 to 8 letters, digits or $ "
        "# @ + - _ gets INCORRECT PARAMETER.\n"
        "\n"
        "Example (S FI is STORE FIRST, S FIL is STORE FILE):\n"
        "  DISPLAY SURFACE ORTHOGONAL XY\n"
        "  S FI\n"
        "  STORE FILE TOPVIEW",
    .questions = questions,
    .run = run_store,
};

}  // namespace igds
