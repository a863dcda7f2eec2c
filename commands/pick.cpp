#include "commands/pick.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/picture.h"
#include "devices/layout.h"
#include "devices/render.h"
#include "workspace/error.h"
#include "workspace/kernels/fit.h"

namespace igds {

namespace {
constexpr Choice pick_word[] = {{"PICK", 0, {}, "point with the cross-hair on the image shown"}};
}  // namespace

std::span<const Choice> pick_choices() {
  return pick_word;
}

bool is_pick(std::span<const std::string_view> words) {
  return words.size() == 1 && choose(pick_word, words[0]) != nullptr;
}

const Prompt pick_point_prompt{"POINT?",
                               "Point at an input point of the image shown with the cross-hair "
                               "and click (or type its screen address X Y: X 0..1023, Y 0..779)."};
const Prompt pick_place_prompt{"NEW PLACE?",
                               "Point at where the point goes with the cross-hair and click (or "
                               "type its screen address X Y); the coordinate the view does not "
                               "show is kept."};

namespace {

// How the image is placed in the layout a pick is read in (devices/layout.h): the screen of tek
// mode has the dialogue below the picture; xterm's Tek window, none mode and the page have the
// picture alone.
Placement placement_of(const Image& shown, TermMode mode, PickLayout in) {
  const bool dialogue = in == PickLayout::screen && mode == TermMode::tek;
  const TekLayout layout = dialogue ? dialogue_layout() : full_layout();
  const Box& sq = layout.image;
  const double m = tek_screen::image_margin;
  const Box box{sq.x0 + m, sq.y0 + m, sq.x1 - m, sq.y1 - m};
  return fit(picture_of(shown).drawing, box, tek_screen::mark);
}

}  // namespace

Point2 pick_image_point(Context& ctx, const Prompt& prompt, const Image& shown, bool rounded) {
  for (;;) {
    if (const auto picked = ctx.pick(prompt)) {
      const Placement p = placement_of(shown, ctx.options().term, picked->layout);
      const DevicePoint at = picked->at;
      Point2 point{(at.x - p.dx) / p.scale, (at.y - p.dy) / p.scale};
      const double step = std::pow(10.0, std::floor(std::log10(1 / p.scale)));
      if (rounded && std::isfinite(step) && step > 0)
        point = {std::round(point.x / step) * step, std::round(point.y / step) * step};
      return point;
    }
    ctx.report(
        fmt::format("{}: A CROSS-HAIR PICK OR X Y (0..1023 0..779)", reports::incorrect_entry));
  }
}

namespace {

constexpr const char* no_input_points =
    "THE CURRENT IMAGE SHOWS NO INPUT POINTS OF THE SURFACE (DISPLAY INPUT OR SURFACE FIRST)";

// Where input point (i, j) is in IMAGE, rows and columns apart: every point of an input image;
// every (INTCU+1)th row and (INTST+1)th column of a surface's grid. {0, 0}: nowhere.
std::array<std::size_t, 2> input_steps(const Workspace& ws, const Image& shown) {
  const auto& s = shown.points.shape;
  const std::size_t nocur = std::size_t(ws.nocur), nostr = std::size_t(ws.nostr);
  if (nocur * nostr == 0 || ws.inppn.size() != 3 * nocur * nostr) return {0, 0};
  if (shown.desim.what == 0 && s == std::vector<std::size_t>{nocur, nostr, 2}) return {1, 1};
  if (shown.desim.what == 1 || shown.desim.what == 3) {
    const GridShape grid = intpn_shape(ws.nocur, ws.nostr, ws.intcu, ws.intst);
    if (s == std::vector<std::size_t>{grid.rows, grid.cols, 2})
      return {std::size_t(ws.intcu) + 1, std::size_t(ws.intst) + 1};
  }
  return {0, 0};
}

}  // namespace

bool shows_input_points(const Workspace& ws, const Image& shown) {
  return input_steps(ws, shown)[0] != 0;
}

int nearest_input_point(const Workspace& ws, const Image& shown, Point2 at) {
  const auto [row_step, column_step] = input_steps(ws, shown);
  if (row_step == 0) throw Report(no_input_points);
  const auto& s = shown.points.shape;
  const std::size_t nocur = std::size_t(ws.nocur), nostr = std::size_t(ws.nostr);
  int best = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < nocur; ++i)
    for (std::size_t j = 0; j < nostr; ++j) {
      const double* p = shown.points.data() + 2 * (i * row_step * s[1] + j * column_step);
      const double d = std::hypot(p[0] - at.x, p[1] - at.y);
      if (d < nearest) nearest = d, best = int(i * nostr + j + 1);
    }
  if (best == 0) throw Report(no_input_points);  // no point of it is finite
  return best;
}

