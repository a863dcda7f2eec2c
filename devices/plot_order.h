// The order in which a plotter draws the strokes of a picture (spec hpgl.md, Quality of a plot),
// and the pen-up travel an order costs.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "devices/device.h"

namespace igds {

// Polylines stored one after another in one buffer: path k is points[starts[k]] up to, not
// including, points[starts[k + 1]].
struct PathList {
  std::vector<DevicePoint> points;
  std::vector<std::size_t> starts{0};

  std::size_t size() const { return starts.size() - 1; }
  std::span<const DevicePoint> operator[](std::size_t k) const {
    return {points.data() + starts[k], starts[k + 1] - starts[k]};
  }
  void clear() {
    points.clear();
    starts.assign(1, 0);
  }
};

// Pen-up travel, in plotter units, of drawing `paths` in this order from `from`, then to `to`.
double pen_up_travel(const std::vector<DevicePath>& paths, DevicePoint from, DevicePoint to);
double pen_up_travel(const PathList& paths, DevicePoint from, DevicePoint to);

// The plot order of spec hpgl.md, Quality of a plot: duplicate segments dropped (the first
// drawn is kept; a zero-length segment cuts its path), paths whose ends meet (two at a point)
// joined, then paths taken greedily by the nearest end from `start` (reversed when that end is
// nearer; equal distances go to the earlier end); a path that starts where the last one ended
// continues it without lifting the pen. Deterministic. Into `out`, whose buffers are reused;
// O(n log n) in the number of segments, with no allocation per path.
void plot_order(std::span<const DevicePath> paths, DevicePoint start, PathList& out);

// The same order as separate paths.
std::vector<DevicePath> plot_order(const std::vector<DevicePath>& paths, DevicePoint start);

}  // namespace igds
