// The HP-GL/1 encoder and the plot layout (spec hpgl.md).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "devices/device.h"
#include "devices/picture.h"
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

// The plot's margin on every side of the sheet, the gap between image and description, and
// the half side of an input point's square.
inline constexpr double plot_margin_mm = 10, plot_gap_mm = 6, plot_mark_mm = 0.6;

// A Device that writes HP-GL: pen-up moves and pen-down polylines, relative (PR) by default or
// absolute (PA), labels with LB. Counts what it draws as PlotStats (bytes excepted). The pen
// starts at the origin; finish() puts it away and counts the travel back to the origin.
class HpglEncoder : public Device {
 public:
  HpglEncoder(const PlotterModel& model, bool absolute);

  void move(DevicePoint p) override;
  void draw(DevicePoint p) override;
  // An LB label at p (absolute move), ended by ETX; the next move is absolute again.
  void text(DevicePoint p, std::string_view line) override;
  // The 7475A takes one sheet at a time: nothing to send.
  void page() override {}
  // PU;SP0; at the end of the plot.
  void finish();

  const std::string& bytes() const { return out_; }
  const PlotStats& stats() const { return stats_; }

 private:
  void close_pd();
  void coordinates(DevicePoint p);
  void relative_mode(bool on);

  const PlotterModel& model_;
  bool absolute_;
  std::string out_;
  PlotStats stats_;
  DevicePoint at_{0, 0};     // where the pen is (estimated after a label)
  bool at_exact_ = true;     // false after a label: its end is only estimated
  bool relative_ = false;    // PR in force on the plotter
  bool pd_open_ = false;     // a PD list is being written
  double travel_units_ = 0;  // pen-up travel in plotter units
};

// Where a plot goes on the sheet, in plotter units: the image's placement, the first label
// line's baseline-left corner, the label's character advance and line spacing.
struct PlotLayout {
  Placement at;
  double mark = 0;
  DevicePoint text;
  double advance = 0, line = 0;
};

// The image in the hard-clip area of the paper less a margin, landscape, aspect kept, with the
// description to its right, the two centred across the sheet.
PlotLayout plot_layout(const Picture& picture, const PlotOptions& options);

// The plot of `picture` placed by `layout`: clipped to the hard-clip limits, in plot order, the
// description first as labels.
Plot plot_placed(const Picture& picture, const PlotLayout& layout, const PlotOptions& options);

}  // namespace igds
