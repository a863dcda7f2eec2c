#include "commands/picture.h"

#include "commands/context.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "commands/view.h"
#include "devices/layout.h"
#include "devices/render.h"
#include "workspace/kernels/hidden.h"
#include "workspace/numbers/typed.h"

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

bool inside(Point2 p, const Box& b) {
  return p.x >= b.x0 && p.x <= b.x1 && p.y >= b.y0 && p.y <= b.y1;
}

void add_polyline(Drawing2& drawing, const std::vector<Point2>& line, Identity id) {
  std::vector<double> xy(2 * line.size());
  for (std::size_t k = 0; k < line.size(); ++k) line[k].store(&xy[2 * k]);
  drawing.add_polyline(Point2View(xy.data(), line.size()), {}, id);
}

// Adds the pieces of `line` (a vector or a view of points) inside a ZOOM window to the drawing,
// one polyline each.
template <class Line>
void add_clipped(Drawing2& drawing, const Line& line, Identity id, const Box& w) {
  std::vector<Point2> piece;
  auto flush = [&] {
    if (piece.size() >= 2) add_polyline(drawing, piece, id);
    piece.clear();
  };
  // Where a point lies against the window: 0 inside, else a bit for each side it is beyond.
  auto side = [&w](Point2 p) {
    return (p.x < w.x0 ? 1 : p.x > w.x1 ? 2 : 0) | (p.y < w.y0 ? 4 : p.y > w.y1 ? 8 : 0);
  };
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    Point2 a = line[i], b = line[i + 1];
    if (!finite(a) || !finite(b)) {
      flush();
      continue;
    }
    // Both beyond one side: nothing of it is inside; both inside: nothing to clip (most segments
    // of a large grid are one or the other).
    const int sa = side(a), sb = side(b);
    if ((sa & sb) != 0 || ((sa | sb) != 0 && !clip_segment(a, b, w))) {
      flush();
      continue;
    }
    if (!piece.empty() && !(piece.back().x == a.x && piece.back().y == a.y)) flush();
    if (piece.empty()) piece.push_back(a);
    piece.push_back(b);
    // A segment that left the window ends its piece.
    if (!(b.x == line[i + 1].x && b.y == line[i + 1].y)) flush();
  }
  flush();
}

// Adds `line` to the drawing (the devices break it wherever a point is not finite); with a
// ZOOM window, only its pieces inside the window.
void add_line(Drawing2& drawing, const std::vector<Point2>& line, Identity id,
              const Box* window = nullptr) {
  if (window)
    add_clipped(drawing, line, id, *window);
  else
    add_polyline(drawing, line, id);
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

void add_arrows(Drawing2& drawing, const Array& arrows, const Grid& g, const Box* window) {
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
    add_line(drawing, {base, tip, left, right, tip}, id, window);
  }
}

// What a point number must keep clear of: the picture's lines and marks and the numbers placed
// before it, and the picture's bounds. Kept in square buckets so that each number looks only at
// what is near it.
class Room {
 public:
  Room(const Box& area, double bucket) : area_(area), bucket_(bucket) {
    nx_ = std::clamp(static_cast<int>((area.x1 - area.x0) / bucket) + 1, 1, 256);
    ny_ = std::clamp(static_cast<int>((area.y1 - area.y0) / bucket) + 1, 1, 256);
    buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
  }
  void add_segment(Point2 a, Point2 b) {
    add({std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)},
        {a, b, false});
  }
  void add_box(const Box& b) { add(b, {{b.x0, b.y0}, {b.x1, b.y1}, true}); }
  // True when `b` lies inside the area and meets nothing kept.
  bool free(const Box& b) const {
    if (b.x0 < area_.x0 || b.y0 < area_.y0 || b.x1 > area_.x1 || b.y1 > area_.y1) return false;
    // The bucket at the middle first: in a dense picture it holds what is in the way.
    const auto [ic, jc, ic1, jc1] = span({(b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2, 0, 0});
    if (meets(b, ic, jc)) return false;
    const auto [i0, j0, i1, j1] = span(b);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        if ((i != ic || j != jc) && meets(b, i, j)) return false;
    return true;
  }

 private:
  struct Obstacle {
    Point2 a, b;  // a segment, or a box's corners
    bool box;
  };
  // Something of bucket i j meets `b`.
  bool meets(const Box& b, int i, int j) const {
    for (std::size_t k : buckets_[static_cast<std::size_t>(j) * nx_ + i]) {
      const Obstacle& o = obstacles_[k];
      if (o.box) {
        if (o.a.x <= b.x1 && b.x0 <= o.b.x && o.a.y <= b.y1 && b.y0 <= o.b.y) return true;
      } else {
        Point2 a = o.a, e = o.b;
        if (clip_segment(a, e, b)) return true;
      }
    }
    return false;
  }
  std::array<int, 4> span(const Box& b) const {
    auto index = [&](double v, double from, int n) {
      const double f = std::floor((v - from) / bucket_);
      return static_cast<int>(std::clamp(f, 0.0, double(n - 1)));
    };
    return {index(b.x0, area_.x0, nx_), index(b.y0, area_.y0, ny_), index(b.x1, area_.x0, nx_),
            index(b.y1, area_.y0, ny_)};
  }
  void add(const Box& extent, Obstacle o) {
    if (!std::isfinite(extent.x0) || !std::isfinite(extent.y0) || !std::isfinite(extent.x1) ||
        !std::isfinite(extent.y1))
      return;
    obstacles_.push_back(o);
    const auto [i0, j0, i1, j1] = span(extent);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        buckets_[static_cast<std::size_t>(j) * nx_ + i].push_back(obstacles_.size() - 1);
  }
  Box area_;
  double bucket_;
  int nx_ = 1, ny_ = 1;
  std::vector<Obstacle> obstacles_;
  std::vector<std::vector<std::size_t>> buckets_;
};

