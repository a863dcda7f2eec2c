// DISPLAY FIRST | SECOND | FILE | INPUT | SURFACE (manual 4.4): a new current image, drawn;
// and PICTURE, a DUCT 4.4 picture file projected like a surface (docs/exchange.md); COMBS, the
// surface with the curvature combs of its curves and stringers (docs/kernels.md, "Curvature").
#include "commands/answers.h"
#include "commands/command.h"
#include "commands/reports.h"
#include "commands/view.h"

#include <vector>

#include <fmt/format.h>

#include "workspace/exchange/duct.h"

namespace igds {

namespace {

enum Option { first, second, file, input, surface, picture, hidden, combs };

constexpr Choice options[] = {
    {"FIRST", first, {}, "the copy kept by STORE FIRST"},
    {"SECOND", second, {}, "the copy kept by STORE SECOND"},
    {"FILE", file, "[name]", "the image kept by STORE FILE in NAME.IGDSIMAG"},
    {"INPUT", input, "[projection [parameters]]", "the input points, border and tangents"},
    {"SURFACE", surface, "[HIDDEN] [projection [parameters]]", "the whole interpolated grid"},
    {"PICTURE", picture, "[name [projection [parameters]]]",
     "the DUCT picture NAME.DUCTPIC, projected like a surface"},
    {"HIDDEN", hidden, "[projection [parameters]]",
     "the interpolated grid without the lines the surface hides"},
    {"COMBS", combs, "[projection [parameters]]",
     "the interpolated grid with the curvature combs of its curves and stringers"},
};

const Prompt file_prompt{"FILE NAME?",
                         "The name of an image kept with STORE FILE: 1 to 8 letters, digits "
                         "or $ # @ + - _ (type IGDSIMAG)."};

const Prompt picture_prompt{"FILE NAME?",
                            "The name of a DUCT picture file: 1 to 8 letters, digits or "
                            "$ # @ + - _ (type DUCTPIC)."};

// NAME.DUCTPIC read and drawn in space before the projection is asked: a damaged or foreign
// picture is refused at once, with its line, and nothing changes.
Image ask_picture(Context& ctx) {
  // The name, then whatever followed it on the line answers the projection's questions.
  const std::string name = ask_for(ctx, picture_prompt, [&](const std::vector<std::string>& w) {
    const auto n = cms_name(w[0]);
    if (!n) throw ParameterError(name_rule);
    ctx.unread(std::vector<std::string>(w.begin() + 1, w.end()));
    return *n;
  });
  constexpr std::string_view kept = "CURRENT IMAGE KEPT";
  std::string text = read_user_file(ctx.disk(), name, "DUCTPIC", duct_max_file_bytes, kept);
  Drawing3 drawing;
  try {
    drawing = duct_drawing(read_duct(text));
  } catch (const DuctError& e) {
    throw Report(fmt::format("FILE DAMAGED: {}.DUCTPIC ({}); {}", name, e.reason(), kept));
  }
  return ask_image(ctx, [&](const Workspace&, const View& view) {
    return picture_image(name, text, drawing, view);
  });
}

// DISPLAY SURFACE HIDDEN [projection [parameters]]: HIDDEN on the line after SURFACE asks for
// DISPLAY HIDDEN's image (docs/decisions.md). No projection starts with H; H alone is HIDDEN only
// with more words after it, as at DISPLAY's question, where H alone is HELP.
constexpr Choice surface_words[] = {{"HIDDEN", hidden}};
bool hidden_follows(Context& ctx) {
  if (!ctx.has_pending()) return false;
  const std::vector<std::string> words = ctx.ask(projection_prompt);
  const bool hidden = !words.empty() && choose(surface_words, words[0]) &&
                      (words[0].size() > 1 || words.size() > 1);
  ctx.unread(std::vector<std::string>(words.begin() + (hidden ? 1 : 0), words.end()));
  return hidden;
}

void show(Context& ctx, ImageRef image) {
  Workspace& ws = ctx.workspace();
  ws.image = std::move(image);
  ctx.show(ws.image);
}

void run_display(Context& ctx, const Choice* option) {
  const Workspace& ws = ctx.workspace();
  switch (static_cast<Option>(option->code)) {
    case first:
    case second: {
      expect_no_more_words(ctx, reports::incorrect_parameter);  // the manual's 4.4
      const auto& copy = option->code == first ? ws.temp1 : ws.temp2;
      if (!copy) throw Report(reports::image_not_found);
      show(ctx, copy);
      return;
    }
    case file:
      show(ctx,
           std::make_shared<const Image>(load_image(ctx.disk(), ask_file_name(ctx, file_prompt))));
      return;
    case input:
      if (!ws.has_input()) throw Report(reports::input_not_found);
      show(ctx, std::make_shared<const Image>(ask_image(ctx, input_image)));
      return;
    case surface:
      if (!ws.has_surface()) throw Report(reports::surface_not_found);
      show(ctx, std::make_shared<const Image>(
                    ask_image(ctx, hidden_follows(ctx) ? hidden_surface_image : surface_image)));
      return;
    case picture:
      show(ctx, std::make_shared<const Image>(ask_picture(ctx)));
      return;
    case hidden:
      if (!ws.has_surface()) throw Report(reports::surface_not_found);
      show(ctx, std::make_shared<const Image>(ask_image(ctx, hidden_surface_image)));
      return;
    case combs:
      if (!ws.has_surface()) throw Report(reports::surface_not_found);
      show(ctx, std::make_shared<const Image>(ask_image(ctx, comb_image)));
      return;
  }
}

// FILE NAME?, then the projection's questions.
const std::vector<const Prompt*> questions = [] {
  std::vector<const Prompt*> all{&file_prompt, &picture_prompt};
  for (const Prompt* q : view_questions()) all.push_back(q);
  return all;
}();

}  // namespace

std::string_view image_kind_word(int what) {
  return what == 0   ? options[input].word
         : what == 1 ? options[surface].word
         : what == 2 ? options[picture].word
         : what == 3 ? options[combs].word
                     : "IMAGE";
}

std::string_view hidden_word() {
  return options[hidden].word;
}

extern const Command display_command{
    .name = "DISPLAY",
    .options = options,
    .follows = {},
    .option_prompt =
        {"FIRST, SECOND, FILE, INPUT, SURFACE, PICTURE, HIDDEN OR COMBS?",
         "INPUT, SURFACE, HIDDEN (hidden lines removed), COMBS (curvature): project the "
         "surface; FIRST, SECOND, FILE: kept images; PICTURE: a DUCT file.",
         options},
    .bad_option = reports::incorrect_parameter,  // the manual's 4.4
    .summary =
        "projects and draws the input, the surface, its combs or a DUCT picture, or a "
        "kept image",
    .long_help =
        "DISPLAY makes a new current image and draws it on the left of the screen with a short "
        "description beside it. The screen is not erased first (ERASE does that): images are "
        "drawn one over the other.\n"
        "\n"
        "  DISPLAY INPUT [projection [parameters]]   the input points, the border joined by "
        "segments, the non-zero border tangents as arrows (INPUT NOT FOUND if there is no "
        "surface).\n"
        "  DISPLAY SURFACE [HIDDEN] [projection [parameters]] the whole interpolated grid, joined "
        "along the curves and the stringers (SURFACE NOT FOUND if there is none); HIDDEN after "
        "SURFACE draws it as DISPLAY HIDDEN does.\n"
        "  DISPLAY FIRST | SECOND   the copy kept by STORE FIRST or SECOND (IMAGE NOT FOUND if "
        "there is none).\n"
        "  DISPLAY FILE [name]      the image kept by STORE FILE in NAME.IGDSIMAG (FILE NOT "
        "FOUND).\n"
        "  DISPLAY PICTURE [name [projection [parameters]]]  the DUCT 4.4 picture file "
        "NAME.DUCTPIC (EXPORT DUCT writes them; so did DUCT), projected like a surface: lines, "
        "conic arcs, Bezier spans, marks and texts, dashes and colours as the device draws them. "
        "A damaged picture gets FILE DAMAGED with the line and what is wrong; the current image "
        "is kept.\n"
        "  DISPLAY HIDDEN [projection [parameters]]  the surface as DISPLAY SURFACE draws it, "
        "without the parts of its curves and stringers that the surface itself hides, found to "
        "the device's resolution; PLOT, EXPORT, STORE, ZOOM, UNDO and REDO keep them hidden.\n"
        "  DISPLAY COMBS [projection [parameters]]  the surface's grid with the curvature combs of "
        "its curves and stringers, the fairness check of a hull: at every interpolated point a "
        "line normal to the curve (or stringer), away from the centre of curvature, as long as "
        "the curvature times the scale, and the line joining the ends. The curvature is the exact "
        "one of the patches. The scale, written in the description (SCALE 50: a curvature of 0.1 "
        "gives a comb 5 long, in the units of the points), is 1, 2 or 5 times a power of ten, "
        "chosen so that the largest comb is at most a fifth of the surface's larger side. A fair "
        "line has a smooth comb; a bump in the comb is a bump in the line, a comb changing side "
        "an inflection. PLOT and EXPORT draw the combs with the image (SURFACE NOT FOUND if "
        "there is no surface).\n"
        "\n"
        "Projections and their parameters (what is not on the line is asked):\n"
        "  CONIC x y z         perspective from the view point x y z towards the centre of the "
        "input points; the eye must be outside the surface.\n"
        "  ISOMETRIC axis angle  the axis dropped (1 x, 2 y, 3 z) is drawn at the angle, 0 to 90 "
        "degrees, to the first of the other two.\n"
        "  ASSONOMETRIC a b c  a true axonometric view: the angles between the projected x-y, y-z "
        "and z-x axes, each 90 to 180, sum 360; 110 130 120 is a good view. AXONOMETRIC is the "
        "same.\n"
        "  ORTHOGONAL plane    XY, YZ or XZ.\n"
        "A wrong projection or parameter gets INCORRECT PARAMETER and the reason; typed at a "
        "question, the question is asked again.\n"
        "\n"
        "Examples:\n"
        "  DISPLAY SURFACE ASSONOMETRIC 110 130 120\n"
        "  D I C 100 -50 80        (DISPLAY INPUT CONIC, view point 100 -50 80)\n"
        "  D SU O XY\n"
        "  D H ASSONOMETRIC 110 130 120   (the same surface, hidden lines removed)\n"
        "  DISPLAY PICTURE HULL ORTHOGONAL XY\n"
        "  DISPLAY COMBS ORTHOGONAL YZ",
    .questions = questions,
    .run = run_display,
};

}  // namespace igds
