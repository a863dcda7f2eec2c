#include "devices/render.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>

#include "workspace/drawing/flatten.h"
#include "workspace/kernels/memory.h"
#include "workspace/kernels/parallel.h"

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

// Where placed paths go: a list (the plotter reorders them) or a device at once. A path is
// written into the buffer open() returns, from its size at that moment, and handed over by
// close(), which drops it when it has fewer than two points.
class Sink {
 public:
  virtual ~Sink() = default;
  virtual DevicePath& open() = 0;
  virtual void close(std::size_t start, const Style& style) = 0;
  virtual void text(DevicePoint at, const std::string& text, const Style& style) = 0;
  bool clipped = false;
  bool texts_cut = false;
};

class ListSink final : public Sink {
 public:
  ListSink(Placed& out, PathList& list) : out_(out), list_(list) {}
  DevicePath& open() override { return list_.points; }
  void close(std::size_t start, const Style& style) override {
    auto& points = list_.points;
    if (points.size() - start < 2) {
      points.resize(start);
      return;
    }
    list_.starts.push_back(points.size());
    out_.styles.push_back(style);
    out_.box.add(std::span<const DevicePoint>(points).subspan(start));
  }
  void text(DevicePoint at, const std::string& text, const Style& style) override {
    out_.texts.push_back({at, text, style});
  }

 private:
  Placed& out_;
  PathList& list_;
};

class DeviceSink final : public Sink {
 public:
  explicit DeviceSink(Device& device) : device_(device) {}
  DevicePath& open() override {
    piece_.clear();
    return piece_;
  }
  void close(std::size_t start, const Style& style) override {
    if (piece_.size() - start >= 2) {
      device_.style(style);
      device_.polyline(std::span<const DevicePoint>(piece_).subspan(start));
    }
    piece_.clear();
  }
  void text(DevicePoint at, const std::string& text, const Style& style) override {
    device_.style(style);
    device_.text(at, text);
  }

 private:
  Device& device_;
  DevicePath piece_;
};

// Clips one polyline in device units and hands its visible pieces to the sink.
void place_line(const std::vector<Point2>& line, const Box& clip, const Style& style, Sink& sink) {
  DevicePath* piece = &sink.open();
  std::size_t start = piece->size();
  auto add = [&](DevicePoint p) {
    if (piece->size() == start || !(piece->back() == p)) piece->push_back(p);
  };
  if (std::all_of(line.begin(), line.end(), [&](Point2 p) { return inside(p, clip); })) {
    // Nothing to clip: rounding alone.
    for (Point2 p : line) add({nearest(p.x), nearest(p.y)});
    sink.close(start, style);
    return;
  }
  auto flush = [&] {
    sink.close(start, style);
    piece = &sink.open();
    start = piece->size();
  };
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    Point2 a = line[i], b = line[i + 1];
    if (!inside(a, clip) || !inside(b, clip)) sink.clipped = true;
    if (!clip_segment(a, b, clip)) {
      flush();
      continue;
    }
    DevicePoint da = rounded(a, clip);
    if (piece->size() > start && !(piece->back() == da)) flush();
    add(da);
    add(rounded(b, clip));
  }
  if (line.size() == 1 && !inside(line[0], clip)) sink.clipped = true;
  sink.close(start, style);
}

// A placement and a clip box with x and y side by side, as one instruction takes two doubles: a
// point is placed, checked and rounded both coordinates at once.
struct PlainPlacement {
  using Pair = double __attribute__((vector_size(16)));
  using Ints = int __attribute__((vector_size(8)));
  using Mask = long long __attribute__((vector_size(16)));
  Pair scale, shift, low, high;
  PlainPlacement(const Placement& at, const Box& clip)
      : scale{at.scale, at.scale},
        shift{at.dx, at.dy},
        low{clip.x0, clip.y0},
        high{clip.x1, clip.y1} {}

