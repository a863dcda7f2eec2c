// END APL | CMS (manual 4.9): leave IGDS; the session is saved either way.
#include "commands/answers.h"
#include "commands/command.h"

namespace igds {

namespace {

enum Option { apl, cms };

constexpr Choice options[] = {
    {"APL", apl, {}, "the APL environment, with the workspace's variables"},
    {"CMS", cms, {}, "leave igds (the session is kept)"},
};

void run_end(Context& ctx, const Choice* option) {
  expect_no_more_words(ctx);
  ctx.end_session(option->code == apl);
}

}  // namespace

extern const Command end_command{
    .name = "END",
    .options = options,
    .follows = {},
    .option_prompt = {"APL OR CMS?",
                      "APL: look at the workspace variables; CMS: leave igds (the session is "
                      "kept either way).",
                      options},
    .summary = "APL: the APL environment; CMS: leaves igds",
    .long_help =
        "END ends the IGDS conversation. Everything (surface, images, copies, the HELP setting) "
        "is already saved on the disk in BINSAVE.IGDSCONT and comes back the next time igds "
        "starts on this disk.\n"
        "\n"
        "  END CMS  leave igds and return to the shell (Ctrl-D at READY does the same).\n"
        "  END APL  enter the APL environment, prompted by six blanks, where the workspace "
        "variables can be looked at: )VARS    the names of the variables INPPN    a variable, "
        "displayed as APL does (also NOCUR, NOSTR, INTCU, INTST, INPTG, PATCHES, INTPN, IMAGE, "
        "DESIM, TEMP1, DEST1, TEMP2, DEST2, STATUS) ⍴INPPN   its shape (RHO INPPN also works) "
        "START    back to IGDS (READY) )OFF     leave igds\n"
        "\n"
        "Example:\n"
        "  END APL NOCUR\n"
        "  4 )OFF",
    .questions = {},
    .run = run_end,
};

}  // namespace igds
