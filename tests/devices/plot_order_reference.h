// The plot order as it was first written (hash set of segments, a vector per piece, a hash map of
// ends, a vector per grid cell): the reference that devices/plot_order.cpp must match byte for
// byte, and the "before" of the plot-order benchmark. Kept as it was; do not tune it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "devices/device.h"

namespace igds::test::reference {

inline double distance(DevicePoint a, DevicePoint b) {
  return std::hypot(double(a.x) - b.x, double(a.y) - b.y);
}

struct SegmentKey {
  std::uint64_t a, b;
  friend bool operator==(SegmentKey, SegmentKey) = default;
};
struct SegmentHash {
  std::size_t operator()(SegmentKey k) const {
    return std::hash<std::uint64_t>{}(k.a * 0x9E3779B97F4A7C15ull ^ k.b);
  }
};

inline std::uint64_t pack(DevicePoint p) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(p.x)) << 32) |
         static_cast<std::uint32_t>(p.y);
}

// Each segment once, in either direction; a path is cut where a segment was seen before.
inline std::vector<DevicePath> without_duplicates(const std::vector<DevicePath>& paths) {
  std::unordered_set<SegmentKey, SegmentHash> seen;
  std::vector<DevicePath> out;
  for (const auto& path : paths) {
    DevicePath piece;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      std::uint64_t a = pack(path[i]), b = pack(path[i + 1]);
      bool fresh = a != b && seen.insert({std::min(a, b), std::max(a, b)}).second;
      if (!fresh) {
        if (piece.size() >= 2) out.push_back(std::move(piece));
        piece.clear();
        continue;
      }
      if (piece.empty()) piece.push_back(path[i]);
      piece.push_back(path[i + 1]);
    }
    if (piece.size() >= 2) out.push_back(std::move(piece));
  }
  return out;
}

// The ends of the paths in a uniform grid of cells, for nearest-end queries.
class EndGrid {
 public:
  explicit EndGrid(const std::vector<DevicePath>& paths, DevicePoint start) : paths_(paths) {
    std::size_t n = paths.size();
    x0_ = x1_ = start.x, y0_ = y1_ = start.y;
    for (const auto& p : paths)
      for (DevicePoint e : {p.front(), p.back()}) {
        x0_ = std::min<long>(x0_, e.x), x1_ = std::max<long>(x1_, e.x);
        y0_ = std::min<long>(y0_, e.y), y1_ = std::max<long>(y1_, e.y);
      }
    long side = std::max<long>(1, static_cast<long>(std::sqrt(static_cast<double>(n))));
    long span = std::max<long>(x1_ - x0_, y1_ - y0_) + 1;
    cell_ = std::max<long>(1, (span + side - 1) / side);
    nx_ = (x1_ - x0_) / cell_ + 1, ny_ = (y1_ - y0_) / cell_ + 1;
    cells_.resize(static_cast<std::size_t>(nx_ * ny_));
    for (std::size_t i = 0; i < n; ++i) {
      cells_[cell_of(paths[i].front())].push_back(2 * i);
      cells_[cell_of(paths[i].back())].push_back(2 * i + 1);
    }
    next_.resize(n + 1), prev_.resize(n + 1);
    // A list of the paths not yet taken, for the queries that the grid would make slow.
    for (std::size_t i = 0; i <= n; ++i) next_[i] = (i + 1) % (n + 1), prev_[i] = (i + n) % (n + 1);
    left_ = n;
  }

  // The end (2 * path + 1 for the last point) nearest to q: smallest distance, then id.
  std::size_t nearest(DevicePoint q) const {
    Best best;
    long qx = (q.x - x0_) / cell_, qy = (q.y - y0_) / cell_;
    std::size_t budget = 4 * left_ + 64, scanned = 0;
    long rings = std::max(nx_, ny_);
    for (long r = 0; r <= rings; ++r) {
      if (best.id != none && r >= 1) {
        double reach = static_cast<double>((r - 1) * cell_);
        if (reach * reach > best.d2) break;
      }
      for (long cx = qx - r; cx <= qx + r; ++cx)
        for (long cy = qy - r; cy <= qy + r; ++cy) {
          if (std::max(std::labs(cx - qx), std::labs(cy - qy)) != r) {
            cy = qy + r - 1;  // inside the ring: jump to its top row
            continue;
          }
          if (cx < 0 || cy < 0 || cx >= nx_ || cy >= ny_) continue;
          for (std::size_t id : cells_[static_cast<std::size_t>(cx * ny_ + cy)])
            consider(best, q, id);
          if (++scanned > budget) return brute(q);
        }
    }
    return best.id;
  }

