// HELP [SHORT | LONG] (manual 4.10 and 6): explanations at READY. At any other prompt the
// interpreter answers HELP itself, with the prompt's short help or the command's long help.
#include <string>

#include "commands/command.h"
#include "commands/entries.h"

namespace igds {

namespace {

enum Option { short_help, long_help };

constexpr std::string_view overview = R"(IGDS - Interactive Design of Interpolated Surfaces

A surface is defined by a rectangular grid of input points: NOCUR curves crossing
NOSTR stringers, with the tangents at the border of the grid. IGDS interpolates it
with bicubic Coons patches, inserting INTCU curves and INTST stringers between the
input ones, and shows projections of it. Commands, typed after READY:

  BUILD                  a new surface: grid size, points, tangents, density
  CHANGE GRID|TANGENTS|POINTS      modify the current surface
  RESTORE [name]         the surface saved in NAME IGDSDATA
  DISPLAY INPUT|SURFACE [projection [parameters]]   project and draw
  DISPLAY FIRST|SECOND|FILE [name] draw a kept image again
  PLOT SELECTRIC|EBCDIC  draw the current image on the HP plotter
  STORE FIRST|SECOND|FILE [name]   keep a copy of the current image
  SAVE [name]            the surface into NAME IGDSDATA
  WRITE [name]           the surface as card images into NAME IGDSCHAR
  END CMS|APL            leave (everything is kept for the next session)
  HELP [SHORT|LONG]      explanations; at any question, HELP explains it
  ERASE                  a clean screen
  EXPORT SVG|TEK|HPGL [name]       the current image into a file

Any word may be cut short: the first entry of the list that starts with the
letters typed wins (S is STORE, SA is SAVE, D SU is DISPLAY SURFACE). What is not
on the line is asked for. Numbers may be written the APL way (¯3.5 is -3.5).
Lines starting with * or ⍝ are comments. Ctrl-C gives up the command in progress.
HELP SHORT makes HELP answer in a line or two, HELP LONG in full (the setting is
kept from one session to the next).

A small session:
  BUILD
  NUMBER OF CURVES AND STRINGERS? 2 2
  POINTS? 1 0 0 0  0 10 0  10 0 0  10 10 5
  POINTS?
  TANGENTS?
  INTERPOLATED CURVES AND STRINGERS? 5 5
  READY
  DISPLAY SURFACE ASSONOMETRIC 110 130 120
  READY
  SAVE TWIST)";

void run_help(Context& ctx, int option) {
  expect_no_more_words(ctx);
  Workspace& ws = ctx.workspace();
  if (option >= 0) ws.status[0] = option == long_help ? 1 : 0;
  if (ws.status[0] == 1) {
    std::string_view text = overview;
    while (!text.empty()) {
      auto end = text.find('\n');
      ctx.say(text.substr(0, end));
      text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    }
    return;
  }
  std::string names;
  for (const Command* command : command_table()) {
    names += names.empty() ? "" : " ";
    names += command->name;
  }
  ctx.say("Type a command: " + names + ".");
  ctx.say("A first letter is enough (S is STORE); HELP LONG explains them all.");
}

}  // namespace

extern const Command help_command{
    .name = "HELP",
    .options = {"SHORT", "LONG"},
    // No question: HELP alone answers in the length in force (STATUS[1]).
    .option_prompt = {},
    .short_help = "HELP SHORT or LONG: explanations; at any question HELP explains it.",
    .long_help = overview,
    .run = run_help,
};

}  // namespace igds