// The point numbers of DISPLAY INPUT (docs/decisions.md): each beside its point, in the first
// place around it (the corner towards the middle of the picture first) where it meets no line,
// mark or other number and stays inside the picture's bounds (so the numbers never change the
// picture's scale). A number with no such place is left out: ZOOM shows it.
void add_point_numbers(Drawing2& drawing, const Grid& g, const Box* window) {
  const Box shown = window ? *window : bounds(drawing);
  if (!(shown.x0 <= shown.x1) || !(shown.y0 <= shown.y1)) return;
  // One 4013 point in drawing units, in the smallest square a picture is drawn in (tek mode's,
  // devices/layout.h); drawn larger, a number's cell only shrinks towards its corner.
  const TekLayout smallest = dialogue_layout();
  const double room =
      smallest.image.x1 - smallest.image.x0 - 2 * tek_screen::image_margin - 2 * tek_screen::mark;
  const double unit = std::max(shown.x1 - shown.x0, shown.y1 - shown.y0) / room;
  if (!(unit > 0) || !std::isfinite(unit)) return;
  std::size_t shown_points = 0;
  for (std::size_t c = 0; c < g.planes; ++c)
    for (std::size_t r = 0; r < g.rows; ++r)
      shown_points += finite(g.at(c, r)) && inside(g.at(c, r), shown);
  if (shown_points > max_numbered_points) return;
  Room free_room(shown, 8 * unit);  // buckets of about half a character cell
  std::vector<Point2> points;
  for (const auto& item : drawing.items()) {
    const auto pts = drawing.points(item);
    if (item.kind == Drawing2::Kind::polyline) {
      for (std::size_t k = 0; k + 1 < pts.size(); ++k) free_room.add_segment(pts[k], pts[k + 1]);
      if (item.closed && pts.size() > 2) free_room.add_segment(pts[pts.size() - 1], pts[0]);
    } else if (item.kind == Drawing2::Kind::mark) {
      const double h = item.size * unit;
      free_room.add_box({pts[0].x - h, pts[0].y - h, pts[0].x + h, pts[0].y + h});
    }
  }
  // A 4013 character cell: 14 points wide, from 4 below the baseline to 16 above; one point more
  // on every side for the rounding to device units.
  const double gap = (point_mark + 2) * unit, pad = unit, below = 4 * unit, above = 16 * unit;
  const double mid_x = (shown.x0 + shown.x1) / 2, mid_y = (shown.y0 + shown.y1) / 2;
  for (std::size_t c = 0; c < g.planes; ++c)
    for (std::size_t r = 0; r < g.rows; ++r) {
      const Point2 p = g.at(c, r);
      if (!finite(p) || (window && !inside(p, *window))) continue;
      const int k = static_cast<int>(c * g.rows + r + 1);
      const std::string number = std::to_string(k);
      const double width = tek_screen::char_width * unit * static_cast<double>(number.size());
      // Towards the middle first; then the other corners; then a little farther from the point
      // (beside a slanting border line); then straight above, below or beside it (in the angle
      // two border lines make at a corner of the picture).
      const double sx = p.x <= mid_x ? 1 : -1, sy = p.y <= mid_y ? 1 : -1;
      constexpr double steps[][2] = {{1, 1}, {2, 1}, {1, 2}, {2, 2}, {3, 1},
                                     {1, 3}, {1, 4}, {4, 1}, {1, 6}, {6, 1}};
      constexpr double sides[][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1},
                                     {0, 1}, {0, -1}, {1, 0},  {-1, 0}};
      auto place_at = [&](const double* step, const double* side) {
        const double dx = sx * side[0], dy = sy * side[1];
        const Point2 at{dx > 0   ? p.x + step[0] * gap
                        : dx < 0 ? p.x - step[0] * gap - width
                                 : p.x - width / 2,
                        dy > 0   ? p.y + step[1] * gap + below
                        : dy < 0 ? p.y - step[1] * gap - above
                                 : p.y - (above - below) / 2};
        const Box cell{at.x - pad, at.y - below - pad, at.x + width + pad, at.y + above + pad};
        if (!free_room.free(cell)) return false;
        drawing.add_text(at, number, 1, {}, {Role::label, k});
        free_room.add_box(cell);
        return true;
      };
      std::any_of(std::begin(steps), std::end(steps), [&](const double* step) {
        return std::any_of(std::begin(sides), std::end(sides),
                           [&](const double* side) { return place_at(step, side); });
      });
    }
}