  // The point at p[0], p[1] placed, rounded and added to the `size` points of `line` unless it
  // is the last of them again; false when it is not finite or falls outside the clip box.
  bool add(const double* p, DevicePoint* line, std::size_t& size) const {
    Pair v;
    std::memcpy(&v, p, sizeof v);
    const Pair q = shift + scale * v;
    // Also false for a NaN.
    const Mask inside = (q >= low) & (q <= high);
    if (!(inside[0] & inside[1])) return false;
    // To the nearest unit, halves up: floor(q + 0.5), truncated and then corrected below zero.
    const Pair h = q + 0.5;
    Ints i = __builtin_convertvector(h, Ints);
    i += __builtin_convertvector(h < __builtin_convertvector(i, Pair), Ints);
    const DevicePoint r{i[0], i[1]};
    if (size == 0 || !(line[size - 1] == r)) line[size++] = r;
    return true;
  }
};

// An open polyline whose points are all finite and fall inside `clip` once placed, rounded
// straight into the sink (the usual case, and most of the points of a large drawing); false,
// with nothing handed over, when a point is not finite or falls outside.
bool place_plain(PointsView<Point2, const double> points, const Placement& at, const Box& clip,
                 const Style& style, Sink& sink) {
  const double* base = points.data();
  const std::size_t stride = points.stride(), n = points.size();
  DevicePath& out = sink.open();
  const std::size_t start = out.size();
  out.resize(start + n);
  DevicePoint* const first = out.data() + start;
  // Points far apart (a stringer of a grid: a row's length between them) are asked for early,
  // many at once: the processor's own prefetching does not follow such strides.
  const std::size_t ahead = stride > 8 ? 16 : 0;
  std::size_t size = 0;
  const PlainPlacement plain(at, clip);
  for (std::size_t i = 0; i < n; ++i) {
    if (ahead && i + ahead < n) __builtin_prefetch(base + (i + ahead) * stride);
    if (!plain.add(base + i * stride, first, size)) {
      out.resize(start);
      return false;
    }
  }
  out.resize(start + size);
  sink.close(start, style);
  return true;
}

// Side by side polylines of a shared pool: as many as `block` items from `items[0]` that each
// take `count` points `stride` doubles apart, starting one point after the one before (the
// stringers of a grid). The number of such items.
std::size_t side_by_side(std::span<const Drawing2::Item> items, std::size_t block) {
  const auto& a = items[0];
  constexpr std::size_t n = Point2::dimension;
  if (a.kind != Drawing2::Kind::polyline || a.closed || a.pool == 0 || a.stride <= n) return 0;
  std::size_t k = 1;
  while (k < items.size() && k < block) {
    const auto& b = items[k];
    if (b.kind != a.kind || b.closed || b.pool != a.pool || b.stride != a.stride ||
        b.count != a.count || b.first != a.first + k * n)
      break;
    ++k;
  }
  return k;
}

