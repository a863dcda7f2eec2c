// BUILD (manual 4.1): a new current surface from the keyboard.
#include "commands/command.h"
#include "commands/entries.h"
#include "workspace/error.h"

namespace igds {

namespace {

const Prompt size_prompt{"NUMBER OF CURVES AND STRINGERS?",
                         "Two whole numbers >= 2: NOCUR, the input curves, and NOSTR, the input "
                         "stringers (points on each curve)."};

void run_build(Context& ctx, int) {
  expect_no_more_words(ctx);
  GridSize size;
  for (;;) {
    auto words = ctx.ask(size_prompt);
    if (words.empty()) continue;
    if (auto parsed = parse_grid_size(words)) {
      size = *parsed;
      break;
    }
    ctx.report(reports::incorrect_entry);
  }
  Array inppn({static_cast<std::size_t>(size.nocur) * static_cast<std::size_t>(size.nostr), 3});
  ask_point_entries(ctx, inppn);
  Array inptg = zero_tangents(size.nocur, size.nostr);
  ask_tangent_entries(ctx, size.nocur, size.nostr, inptg);
  Density density = ask_density(ctx, size.nocur, size.nostr);
  Surface surface = interpolate_surface(size.nocur, size.nostr, density, inppn, inptg);

  // Only now, with everything asked and interpolated, does the workspace change.
  make_current(ctx.workspace(), size.nocur, size.nostr, density, std::move(inppn), std::move(inptg),
               std::move(surface));
}

}  // namespace

extern const Command build_command{
    .name = "BUILD",
    .options = {},
    .option_prompt = {},
    .short_help = "BUILD: define a new current surface from points and border tangents typed in.",
    .long_help = R"(BUILD defines a new current surface, replacing the old one. Nothing else may
follow the word BUILD on its line. IGDS then asks four things:

 1. NUMBER OF CURVES AND STRINGERS? NOCUR and NOSTR, two whole numbers >= 2. Each
    curve crosses every stringer, so there are NOCUR x NOSTR input points, numbered
    along the first curve (1 to NOSTR), then along the second, and so on.
 2. POINTS? Entries "k x y z": the coordinates of point k. More triplets on the
    same entry go to k+1, k+2, ...  Entries may come in any order and take several
    lines; an empty line ends them. Points never given are at 0 0 0.
 3. TANGENTS? Entries "k tx ty tz" at the border points: along the curve at the
    two ends of a curve, along the stringer at the two ends of a stringer. A corner
    needs both: "k tx ty tz 1" along the curve, "k tx ty tz 0" along the stringer.
    Tangents are per unit of chord length (modulus 1 is the natural speed). An empty
    line ends them; tangents never given are zero.
 4. INTERPOLATED CURVES AND STRINGERS? INTCU and INTST, whole numbers >= 0: how many
    curves to insert between two input curves, and stringers between two stringers.

Then the surface is interpolated with bicubic Coons patches. An entry that is not
correct gets INCORRECT ENTRY and is ignored; type it again. HELP at any of these
questions explains it; Ctrl-C gives up and keeps the old surface.

Example, a 3 x 3 saddle with 4 interpolated curves and stringers:
  BUILD
  NUMBER OF CURVES AND STRINGERS? 3 3
  POINTS? 1  0 0 0   0 10 2   0 20 0
  POINTS? 4  10 0 2  10 10 0  10 20 2
  POINTS? 7  20 0 0  20 10 2  20 20 0
  POINTS?
  TANGENTS? 1 0 1 0 1
  TANGENTS? 1 1 0 0 0
  TANGENTS?
  INTERPOLATED CURVES AND STRINGERS? 4 4)",
    .run = run_build,
};

}  // namespace igds
