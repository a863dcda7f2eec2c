// The interface every output device implements (docs/devices.md, step 4): integer device
// coordinates, and a device that remembers its own state so that it emits nothing redundant.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "workspace/drawing/drawing.h"

namespace igds {

struct DevicePoint {
  int x = 0, y = 0;
  friend bool operator==(DevicePoint, DevicePoint) = default;
};

// A polyline in device coordinates: a move to the first point, vectors to the others.
using DevicePath = std::vector<DevicePoint>;

// The smallest box that holds some device points; empty (x0 > x1) until one is added.
struct DeviceBox {
  int x0 = std::numeric_limits<int>::max(), y0 = std::numeric_limits<int>::max();
  int x1 = std::numeric_limits<int>::min(), y1 = std::numeric_limits<int>::min();

  bool empty() const { return x0 > x1; }
  // Two points at a time in two chains, with no branch: a path just written is measured while
  // it is still in the cache.
  void add(std::span<const DevicePoint> points);
  void add(const DeviceBox& b) {
    x0 = std::min(x0, b.x0), x1 = std::max(x1, b.x1);
    y0 = std::min(y0, b.y0), y1 = std::max(y1, b.y1);
  }
  friend bool operator==(const DeviceBox&, const DeviceBox&) = default;
};

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

// Lists of paths one after another, path k of all counted across them: a large drawing's placed
// paths, each part placed on a thread of its own and none copied after the other.
struct PathParts {
  std::vector<PathList> parts;

  std::size_t size() const {
    std::size_t n = 0;
    for (const PathList& p : parts) n += p.size();
    return n;
  }
  std::span<const DevicePoint> operator[](std::size_t k) const {
    for (const PathList& p : parts) {
      if (k < p.size()) return p[k];
      k -= p.size();
    }
    return {};
  }
};

class Device {
 public:
  virtual ~Device() = default;
  // Pen up (a dark vector) to `p`. Nothing is sent when the pen is already there.
  virtual void move(DevicePoint p) = 0;
  // Pen down from the current position to `p`.
  virtual void draw(DevicePoint p) = 0;
  // One line of plain text whose first character has its baseline-left corner at `p`.
  virtual void text(DevicePoint p, std::string_view line) = 0;
  // A clean screen or sheet.
  virtual void page() = 0;
  // The pen and dash of what follows. Each device shows what it can (docs/devices.md) and sends
  // nothing while the style stays the same; the default is pen 1, solid.
  virtual void style(const Style&) {}
  // One polyline: a move to the first point, vectors to the others. Devices may send it faster.
  virtual void polyline(std::span<const DevicePoint> points) {
    if (points.empty()) return;
    move(points.front());
    for (std::size_t i = 1; i < points.size(); ++i) draw(points[i]);
  }
  // The paths of a placed drawing in order, path k in styles[k]: style() then polyline() for
  // each. A device writing a large file may make the same bytes faster.
  virtual void paths(const PathParts& paths, std::span<const Style> styles) {
    for (std::size_t k = 0; k < paths.size(); ++k) {
      style(styles[k]);
      polyline(paths[k]);
    }
  }
};

}  // namespace igds