// place_plain for `items` side by side (side_by_side), a row of points of them all at a time:
// each row is read as the few cache lines it lies in, where one stringer alone would read a line
// for each of its points. False, with nothing handed over, when place_plain would refuse one.
bool place_side_by_side(const Drawing2& drawing, std::span<const Drawing2::Item> items,
                        const Placement& at, const Box& clip, Sink& sink,
                        std::vector<DevicePoint>& block, std::vector<std::size_t>& sizes) {
  const std::size_t m = items.size(), count = items[0].count, stride = items[0].stride;
  constexpr std::size_t n = Point2::dimension;
  const double* base = drawing.points(items[0]).data();
  block.resize(m * count);
  sizes.assign(m, 0);
  // Rows a row's length apart are asked for some rows ahead, each of its cache lines: the
  // processor's own prefetching does not follow such strides.
  constexpr std::size_t ahead = 8, line = 64 / sizeof(double);
  const PlainPlacement plain(at, clip);
  for (std::size_t i = 0; i < count; ++i) {
    const double* row = base + i * stride;
    if (i + ahead < count)
      for (std::size_t d = 0; d < m * n; d += line) __builtin_prefetch(row + ahead * stride + d);
    for (std::size_t j = 0; j < m; ++j)
      if (!plain.add(row + j * n, block.data() + j * count, sizes[j])) return false;
  }
  for (std::size_t j = 0; j < m; ++j) {
    DevicePath& out = sink.open();
    const std::size_t start = out.size();
    out.insert(out.end(), block.begin() + long(j * count),
               block.begin() + long(j * count + sizes[j]));
    sink.close(start, items[j].style);
  }
  return true;
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

// The lines, curves and marks of items [from, to) placed into the sink, in item order.
void place_lines(const Drawing2& drawing, std::size_t from, std::size_t to, const Placement& at,
                 const Box& clip, const Rendering& rendering, Sink& sink) {
  std::vector<std::vector<Point2>> lines;
  std::vector<Point2> flat;
  std::vector<DevicePoint> block;
  std::vector<std::size_t> sizes;
  const double tolerance = rendering.tolerance * rendering.point;
  const auto items = drawing.items().first(to);
  // The items side by side not yet placed as a block: until `plain_until`, one by one.
  std::size_t plain_until = from;
  for (std::size_t k = from; k < to; ++k) {
    const auto& item = items[k];
    if (k >= plain_until) {
      const std::size_t m = side_by_side(items.subspan(k), 16);
      if (m > 1 && place_side_by_side(drawing, items.subspan(k, m), at, clip, sink, block, sizes)) {
        k += m - 1;
        continue;
      }
      plain_until = k + std::max<std::size_t>(m, 1);
    }
    lines.clear();
    const auto points = drawing.points(item);
    switch (item.kind) {
      case Drawing2::Kind::polyline:
        if (!item.closed && place_plain(points, at, clip, item.style, sink)) break;
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
    for (const auto& line : lines) place_line(line, clip, item.style, sink);
  }
}

// The texts of the drawing placed into the sink (after every line), each cut to its room.
void place_texts(const Drawing2& drawing, const Placement& at, const Box& clip,
                 const Rendering& rendering, Sink& sink) {
  std::string cut;
  for (const auto& item : drawing.items()) {
    if (item.kind != Drawing2::Kind::text) continue;
    const Point2 p = drawing.points(item)[0];
    if (!finite(p)) continue;
    const Point2 q = at.apply(p);
    if (!inside(q, clip)) {
      sink.clipped = true;
      continue;
    }
    const DevicePoint where = rounded(q, clip);
    const std::string& text = drawing.text(item);
    if (rendering.char_width > 0) {
      const double room = std::floor((rendering.text_right - where.x) / rendering.char_width);
      if (room < static_cast<double>(text.size())) {
        sink.texts_cut = true;
        if (room < 1) continue;
        cut.assign(text, 0, static_cast<std::size_t>(room));
        sink.text(where, cut, item.style);
        continue;
      }
    }
    sink.text(where, text, item.style);
  }
}

// The box of points read `stride` doubles apart, the points with a coordinate that is not finite
// left out; with no branch a point, in two chains.
struct Extent {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  double low[4] = {inf, inf, inf, inf}, high[4] = {-inf, -inf, -inf, -inf};

  void add(const double* p, std::size_t stride, std::size_t count) {
    std::size_t i = 0;
    for (; i + 2 <= count; i += 2) {
      take(0, p + i * stride);
      take(2, p + (i + 1) * stride);
    }
    if (i < count) take(0, p + i * stride);
  }
  Box box() const {
    return {std::min(low[0], low[2]), std::min(low[1], low[3]), std::max(high[0], high[2]),
            std::max(high[1], high[3])};
  }

 private:
  void take(int c, const double* p) {
    constexpr double most = std::numeric_limits<double>::max();
    const bool finite = std::abs(p[0]) <= most && std::abs(p[1]) <= most;
    low[c] = std::min(low[c], finite ? p[0] : inf);
    low[c + 1] = std::min(low[c + 1], finite ? p[1] : inf);
    high[c] = std::max(high[c], finite ? p[0] : -inf);
    high[c + 1] = std::max(high[c + 1], finite ? p[1] : -inf);
  }
};

}  // namespace

Box bounds(const Drawing2& drawing) {
  // An item whose points lie far apart in a shared pool (a stringer of a grid) is not read when
  // items of consecutive points (the curves) cover its whole range already: reading a point per
  // cache line would cost more than everything else here.
  struct Run {
    std::uint32_t pool;
    std::size_t from, to;  // in doubles
  };
  constexpr std::size_t n = Point2::dimension;
  std::vector<Run> runs;
  for (const auto& item : drawing.items())
    if (item.pool != 0 && item.stride == n && item.count > 0)
      runs.push_back({item.pool, item.first, item.first + n * item.count});
  const auto before = [](const Run& a, const Run& b) {
    return a.pool != b.pool ? a.pool < b.pool : a.from < b.from;
  };
  std::sort(runs.begin(), runs.end(), before);
  std::vector<Run> merged;
  for (const Run& r : runs)
    if (!merged.empty() && merged.back().pool == r.pool && r.from <= merged.back().to)
      merged.back().to = std::max(merged.back().to, r.to);
    else
      merged.push_back(r);
  auto covered = [&](const Drawing2::Item& item) {
    const std::size_t last = item.first + item.stride * (item.count - 1) + n;
    auto at = std::upper_bound(merged.begin(), merged.end(), Run{item.pool, item.first, 0}, before);
    if (at == merged.begin()) return false;
    --at;
    return at->pool == item.pool && at->from <= item.first && last <= at->to;
  };

  // A pool whose items of consecutive points cover all of it, shared with its box (an image whose
  // box was found as its points were made or checked): that box, and none of the pool's items
  // read.
  const double inf = std::numeric_limits<double>::infinity();
  Box b{inf, inf, -inf, -inf};
  std::vector<std::uint32_t> known;
  for (const Run& r : merged) {
    const auto& extent = drawing.pool_extent(r.pool);
    if (!extent || r.from != 0 || r.to < drawing.pool_size(r.pool)) continue;
    known.push_back(r.pool);
    const auto& e = *extent;
    b = {std::min(b.x0, e[0]), std::min(b.y0, e[1]), std::max(b.x1, e[2]), std::max(b.y1, e[3])};
  }
  auto is_known = [&](std::uint32_t pool) {
    return pool != 0 && std::find(known.begin(), known.end(), pool) != known.end();
  };

  // The points to read, split between as many threads as pay (a grid's are tens of megabytes).
  std::vector<std::pair<std::size_t, std::size_t>> read;  // item, its points before
  std::size_t points = 0;
  const auto items = drawing.items();
  for (std::size_t k = 0; k < items.size(); ++k) {
    const auto& item = items[k];
    if (item.count == 0 || is_known(item.pool) ||
        (item.pool != 0 && item.stride != n && covered(item)))
      continue;
    read.push_back({k, points});
    points += drawing.points(item).size();
  }
  if (points == 0) return b;
  const unsigned threads = threads_for(2 * points);
  std::vector<Box> parts(threads);
  parallel_for(threads, threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t t = first; t < last; ++t) {
      const std::size_t from = points * t / threads, to = points * (t + 1) / threads;
      Extent e;  // here, not in parts: the threads' boxes share a cache line
      auto r = std::upper_bound(read.begin(), read.end(), from,
                                [](std::size_t p, const auto& item) { return p < item.second; });
      for (--r; r != read.end() && r->second < to; ++r) {
        const auto these = drawing.points(items[r->first]);
        const std::size_t begin = std::max(from, r->second) - r->second;
        const std::size_t end = std::min(to - r->second, these.size());
        e.add(these.data() + begin * these.stride(), these.stride(), end - begin);
      }
      parts[t] = e.box();
    }
  });
  for (const Box& p : parts)
    b = {std::min(b.x0, p.x0), std::min(b.y0, p.y0), std::max(b.x1, p.x1), std::max(b.y1, p.y1)};
  return b;
}

