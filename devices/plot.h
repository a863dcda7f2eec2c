// PLOT: an image on an HP-GL pen plotter (spec hpgl.md), and EXPORT SVG.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "workspace/state.h"

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
  bool clipped = false;  // something lay outside the hard-clip limits and was clipped
};

struct Plot {
  std::string hpgl;  // one complete plot: IN;SP1; ... PU;SP0;
  PlotStats stats;
};

Plot plot_hpgl(const Image& image, const PlotOptions& options);

// What PLOT says after a plot, e.g. `PLOT0001.HPGL: 1440 VECTORS, 12 PEN LIFTS, PEN-UP TRAVEL
// 143 MM, 11520 BYTES`, and the line it adds when something was clipped.
std::string plot_summary(std::string_view where, const PlotStats& stats);
inline constexpr std::string_view plot_clipped_notice =
    "PARTS OF THE IMAGE OUTSIDE THE PAPER WERE CLIPPED";

// A standalone SVG of the image: viewBox in device units, polylines, description as text.
std::string svg_of(const Image& image);

}  // namespace igds
