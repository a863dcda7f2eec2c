// The HP-GL/1 encoder and the plot layout (spec hpgl.md).
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "devices/device.h"
#include "devices/plot.h"

namespace igds {

// A plotter model: its unit and its hard-clip limits per paper (plotter units, origin lower left).
struct PlotterModel {
  std::string_view name;
  double unit_mm;
  DevicePoint limits[4];  // by Paper: a4, a3, letter, b
  DevicePoint limit(Paper paper) const { return limits[static_cast<int>(paper)]; }
};

// HP 7475A (spec hpgl.md, Paper).
inline constexpr PlotterModel hp7475a{
    "7475A", 0.02488, {{11040, 7721}, {16158, 11040}, {10365, 7962}, {16640, 10365}}};

// Label characters (SI, in cm) and their spacing: HP-GL puts 1.5 widths between character
// origins and 2 heights between lines.
inline constexpr double label_width_cm = 0.2, label_height_cm = 0.3;
inline double label_advance(const PlotterModel& model) {
  return 1.5 * label_width_cm * 10 / model.unit_mm;
}

// A Device that writes HP-GL: pen-up moves and pen-down polylines, relative (PR) by default or
// absolute (PA), labels with LB, pens (SP) and line types (LT). Counts what it draws as
// PlotStats (bytes excepted). The pen starts at the origin; finish() puts it away and counts the
// travel back to the origin.
class HpglEncoder : public Device {
 public:
  HpglEncoder(const PlotterModel& model, bool absolute);

  void move(DevicePoint p) override;
  void draw(DevicePoint p) override;
  // An LB label at p (absolute move), ended by ETX; the next move is absolute again.
  void text(DevicePoint p, std::string_view line) override;
  // The 7475A takes one sheet at a time: nothing to send.
  void page() override {}
  // SP n for the pen (the 7475A has 6), LT for the dash: solid LT;, dashed LT2;, chain LT4;,
  // dotted LT1;. The weight is the pen's own.
  void style(const Style& style) override;
  // draw() to each point of `points` in turn (from the last to the first when `reversed`): the
  // bulk of a plot, without a call per point.
  void draw_run(std::span<const DevicePoint> points, bool reversed);
  // PU;SP0; at the end of the plot.
  void finish();
  // Room for about `vectors` more vectors, so that a large plot is not copied as it grows.
  void reserve(std::size_t vectors);

  std::string_view bytes() const { return {out_.data(), size_}; }
  std::string take_bytes() {  // the plot, without a copy
    out_.resize(size_);
    return std::move(out_);
  }
  const PlotStats& stats() const { return stats_; }

 private:
  void close_pd();
  void coordinates(DevicePoint p);
  void relative_mode(bool on);
  // Room for `bytes` more at out_[size_]: out_ is kept longer than what it holds.
  char* room(std::size_t bytes) {
    if (size_ + bytes > out_.size()) grow(bytes);
    return out_.data() + size_;
  }
  void grow(std::size_t bytes);
  void put(std::string_view s) {
    std::copy(s.begin(), s.end(), room(s.size()));
    size_ += s.size();
  }
  void put(char c) {
    *room(1) = c;
    ++size_;
  }

  const PlotterModel& model_;
  bool absolute_;
  std::string out_;  // the plot in its first size_ bytes
  std::size_t size_ = 0;
  PlotStats stats_;
  DevicePoint at_{0, 0};     // where the pen is (estimated after a label)
  bool at_exact_ = true;     // false after a label: its end is only estimated
  bool relative_ = false;    // PR in force on the plotter
  bool pd_open_ = false;     // a PD list is being written
  Style style_;              // the pen and line type in force
  double travel_units_ = 0;  // pen-up travel in plotter units
};

}  // namespace igds
