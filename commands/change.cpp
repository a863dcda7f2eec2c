// CHANGE GRID | TANGENTS | POINTS (manual 4.2): a new version of the current surface.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/entries.h"
#include "commands/reports.h"
#include "commands/surface.h"
#include "workspace/apl.h"

namespace igds {

namespace {

enum Option { grid, tangents, points };

constexpr Choice options[] = {
    {"GRID", grid, {}, "new numbers of interpolated curves and stringers"},
    {"TANGENTS", tangents, {}, "new border tangents, then CHANGE GRID TOO?"},
    {"POINTS", points, {}, "new input points, then CHANGE TANGENTS TOO? and CHANGE GRID TOO?"},
};

const Prompt change_grid_prompt{
    "CHANGE GRID TOO? (Y OR N)",
    "Y to give new numbers of interpolated curves and stringers, N to keep\n"
    "them; or type the two numbers (INTCU INTST) at once.",
    yes_no()};
const Prompt change_tangents_prompt{
    "CHANGE TANGENTS TOO? (Y OR N)",
    "Y to change border tangents, N to keep them; or type a tangent entry\n"
    "(k tx ty tz, and 1 or 0 at a corner) at once.",
    yes_no()};

constexpr std::string_view answer_first = "ANSWER Y OR N FIRST (CTRL-C GIVES UP CHANGE)";

// A reply to a Y/N question that is neither: a command typed too early says so.
void refuse_command_word(const std::vector<std::string>& words) {
  if (!parse_apl_number(words[0])) {
    std::string reason = command_word_reason(words[0], answer_first);
    if (!reason.empty()) throw EntryError(reason);
  }
}

// The follow-up of CHANGE TANGENTS and POINTS: Y/N, or the two numbers directly.
Density ask_grid_too(Context& ctx, const Workspace& ws) {
  for (;;) {
    auto words = ctx.ask(change_grid_prompt);
    if (words.empty()) continue;
    if (auto yes = parse_yes_no(words)) {
      if (*yes) return ask_density(ctx, ws.nocur, ws.nostr);
      return {ws.intcu, ws.intst};
    }
    try {
      refuse_command_word(words);
      return parse_density(words, ws.nocur, ws.nostr);
    } catch (const EntryError& e) {
      ctx.report(e.what());
    }
  }
}

// The follow-up of CHANGE POINTS: Y/N, or the first tangent entry directly.
void ask_tangents_too(Context& ctx, const Workspace& ws, Array& inptg, Edits& edits) {
  for (;;) {
    auto words = ctx.ask(change_tangents_prompt);
    if (words.empty()) continue;
    if (auto yes = parse_yes_no(words)) {
      if (*yes) ask_tangent_entries(ctx, ws.nocur, ws.nostr, inptg, &edits);
      return;
    }
    try {
      refuse_command_word(words);
      apply_tangent_entry(words, ws.nocur, ws.nostr, inptg, &edits);
    } catch (const EntryError& e) {
      ctx.report(e.what());
      continue;
    }
    ask_tangent_entries(ctx, ws.nocur, ws.nostr, inptg, &edits);
    return;
  }
}

void run_change(Context& ctx, const Choice* option) {
  Workspace& ws = ctx.workspace();
  if (!ws.has_input()) throw Report(reports::input_not_found);
  Array inppn = ws.inppn;
  Array inptg = ws.inptg;
  Edits point_edits = Edits::none(), tangent_edits = Edits::none();
  Density density;
  const auto what = static_cast<Option>(option->code);
  if (what == grid) {
    density = ask_density(ctx, ws.nocur, ws.nostr);
  } else {
    if (what == points) {
      ask_point_entries(ctx, inppn, &point_edits);
      ask_tangents_too(ctx, ws, inptg, tangent_edits);
    } else {
      ask_tangent_entries(ctx, ws.nocur, ws.nostr, inptg, &tangent_edits);
    }
    density = ask_grid_too(ctx, ws);
  }
  const Changes changes = ws.changes;
  // The new surface is computed into the arrays of the old one (no fresh pages on a large grid);
  // the kernels check everything first and leave them as they were when they refuse.
  SurfaceInput input{ws.nocur, ws.nostr, density.intcu, density.intst, &inppn, &inptg};
  Surface surface{std::move(ws.patches), std::move(ws.intpn)};
  auto give_back = [&] {
    ws.patches = std::move(surface.patches);
    ws.intpn = std::move(surface.intpn);
  };
  try {
    if (what == grid && !surface.patches.empty())
      refit_into(input, surface.patches, surface.intpn);  // the patches do not depend on the grid
    else
      interpolate_into(input, surface);
  } catch (const DataError& e) {
    give_back();
    throw worded(e, "THE SURFACE IS NOT CHANGED");
  } catch (...) {
    give_back();
    throw;
  }
  make_current(ws, ws.nocur, ws.nostr, density, std::move(inppn), std::move(inptg),
               std::move(surface));
  // The grid of input points is the same: only the parts the entries changed are new.
  ws.changes = changes;
  ws.changes.edited(point_edits, tangent_edits);
}

constexpr const Prompt* questions[] = {&density_prompt, &points_prompt, &change_tangents_prompt,
                                       &tangents_prompt, &change_grid_prompt};

}  // namespace

extern const Command change_command{
    .name = "CHANGE",
    .options = options,
    .follows = {},
    .option_prompt = {"GRID, TANGENTS OR POINTS?",
                      "GRID: new numbers of interpolated curves and stringers; TANGENTS: new\n"
                      "border tangents; POINTS: new input points.",
                      options},
    .summary = "changes the current surface and interpolates it again",
    .long_help = R"(CHANGE modifies the current surface (there must be one: BUILD or
RESTORE it first, else INPUT NOT FOUND). The entries are typed as in
BUILD; what is not changed keeps its value, and the surface is
interpolated again at the end.

  CHANGE GRID      asks INTCU INTST, the numbers of curves and
                   stringers to insert between two input ones.
  CHANGE TANGENTS  takes tangent entries "k tx ty tz" ("k tx ty tz f"
                   at a corner, f = 1 along the curve, 0 along the
                   stringer) up to an empty line, then asks
                   CHANGE GRID TOO? (Y OR N): answer Y or N, or type
                   the two numbers.
  CHANGE POINTS    takes point entries "k x y z [x y z ...]" up to an
                   empty line, then asks CHANGE TANGENTS TOO? (Y OR N)
                   (Y, N or a tangent entry) and CHANGE GRID TOO?

Tangents are per unit of chord length: 1 along the chord is the
natural pace, lengths much above 3 make loops.

Abbreviations work as everywhere: C G is CHANGE GRID. Ctrl-C gives up
and keeps the surface as it was.

Example: move point 5 up and use a finer grid.
  CHANGE POINTS
  POINTS? 5 10 10 4
  POINTS?
  CHANGE TANGENTS TOO? (Y OR N) N
  CHANGE GRID TOO? (Y OR N) 8 8)",
    .questions = questions,
    .run = run_change,
};

}  // namespace igds