  void take(std::size_t path) {
    for (std::size_t id : {2 * path, 2 * path + 1}) {
      auto& cell = cells_[cell_of(end(id))];
      cell.erase(std::find(cell.begin(), cell.end(), id));
    }
    next_[prev_[path]] = next_[path];
    prev_[next_[path]] = prev_[path];
    --left_;
  }

  DevicePoint end(std::size_t id) const {
    return id % 2 ? paths_[id / 2].back() : paths_[id / 2].front();
  }

 private:
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  struct Best {
    double d2 = std::numeric_limits<double>::infinity();
    std::size_t id = none;
  };

  void consider(Best& best, DevicePoint q, std::size_t id) const {
    DevicePoint e = end(id);
    double dx = double(e.x) - q.x, dy = double(e.y) - q.y, d2 = dx * dx + dy * dy;
    if (d2 < best.d2 || (d2 == best.d2 && id < best.id)) best = {d2, id};
  }

  std::size_t brute(DevicePoint q) const {
    Best best;
    std::size_t n = paths_.size();
    for (std::size_t i = next_[n]; i != n; i = next_[i]) {
      consider(best, q, 2 * i);
      consider(best, q, 2 * i + 1);
    }
    return best.id;
  }

  std::size_t cell_of(DevicePoint p) const {
    return static_cast<std::size_t>((p.x - x0_) / cell_ * ny_ + (p.y - y0_) / cell_);
  }

  const std::vector<DevicePath>& paths_;
  long x0_, x1_, y0_, y1_, cell_, nx_, ny_;
  std::vector<std::vector<std::size_t>> cells_;
  std::vector<std::size_t> next_, prev_;
  std::size_t left_ = 0;
};

// Paths whose ends meet, two at a point and no more, become one path (a point where three or
// more ends meet is left to the ordering). End e of piece p is 2p (first point) or 2p + 1.
inline std::vector<DevicePath> joined(std::vector<DevicePath> pieces) {
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> ends;
  auto end_point = [&](std::size_t e) {
    return e % 2 ? pieces[e / 2].back() : pieces[e / 2].front();
  };
  for (std::size_t e = 0; e < 2 * pieces.size(); ++e) ends[pack(end_point(e))].push_back(e);
  std::vector<char> used(pieces.size(), 0);
  // From end `e` of piece `p`, the pieces that follow on, each turned to continue the chain.
  auto chain = [&](std::size_t p, std::size_t e) {
    std::vector<std::size_t> ids;  // the end by which each following piece is entered
    for (;;) {
      const auto& at = ends[pack(end_point(e))];
      if (at.size() != 2) break;
      std::size_t other = at[0] == e ? at[1] : at[0];
      if (other / 2 == p || used[other / 2]) break;
      used[other / 2] = 1;
      ids.push_back(other);
      e = other ^ 1;
    }
    return ids;
  };
  std::vector<DevicePath> out;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (used[p]) continue;
    used[p] = 1;
    auto after = chain(p, 2 * p + 1), before = chain(p, 2 * p);
    DevicePath path;
    // The pieces before, walked back from p's first point, are drawn in the other direction.
    for (std::size_t k = before.size(); k-- > 0;) {
      const DevicePath& q = pieces[before[k] / 2];
      bool entered_at_first = before[k] % 2 == 0;
      std::size_t skip = path.empty() ? 0 : 1;
      if (entered_at_first)
        path.insert(path.end(), q.rbegin() + static_cast<long>(skip), q.rend());
      else
        path.insert(path.end(), q.begin() + static_cast<long>(skip), q.end());
    }
    path.insert(path.end(), pieces[p].begin() + (path.empty() ? 0 : 1), pieces[p].end());
    for (std::size_t id : after) {
      const DevicePath& q = pieces[id / 2];
      if (id % 2 == 0)
        path.insert(path.end(), q.begin() + 1, q.end());
      else
        path.insert(path.end(), q.rbegin() + 1, q.rend());
    }
    out.push_back(std::move(path));
  }
  return out;
}

inline std::vector<DevicePath> plot_order(const std::vector<DevicePath>& paths, DevicePoint start) {
  std::vector<DevicePath> pieces = joined(without_duplicates(paths));
  std::vector<DevicePath> out;
  if (pieces.empty()) return out;
  EndGrid grid(pieces, start);
  DevicePoint at = start;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    std::size_t id = grid.nearest(at);
    std::size_t i = id / 2;
    grid.take(i);
    DevicePath& piece = pieces[i];
    if (id % 2) std::reverse(piece.begin(), piece.end());
    // Ends that meet make one path: the pen stays down.
    if (!out.empty() && out.back().back() == piece.front())
      out.back().insert(out.back().end(), piece.begin() + 1, piece.end());
    else
      out.push_back(std::move(piece));
    at = out.back().back();
  }
  return out;
}

}  // namespace igds::test::reference
