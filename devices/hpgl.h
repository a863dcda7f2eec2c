// The HP-GL/1 encoder and the plot layout (docs/devices.md, "HP-GL plotter").
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "devices/device.h"
#include "devices/hpgl_plot.h"
#include "devices/plot_order.h"
#include "workspace/text_out.h"

namespace igds {

// A plotter model: its unit and its hard-clip limits per paper (plotter units, origin lower left).
struct PlotterModel {
  std::string_view name;
  double unit_mm;
  DevicePoint limits[4];  // by Paper: a4, a3, letter, b
  DevicePoint limit(Paper paper) const { return limits[static_cast<int>(paper)]; }
};

// HP 7475A (docs/devices.md, "HP-GL plotter").
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
// PlotStats. The pen starts at the origin; finish() puts it away and counts the travel back to
// the origin. The plot goes into `out` as it is made (a file being written, or a StringOut).
class HpglEncoder : public Device {
 public:
  HpglEncoder(const PlotterModel& model, bool absolute, TextOut& out);

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
  // The strokes of `order` (lines' points), each polyline from a pen-up move, in the style set:
  // the bytes of draw_polyline's for each in turn, a large plot's made on the cores.
  void draw_order(const PlotOrder& order, std::span<const Line> lines);
  // PU;SP0; at the end of the plot; the statistics count its bytes.
  void finish();
  const PlotStats& stats() const { return stats_; }

 private:
  void close_pd();
  // Polyline k of `order`, point by point.
  void draw_polyline(const PlotOrder& order, std::span<const Line> lines, std::size_t k);
  void coordinates(DevicePoint p);
  void relative_mode(bool on);
  char* room(std::size_t bytes) { return out_->room(bytes); }
  void put(std::string_view s) { out_->put(s); }
  void put(char c) { out_->put(c); }

  const PlotterModel& model_;
  bool absolute_;
  TextOut* out_;
  std::uint64_t start_;  // where the plot starts in out_
  PlotStats stats_;
  DevicePoint at_{0, 0};     // where the pen is (estimated after a label)
  bool at_exact_ = true;     // false after a label: its end is only estimated
  bool relative_ = false;    // PR in force on the plotter
  bool pd_open_ = false;     // a PD list is being written
  Style style_;              // the pen and line type in force
  double travel_units_ = 0;  // pen-up travel in plotter units
};

}  // namespace igds