// The visible parts of the curves and stringers of a hidden-line image (docs/decisions.md,
// "Hidden lines"), decided on a raster of hidden_line_cells across what is shown.
void add_visible(Drawing2& drawing, const Image& image, const Grid& g, const Box* window) {
  Box shown{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  if (window) {
    shown = *window;
  } else {
    for (std::size_t k = 0; k < g.planes * g.rows; ++k) {
      const Point2 p{g.data[2 * k], g.data[2 * k + 1]};
      if (!finite(p)) continue;
      shown = {std::min(shown.x0, p.x), std::min(shown.y0, p.y), std::max(shown.x1, p.x),
               std::max(shown.y1, p.y)};
    }
    if (!(shown.x0 <= shown.x1)) return;
    // The grid's corners, as points that draw nothing: the picture keeps the whole surface's
    // scale and place, whatever is hidden.
    add_polyline(drawing, {{shown.x0, shown.y0}}, {});
    add_polyline(drawing, {{shown.x1, shown.y1}}, {});
  }
  const double side = std::max(shown.x1 - shown.x0, shown.y1 - shown.y0);
  const SeenGrid seen{g.planes, g.rows, g.data, image.nearness.data()};
  const auto pieces =
      visible_pieces(seen, {shown.x0, shown.y0, shown.x1, shown.y1, side / hidden_line_cells});
  std::vector<Point2> line;
  for (const VisiblePiece& piece : pieces) {
    const bool curve = piece.line < g.planes;
    const std::size_t fixed = curve ? piece.line : piece.line - g.planes;
    auto at = [&](std::size_t k) { return curve ? g.at(fixed, k) : g.at(k, fixed); };
    // The point at parameter t: point k of the line, or between two in proportion.
    auto point = [&](double t) {
      const auto k = static_cast<std::size_t>(t);
      const double f = t - double(k);
      if (f == 0) return at(k);
      const Point2 a = at(k), b = at(k + 1);
      return Point2{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
    };
    line.clear();
    line.push_back(point(piece.from));
    for (auto k = static_cast<std::size_t>(std::floor(piece.from)) + 1; double(k) < piece.to; ++k)
      line.push_back(at(k));
    line.push_back(point(piece.to));
    const Identity id = curve ? Identity{Role::curve, static_cast<int>(fixed + 1)}
                              : Identity{Role::stringer, static_cast<int>(fixed + 1)};
    add_line(drawing, line, id, window);
  }
}

// DISPLAY COMBS: every curve's comb, then every stringer's, each as one path that goes out along
// a hair, across to the next comb's end and back along its hair, then along the line to the next
// hair (every hair drawn once, all finite for every device and file), and the envelope joining
// the combs' ends.
void add_combs(Drawing2& drawing, const Array& combs, const Grid& g, const Box* window) {
  if (combs.shape != std::vector<std::size_t>{g.planes, g.rows, 4}) return;
  auto comb = [&](std::size_t count, auto index, std::size_t column, Identity id) {
    auto end = [&](std::size_t k) {
      const double* e = combs.data() + 4 * index(k) + column;
      return Point2{e[0], e[1]};
    };
    auto base = [&](std::size_t k) { return g.at(index(k) / g.rows, index(k) % g.rows); };
    std::vector<Point2> hairs, envelope;
    hairs.reserve(2 * count);
    envelope.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
      const bool out = k % 2 == 0;
      hairs.push_back(out ? base(k) : end(k));
      hairs.push_back(out ? end(k) : base(k));
      envelope.push_back(end(k));
    }
    add_line(drawing, hairs, id, window);
    add_line(drawing, envelope, id, window);
  };
  for (std::size_t c = 0; c < g.planes; ++c)
    comb(g.rows, [&](std::size_t k) { return c * g.rows + k; }, 0,
         {Role::comb, static_cast<int>(c + 1), 1});
  for (std::size_t r = 0; r < g.rows; ++r)
    comb(g.planes, [&](std::size_t k) { return k * g.rows + r; }, 2,
         {Role::comb, static_cast<int>(r + 1), 0});
}

std::string fitted(std::string_view text, std::size_t width) {
  std::string line(text);
  if (line.size() > width) line.resize(width);
  return line;
}

}  // namespace

