// PLOT: a picture on an HP-GL pen plotter (docs/devices.md, "HP-GL plotter"): the layout on the
// sheet, the stroke order, the statistics.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "devices/render.h"
#include "workspace/drawing/drawing.h"
#include "workspace/text_out.h"

namespace igds {

enum class Paper { a4, a3, letter, b };
std::optional<Paper> paper_named(std::string_view name);  // A4 A3 LETTER B, any case

struct PlotOptions {
  Paper paper = Paper::a4;
  bool absolute = false;  // PA polylines instead of PR: the same drawing, for checking
};

struct PlotStats {
  std::size_t vectors = 0;    // pen-down segments drawn
  std::size_t pen_lifts = 0;  // pen-up moves
  double pen_up_mm = 0;       // pen-up travel, including the legs from and back to the start
  std::size_t bytes = 0;
  bool clipped = false;    // something lay outside the hard-clip limits and was clipped
  bool texts_cut = false;  // a text of the drawing was cut at the caption's strip
};

struct Plot {
  std::string hpgl;  // one complete plot: IN;SP1; ... PU;SP0;
  PlotStats stats;
};

// The plot's margin on every side of the sheet and the gap between image and description.
inline constexpr double plot_margin_mm = 10, plot_gap_mm = 6;
// A 4013 point on the plot: 1024 of them across the tube's 210 mm.
inline constexpr double plot_point_mm = 0.2;

// Where a plot goes on the sheet, in plotter units: the drawing's placement, the first label
// line's baseline-left corner, the label's character advance and line spacing.
struct PlotLayout {
  Placement at;
  double mark = 0;
  DevicePoint text;
  double advance = 0, line = 0;
};

// The drawing in the hard-clip area of the paper less a margin, landscape, aspect kept, with the
// caption to its right, the two centred across the sheet.
PlotLayout plot_layout(const Picture& picture, const PlotOptions& options);

// The plot of `picture` placed by `layout`: clipped to the hard-clip limits, in plot order (pen
// by pen), the caption first as labels; into `out` as it is made (a file being written).
PlotStats plot_placed(const Picture& picture, const PlotLayout& layout, const PlotOptions& options,
                      TextOut& out);
Plot plot_placed(const Picture& picture, const PlotLayout& layout, const PlotOptions& options);

// The plot of `picture` laid out by plot_layout.
PlotStats plot_hpgl(const Picture& picture, const PlotOptions& options, TextOut& out);
Plot plot_hpgl(const Picture& picture, const PlotOptions& options);

// What PLOT says after a plot, e.g. `PLOT0001.HPGL: 1440 VECTORS, 12 PEN LIFTS, PEN-UP TRAVEL
// 143 MM, 11520 BYTES`, and the line it adds when something was clipped.
std::string plot_summary(std::string_view where, const PlotStats& stats);
inline constexpr std::string_view plot_clipped_notice =
    "PARTS OF THE IMAGE OUTSIDE THE PAPER WERE CLIPPED";
// And when a text of the drawing was cut, not to run into the caption or off the paper.
inline constexpr std::string_view plot_texts_cut_notice =
    "TEXTS OF THE IMAGE TOO LONG FOR THEIR ROOM WERE CUT";

}  // namespace igds