std::string point_words(const Array& inppn, int k) {
  const double* p = inppn.data() + 3 * (k - 1);
  return fmt::format("POINT {} AT {} {} {}", k, plain_number(p[0]), plain_number(p[1]),
                     plain_number(p[2]));
}

std::optional<std::array<double, 3>> placed_in_view(const Description& desim,
                                                    std::array<double, 3> point, Point2 at) {
  if (desim.projection != Projection::orthogonal) return std::nullopt;
  // The planes as the manual numbers them (workspace/kernels/project.h): 1 XY, 2 XZ, 3 YZ.
  const double plane = desim.parameters[0];
  const std::array<int, 2> axes = plane == 1   ? std::array{0, 1}
                                  : plane == 2 ? std::array{0, 2}
                                  : plane == 3 ? std::array{1, 2}
                                               : std::array{-1, -1};
  if (axes[0] < 0) return std::nullopt;
  point[std::size_t(axes[0])] = at.x;
  point[std::size_t(axes[1])] = at.y;
  return point;
}

namespace {

void run_pick(Context& ctx, const Choice*) {
  expect_no_more_words(ctx);
  const Workspace& ws = ctx.workspace();
  if (!ws.has_input()) throw Report(reports::input_not_found);
  if (!ws.image) throw Report(reports::image_not_found);
  const ImageRef shown = ws.image;  // the image stays the one picked on
  if (!shows_input_points(ws, *shown)) throw Report(no_input_points);
  const Point2 at = pick_image_point(ctx, pick_point_prompt, *shown);
  ctx.say(point_words(ws.inppn, nearest_input_point(ws, *shown, at)));
}

constexpr const Prompt* questions[] = {&pick_point_prompt};

}  // namespace

extern const Command pick_command{
    .name = pick_word[0].word,
    .options = {},
    .follows = {},
    .option_prompt = {},
    .bad_option = reports::incorrect_command,
    .summary = "names the input point nearest the cross-hair on the image shown",
    .long_help =
        "PICK puts up the cross-hair (POINT?): point at an input point of the current image and "
        "click. igds names the input point nearest the place picked, with its coordinates: POINT "
        "7 AT 10 5 2. The image must show the current surface's input points: DISPLAY INPUT, "
        "SURFACE or COMBS of it, zoomed or not (otherwise THE CURRENT IMAGE SHOWS NO INPUT "
        "POINTS OF THE SURFACE; IMAGE NOT FOUND without an image). Without a cross-hair the "
        "answer to POINT? is an address X Y (X 0..1023, Y 0..779), as for ZOOM PICK, on the page "
        "EXPORT TEK draws: a command file names the same point under every terminal mode. Typed "
        "on the screen of tek mode, it is on that screen, where the picture sits above the "
        "dialogue.\n"
        "\n"
        "CHANGE POINTS takes a picked point too: PICK at POINTS? picks it and names it, then NEW "
        "X Y Z? asks where it goes: type its coordinates, or in an ORTHOGONAL view PICK again and "
        "point at its new place (the coordinate the view does not show is kept).\n"
        "\n"
        "Example:\n"
        "  DISPLAY INPUT ORTHOGONAL XY\n"
        "  PICK",
    .questions = questions,
    .run = run_pick,
};

}  // namespace igds
