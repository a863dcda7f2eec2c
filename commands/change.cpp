// CHANGE GRID | TANGENTS | POINTS (manual 4.2) | TWISTS (Marks 1970): a new version of the
// current surface.
#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/entries.h"
#include "commands/pick.h"
#include "commands/reports.h"
#include "commands/surface.h"
#include "workspace/numbers/typed.h"

namespace igds {

namespace {

enum Option { grid, tangents, points, twists };

// TWISTS comes after POINTS, so that no abbreviation of the manual changes meaning (C T is
// CHANGE TANGENTS, C TW CHANGE TWISTS).
constexpr Choice options[] = {
    {"GRID", grid, {}, "new numbers of interpolated curves and stringers"},
    {"TANGENTS", tangents, {}, "new border tangents, then CHANGE GRID TOO?"},
    {"POINTS", points, {}, "new input points, then CHANGE TANGENTS TOO? and CHANGE GRID TOO?"},
    {"TWISTS", twists, "[ZERO|MARKS]", "the twists of the patches: ZERO or MARKS"},
};

enum TwistChoice { zero_twists, marks_twists };
constexpr Choice twist_choices[] = {
    {"ZERO", zero_twists, {}, "zero twists, as IGDS 1975"},
    {"MARKS", marks_twists, {}, "Marks 1970: Birkhoff and de Boor's twists from the points"},
};
const Prompt twists_prompt{"TWISTS? (ZERO OR MARKS)",
                           "ZERO: the twists of the manual (flat patch corners); MARKS: the twists "
                           "of Marks 1970, estimated from the neighbouring points.",
                           twist_choices};

bool ask_twists(Context& ctx) {
  return ask_for(ctx, twists_prompt, [](const std::vector<std::string>& words) {
    const Choice* c = words.size() == 1 ? choose(twist_choices, words[0]) : nullptr;
    if (!c) throw EntryError("ANSWER ZERO OR MARKS");
    return c->code == marks_twists;
  });
}

const Prompt change_grid_prompt{
    "CHANGE GRID TOO? (Y OR N)",
    "Y to give new numbers of interpolated curves and stringers, N to keep "
    "them; or type the two numbers (INTCU INTST) at once.",
    yes_no()};
const Prompt change_tangents_prompt{
    "CHANGE TANGENTS TOO? (Y OR N)",
    "Y to change border tangents, N to keep them; or type a tangent entry "
    "(k tx ty tz, and 1 or 0 at a corner) at once.",
    yes_no()};

constexpr std::string_view answer_first = "ANSWER Y OR N FIRST (CTRL-C GIVES UP CHANGE)";

// A reply to a Y/N question that is neither: a command typed too early says so.
void refuse_command_word(std::span<const std::string_view> words) {
  if (!parse_typed_number(words[0])) {
    std::string reason = command_word_reason(words[0], answer_first);
    if (!reason.empty()) throw EntryError(reason);
  }
}

// PICK at CHANGE POINTS' POINTS?: the point picked on the image shown, rather than its number.
const Prompt change_points_prompt{"POINTS?",
                                  "A point number k and x y z (more go to k+1, ...); PICK: point "
                                  "at one on the image shown; an empty line ends the points.",
                                  pick_choices()};
const Prompt new_place_prompt{"NEW X Y Z?",
                              "The point's new x y z; in an ORTHOGONAL view PICK: point at where "
                              "it goes (the third coordinate kept); an empty line leaves it.",
                              pick_choices()};

// PICK at POINTS?: the point nearest the cross-hair, named, then its new place typed or (in an
// orthogonal view) picked. Throws EntryError when there is nothing to pick on.
void change_picked_point(Context& ctx, const Workspace& ws, Array& inppn, Edits& edits) {
  if (!ws.image) throw EntryError("THERE IS NO IMAGE TO PICK ON (DISPLAY INPUT OR SURFACE FIRST)");
  const ImageRef shown = ws.image;
  if (!shows_input_points(ws, *shown))
    throw EntryError("THE CURRENT IMAGE SHOWS NO INPUT POINTS OF THE SURFACE");
  const int k = nearest_input_point(ws, *shown, pick_image_point(ctx, pick_point_prompt, *shown));
  ctx.say(point_words(inppn, k));
  const std::size_t first = 3 * std::size_t(k - 1);
  for (;;) {
    const auto words = ctx.ask_words(new_place_prompt);
    if (words.empty()) return;  // the point stays where it is
    try {
      if (!is_pick(words)) {
        if (words.size() != 3) throw EntryError("GIVE X Y Z, OR PICK IN AN ORTHOGONAL VIEW");
        const std::string number = std::to_string(k);
        const std::string_view entry[] = {number, words[0], words[1], words[2]};
        apply_point_entry(entry, inppn, &edits);
      } else {
        const std::array<double, 3> now{inppn.ravel[first], inppn.ravel[first + 1],
                                        inppn.ravel[first + 2]};
        if (!placed_in_view(shown->desim, now, {}))
          throw EntryError("A PLACE IS PICKED IN AN ORTHOGONAL VIEW ONLY: TYPE X Y Z");
        const auto placed = placed_in_view(shown->desim, now,
                                           pick_image_point(ctx, pick_place_prompt, *shown, true));
        std::copy(placed->begin(), placed->end(),
                  inppn.ravel.begin() + static_cast<std::ptrdiff_t>(first));
        edits.part(first, first + 3);
      }
    } catch (const EntryError& e) {
      ctx.report(e.what());
      continue;
    }
    ctx.say(point_words(inppn, k));
    return;
  }
}

// The point entries of CHANGE POINTS: those of BUILD, and PICK.
void ask_changed_points(Context& ctx, const Workspace& ws, Array& inppn, Edits& edits) {
  for (;;) {
    const auto words = ctx.ask_words(change_points_prompt);
    if (words.empty()) return;
    try {
      if (is_pick(words))
        change_picked_point(ctx, ws, inppn, edits);
      else
        apply_point_entry(words, inppn, &edits);
    } catch (const EntryError& e) {
      ctx.report(e.what());
    }
  }
}

// The follow-up of CHANGE TANGENTS and POINTS: Y/N, or the two numbers directly.
Density ask_grid_too(Context& ctx, const Workspace& ws) {
  for (;;) {
    const auto words = ctx.ask_words(change_grid_prompt);
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

// The follow-up of CHANGE POINTS: Y/N, or the first tangent entry (or AUTO) directly. True when
// AUTO was typed (from the new points `inppn`).
bool ask_tangents_too(Context& ctx, const Workspace& ws, const Array& inppn, Array& inptg,
                      Edits& edits) {
  for (;;) {
    const auto words = ctx.ask_words(change_tangents_prompt);
    if (words.empty()) continue;
    if (auto yes = parse_yes_no(words)) {
      return *yes && ask_tangent_entries(ctx, ws.nocur, ws.nostr, inppn, inptg, &edits);
    }
    bool automatic = false;
    if (is_auto_entry(words)) {
      apply_auto_tangents(ws.nocur, ws.nostr, inppn, inptg, &edits);
      automatic = true;
    } else {
      try {
        refuse_command_word(words);
        apply_tangent_entry(words, ws.nocur, ws.nostr, inptg, &edits);
      } catch (const EntryError& e) {
        ctx.report(e.what());
        continue;
      }
    }
    return ask_tangent_entries(ctx, ws.nocur, ws.nostr, inppn, inptg, &edits) || automatic;
  }
}

void run_change(Context& ctx, const Choice* option) {
  Workspace& ws = ctx.workspace();
  if (!ws.has_input()) throw Report(reports::input_not_found);
  Array inppn = ws.inppn;
  Array inptg = ws.inptg;
  Edits point_edits = Edits::none(), tangent_edits = Edits::none();
  Density density{ws.intcu, ws.intst};
  SurfaceModes modes{ws.marks_twists(), ws.auto_tangents()};
  const auto what = static_cast<Option>(option->code);
  if (what == grid) {
    density = ask_density(ctx, ws.nocur, ws.nostr);
  } else if (what == twists) {
    modes.marks_twists = ask_twists(ctx);
  } else {
    if (what == points) {
      ask_changed_points(ctx, ws, inppn, point_edits);
      // Tangents set by AUTO were the old points': only AUTO again keeps the surface's flag.
      modes.auto_tangents = ask_tangents_too(ctx, ws, inppn, inptg, tangent_edits);
    } else {
      // Entries after an AUTO override single tangents; the surface keeps the flag.
      modes.auto_tangents =
          ask_tangent_entries(ctx, ws.nocur, ws.nostr, inppn, inptg, &tangent_edits) ||
          modes.auto_tangents;
    }
    density = ask_grid_too(ctx, ws);
  }
  SurfaceInput input{ws.nocur, ws.nostr, density.intcu,     density.intst,
                     &inppn,   &inptg,   modes.marks_twists};
  // PATCHES of the workspace's own (FIT's, END APL's) are kept, and INTPN made from them: they
  // are still not the interpolation's.
  const bool refitted = what == grid && !ws.patches.empty();
  const bool derived = !refitted || ws.changes.derived;
  Surface surface = interpolate_surface(ws, input, refitted);
  // The grid of input points is the same: only the parts the entries changed are new.
  const EditedInputs edited{point_edits, tangent_edits};
  make_current(ws, ws.nocur, ws.nostr, density, std::move(inppn), std::move(inptg),
               std::move(surface), modes, derived, &edited);
}

constexpr const Prompt* questions[] = {
    &density_prompt,   &change_points_prompt, &pick_point_prompt,
    &new_place_prompt, &pick_place_prompt,    &change_tangents_prompt,
    &tangents_prompt,  &change_grid_prompt,   &twists_prompt};

}  // namespace

extern const Command change_command{
    .name = "CHANGE",
    .options = options,
    .follows = {},
    .option_prompt = {"GRID, TANGENTS, POINTS OR TWISTS?",
                      "GRID: new numbers of interpolated curves and stringers; TANGENTS: new "
                      "border tangents; POINTS: new input points; TWISTS: ZERO or MARKS.",
                      options},
    .summary = "changes the current surface and interpolates it again",
    .long_help =
        "CHANGE modifies the current surface (there must be one: BUILD or RESTORE it first, else "
        "INPUT NOT FOUND). The entries are typed as in BUILD; what is not changed keeps its "
        "value, and the surface is interpolated again at the end.\n"
        "\n"
        "  CHANGE GRID      asks INTCU INTST, the numbers of curves and stringers to insert "
        "between two input ones.\n"
        "  CHANGE TANGENTS  takes tangent entries \"k tx ty tz\" (\"k tx ty tz f\" at a corner, f "
        "= 1 "
        "along the curve, 0 along the stringer) up to an empty line, then asks CHANGE GRID TOO? "
        "(Y OR N): answer Y or N, or type the two numbers.\n"
        "  CHANGE POINTS    takes point entries \"k x y z [x y z ...]\" up to an empty line, then "
        "asks CHANGE TANGENTS TOO? (Y OR N) (Y, N, AUTO or a tangent entry) and CHANGE GRID TOO? "
        "PICK at POINTS? takes the point by pointing at it on the image shown (DISPLAY INPUT, "
        "SURFACE or COMBS of the surface) with the cross-hair (POINT?): igds names it, POINT 7 AT "
        "10 5 2, and asks NEW X Y Z?: type the coordinates, or in an ORTHOGONAL view PICK and "
        "point at where it goes (NEW PLACE?; the coordinate the view does not show is kept). From "
        "a command file a pick is a line X Y, its address on the page EXPORT TEK draws (0..1023, "
        "0..779).\n"
        "  CHANGE TWISTS    asks TWISTS? (ZERO OR MARKS), or takes the word on the line (C TW M): "
        "ZERO, the default, gives every patch corner the zero twist of IGDS 1975; MARKS the twist "
        "of Marks 1970 (Birkhoff and de Boor, from the four diagonal neighbours; zero at the "
        "border). The choice belongs to the surface: SAVE, the session, STATUS[3] and WRITE keep "
        "it, and PATCHES, the grid and every export follow it.\n"
        "\n"
        "Tangents are per unit of chord length: 1 along the chord is the natural pace, lengths "
        "much above 3 make loops. AUTO at TANGENTS? sets every border tangent from the points by "
        "Marks's rule; the entries typed after it replace single tangents. CHANGE POINTS keeps "
        "the surface's AUTO mark only when AUTO is typed again for the new points.\n"
        "\n"
        "Abbreviations work as everywhere: C G is CHANGE GRID. Ctrl-C gives up and keeps the "
        "surface as it was.\n"
        "\n"
        "Example: move point 5 up and use a finer grid.\n"
        "  CHANGE POINTS\n"
        "  POINTS? 5 10 10 4\n"
        "  POINTS?\n"
        "  CHANGE TANGENTS TOO? (Y OR N) N\n"
        "  CHANGE GRID TOO? (Y OR N) 8 8\n"
        "Or by pointing, on DISPLAY INPUT ORTHOGONAL XZ:\n"
        "  POINTS? PICK\n"
        "  POINT?                 (the cross-hair: click on the point)\n"
        "  POINT 5 AT 10 10 0\n"
        "  NEW X Y Z? PICK\n"
        "  NEW PLACE?             (click where it goes: x and z change, y stays)\n"
        "  POINT 5 AT 10.2 10 3.9",
    .questions = questions,
    .run = run_change,
};

}  // namespace igds
