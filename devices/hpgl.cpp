#include "devices/hpgl.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace igds {

namespace {

double distance(DevicePoint a, DevicePoint b) {
  return std::hypot(double(a.x) - b.x, double(a.y) - b.y);
}

}  // namespace

HpglEncoder::HpglEncoder(const PlotterModel& model, bool absolute)
    : model_(model), absolute_(absolute) {
  out_ = fmt::format("IN;SP1;SI{},{};", label_width_cm, label_height_cm);
  // After IN the pen is somewhere near the origin: the first move is absolute.
  at_exact_ = false;
}

void HpglEncoder::relative_mode(bool on) {
  if (on == relative_) return;
  out_ += on ? "PR;" : "PA;";
  relative_ = on;
}

void HpglEncoder::coordinates(DevicePoint p) {
  // The commonest bytes of a plot: two integers by to_chars, appended at once.
  if (relative_) p = {p.x - at_.x, p.y - at_.y};
  char buffer[32];
  char* end = std::to_chars(buffer, buffer + 15, p.x).ptr;
  *end++ = ',';
  end = std::to_chars(end, buffer + sizeof buffer, p.y).ptr;
  out_.append(buffer, end);
}

void HpglEncoder::reserve(std::size_t vectors) {
  out_.reserve(out_.size() + 6 * vectors);
}

void HpglEncoder::close_pd() {
  if (!pd_open_) return;
  out_ += ';';
  pd_open_ = false;
}

void HpglEncoder::move(DevicePoint p) {
  if (at_exact_ && at_ == p) return;
  close_pd();
  // A position known only roughly (after IN or a label) is left by an absolute move.
  relative_mode(!absolute_ && at_exact_);
  out_ += "PU";
  coordinates(p);
  out_ += ';';
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
    out_ += "PD";
    pd_open_ = true;
  } else {
    out_ += ',';
  }
  coordinates(p);
  ++stats_.vectors;
  at_ = p;
}

void HpglEncoder::text(DevicePoint p, std::string_view line) {
  close_pd();
  if (!(at_exact_ && at_ == p)) {
    relative_mode(false);
    fmt::format_to(std::back_inserter(out_), "PU{},{};", p.x, p.y);
    travel_units_ += distance(at_, p);
    ++stats_.pen_lifts;
  }
  out_ += "LB";
  for (char c : line) out_ += (c >= 0x20 && c < 0x7F) ? c : '?';
  out_ += '\x03';
  // The pen ends after the last character: its place is only estimated.
  double width = label_advance(model_) * static_cast<double>(line.size());
  at_ = {p.x + static_cast<int>(std::lround(width)), p.y};
  at_exact_ = false;
}

void HpglEncoder::style(const Style& style) {
  if (style.pen != style_.pen) {
    close_pd();
    fmt::format_to(std::back_inserter(out_), "SP{};", std::clamp(style.pen, 1, 6));
  }
  if (style.dash != style_.dash) {
    close_pd();
    switch (style.dash) {
      case Dash::solid:
        out_ += "LT;";
        break;
      case Dash::dotted:
        out_ += "LT1;";
        break;
      case Dash::dashed:
        out_ += "LT2;";
        break;
      case Dash::chain:
        out_ += "LT4;";
        break;
    }
  }
  style_ = style;
}

void HpglEncoder::finish() {
  close_pd();
  out_ += "PU;SP0;";
  travel_units_ += distance(at_, {0, 0});
  stats_.pen_up_mm = travel_units_ * model_.unit_mm;
  stats_.bytes = out_.size();
}

}  // namespace igds
