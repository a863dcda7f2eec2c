// END APL | CMS (manual 4.9): leave IGDS; the session is saved either way.
#include "commands/command.h"
#include "commands/entries.h"

namespace igds {

namespace {

void run_end(Context& ctx, int option) {
  expect_no_more_words(ctx);
  ctx.end_session(option == 0);
}

}  // namespace

extern const Command end_command{
    .name = "END",
    .options = {"APL", "CMS"},
    .option_prompt = {"APL OR CMS?",
                      "APL: look at the workspace variables; CMS: leave igds (the session is "
                      "kept either way)."},
    .short_help = "END CMS: leave igds; END APL: look at the workspace variables first.",
    .long_help = R"(END ends the IGDS conversation. Everything (surface, images, copies, the HELP
setting) is already saved on the disk in BINSAVE IGDSCONT and comes back the next
time igds starts on this disk.

  END CMS   leave igds and return to the shell (Ctrl-D at READY does the same).
  END APL   enter a small APL environment, prompted by six blanks, where the
            workspace variables can be looked at:
              )VARS          the names of the variables
              INPPN          a variable, displayed as APL does (also NOCUR, NOSTR,
                             INTCU, INTST, INPTG, PATCHES, INTPN, IMAGE, DESIM,
                             TEMP1, DEST1, TEMP2, DEST2, STATUS)
              ⍴INPPN         its shape (RHO INPPN also works)
              START          back to IGDS (READY)
              )OFF           leave igds

Example:
  END APL
        NOCUR
  4
        )OFF)",
    .run = run_end,
};

}  // namespace igds
