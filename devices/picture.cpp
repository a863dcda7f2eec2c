#include "devices/picture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

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

// Adds `line` to `out`, split wherever a point is not finite.
void add_line(std::vector<std::vector<Point2>>& out, std::vector<Point2>&& line) {
  if (std::all_of(line.begin(), line.end(), finite)) {
    if (line.size() >= 2) out.push_back(std::move(line));
    return;
  }
  std::vector<Point2> piece;
  for (Point2 p : line) {
    if (finite(p)) {
      piece.push_back(p);
      continue;
    }
    if (piece.size() >= 2) out.push_back(piece);
    piece.clear();
  }
  if (piece.size() >= 2) out.push_back(std::move(piece));
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

void add_arrows(Picture& pic, const Array& arrows, const Grid& g) {
  if (arrows.rank() != 2 || arrows.shape[1] != 4 || arrows.size() != arrows.shape[0] * 4) return;
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
  for (std::size_t i = 0; i < n; ++i) {
    double len = std::hypot(a[4 * i + 2], a[4 * i + 3]);
    if (std::isfinite(len) && std::isfinite(a[4 * i]) && std::isfinite(a[4 * i + 1]))
      longest = std::max(longest, len);
  }
  if (longest == 0) return;
  if (!(extent > 0) || !std::isfinite(extent)) extent = longest;
  double s = arrow_fraction * extent / longest;
  // Head: two barbs of a quarter of the shaft at 25 degrees, drawn as a closed triangle.
  const double c = std::cos(std::numbers::pi / 180 * 25),
               sn = std::sin(std::numbers::pi / 180 * 25);
  for (std::size_t i = 0; i < n; ++i) {
    Point2 base{a[4 * i], a[4 * i + 1]};
    double vx = s * a[4 * i + 2], vy = s * a[4 * i + 3];
    double len = std::hypot(vx, vy);
    if (!finite(base) || !std::isfinite(len) || len == 0) continue;
    Point2 tip{base.x + vx, base.y + vy};
    double bx = -0.25 * vx, by = -0.25 * vy;  // a quarter of the shaft, pointing back
    Point2 left{tip.x + c * bx - sn * by, tip.y + sn * bx + c * by};
    Point2 right{tip.x + c * bx + sn * by, tip.y - sn * bx + c * by};
    add_line(pic.paths, {base, tip, left, right, tip});
  }
}

const char* projection_name(Projection p) {
  switch (p) {
    case Projection::conic:
      return "CONIC";
    case Projection::assonometric:
      return "ASSONOMETRIC";
    case Projection::isometric:
      return "ISOMETRIC";
    case Projection::orthogonal:
      return "ORTHOGONAL";
  }
  return "PROJECTION";
}

std::string fitted(std::string line, std::size_t width) {
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
  lines.push_back(fitted(desim.what == 0 ? "INPUT" : desim.what == 1 ? "SURFACE" : "IMAGE", width));
  lines.push_back(fitted(projection_name(desim.projection), width));
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
    case Projection::orthogonal: {
      int plane = static_cast<int>(p[0]);
      items.push_back(plane == 1 ? "XY" : plane == 2 ? "XZ" : plane == 3 ? "YZ" : "?");
      break;
    }
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

Picture picture_of(const Image& image) {
  Picture pic;
  pic.description = describe(image.desim, description_width);
  Grid g = grid_of(image.points);
  if (g.planes == 0 || g.rows == 0) return pic;
  if (image.desim.what == 0) {
    add_line(pic.paths, border_of(g));
    add_arrows(pic, image.arrows, g);
    for (std::size_t c = 0; c < g.planes; ++c)
      for (std::size_t r = 0; r < g.rows; ++r)
        if (finite(g.at(c, r))) pic.marks.push_back(g.at(c, r));
    return pic;
  }
  pic.paths.reserve(g.planes + g.rows);
  for (std::size_t c = 0; c < g.planes; ++c) {
    std::vector<Point2> line(g.rows);
    for (std::size_t r = 0; r < g.rows; ++r) line[r] = g.at(c, r);
    add_line(pic.paths, std::move(line));
  }
  for (std::size_t r = 0; r < g.rows; ++r) {
    std::vector<Point2> line(g.planes);
    for (std::size_t c = 0; c < g.planes; ++c) line[c] = g.at(c, r);
    add_line(pic.paths, std::move(line));
  }
  return pic;
}

Box bounds(const Picture& picture) {
  const double inf = std::numeric_limits<double>::infinity();
  Box b{inf, inf, -inf, -inf};
  auto add = [&](Point2 p) {
    if (!finite(p)) return;
    b.x0 = std::min(b.x0, p.x), b.x1 = std::max(b.x1, p.x);
    b.y0 = std::min(b.y0, p.y), b.y1 = std::max(b.y1, p.y);
  };
  for (const auto& path : picture.paths)
    for (Point2 p : path) add(p);
  for (Point2 p : picture.marks) add(p);
  return b;
}

Placement fit(const Picture& picture, const Box& box, double mark) {
  if (picture.marks.empty()) mark = 0;
  Box b = bounds(picture);
  double cx = (box.x0 + box.x1) / 2, cy = (box.y0 + box.y1) / 2;
  if (!(b.x0 <= b.x1)) return {1, cx, cy};
  double w = b.x1 - b.x0, h = b.y1 - b.y0;
  double room_w = std::max(0.0, box.x1 - box.x0 - 2 * mark);
  double room_h = std::max(0.0, box.y1 - box.y0 - 2 * mark);
  double scale = 1;
  if (w > 0 && h > 0)
    scale = std::min(room_w / w, room_h / h);
  else if (w > 0)
    scale = room_w / w;
  else if (h > 0)
    scale = room_h / h;
  // An extent that overflows (points near the largest double) collapses to the centre.
  if (!std::isfinite(scale) || !std::isfinite(w) || !std::isfinite(h)) scale = 0;
  double mx = b.x0 / 2 + b.x1 / 2, my = b.y0 / 2 + b.y1 / 2;
  return {scale, cx - scale * mx, cy - scale * my};
}

bool clip_segment(Point2& a, Point2& b, const Box& clip) {
  if (!finite(a) || !finite(b)) return false;
  // Liang-Barsky: the parameter interval of a + t (b - a) inside each of the four half planes.
  double t0 = 0, t1 = 1, dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - clip.x0, clip.x1 - a.x, a.y - clip.y0, clip.y1 - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    double t = q[i] / p[i];
    if (p[i] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  Point2 a0 = a;
  if (t1 < 1) b = {a0.x + t1 * dx, a0.y + t1 * dy};
  if (t0 > 0) a = {a0.x + t0 * dx, a0.y + t0 * dy};
  return true;
}

namespace {

// To the nearest unit, halves up (never truncated): floor(v + 0.5) without a library call.
int nearest(double v) {
  double h = v + 0.5;
  int i = static_cast<int>(h);
  return h < i ? i - 1 : i;
}

DevicePoint rounded(Point2 p, const Box& clip) {
  // Clamping only absorbs the last ulp of the interpolation in clip_segment.
  double x = std::clamp(p.x, clip.x0, clip.x1), y = std::clamp(p.y, clip.y0, clip.y1);
  return {nearest(x), nearest(y)};
}

bool inside(Point2 p, const Box& clip) {
  return p.x >= clip.x0 && p.x <= clip.x1 && p.y >= clip.y0 && p.y <= clip.y1;
}

// Clips one polyline in device units, appending the visible pieces to `out`.
void place_line(const std::vector<Point2>& line, const Box& clip, Placed& out) {
  DevicePath piece;
  if (std::all_of(line.begin(), line.end(), [&](Point2 p) { return inside(p, clip); })) {
    // Nothing to clip (the usual case): rounding alone.
    piece.reserve(line.size());
    for (Point2 p : line) {
      DevicePoint d{nearest(p.x), nearest(p.y)};
      if (piece.empty() || !(piece.back() == d)) piece.push_back(d);
    }
    if (piece.size() >= 2) out.paths.push_back(std::move(piece));
    return;
  }
  auto flush = [&] {
    if (piece.size() >= 2) out.paths.push_back(std::move(piece));
    piece.clear();
  };
  auto add = [&](DevicePoint p) {
    if (piece.empty() || !(piece.back() == p)) piece.push_back(p);
  };
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    Point2 a = line[i], b = line[i + 1];
    if (!inside(a, clip) || !inside(b, clip)) out.clipped = true;
    if (!clip_segment(a, b, clip)) {
      flush();
      continue;
    }
    DevicePoint da = rounded(a, clip);
    if (!piece.empty() && !(piece.back() == da)) flush();
    add(da);
    add(rounded(b, clip));
  }
  if (line.size() == 1 && !inside(line[0], clip)) out.clipped = true;
  flush();
}

}  // namespace

Placed place(const Picture& picture, const Placement& at, double mark, const Box& clip) {
  Placed out;
  std::vector<Point2> line;
  for (const auto& path : picture.paths) {
    line.clear();
    for (Point2 p : path) line.push_back(at.apply(p));
    place_line(line, clip, out);
  }
  for (Point2 m : picture.marks) {
    Point2 c = at.apply(m);
    place_line({{c.x - mark, c.y - mark},
                {c.x + mark, c.y - mark},
                {c.x + mark, c.y + mark},
                {c.x - mark, c.y + mark},
                {c.x - mark, c.y - mark}},
               clip, out);
  }
  return out;
}

}  // namespace igds
