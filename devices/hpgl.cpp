#include "devices/hpgl.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "workspace/numbers/decimal.h"

namespace igds {

namespace {

constexpr std::size_t none = static_cast<std::size_t>(-1);

// The pair of a vector to p from `at`: p's coordinates, or in relative mode their differences.
char* put_vector(char* out, bool relative, DevicePoint p, DevicePoint at) {
  return relative ? put_pair(out, p.x - at.x, p.y - at.y) : put_pair(out, p.x, p.y);
}

double distance(DevicePoint a, DevicePoint b) {
  return std::hypot(double(a.x) - b.x, double(a.y) - b.y);
}

}  // namespace

HpglEncoder::HpglEncoder(const PlotterModel& model, bool absolute, TextOut& out)
    : model_(model), absolute_(absolute), out_(&out), start_(out.offset()) {
  put(fmt::format("IN;SP1;SI{},{};", label_width_cm, label_height_cm));
  // After IN the pen is somewhere near the origin: the first move is absolute.
  at_exact_ = false;
}

void HpglEncoder::relative_mode(bool on) {
  if (on == relative_) return;
  put(on ? "PR;" : "PA;");
  relative_ = on;
}

void HpglEncoder::coordinates(DevicePoint p) {
  // The commonest bytes of a plot: two integers, written in place.
  if (relative_) p = {p.x - at_.x, p.y - at_.y};
  out_->commit(put_pair(room(24), p.x, p.y));
}

void HpglEncoder::close_pd() {
  if (!pd_open_) return;
  put(';');
  pd_open_ = false;
}

void HpglEncoder::move(DevicePoint p) {
  if (at_exact_ && at_ == p) return;
  close_pd();
  // A position known only roughly (after IN or a label) is left by an absolute move.
  relative_mode(!absolute_ && at_exact_);
  put("PU");
  coordinates(p);
  put(';');
  travel_units_ += distance(at_, p);
  ++stats_.pen_lifts;
  at_ = p;
  at_exact_ = true;
}

void HpglEncoder::draw(DevicePoint p) {
  if (!at_exact_) {
    move(p);
    return;
  }
  if (at_ == p) return;
  if (!pd_open_) {
    relative_mode(!absolute_);
    put("PD");
    pd_open_ = true;
  } else {
    put(',');
  }
  coordinates(p);
  ++stats_.vectors;
  at_ = p;
}

void HpglEncoder::draw_run(std::span<const DevicePoint> points, bool reversed) {
  const std::size_t n = points.size();
  std::size_t i = 0;
  // Until the pen is down at an exact place, point by point.
  for (; i < n && !(at_exact_ && pd_open_ && relative_ == !absolute_); ++i)
    draw(points[reversed ? n - 1 - i : i]);
  if (i == n) return;
  // The rest with the pen down: at most 24 bytes a point, written through locals (a store
  // through a char pointer would otherwise make every member be read again), as many points at
  // a time as the output has room for.
  DevicePoint at = at_;
  std::size_t vectors = 0;
  const bool relative = relative_;
  constexpr std::size_t most = TextOut::max_room / 24;
  while (i < n) {
    char* out = room(24 * std::min(n - i, most));
    for (const std::size_t end = std::min(n, i + most); i < end; ++i) {
      const DevicePoint p = points[reversed ? n - 1 - i : i];
      if (at == p) continue;
      *out++ = ',';
      out = put_vector(out, relative, p, at);
      ++vectors;
      at = p;
    }
    out_->commit(out);
  }
  stats_.vectors += vectors;
  at_ = at;
}

void HpglEncoder::draw_polyline(const PlotOrder& order, std::span<const Line> lines,
                                std::size_t k) {
  for (std::size_t s = order.starts[k]; s < order.starts[k + 1]; ++s) {
    const Stroke& stroke = order.strokes[s];
    if (s == order.starts[k]) move(stroke.begin(lines));
    draw_run(lines[stroke.line].subspan(stroke.first, stroke.last - stroke.first + 1),
             stroke.reversed);
  }
}

void HpglEncoder::draw_order(const PlotOrder& order, std::span<const Line> lines) {
  std::size_t k = 0;
  // Until the pen is at an exact place in the plot's mode (after IN or a label it is not),
  // polyline by polyline.
  for (; k < order.size() && !(at_exact_ && relative_ == !absolute_); ++k)
    draw_polyline(order, lines, k);
  const std::size_t from = k;
  if (from == order.size()) return;
  // From here a polyline's bytes depend only on where the pen is and whether a PD list is open
  // when it starts. Both are found polyline by polyline, in order, with the pen-up moves'
  // statistics; the points are then written on the cores (put_each) in chunks, each needing only
  // the point before it: the same bytes as draw_polyline's.
  auto point = [&](std::size_t s, std::size_t i) {
    const Stroke& t = order.strokes[s];
    return lines[t.line][t.reversed ? t.last - i : t.first + i];
  };
  struct Opening {
    DevicePoint before;      // where the pen was
    bool lift = false;       // a pen-up move to the polyline ...
    bool close = false;      // ... after a ';' that ends a PD list
    bool pd = false;         // its first vector starts a PD list
    std::size_t stroke = 0;  // its first vector's end: point `at` of stroke `stroke`
    std::size_t at = 0;
  };
  std::vector<Opening> openings(order.size() - from);
  for (; k < order.size(); ++k) {
    if (order.starts[k] == order.starts[k + 1]) continue;
    const DevicePoint begin = order.strokes[order.starts[k]].begin(lines);
    Opening& o = openings[k - from];
    o.before = at_;
    o.lift = at_ != begin;
    o.close = o.lift && pd_open_;
    if (o.lift) {
      travel_units_ += distance(at_, begin);
      ++stats_.pen_lifts;
      pd_open_ = false;
    }
    o.pd = !pd_open_;
    // The first point away from the polyline's first (when every point is there, a stroke of the
    // next polyline: none of this one's).
    o.stroke = order.starts[k + 1];
    for (std::size_t s = order.starts[k]; s < order.starts[k + 1] && !pd_open_; ++s)
      for (std::size_t i = 0; i <= order.strokes[s].last - order.strokes[s].first; ++i)
        if (point(s, i) != begin) {
          o.stroke = s, o.at = i, pd_open_ = true;
          break;
        }
    at_ = order.strokes[order.starts[k + 1] - 1].end(lines);
  }
  // The strokes' points in chunks of at most 160: the stroke's points first .. last - 1.
  struct Chunk {
    std::size_t polyline, stroke, first, last;
  };
  constexpr std::size_t chunk_points = 160;
  std::vector<Chunk> chunks;
  for (k = from; k < order.size(); ++k)
    for (std::size_t s = order.starts[k]; s < order.starts[k + 1]; ++s) {
      const std::size_t points = order.strokes[s].last - order.strokes[s].first + 1;
      for (std::size_t i = 0; i < points; i += chunk_points)
        chunks.push_back({k - from, s, i, std::min(points, i + chunk_points)});
    }
  std::vector<std::size_t> vectors(chunks.size());
  const bool relative = relative_;
  // A move's ";PU", pair and ";", then a separator (or PD) and a pair a point: 24 bytes.
  put_each(*out_, chunks.size(), 28 + 1 + 24 * chunk_points, [&](char* w, std::size_t c) {
    const Chunk& chunk = chunks[c];
    const Opening& o = openings[chunk.polyline];
    const std::size_t s = chunk.stroke;
    DevicePoint at;
    if (chunk.first > 0) {
      at = point(s, chunk.first - 1);
    } else if (s == order.starts[from + chunk.polyline]) {
      at = order.strokes[s].begin(lines);
      if (o.lift) {
        if (o.close) *w++ = ';';
        *w++ = 'P', *w++ = 'U';
        w = put_vector(w, relative, at, o.before);
        *w++ = ';';
      }
    } else {
      at = order.strokes[s - 1].end(lines);
    }
    const std::size_t pd_at = o.pd && o.stroke == s ? o.at : none;
    std::size_t drawn = 0;
    // The stroke's points and the mode through locals: a store through `w` (a char pointer)
    // could change anything as far as the compiler knows, and the stroke (and the mode, captured
    // by reference) would be read again at every point.
    const Stroke& stroke = order.strokes[s];
    const bool reversed = stroke.reversed, by_difference = relative;
    const DevicePoint* const base =
        lines[stroke.line].data() + (reversed ? stroke.last : stroke.first);
    const std::ptrdiff_t step = reversed ? -1 : 1;
    for (std::size_t i = chunk.first; i < chunk.last; ++i) {
      const DevicePoint p = base[step * static_cast<std::ptrdiff_t>(i)];
      if (p == at) continue;
      if (i == pd_at)
        *w++ = 'P', *w++ = 'D';
      else
        *w++ = ',';
      w = put_vector(w, by_difference, p, at);
      ++drawn;
      at = p;
    }
    vectors[c] = drawn;
    return w;
  });
  for (std::size_t v : vectors) stats_.vectors += v;
}

void HpglEncoder::text(DevicePoint p, std::string_view line) {
  close_pd();
  if (!(at_exact_ && at_ == p)) {
    relative_mode(false);
    put(fmt::format("PU{},{};", p.x, p.y));
    travel_units_ += distance(at_, p);
    ++stats_.pen_lifts;
  }
  put("LB");
  for (char c : line) put((c >= 0x20 && c < 0x7F) ? c : '?');
  put('\x03');
  // The pen ends after the last character: its place is only estimated.
  double width = label_advance(model_) * static_cast<double>(line.size());
  at_ = {p.x + static_cast<int>(std::lround(width)), p.y};
  at_exact_ = false;
}

void HpglEncoder::style(const Style& style) {
  if (style.pen != style_.pen) {
    close_pd();
    put(fmt::format("SP{};", std::clamp(style.pen, 1, 6)));
  }
  if (style.dash != style_.dash) {
    close_pd();
    switch (style.dash) {
      case Dash::solid:
        put("LT;");
        break;
      case Dash::dotted:
        put("LT1;");
        break;
      case Dash::dashed:
        put("LT2;");
        break;
      case Dash::chain:
        put("LT4;");
        break;
    }
  }
  style_ = style;
}

void HpglEncoder::finish() {
  close_pd();
  put("PU;SP0;");
  travel_units_ += distance(at_, {0, 0});
  stats_.pen_up_mm = travel_units_ * model_.unit_mm;
  stats_.bytes = static_cast<std::size_t>(out_->offset() - start_);
}

}  // namespace igds
