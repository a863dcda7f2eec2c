// BUILD (manual 4.1): a new current surface from the keyboard.
#include "commands/answers.h"
#include "commands/command.h"
#include "commands/entries.h"
#include "commands/surface.h"

namespace igds {

namespace {

void run_build(Context& ctx, const Choice*) {
  expect_no_more_words(ctx);
  const GridSize size = ask_grid_size(ctx);
  Array inppn({static_cast<std::size_t>(size.nocur) * static_cast<std::size_t>(size.nostr), 3});
  ask_point_entries(ctx, inppn);
  Array inptg = zero_tangents(size.nocur, size.nostr);
  const bool automatic = ask_tangent_entries(ctx, size.nocur, size.nostr, inppn, inptg);
  Density density = ask_density(ctx, size.nocur, size.nostr);
  Surface surface = interpolate_surface(
      ctx.workspace(), {size.nocur, size.nostr, density.intcu, density.intst, &inppn, &inptg});

  // Only now, with everything asked and interpolated, does the workspace change. A new surface
  // has the manual's zero twists (CHANGE TWISTS MARKS gives Marks's).
  make_current(ctx.workspace(), size.nocur, size.nostr, density, std::move(inppn), std::move(inptg),
               std::move(surface), {.marks_twists = false, .auto_tangents = automatic});
}

constexpr const Prompt* questions[] = {&size_prompt, &points_prompt, &tangents_prompt,
                                       &density_prompt};

}  // namespace

extern const Command build_command{
    .name = "BUILD",
    .options = {},
    .follows = {},
    .option_prompt = {},
    .summary = "a new surface: grid size, points, tangents, density",
    .long_help =
        "BUILD defines a new current surface, replacing the old one. Nothing may follow the word "
        "BUILD on its line. IGDS then asks four things:\n"
        "\n"
        " 1. NUMBER OF CURVES AND STRINGERS? NOCUR and NOSTR. Each curve crosses every stringer, "
        "so there are NOCUR x NOSTR input points, numbered along the first curve (1 to NOSTR), "
        "then along the second, and so on. 1 N (or N 1) is a single curve of N points.\n"
        " 2. POINTS? Entries \"k x y z\": the coordinates of point k. More triplets on the same "
        "entry go to k+1, k+2, ... Entries may come in any order and take several lines; an empty "
        "line ends them. Points never given are at 0 0 0.\n"
        " 3. TANGENTS? Entries \"k tx ty tz\" at the border points: along the curve at the two "
        "ends "
        "of a curve, along the stringer at the two ends of a stringer. A corner needs both: \"k tx "
        "ty tz 1\" along the curve, \"k tx ty tz 0\" along the stringer. An empty line ends them; "
        "tangents never given are zero. AUTO (alone on its line) sets every border tangent from "
        "the points by Marks's rule (Marks 1970: the F-mesh tangent of the neighbour, the end arc "
        "made a parabola); entries typed after AUTO replace single tangents. HELP and DISPLAY "
        "INPUT then say TANGENTS AUTO.\n"
        " 4. INTERPOLATED CURVES AND STRINGERS? INTCU and INTST, whole numbers >= 0: the curves "
        "to insert between two input curves, and the stringers between two stringers.\n"
        "\n"
        "Tangents are per unit of chord length: a tangent of length 1 along the chord is the "
        "natural pace; 0.5 flattens the end of the arc, 2 or 3 makes it bulge, and lengths much "
        "above 3 make loops. (The manual's advice to take \"the length of the ending segments\" "
        "belongs to another scaling; igds follows its equations.)\n"
        "\n"
        "Then the surface is interpolated with bicubic Coons patches. An entry that is not "
        "correct gets INCORRECT ENTRY with the reason and is ignored; type it again. HELP at any "
        "question explains it; Ctrl-C gives up and keeps the old surface.\n"
        "\n"
        "Example, a 3 x 3 saddle with 4 interpolated curves and stringers:\n"
        "  BUILD\n"
        "  NUMBER OF CURVES AND STRINGERS? 3 3\n"
        "  POINTS? 1  0 0 0   0 10 2   0 20 0\n"
        "  POINTS? 4  10 0 2  10 10 0  10 20 2\n"
        "  POINTS? 7  20 0 0  20 10 2  20 20 0\n"
        "  POINTS?\n"
        "  TANGENTS? 1 0 1 0 1\n"
        "  TANGENTS? 1 1 0 0 0\n"
        "  TANGENTS?\n"
        "  INTERPOLATED CURVES AND STRINGERS? 4 4",
    .questions = questions,
    .run = run_build,
};

}  // namespace igds
