// ZOOM [x0 y0 x1 y1 | factor [x y] | PICK]: a part of the current image shown larger; ZOOM
// alone shows the whole image again. Not in the 1975 manual: the storage tube could not.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/pick.h"
#include "commands/picture.h"
#include "devices/layout.h"
#include "devices/render.h"
#include "workspace/error.h"
#include "workspace/images.h"
#include "workspace/numbers/typed.h"

namespace igds {

namespace {

using Window = std::array<double, 4>;

const Prompt first_corner{"FIRST CORNER?",
                          "Point at one corner of the part to show with the cross-hair and click "
                          "(or type its screen address X Y: X 0..1023, Y 0..779)."};
const Prompt second_corner{"SECOND CORNER?",
                           "Point at the opposite corner with the cross-hair and click (or type "
                           "its screen address X Y: X 0..1023, Y 0..779)."};

// The box of the image's finite points (x0 > x1 when there are none).
Window extent_of(const Image& image) {
  const double inf = std::numeric_limits<double>::infinity();
  Window w{inf, inf, -inf, -inf};
  const Array& p = image.points;
  for (std::size_t i = 0; i + 1 < p.size(); i += 2) {
    const double x = p.data()[i], y = p.data()[i + 1];
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    w = {std::min(w[0], x), std::min(w[1], y), std::max(w[2], x), std::max(w[3], y)};
  }
  return w;
}

// The window with corners a and b, in either order; refused when it has no area.
Window corners(double ax, double ay, double bx, double by) {
  const Window w{std::min(ax, bx), std::min(ay, by), std::max(ax, bx), std::max(ay, by)};
  if (!(w[0] < w[2]) || !(w[1] < w[3]))
    throw ParameterError("THE TWO CORNERS MUST DIFFER IN X AND IN Y");
  return w;
}

std::vector<double> numbers_of(std::span<const std::string_view> words) {
  std::vector<double> v;
  for (const auto& w : words) {
    const auto n = parse_typed_number(w);
    if (!n || !std::isfinite(*n)) throw ParameterError(fmt::format("{} IS NOT A NUMBER", w));
    v.push_back(*n);
  }
  return v;
}

// ZOOM f [x y]: the whole image's extent divided by f, centred on x y (by default on the centre
// of what is shown now).
Window by_factor(const Image& image, const std::vector<double>& v) {
  const double f = v[0];
  if (!(f > 0)) throw ParameterError("THE FACTOR MUST BE GREATER THAN 0");
  const Window all = extent_of(image);
  if (!(all[0] <= all[2])) throw ParameterError("THE IMAGE HAS NO POINTS");
  const Window now = image.window.value_or(all);
  const double cx = v.size() == 3 ? v[1] : (now[0] + now[2]) / 2;
  const double cy = v.size() == 3 ? v[2] : (now[1] + now[3]) / 2;
  // An image of one point or one line still gets a square of some size.
  const double side = std::max(all[2] - all[0], all[3] - all[1]);
  const double w = (all[2] - all[0] > 0 ? all[2] - all[0] : side) / f;
  const double h = (all[3] - all[1] > 0 ? all[3] - all[1] : side) / f;
  if (!(w > 0) || !(h > 0)) throw ParameterError("THE IMAGE HAS NO SIZE");
  return corners(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2);
}

Window by_picks(Context& ctx, const Image& shown) {
  std::array<Point2, 2> picked;
  const Prompt* prompts[] = {&first_corner, &second_corner};
  for (int k = 0; k < 2; ++k) picked[k] = pick_image_point(ctx, *prompts[k], shown);
  return corners(picked[0].x, picked[0].y, picked[1].x, picked[1].y);
}

void run_zoom(Context& ctx, const Choice*) {
  Workspace& ws = ctx.workspace();
  if (!ws.image) throw Report(reports::image_not_found);
  const Image& shown = *ws.image;
  std::optional<Window> window;
  if (ctx.has_pending()) {
    const auto words = ctx.ask_words({});
    if (is_pick(words)) {
      window = by_picks(ctx, shown);
    } else {
      const std::vector<double> v = numbers_of(words);
      if (v.size() == 4)
        window = corners(v[0], v[1], v[2], v[3]);
      else if (v.size() == 1 || v.size() == 3)
        window = by_factor(shown, v);
      else
        throw ParameterError("GIVE X0 Y0 X1 Y1, A FACTOR [X Y], OR PICK");
    }
  }
  // The same points, shown through the window: a new current image (STORE keeps it zoomed).
  auto zoomed = std::make_shared<Image>(shown);
  zoomed->window = window;
  ws.image = std::shared_ptr<const Image>(std::move(zoomed));
  // Unlike DISPLAY, on a clean screen: the part larger over the whole image would be unreadable.
  ctx.erase();
  ctx.show(ws.image);
}

constexpr const Prompt* questions[] = {&first_corner, &second_corner};

}  // namespace

extern const Command zoom_command{
    .name = "ZOOM",
    .options = {},
    .follows = "[x0 y0 x1 y1 | factor [x y] | PICK]",
    .option_prompt = {},
    .summary = "shows a part of the current image larger, or the whole image again",
    .long_help =
        "ZOOM shows a part of the current image larger: the part inside a window is scaled to the "
        "picture's square and everything outside it is cut away, on a clean screen (unlike "
        "DISPLAY, which draws over what is there). The description beside the picture says "
        "ZOOMED. Coordinates are those of the image (the projected x y, as LIST IMAGES and the "
        "none terminal's IMAGE line show them).\n"
        "\n"
        "  ZOOM x0 y0 x1 y1   the window with corners x0 y0 and x1 y1\n"
        "  ZOOM f [x y]       the whole image f times larger, centred on x y (without them, on "
        "the centre of what is shown)\n"
        "  ZOOM PICK          the window's two corners picked on the Tektronix screen with the "
        "cross-hair (FIRST CORNER?, SECOND CORNER?); from a command file, each as its "
        "address X Y on the page EXPORT TEK draws, whatever the terminal mode\n"
        "  ZOOM               the whole image again\n"
        "\n"
        "The zoomed image is the current image: STORE FIRST keeps it zoomed, EXPORT and PLOT draw "
        "it zoomed. The window is not written to the disk: STORE FILE and the session keep the "
        "whole image. With no current image ZOOM says IMAGE NOT FOUND.\n"
        "\n"
        "Example (Z is ZOOM):\n"
        "  DISPLAY INPUT ORTHOGONAL XY\n"
        "  ZOOM 0 0 30 10\n"
        "  ZOOM 4 45 0\n"
        "  ZOOM",
    .questions = questions,
    .run = run_zoom,
};

}  // namespace igds
