#include "devices/hpgl.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "workspace/numbers/decimal.h"

namespace igds {

namespace {

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
      out = relative ? put_pair(out, p.x - at.x, p.y - at.y) : put_pair(out, p.x, p.y);
      ++vectors;
      at = p;
    }
    out_->commit(out);
  }
  stats_.vectors += vectors;
  at_ = at;
}

void HpglEncoder::draw_order(const PlotOrder& order, std::span<const Line> lines) {
  for (std::size_t k = 0; k < order.size(); ++k)
    for (std::size_t s = order.starts[k]; s < order.starts[k + 1]; ++s) {
      const Stroke& stroke = order.strokes[s];
      if (s == order.starts[k]) move(stroke.begin(lines));
      draw_run(lines[stroke.line].subspan(stroke.first, stroke.last - stroke.first + 1),
               stroke.reversed);
    }
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