bool has_marks(const Drawing2& drawing) {
  return std::any_of(drawing.items().begin(), drawing.items().end(),
                     [](const auto& item) { return item.kind == Drawing2::Kind::mark; });
}

Placement fit(const Drawing2& drawing, const Box& box, double mark) {
  return fit(bounds(drawing), has_marks(drawing), box, mark);
}

Placement fit(const Box& b, bool marks, const Box& box, double mark) {
  if (!marks) mark = 0;
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

// The number of points of the polylines of items [0, k) for each k, a point read a row apart
// from the one before (a stringer's) counted `apart` times and any other `near` times.
std::vector<std::size_t> polyline_points(const Drawing2& drawing, std::size_t near = 1,
                                         std::size_t apart = 1) {
  const auto items = drawing.items();
  std::vector<std::size_t> before(items.size() + 1, 0);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const auto& item = items[k];
    const std::size_t weight = item.stride > Point2::dimension ? apart : near;
    before[k + 1] =
        before[k] +
        (item.kind == Drawing2::Kind::polyline ? (item.count + (item.closed ? 1 : 0)) * weight : 0);
  }
  return before;
}

// The number of threads worth placing `points` on.
unsigned placing_threads(std::size_t points) {
  return std::min(threads_for(2 * points), 2u);
}

}  // namespace

