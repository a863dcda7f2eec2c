#include "devices/render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "workspace/drawing/flatten.h"

namespace igds {

namespace {

bool finite(Point2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

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

// Where placed paths go: a list (the plotter reorders them) or a device at once.
class Sink {
 public:
  virtual ~Sink() = default;
  virtual void path(DevicePath& points, const Style& style) = 0;
  virtual void text(DevicePoint at, const std::string& text, const Style& style) = 0;
  bool clipped = false;
};

class ListSink final : public Sink {
 public:
  explicit ListSink(Placed& out) : out_(out) {}
  void path(DevicePath& points, const Style& style) override {
    out_.paths.push_back({std::move(points), style});
    points = {};
  }
  void text(DevicePoint at, const std::string& text, const Style& style) override {
    out_.texts.push_back({at, text, style});
  }

 private:
  Placed& out_;
};

class DeviceSink final : public Sink {
 public:
  explicit DeviceSink(Device& device) : device_(device) {}
  void path(DevicePath& points, const Style& style) override {
    device_.style(style);
    device_.polyline(points);
    points.clear();
  }
  void text(DevicePoint at, const std::string& text, const Style& style) override {
    device_.style(style);
    device_.text(at, text);
  }

 private:
  Device& device_;
};

// Clips one polyline in device units and hands its visible pieces to the sink; `piece` is
// reused from call to call.
void place_line(const std::vector<Point2>& line, const Box& clip, const Style& style, Sink& sink,
                DevicePath& piece) {
  piece.clear();
  if (std::all_of(line.begin(), line.end(), [&](Point2 p) { return inside(p, clip); })) {
    // Nothing to clip (the usual case): rounding alone.
    for (Point2 p : line) {
      DevicePoint d{nearest(p.x), nearest(p.y)};
      if (piece.empty() || !(piece.back() == d)) piece.push_back(d);
    }
    if (piece.size() >= 2) sink.path(piece, style);
    return;
  }
  auto flush = [&] {
    if (piece.size() >= 2) sink.path(piece, style);
    piece.clear();
  };
  auto add = [&](DevicePoint p) {
    if (piece.empty() || !(piece.back() == p)) piece.push_back(p);
  };
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    Point2 a = line[i], b = line[i + 1];
    if (!inside(a, clip) || !inside(b, clip)) sink.clipped = true;
    if (!clip_segment(a, b, clip)) {
      flush();
      continue;
    }
    DevicePoint da = rounded(a, clip);
    if (!piece.empty() && !(piece.back() == da)) flush();
    add(da);
    add(rounded(b, clip));
  }
  if (line.size() == 1 && !inside(line[0], clip)) sink.clipped = true;
  flush();
}

// Adds `points` placed to `line`, split into `out` wherever a point is not finite.
template <class Points>
void placed_pieces(const Points& points, bool closed, const Placement& at,
                   std::vector<std::vector<Point2>>& out) {
  std::vector<Point2> line;
  line.reserve(points.size() + (closed ? 1 : 0));
  auto flush = [&] {
    if (line.size() >= 2) out.push_back(line);
    line.clear();
  };
  for (Point2 p : points) {
    if (!finite(p)) {
      flush();
      continue;
    }
    line.push_back(at.apply(p));
  }
  if (closed && !points.empty() && finite(points.front()) && !line.empty())
    line.push_back(at.apply(points.front()));
  flush();
}

// The strokes of a mark of half side `h` at `c`, in device units.
void mark_strokes(MarkShape shape, Point2 c, double h, std::vector<std::vector<Point2>>& out) {
  switch (shape) {
    case MarkShape::square:
      out.push_back({{c.x - h, c.y - h},
                     {c.x + h, c.y - h},
                     {c.x + h, c.y + h},
                     {c.x - h, c.y + h},
                     {c.x - h, c.y - h}});
      return;
    case MarkShape::dot: {
      const double d = std::max(h / 6, 0.5);
      out.push_back({{c.x - d, c.y - d},
                     {c.x + d, c.y - d},
                     {c.x + d, c.y + d},
                     {c.x - d, c.y + d},
                     {c.x - d, c.y - d}});
      return;
    }
    case MarkShape::cross:
      out.push_back({{c.x - h, c.y - h}, {c.x + h, c.y + h}});
      out.push_back({{c.x - h, c.y + h}, {c.x + h, c.y - h}});
      return;
    case MarkShape::plus:
      out.push_back({{c.x - h, c.y}, {c.x + h, c.y}});
      out.push_back({{c.x, c.y - h}, {c.x, c.y + h}});
      return;
    case MarkShape::diamond:
      out.push_back(
          {{c.x, c.y - h}, {c.x + h, c.y}, {c.x, c.y + h}, {c.x - h, c.y}, {c.x, c.y - h}});
      return;
    case MarkShape::circle: {
      // Enough sides that the polygon stays within a quarter unit of the circle.
      const int sides = std::clamp(
          static_cast<int>(std::ceil(std::numbers::pi / std::acos(1 - 0.25 / std::max(h, 0.5)))), 8,
          64);
      std::vector<Point2> ring;
      for (int k = 0; k <= sides; ++k) {
        const double a = 2 * std::numbers::pi * k / sides;
        ring.push_back({c.x + h * std::cos(a), c.y + h * std::sin(a)});
      }
      out.push_back(std::move(ring));
      return;
    }
  }
}

void place_into(const Drawing2& drawing, const Placement& at, const Box& clip,
                const Rendering& rendering, Sink& sink) {
  std::vector<std::vector<Point2>> lines;
  DevicePath piece;
  std::vector<Point2> flat;
  const double tolerance = rendering.tolerance * rendering.point;
  for (const auto& item : drawing.items()) {
    lines.clear();
    const auto points = drawing.points(item);
    switch (item.kind) {
      case Drawing2::Kind::polyline:
        placed_pieces(points, item.closed, at, lines);
        break;
      case Drawing2::Kind::curve: {
        // Span by span, in device units, to the tolerance.
        const auto weights = drawing.weights(item);
        const std::size_t degree = item.degree;
        std::vector<Point2> controls(degree + 1);
        flat.clear();
        for (std::size_t first = 0; first + degree < points.size(); first += degree) {
          for (std::size_t k = 0; k <= degree; ++k) controls[k] = at.apply(points[first + k]);
          flatten_span(static_cast<int>(degree), controls,
                       weights.empty() ? weights : weights.subspan(first, degree + 1), tolerance,
                       flat);
        }
        placed_pieces(flat, false, Placement{}, lines);
        break;
      }
      case Drawing2::Kind::mark: {
        const Point2 c = points[0];
        if (finite(c)) mark_strokes(item.shape, at.apply(c), item.size * rendering.point, lines);
        break;
      }
      case Drawing2::Kind::text:
        break;
    }
    for (const auto& line : lines) place_line(line, clip, item.style, sink, piece);
  }
  for (const auto& item : drawing.items()) {
    if (item.kind != Drawing2::Kind::text) continue;
    const Point2 p = drawing.points(item)[0];
    if (!finite(p)) continue;
    const Point2 q = at.apply(p);
    if (!inside(q, clip)) {
      sink.clipped = true;
      continue;
    }
    sink.text(rounded(q, clip), drawing.text(item), item.style);
  }
}

}  // namespace

Box bounds(const Drawing2& drawing) {
  const double inf = std::numeric_limits<double>::infinity();
  Box b{inf, inf, -inf, -inf};
  for (const auto& item : drawing.items()) {
    for (Point2 p : drawing.points(item)) {
      if (!finite(p)) continue;
      b.x0 = std::min(b.x0, p.x), b.x1 = std::max(b.x1, p.x);
      b.y0 = std::min(b.y0, p.y), b.y1 = std::max(b.y1, p.y);
    }
  }
  return b;
}

Placement fit(const Drawing2& drawing, const Box& box, double mark) {
  const bool marks =
      std::any_of(drawing.items().begin(), drawing.items().end(),
                  [](const auto& item) { return item.kind == Drawing2::Kind::mark; });
  if (!marks) mark = 0;
  Box b = bounds(drawing);
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

Placed place(const Drawing2& drawing, const Placement& at, const Box& clip,
             const Rendering& rendering) {
  Placed out;
  ListSink sink(out);
  place_into(drawing, at, clip, rendering, sink);
  out.clipped = sink.clipped;
  return out;
}

bool render(const Drawing2& drawing, const Placement& at, const Box& clip,
            const Rendering& rendering, Device& device) {
  DeviceSink sink(device);
  place_into(drawing, at, clip, rendering, sink);
  return sink.clipped;
}

}  // namespace igds
