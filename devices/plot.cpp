#include "devices/plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "devices/hpgl.h"
#include "devices/picture.h"
#include "devices/plot_order.h"

namespace igds {

std::optional<Paper> paper_named(std::string_view name) {
  std::string up;
  for (char c : name) up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (up == "A4") return Paper::a4;
  if (up == "A3") return Paper::a3;
  if (up == "LETTER") return Paper::letter;
  if (up == "B") return Paper::b;
  return std::nullopt;
}

PlotLayout plot_layout(const Picture& picture, const PlotOptions& options) {
  const PlotterModel& model = hp7475a;
  DevicePoint lim = model.limit(options.paper);
  const double per_mm = 1 / model.unit_mm;
  PlotLayout l;
  l.mark = plot_mark_mm * per_mm;
  l.advance = label_advance(model);
  l.line = 2 * label_height_cm * 10 * per_mm;
  std::size_t columns = 0;
  for (const auto& d : picture.description) columns = std::max(columns, d.size());
  const double margin = plot_margin_mm * per_mm, gap = plot_gap_mm * per_mm;
  const double strip = static_cast<double>(columns) * l.advance;
  Box room{margin, margin, lim.x - margin - gap - strip, lim.y - margin};
  l.at = fit(picture, room, l.mark);
  // The image and its description, side by side, centred across the sheet.
  Box b = bounds(picture);
  double left = room.x0, right = room.x0, top = room.y1;
  if (b.x0 <= b.x1) {
    double m = picture.marks.empty() ? 0 : l.mark;
    left = l.at.dx + l.at.scale * b.x0 - m;
    right = l.at.dx + l.at.scale * b.x1 + m;
    top = l.at.dy + l.at.scale * b.y1 + m;
  }
  double shift = (lim.x - (right - left + gap + strip)) / 2 - left;
  l.at.dx += shift;
  l.text = {static_cast<int>(std::lround(right + shift + gap)),
            static_cast<int>(std::lround(top - label_height_cm * 10 * per_mm))};
  return l;
}

Plot plot_placed(const Picture& picture, const PlotLayout& layout, const PlotOptions& options) {
  const PlotterModel& model = hp7475a;
  DevicePoint lim = model.limit(options.paper);
  Placed placed = place(picture, layout.at, layout.mark, {0, 0, double(lim.x), double(lim.y)});
  HpglEncoder hpgl(model, options.absolute);
  // The description first, where the pen starts from the origin; a line that would not fit on
  // the sheet is left out (and said, as clipping).
  bool clipped = placed.clipped;
  DevicePoint t = layout.text, pen{0, 0};
  for (const auto& line : picture.description) {
    int end =
        t.x + static_cast<int>(std::lround(layout.advance * static_cast<double>(line.size())));
    int cap = static_cast<int>(std::lround(label_height_cm * 10 / model.unit_mm));
    if (t.x >= 0 && t.y >= 0 && end <= lim.x && t.y + cap <= lim.y) {
      hpgl.text(t, line);
      pen = {end, t.y};
    } else {
      clipped = true;
    }
    t.y -= static_cast<int>(std::lround(layout.line));
  }
  const DevicePoint origin{0, 0};
  PathList ordered;
  plot_order(placed.paths, pen, ordered);
  // Never more pen-up travel than the drawing order.
  if (pen_up_travel(ordered, pen, origin) > pen_up_travel(placed.paths, pen, origin))
    for (const auto& path : placed.paths) draw_path(hpgl, path);
  else
    for (std::size_t k = 0; k < ordered.size(); ++k) hpgl.polyline(ordered[k]);
  hpgl.finish();
  Plot plot{hpgl.bytes(), hpgl.stats()};
  plot.stats.clipped = clipped;
  return plot;
}

std::string plot_summary(std::string_view where, const PlotStats& stats) {
  return fmt::format("{}: {} VECTORS, {} PEN LIFTS, PEN-UP TRAVEL {:.0f} MM, {} BYTES", where,
                     stats.vectors, stats.pen_lifts, stats.pen_up_mm, stats.bytes);
}

Plot plot_hpgl(const Image& image, const PlotOptions& options) {
  Picture picture = picture_of(image);
  return plot_placed(picture, plot_layout(picture, options), options);
}

}  // namespace igds
