// DISPLAY FIRST | SECOND | FILE | INPUT | SURFACE (manual 4.4): a new current image, drawn.
#include "commands/command.h"
#include "commands/entries.h"
#include "commands/file_name.h"
#include "commands/view.h"
#include "workspace/error.h"

namespace igds {

namespace {

enum Option { first, second, file, input, surface };

const Prompt file_prompt{"FILE NAME?",
                         "The name of an image kept with STORE FILE: 1 to 8 letters, digits or "
                         "$ # @ + - _ (type IGDSIMAG)."};
const Prompt projection_prompt{"PROJECTION?",
                               "CONIC, ISOMETRIC, ASSONOMETRIC or ORTHOGONAL (abbreviations "
                               "allowed), parameters may follow."};
const Prompt conic_prompt{"VIEW POINT X Y Z?",
                          "The eye's position x y z, outside the surface; the picture looks at "
                          "the centre of the input points."};
const Prompt isometric_prompt{"AXIS AND ANGLE?",
                              "The axis to drop (1 x, 2 y, 3 z) and the angle of its projection, "
                              "0 to 90 degrees."};
const Prompt assonometric_prompt{"THREE ANGLES?",
                                 "The angles between the projected x-y, y-z and z-x axes, each "
                                 "between 90 and 180, sum 360 (try 110 130 120)."};
const Prompt orthogonal_prompt{"PLANE XY, YZ OR XZ?", "The plane to project on: XY, YZ or XZ."};

const Prompt& parameters_prompt(Projection projection) {
  switch (projection) {
    case Projection::conic:
      return conic_prompt;
    case Projection::isometric:
      return isometric_prompt;
    case Projection::assonometric:
      return assonometric_prompt;
    case Projection::orthogonal:
      break;
  }
  return orthogonal_prompt;
}

// A non-empty reply: an empty line asks again.
std::vector<std::string> ask_words(Context& ctx, const Prompt& prompt) {
  for (;;) {
    auto words = ctx.ask(prompt);
    if (!words.empty()) return words;
  }
}

View ask_view(Context& ctx) {
  auto words = ask_words(ctx, projection_prompt);
  auto projection = projection_named(words[0]);
  if (!projection) throw Report(reports::incorrect_parameter);
  words.erase(words.begin());
  ctx.unread(std::move(words));
  auto view = parse_view(*projection, ask_words(ctx, parameters_prompt(*projection)));
  if (!view) throw Report(reports::incorrect_parameter);
  return *view;
}

void show(Context& ctx, ImageRef image) {
  Workspace& ws = ctx.workspace();
  ws.image = std::move(image);
  ctx.show(ws.image);
}

void run_display(Context& ctx, int option) {
  const Workspace& ws = ctx.workspace();
  switch (option) {
    case first:
    case second: {
      expect_no_more_words(ctx);
      const auto& copy = option == first ? ws.temp1 : ws.temp2;
      if (!copy) throw Report(reports::image_not_found);
      show(ctx, copy);
      return;
    }
    case file: {
      show(ctx,
           std::make_shared<const Image>(load_image(ctx.disk(), ask_file_name(ctx, file_prompt))));
      return;
    }
    case input: {
      if (!ws.has_input()) throw Report(reports::input_not_found);
      show(ctx, std::make_shared<const Image>(input_image(ws, ask_view(ctx))));
      return;
    }
    default: {
      if (!ws.has_surface()) throw Report(reports::surface_not_found);
      show(ctx, std::make_shared<const Image>(surface_image(ws, ask_view(ctx))));
      return;
    }
  }
}

}  // namespace

extern const Command display_command{
    .name = "DISPLAY",
    .options = {"FIRST", "SECOND", "FILE", "INPUT", "SURFACE"},
    .option_prompt = {"FIRST, SECOND, FILE, INPUT OR SURFACE?",
                      "INPUT or SURFACE: project the current surface; FIRST, SECOND or FILE: "
                      "show an image kept by STORE."},
    .short_help =
        "DISPLAY INPUT or SURFACE with a projection, or FIRST, SECOND or FILE name: "
        "show an image.",
    .long_help = R"(DISPLAY makes a new current image and draws it on the left of the screen with
a short description. The screen is not erased first (ERASE does that).

  DISPLAY INPUT [projection [parameters]]    the input points, the border joined by
      segments, the non-zero border tangents as arrows (INPUT NOT FOUND if no surface).
  DISPLAY SURFACE [projection [parameters]]  the whole interpolated grid, joined along
      the curves and the stringers (SURFACE NOT FOUND if none).
  DISPLAY FIRST | SECOND   the copy kept by STORE FIRST or SECOND (IMAGE NOT FOUND).
  DISPLAY FILE [name]      the image kept by STORE FILE in NAME IGDSIMAG (FILE NOT FOUND).

Projections and their parameters (whatever is not on the line is asked for):
  CONIC x y z          perspective from the view point x y z towards the centre of
                       the input points; the eye must be outside the surface.
  ISOMETRIC axis angle the axis dropped (1 x, 2 y, 3 z) is drawn at the angle,
                       0 to 90 degrees, to the first of the other two.
  ASSONOMETRIC a b c   a true axonometric view: the angles between the projected
                       x-y, y-z and z-x axes, each 90 to 180, sum 360; 110 130 120
                       is a good view. AXONOMETRIC is the same.
  ORTHOGONAL plane     XY, YZ or XZ.
A wrong projection or parameter gets INCORRECT PARAMETER.

Examples:
  DISPLAY SURFACE ASSONOMETRIC 110 130 120
  D I C 100 -50 80        (DISPLAY INPUT CONIC, view point 100 -50 80)
  D SU O XY)",
    .run = run_display,
};

}  // namespace igds