std::string plain_number(double value) {
  std::string apl = format_typed_number(value), out;
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

namespace {

// COLOURS and the pens of a picture's drawing when it has several (the 4013 draws them alike);
// "" when it has one.
std::string colours_line(const Drawing2& drawing) {
  std::vector<int> pens;
  for (const auto& item : drawing.items())
    if (std::find(pens.begin(), pens.end(), item.style.pen) == pens.end())
      pens.push_back(item.style.pen);
  std::sort(pens.begin(), pens.end());
  if (pens.size() < 2) return "";
  std::string line = "COLOURS";
  for (int pen : pens) line += fmt::format(" {}", pen);
  return line;
}

}  // namespace

std::vector<std::string> image_caption(const Image& image, std::size_t width) {
  std::vector<std::string> lines = describe(image.desim, width);
  if (image.window) lines.push_back(fitted(zoomed_word, width));
  return lines;
}

std::string zoom_words(const std::array<double, 4>& window) {
  // Five significant digits: a window picked on the screen is not known closer than that.
  auto number = [](double v) { return plain_number(std::stod(fmt::format("{:.5g}", v))); };
  return fmt::format("{} TO {} {} {} {}", zoomed_word, number(window[0]), number(window[1]),
                     number(window[2]), number(window[3]));
}

// How an input image of a surface whose tangents AUTO set says so.
constexpr const char* auto_words = "TANGENTS AUTO";

std::string comb_words(const Image& image) {
  if (image.combs.empty()) return "NO COMBS";
  if (image.comb_scale == 0) return "NO CURVATURE";
  return fmt::format("SCALE {}", plain_number(image.comb_scale));
}

std::string image_line(const Image& image) {
  std::string line = describe_line(image.desim);
  if (image.desim.what == 0 && image.auto_tangents) line += std::string(", ") + auto_words;
  if (image.desim.what == 2 && image.picture) {
    // As the caption says it: the picture's name after PICTURE, its colours.
    line.insert(line.find(','), " " + image.picture->name);
    if (const std::string colours = colours_line(image.picture->drawing); !colours.empty())
      line += ", " + colours;
  }
  if (image.desim.what == 3) line += ", " + comb_words(image);
  if (const auto& w = image.window) line += ", " + zoom_words(*w);
  return line;
}

std::vector<std::string> describe(const Description& desim, std::size_t width) {
  std::vector<std::string> lines;
  lines.push_back(fitted(image_kind_word(desim.what), width));
  if (desim.hidden) lines.push_back(fitted(hidden_word(), width));
  lines.push_back(fitted(projection_word(desim.projection), width));
  const auto& p = desim.parameters;
  std::vector<std::string> items;
  switch (desim.projection) {
    case Projection::conic:
    case Projection::assonometric:
      for (double v : p) items.push_back(plain_number(v));
      break;
    case Projection::isometric: {
      // Compared as read (a file may say any number, beyond an int's range too).
      const double axis = p[0];
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
  auto number = [](double v) { return format_typed_number(v); };
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
  return fmt::format("IMAGE: {}{}{}, {}", image_kind_word(d.what), d.hidden ? " " : "",
                     d.hidden ? hidden_word() : "", projection);
}

namespace {

// A DUCT picture's image: its drawing as projected, its name, and its colours (the 4013 draws
// them all alike, so the description says which there are).
Picture picture_of_duct(const Image& image) {
  Picture pic;
  pic.caption = describe(image.desim, caption_width);
  if (!image.picture) return pic;
  pic.drawing = image.picture->drawing;
  pic.caption.insert(pic.caption.begin() + 1, fitted(image.picture->name, caption_width));
  if (const std::string colours = colours_line(pic.drawing); !colours.empty())
    pic.caption.push_back(fitted(colours, caption_width));
  return pic;
}

}  // namespace

Picture picture_of(std::shared_ptr<const Image> image) {
  if (image->desim.what == 2) return picture_of_duct(*image);
  Picture pic;
  pic.caption = image_caption(*image, caption_width);
  if (image->desim.what == 0 && image->auto_tangents) pic.caption.push_back(auto_words);
  if (image->desim.what == 3) pic.caption.push_back(fitted(comb_words(*image), caption_width));
  Grid g = grid_of(image->points);
  if (g.planes == 0 || g.rows == 0) return pic;
  Drawing2& d = pic.drawing;
  std::optional<Box> zoom;
  if (const auto& w = image->window) zoom = Box{(*w)[0], (*w)[1], (*w)[2], (*w)[3]};
  const Box* window = zoom ? &*zoom : nullptr;
  if (zoom) {
    // The window's corners, as polylines of one point: they draw nothing (devices/render.h drops
    // paths of fewer than two points) but make the window what the picture is scaled to.
    add_polyline(d, {{zoom->x0, zoom->y0}}, {});
    add_polyline(d, {{zoom->x1, zoom->y1}}, {});
  }
  if (image->desim.what == 0) {
    add_line(d, border_of(g), {Role::border}, window);
    add_arrows(d, image->arrows, g, window);
    for (std::size_t c = 0; c < g.planes; ++c)
      for (std::size_t r = 0; r < g.rows; ++r)
        if (finite(g.at(c, r)) && (!window || inside(g.at(c, r), *window)))
          d.add_mark(g.at(c, r), MarkShape::square, point_mark, {},
                     {Role::point, static_cast<int>(c * g.rows + r + 1)});
    add_point_numbers(d, g, window);
    return pic;
  }
  if (image->desim.hidden && image->nearness.size() == g.planes * g.rows) {
    add_visible(d, *image, g, window);
    return pic;
  }
  if (window) {
    // Each curve and stringer read in place (a view of the image's points), cut to the window.
    for (std::size_t c = 0; c < g.planes; ++c)
      add_clipped(d, Point2View(g.data + 2 * c * g.rows, g.rows),
                  {Role::curve, static_cast<int>(c + 1)}, *window);
    for (std::size_t r = 0; r < g.rows; ++r)
      add_clipped(d, Point2View(g.data + 2 * r, g.planes, 2 * g.rows),
                  {Role::stringer, static_cast<int>(r + 1)}, *window);
    add_combs(d, image->combs, g, window);
    return pic;
  }
  // The curves and stringers read the image's own points: no copy of a large grid, and its box
  // when the projection found it.
  const auto pool = d.share(image, g.data, 2 * g.planes * g.rows, image->extent);
  for (std::size_t c = 0; c < g.planes; ++c)
    d.add_polyline(pool, 2 * c * g.rows, g.rows, 2, {}, {Role::curve, static_cast<int>(c + 1)});
  for (std::size_t r = 0; r < g.rows; ++r)
    d.add_polyline(pool, 2 * r, g.planes, 2 * g.rows, {},
                   {Role::stringer, static_cast<int>(r + 1)});
  add_combs(d, image->combs, g, nullptr);
  return pic;
}

Picture picture_of(const ImageRef& image) {
  return picture_of(image.shared());
}

Picture picture_of(const Image& image) {
  return picture_of(std::make_shared<const Image>(image));
}

void show_current_image(Context& ctx, const ImageRef& before) {
  const ImageRef& now = ctx.workspace().image;
  if (same_image(now, before)) return;
  ctx.erase();
  if (now) ctx.show(now);
}

}  // namespace igds
