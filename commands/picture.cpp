#include "commands/picture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "commands/view.h"
#include "devices/layout.h"
#include "workspace/apl.h"

namespace igds {

namespace {

bool finite(Point2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

// IMAGE as planes x rows of points, or nothing when its shape is not planes x rows x 2.
struct Grid {
  std::size_t planes = 0, rows = 0;
  const double* data = nullptr;
  Point2 at(std::size_t plane, std::size_t row) const {
    const double* p = data + 2 * (plane * rows + row);
    return {p[0], p[1]};
  }
};

Grid grid_of(const Array& points) {
  if (points.rank() != 3 || points.shape[2] != 2) return {};
  if (points.size() != points.shape[0] * points.shape[1] * 2) return {};
  return {points.shape[0], points.shape[1], points.data()};
}

// Adds `line` to the drawing (the devices break it wherever a point is not finite).
void add_line(Drawing2& drawing, const std::vector<Point2>& line, Identity id) {
  std::vector<double> xy(2 * line.size());
  for (std::size_t k = 0; k < line.size(); ++k) line[k].store(&xy[2 * k]);
  drawing.add_polyline(Point2View(xy.data(), line.size()), {}, id);
}

// The border of the grid, once around and closed: curve 1, the last stringer, the last curve
// backwards, the first stringer backwards, back to the first point.
std::vector<Point2> border_of(const Grid& g) {
  std::vector<Point2> ring;
  if (g.planes == 1 || g.rows == 1) {
    for (std::size_t c = 0; c < g.planes; ++c)
      for (std::size_t r = 0; r < g.rows; ++r) ring.push_back(g.at(c, r));
    return ring;
  }
  for (std::size_t r = 0; r < g.rows; ++r) ring.push_back(g.at(0, r));
  for (std::size_t c = 1; c < g.planes; ++c) ring.push_back(g.at(c, g.rows - 1));
  for (std::size_t r = g.rows - 1; r-- > 0;) ring.push_back(g.at(g.planes - 1, r));
  for (std::size_t c = g.planes - 1; --c > 0;) ring.push_back(g.at(c, 0));
  ring.push_back(ring.front());
  return ring;
}

void add_arrows(Drawing2& drawing, const Array& arrows, const Grid& g) {
  // Rows x y dx dy, and (since arrows carry it) the point number and 1 along the curve or 0
  // along the stringer.
  const std::size_t columns = arrows.rank() == 2 ? arrows.shape[1] : 0;
  if ((columns != 4 && columns != 6) || arrows.size() != arrows.shape[0] * columns) return;
  // The image's larger side sets the arrows' scale, so they stay short of the image size.
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (std::size_t c = 0; c < g.planes; ++c)
    for (std::size_t r = 0; r < g.rows; ++r) {
      Point2 p = g.at(c, r);
      if (!finite(p)) continue;
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  double extent = x1 >= x0 ? std::max(x1 - x0, y1 - y0) : 0;
  double longest = 0;
  const double* a = arrows.data();
  std::size_t n = arrows.shape[0];
  auto row = [&](std::size_t i) { return a + columns * i; };
  for (std::size_t i = 0; i < n; ++i) {
    double len = std::hypot(row(i)[2], row(i)[3]);
    if (std::isfinite(len) && std::isfinite(row(i)[0]) && std::isfinite(row(i)[1]))
      longest = std::max(longest, len);
  }
  if (longest == 0) return;
  if (!(extent > 0) || !std::isfinite(extent)) extent = longest;
  double s = arrow_fraction * extent / longest;
  // Head: two barbs of a quarter of the shaft at 25 degrees, drawn as a closed triangle.
  const double c = std::cos(std::numbers::pi / 180 * 25),
               sn = std::sin(std::numbers::pi / 180 * 25);
  for (std::size_t i = 0; i < n; ++i) {
    const double* r = row(i);
    Point2 base{r[0], r[1]};
    double vx = s * r[2], vy = s * r[3];
    double len = std::hypot(vx, vy);
    if (!finite(base) || !std::isfinite(len) || len == 0) continue;
    Point2 tip{base.x + vx, base.y + vy};
    double bx = -0.25 * vx, by = -0.25 * vy;  // a quarter of the shaft, pointing back
    Point2 left{tip.x + c * bx - sn * by, tip.y + sn * bx + c * by};
    Point2 right{tip.x + c * bx + sn * by, tip.y - sn * bx + c * by};
    Identity id{Role::tangent};
    if (columns == 6 && std::isfinite(r[4]) && std::isfinite(r[5]))
      id = {Role::tangent, static_cast<int>(r[4]), static_cast<int>(r[5])};
    add_line(drawing, {base, tip, left, right, tip}, id);
  }
}

std::string fitted(std::string_view text, std::size_t width) {
  std::string line(text);
  if (line.size() > width) line.resize(width);
  return line;
}

}  // namespace

std::string plain_number(double value) {
  std::string apl = format_apl_number(value), out;
  for (std::size_t i = 0; i < apl.size(); ++i) {
    // U+00AF (APL high minus) is C2 AF in UTF-8.
    if (apl[i] == '\xC2' && i + 1 < apl.size() && apl[i + 1] == '\xAF') {
      out += '-';
      ++i;
    } else if (apl[i] >= 0x20 && apl[i] < 0x7F) {
      out += apl[i];
    } else {
      out += '?';
    }
  }
  return out;
}

std::vector<std::string> describe(const Description& desim, std::size_t width) {
  std::vector<std::string> lines;
  lines.push_back(fitted(image_kind_word(desim.what), width));
  lines.push_back(fitted(projection_word(desim.projection), width));
  const auto& p = desim.parameters;
  std::vector<std::string> items;
  switch (desim.projection) {
    case Projection::conic:
    case Projection::assonometric:
      for (double v : p) items.push_back(plain_number(v));
      break;
    case Projection::isometric: {
      int axis = static_cast<int>(p[0]);
      const char* name = axis == 1 ? "X" : axis == 2 ? "Y" : axis == 3 ? "Z" : "?";
      items.push_back(fmt::format("AXIS {}", name));
      items.push_back(fmt::format("ANGLE {}", plain_number(p[1])));
      break;
    }
    case Projection::orthogonal:
      items.emplace_back(plane_word(p[0]));
      break;
  }
  // The parameters share a line when they fit, else one line each.
  std::string joined;
  for (const auto& item : items) joined += (joined.empty() ? "" : " ") + item;
  if (joined.size() <= width) {
    if (!joined.empty()) lines.push_back(joined);
  } else {
    for (const auto& item : items) lines.push_back(fitted(item, width));
  }
  return lines;
}

std::string describe_line(const Description& d) {
  const auto& p = d.parameters;
  auto number = [](double v) { return format_apl_number(v); };
  std::string projection(projection_word(d.projection));
  switch (d.projection) {
    case Projection::conic:
      projection += fmt::format(", VIEW POINT {} {} {}", number(p[0]), number(p[1]), number(p[2]));
      break;
    case Projection::assonometric:
      projection += fmt::format(" {} {} {}", number(p[0]), number(p[1]), number(p[2]));
      break;
    case Projection::isometric:
      projection += fmt::format(", AXIS {} ANGLE {}", number(p[0]), number(p[1]));
      break;
    case Projection::orthogonal:
      projection += fmt::format(" {}", plane_word(p[0]));
      break;
  }
  return fmt::format("IMAGE: {}, {}", image_kind_word(d.what), projection);
}

Picture picture_of(std::shared_ptr<const Image> image) {
  Picture pic;
  pic.caption = describe(image->desim, caption_width);
  if (image->desim.what == 0 && image->auto_tangents) pic.caption.push_back("TANGENTS AUTO");
  Grid g = grid_of(image->points);
  if (g.planes == 0 || g.rows == 0) return pic;
  Drawing2& d = pic.drawing;
  if (image->desim.what == 0) {
    add_line(d, border_of(g), {Role::border});
    add_arrows(d, image->arrows, g);
    for (std::size_t c = 0; c < g.planes; ++c)
      for (std::size_t r = 0; r < g.rows; ++r)
        if (finite(g.at(c, r)))
          d.add_mark(g.at(c, r), MarkShape::square, point_mark, {},
                     {Role::point, static_cast<int>(c * g.rows + r + 1)});
    return pic;
  }
  // The curves and stringers read the image's own points: no copy of a large grid.
  const auto pool = d.share(image, g.data, 2 * g.planes * g.rows);
  for (std::size_t c = 0; c < g.planes; ++c)
    d.add_polyline(pool, 2 * c * g.rows, g.rows, 2, {}, {Role::curve, static_cast<int>(c + 1)});
  for (std::size_t r = 0; r < g.rows; ++r)
    d.add_polyline(pool, 2 * r, g.planes, 2 * g.rows, {},
                   {Role::stringer, static_cast<int>(r + 1)});
  return pic;
}

Picture picture_of(const ImageRef& image) {
  return picture_of(image.shared());
}

Picture picture_of(const Image& image) {
  return picture_of(std::make_shared<const Image>(image));
}

}  // namespace igds
