// The order in which a plotter draws the strokes of a picture (docs/devices.md, "HP-GL plotter"),
// and the pen-up travel an order costs.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "devices/device.h"

namespace igds {

// A polyline to order: a view of points held elsewhere (a PathList, a DevicePath).
using Line = std::span<const DevicePoint>;

// Points first..last of line `line`, drawn from last to first when `reversed`.
struct Stroke {
  std::size_t line = 0, first = 0, last = 0;
  bool reversed = false;
  DevicePoint begin(std::span<const Line> lines) const {
    return lines[line][reversed ? last : first];
  }
  DevicePoint end(std::span<const Line> lines) const {
    return lines[line][reversed ? first : last];
  }
};

// An order of the lines' strokes for a plotter: polyline k is strokes[starts[k]] up to, not
// including, strokes[starts[k + 1]], the pen down all along: each stroke after the first starts
// where the one before it ended, and that point is not drawn again.
struct PlotOrder {
  std::vector<Stroke> strokes;
  std::vector<std::size_t> starts{0};
  std::size_t size() const { return starts.size() - 1; }
};

// Pen-up travel, in plotter units, of drawing `paths` in this order from `from`, then to `to`.
double pen_up_travel(const std::vector<DevicePath>& paths, DevicePoint from, DevicePoint to);
double pen_up_travel(std::span<const Line> lines, DevicePoint from, DevicePoint to);
double pen_up_travel(const PlotOrder& order, std::span<const Line> lines, DevicePoint from,
                     DevicePoint to);

// The plot order of docs/devices.md, "HP-GL plotter": duplicate segments dropped (the first
// drawn is kept; a zero-length segment cuts its path), paths whose ends meet (two at a point)
// joined, then paths taken greedily by the nearest end from `start` (reversed when that end is
// nearer; equal distances go to the earlier end); a path that starts where the last one ended
// continues it without lifting the pen. Deterministic. Into `out`, whose buffers are reused;
// O(n log n) in the number of segments, with no allocation per path; the points are not copied.
void plot_order(std::span<const Line> lines, DevicePoint start, PlotOrder& out);
// The same for lines whose points all lie inside `box` (as a placement measures them while it
// writes them): the lines are not read once more to find it.
void plot_order(std::span<const Line> lines, const DeviceBox& box, DevicePoint start,
                PlotOrder& out);

// The same order with its points, into `out`.
void plot_order(std::span<const DevicePath> paths, DevicePoint start, PathList& out);

// The same order as separate paths.
std::vector<DevicePath> plot_order(const std::vector<DevicePath>& paths, DevicePoint start);

}  // namespace igds