Placed place(const Drawing2& drawing, const Placement& at, const Box& clip,
             const Rendering& rendering) {
  const std::vector<std::size_t> before = polyline_points(drawing);
  const std::size_t items = drawing.size(), points = before.back();
  // A large drawing in two parts that take about as long, placed at once on two threads into
  // lists of their own, the second part's paths after the first's.
  const unsigned parts = placing_threads(points);
  std::size_t cut = items;
  if (parts == 2) {
    // A stringer's point takes about a third longer to place than a curve's: 4 to 3.
    const std::vector<std::size_t> cost = polyline_points(drawing, 3, 4);
    cut = static_cast<std::size_t>(std::lower_bound(cost.begin(), cost.end(), cost.back() / 2) -
                                   cost.begin());
  }
  Placed out, second;
  out.paths.parts.resize(parts);
  in_parallel(parts, [&](unsigned part) {
    Placed& to = part == 0 ? out : second;
    PathList& list = out.paths.parts[part];
    const std::size_t from = part == 0 ? 0 : cut, until = part == 0 ? cut : items;
    // Room for every polyline point of the part at once: a large drawing's list is not copied as
    // it grows.
    reserve_large(list.points, before[until] - before[from]);
    ListSink sink(to, list);
    place_lines(drawing, from, until, at, clip, rendering, sink);
    to.clipped = sink.clipped;
  });
  out.styles.insert(out.styles.end(), second.styles.begin(), second.styles.end());
  out.box.add(second.box);
  ListSink sink(out, out.paths.parts.back());  // texts only: no path is added
  sink.clipped = out.clipped || second.clipped;
  place_texts(drawing, at, clip, rendering, sink);
  out.clipped = sink.clipped;
  out.texts_cut = sink.texts_cut;
  return out;
}

bool render(const Drawing2& drawing, const Placement& at, const Box& clip,
            const Rendering& rendering, Device& device, bool* texts_cut) {
  if (placing_threads(polyline_points(drawing).back()) > 1) {
    // Placed on two threads first, then drawn as the sink below draws.
    const Placed placed = place(drawing, at, clip, rendering);
    device.paths(placed.paths, placed.styles);
    for (const auto& t : placed.texts) {
      device.style(t.style);
      device.text(t.at, t.text);
    }
    if (texts_cut) *texts_cut = placed.texts_cut;
    return placed.clipped;
  }
  DeviceSink sink(device);
  place_lines(drawing, 0, drawing.size(), at, clip, rendering, sink);
  place_texts(drawing, at, clip, rendering, sink);
  if (texts_cut) *texts_cut = sink.texts_cut;
  return sink.clipped;
}

}  // namespace igds
