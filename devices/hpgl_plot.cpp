#include "devices/hpgl_plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "devices/hpgl.h"
#include "devices/layout.h"
#include "devices/plot_order.h"
#include "devices/render.h"

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
  l.mark = 3 * plot_point_mm * per_mm;
  l.advance = label_advance(model);
  l.line = 2 * label_height_cm * 10 * per_mm;
  std::size_t columns = 0;
  for (const auto& d : picture.caption) columns = std::max(columns, d.size());
  const double margin = plot_margin_mm * per_mm, gap = plot_gap_mm * per_mm;
  const double strip = static_cast<double>(columns) * l.advance;
  Box room{margin, margin, lim.x - margin - gap - strip, lim.y - margin};
  const Box b = bounds(picture.drawing);
  const bool marks = has_marks(picture.drawing);
  l.at = fit(b, marks, room, l.mark);
  // The drawing and its caption, side by side, centred across the sheet.
  double left = room.x0, right = room.x0, top = room.y1;
  if (b.x0 <= b.x1) {
    double m = marks ? l.mark : 0;
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

PlotStats plot_placed(const Picture& picture, const PlotLayout& layout, const PlotOptions& options,
                      TextOut& out) {
  const PlotterModel& model = hp7475a;
  DevicePoint lim = model.limit(options.paper);
  // A text never runs into the caption's strip, which lies inside the paper.
  const Rendering rendering{.point = plot_point_mm / model.unit_mm,
                            .char_width = layout.advance,
                            .text_right = layout.text.x - layout.advance / 2};
  const Placed placed =
      place(picture.drawing, layout.at, {0, 0, double(lim.x), double(lim.y)}, rendering);
  HpglEncoder hpgl(model, options.absolute, out);
  // The description first, where the pen starts from the origin; a line that would not fit on
  // the sheet is left out (and said, as clipping).
  bool clipped = placed.clipped;
  DevicePoint t = layout.text, pen{0, 0};
  std::vector<std::string_view> caption(picture.caption.begin(), picture.caption.end());
  if (placed.texts_cut) caption.push_back(texts_cut_line);
  for (std::string_view line : caption) {
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
  // Pen by pen (a pen change is slow), each pen's strokes in plot order; the texts of the drawing
  // last, with their pens.
  std::vector<Style> styles;
  for (const Style& s : placed.styles)
    if (std::find(styles.begin(), styles.end(), s) == styles.end()) styles.push_back(s);
  std::vector<Line> lines;
  PlotOrder order;
  const DevicePoint origin{0, 0};
  for (const Style& style : styles) {
    lines.clear();
    for (std::size_t k = 0; k < placed.paths.size(); ++k)
      if (placed.styles[k] == style) lines.push_back(placed.paths[k]);
    plot_order(lines, placed.box, pen, order);  // the box of every style's paths holds these
    hpgl.style(style);
    // Never more pen-up travel than the drawing order.
    if (pen_up_travel(order, lines, pen, origin) > pen_up_travel(lines, pen, origin)) {
      for (const Line& line : lines) hpgl.polyline(line);
      if (!lines.empty() && !lines.back().empty()) pen = lines.back().back();
    } else {
      hpgl.draw_order(order, lines);
      if (order.size() > 0) pen = order.strokes.back().end(lines);
    }
  }
  for (const auto& t : placed.texts) {
    hpgl.style(t.style);
    hpgl.text(t.at, t.text);
  }
  hpgl.finish();
  PlotStats stats = hpgl.stats();
  stats.clipped = clipped;
  stats.texts_cut = placed.texts_cut;
  return stats;
}

Plot plot_placed(const Picture& picture, const PlotLayout& layout, const PlotOptions& options) {
  StringOut out;
  Plot plot;
  plot.stats = plot_placed(picture, layout, options, out);
  plot.hpgl = out.take_text();
  return plot;
}

std::string plot_summary(std::string_view where, const PlotStats& stats) {
  return fmt::format("{}: {} VECTORS, {} PEN LIFTS, PEN-UP TRAVEL {:.0f} MM, {} BYTES", where,
                     stats.vectors, stats.pen_lifts, stats.pen_up_mm, stats.bytes);
}

PlotStats plot_hpgl(const Picture& picture, const PlotOptions& options, TextOut& out) {
  return plot_placed(picture, plot_layout(picture, options), options, out);
}

Plot plot_hpgl(const Picture& picture, const PlotOptions& options) {
  return plot_placed(picture, plot_layout(picture, options), options);
}

}  // namespace igds
