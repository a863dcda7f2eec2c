#include "devices/plot_order.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>

#include "workspace/kernels/parallel.h"

namespace igds {

namespace {

using u64 = std::uint64_t;
constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

double distance(DevicePoint a, DevicePoint b) {
  return std::hypot(double(a.x) - b.x, double(a.y) - b.y);
}

// A sort key and what it belongs to.
struct Keyed {
  u64 key, value;
};

// Room for `size` elements of a trivially copyable T, left unwritten: a sort fills it.
template <class T>
struct Buffer {
  explicit Buffer(std::size_t n) : data(std::make_unique_for_overwrite<T[]>(n)), size(n) {}
  T* begin() const { return data.get(); }
  std::unique_ptr<T[]> data;
  std::size_t size;
};

// Stable LSD radix sort by the low `bits` bits of a key, in passes of at most 11 bits; the
// keys are counted as the elements are made (add), then sorted (sort).
class RadixSort {
 public:
  explicit RadixSort(int bits)
      : passes_((std::max(bits, 0) + 10) / 11),
        digit_(passes_ ? (bits + passes_ - 1) / passes_ : 0),
        count_(static_cast<std::size_t>(passes_) << digit_, 0) {}

  void add(u64 key) {
    const std::size_t mask = (std::size_t{1} << digit_) - 1;
    for (int p = 0; p < passes_; ++p)
      ++count_[(static_cast<std::size_t>(p) << digit_) + ((key >> (p * digit_)) & mask)];
  }

  // Sorts the n elements of a, whose keys were added, through `scratch` (as long as a); a pass
  // whose digit is the same for every element is skipped. Returns a or scratch, whichever holds
  // the sorted elements.
  template <class T, class Key>
  T* sort(T* a, T* scratch, std::size_t n, Key key) {
    const std::size_t buckets = std::size_t{1} << digit_, mask = buckets - 1;
    for (int p = 0; p < passes_ && n > 1; ++p) {
      std::size_t* c = count_.data() + (static_cast<std::size_t>(p) << digit_);
      if (std::find(c, c + buckets, n) != c + buckets) continue;
      std::size_t sum = 0;
      for (std::size_t b = 0; b < buckets; ++b) sum += std::exchange(c[b], sum);
      const int shift = p * digit_;
      for (const T* r = a; r != a + n; ++r) scratch[c[(key(*r) >> shift) & mask]++] = *r;
      std::swap(a, scratch);
    }
    return a;
  }

 private:
  int passes_, digit_;
  std::vector<std::size_t> count_;
};

// Each point inside a box as its place in it: W * H ids, `bits` wide.
struct PointIds {
  long long x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  u64 h = 1;
  int bits = 0;

  explicit PointIds(const DeviceBox& box) {
    if (!box.empty()) x0 = box.x0, y0 = box.y0, x1 = box.x1, y1 = box.y1;
    h = static_cast<u64>(y1 - y0) + 1;
    bits = std::bit_width(static_cast<u64>(x1 - x0) * h + static_cast<u64>(y1 - y0));
  }
  u64 operator()(DevicePoint p) const {
    return static_cast<u64>(p.x - x0) * h + static_cast<u64>(p.y - y0);
  }
};

// The box of the paths' points, found on as many threads as pay.
DeviceBox box_of(std::span<const Line> paths) {
  std::size_t points = 0;
  for (const Line& path : paths) points += path.size();
  const unsigned parts = threads_for(points / 2);
  std::vector<DeviceBox> boxes(parts);
  parallel_for(parts, parts, [&](std::size_t from, std::size_t to) {
    for (std::size_t t = from; t < to; ++t) {
      DeviceBox b;  // here, not in boxes: the threads' boxes share a cache line
      for (std::size_t k = paths.size() * t / parts; k < paths.size() * (t + 1) / parts; ++k)
        b.add(paths[k]);
      boxes[t] = b;
    }
  });
  DeviceBox box;
  for (const DeviceBox& b : boxes) box.add(b);
  return box;
}

// A run of segments of one input path, points first..last, drawn for the first time.
struct Piece {
  std::size_t path, first, last;
};

// The segments of the paths, numbered in drawing order, that are not drawn: those without a
// length, and those drawn before in either direction; in increasing order.
//
// A segment belongs to the first (by number) of its ends' tiles (squares of the plane), so a
// segment and its repeats share a tile. The paths, cut into runs of consecutive segments of one
// tile (a path crosses a tile in one run, not segment by segment), are grouped by tile in drawing
// order; each tile's segments then go through a bitset of their hashes, in the cache, and the few
// whose hash repeats through a table of those seen, on as many threads as pay. Only the runs are
// moved, never the segments.
std::vector<std::size_t> not_drawn(std::span<const Line> paths, const PointIds& ids) {
  std::size_t n = 0;
  for (const auto& path : paths) n += path.empty() ? 0 : path.size() - 1;
  std::vector<std::size_t> dropped;
  std::mutex mutex;
  auto add = [&](const std::vector<std::size_t>& found) {
    const std::lock_guard lock(mutex);
    dropped.insert(dropped.end(), found.begin(), found.end());
  };
  if (ids.bits <= 32 && n <= std::numeric_limits<std::uint32_t>::max() &&
      paths.size() <= std::numeric_limits<std::uint32_t>::max()) {
    // Tiles of side 2^shift, about 16384 segments each where the segments are spread evenly (the
    // table of a tile stays in the cache, and a path crosses a tile in a long run), and at most
    // one tile for every 2048 segments where they are not.
    const u64 width = static_cast<u64>(ids.x1 - ids.x0), height = static_cast<u64>(ids.y1 - ids.y0);
    const double area = static_cast<double>(width + 1) * static_cast<double>(height + 1);
    int shift = 0;
    while (shift < 31 && std::ldexp(static_cast<double>(n), 2 * (shift + 1)) <= 16384 * area)
      ++shift;
    auto tiles_at = [&](int s) { return ((width >> s) + 1) * ((height >> s) + 1); };
    while (shift < 31 && tiles_at(shift) > n / 2048 + 1) ++shift;
    const u64 tiles_y = (height >> shift) + 1, tiles = tiles_at(shift);
    struct Run {
      std::uint32_t tile, path, first, last;  // segments first..last - 1 of the path
    };
    // The paths in `parts` slices of about as many segments, one a thread, each cut into runs.
    const unsigned parts = threads_for(2 * n);
    std::vector<std::size_t> cut{0}, base(paths.size() + 1, 0);
    for (std::size_t k = 0; k < paths.size(); ++k) {
      base[k + 1] = base[k] + (paths[k].empty() ? 0 : paths[k].size() - 1);
      if (cut.size() < parts && base[k + 1] * parts >= n * cut.size()) cut.push_back(k + 1);
    }
    while (cut.size() <= parts) cut.push_back(paths.size());
    std::vector<std::vector<Run>> runs(parts);
    parallel_for(parts, parts, [&](std::size_t from, std::size_t to) {
      for (std::size_t t = from; t < to; ++t) {
        // Made here, then moved to runs[t]: the threads' vectors share a cache line.
        std::vector<Run> out;
        out.reserve((base[cut[t + 1]] - base[cut[t]]) / 16 + 16);
        std::vector<std::size_t> zero;
        auto tile_of = [x0 = ids.x0, y0 = ids.y0, s = shift, ty = tiles_y](DevicePoint p) {
          return static_cast<std::uint32_t>((static_cast<u64>(p.x - x0) >> s) * ty +
                                            (static_cast<u64>(p.y - y0) >> s));
        };
        for (std::size_t k = cut[t]; k < cut[t + 1]; ++k) {
          const DevicePoint* q = paths[k].data();
          const std::size_t segments = paths[k].empty() ? 0 : paths[k].size() - 1;
          const auto p = static_cast<std::uint32_t>(k);
          std::uint32_t tile_a = segments > 0 ? tile_of(q[0]) : 0;
          for (std::size_t i = 0; i < segments;) {
            // A run: segment i, then those after it of its tile and a length.
            const DevicePoint b = q[i + 1];
            if (q[i] == b) {
              zero.push_back(base[k] + i);
              tile_a = tile_of(b), ++i;
              continue;
            }
            std::uint32_t tile_b = tile_of(b);
            const std::uint32_t tile = std::min(tile_a, tile_b);
            const std::size_t first = i;
            for (++i; i < segments; ++i) {
              const DevicePoint c = q[i + 1];
              const std::uint32_t tile_c = tile_of(c);
              if (std::min(tile_b, tile_c) != tile || c == q[i]) break;
              tile_b = tile_c;
            }
            tile_a = tile_b;
            out.push_back(
                {tile, p, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(i)});
          }
        }
        runs[t] = std::move(out);
        add(zero);
      }
    });
    // The runs by tile, in drawing order (slice by slice, each in order): a counting sort.
    std::vector<std::uint32_t> first(tiles + 1, 0);
    std::vector<std::size_t> segments(tiles, 0);
    for (const auto& list : runs)
      for (const Run& r : list) ++first[r.tile + 1], segments[r.tile] += r.last - r.first;
    for (std::size_t c = 0; c < tiles; ++c) first[c + 1] += first[c];
    std::vector<const Run*> by_tile(first[tiles]);
    {
      std::vector<std::uint32_t> at(first.begin(), first.end() - 1);
      for (const auto& list : runs)
        for (const Run& r : list) by_tile[at[r.tile]++] = &r;
    }
    // Each tile alone, its segments in drawing order. Their hashes go through a bitset (in the
    // cache): a hash met before marks a possible repeat, and most tiles have a few. A segment's
    // hash is of the sum of its ends' coordinates (each point as one number, bits_of): the same
    // whichever way it is drawn, without ordering its ends. Only the segments whose hash was met
    // more than once then go, in drawing order, through a table of their keys (open addressing;
    // 0 is an empty slot, and no segment's key is 0 since its ends differ): a key already there
    // is a repeat. Segments that only share a midpoint share a hash, and the table tells them
    // apart.
    auto bits_of = [](DevicePoint q) {
      return static_cast<u64>(static_cast<std::uint32_t>(q.x)) << 32 |
             static_cast<std::uint32_t>(q.y);
    };
    auto find_repeats = [&](std::size_t from, std::size_t to) {
      std::vector<u64> seen, twice, table;
      std::vector<std::uint32_t> hashes, met, candidates;
      std::vector<std::size_t> found;
      for (std::size_t c = from; c < to; ++c) {
        const std::size_t count = segments[c];
        if (count < 2) continue;
        // 16 bits a segment or more, at most 32 KB.
        const int bits = std::min(static_cast<int>(std::bit_width(count)) + 4, 18);
        seen.assign(std::size_t{1} << (bits - 6), 0);
        twice.resize(seen.size(), 0);  // all clear, between tiles
        hashes.resize(count);
        met.resize(count + 1);
        std::uint32_t* const hash = hashes.data();
        std::uint32_t* const again = met.data();
        std::size_t at = 0, n_again = 0;
        for (std::uint32_t w = first[c]; w < first[c + 1]; ++w) {
          if (w + 2 < first[c + 1]) {
            // The points of a run ahead, each of their cache lines: they lie anywhere in the
            // paths' memory.
            const Run& ahead = *by_tile[w + 2];
            const Line& points = paths[ahead.path];
            const auto from = reinterpret_cast<std::uintptr_t>(points.data() + ahead.first);
            const auto to = reinterpret_cast<std::uintptr_t>(points.data() + ahead.last + 1);
            for (std::uintptr_t line = from & ~std::uintptr_t{63}; line < to; line += 64)
              __builtin_prefetch(reinterpret_cast<const void*>(line));
          }
          const Run& r = *by_tile[w];
          const DevicePoint* p = paths[r.path].data();
          u64 a = bits_of(p[r.first]);
          for (std::uint32_t i = r.first; i < r.last; ++i, ++at) {
            const u64 b = bits_of(p[i + 1]);
            const auto h =
                static_cast<std::uint32_t>(((a + b) * 0x9E3779B97F4A7C15u) >> (64 - bits));
            a = b;
            const u64 bit = u64{1} << (h & 63), word = seen[h >> 6];
            seen[h >> 6] = word | bit;
            hash[at] = h;
            again[n_again] = h;  // kept only when met before: no branch
            n_again += (word & bit) != 0;
          }
        }
        if (n_again == 0) continue;
        for (std::size_t k = 0; k < n_again; ++k) twice[again[k] >> 6] |= u64{1} << (again[k] & 63);
        // The segments whose hash was met more than once, by their place in the tile.
        candidates.resize(count + 1);
        std::size_t n_candidates = 0;
        for (std::size_t k = 0; k < count; ++k) {
          candidates[n_candidates] = static_cast<std::uint32_t>(k);
          n_candidates += twice[hash[k] >> 6] >> (hash[k] & 63) & 1;
        }
        for (std::size_t k = 0; k < n_again; ++k) twice[again[k] >> 6] = 0;
        const int table_bits = std::bit_width(2 * n_candidates - 1);
        const std::size_t mask = (std::size_t{1} << table_bits) - 1;
        table.assign(mask + 1, 0);
        // Each candidate's key from its points, the tile's runs walked alongside.
        std::uint32_t w = first[c];
        std::size_t run_at = 0;  // the place in the tile of run w's first segment
        for (std::size_t j = 0; j < n_candidates; ++j) {
          const std::size_t k = candidates[j];
          while (run_at + (by_tile[w]->last - by_tile[w]->first) <= k)
            run_at += by_tile[w]->last - by_tile[w]->first, ++w;
          const Run& r = *by_tile[w];
          const std::size_t i = r.first + (k - run_at);
          const u64 a = ids(paths[r.path][i]), b = ids(paths[r.path][i + 1]);
          const u64 key = a < b ? a << 32 | b : b << 32 | a;
          for (std::size_t h = (key * 0x9E3779B97F4A7C15u) >> (64 - table_bits);;
               h = (h + 1) & mask) {
            if (table[h] == 0) {
              table[h] = key;
              break;
            }
            if (table[h] == key) {
              found.push_back(base[r.path] + i);
              break;
            }
          }
        }
      }
      add(found);
    };
    parallel_for(tiles, tiles > 1 ? parts : 1, find_repeats);
    std::sort(dropped.begin(), dropped.end());
    return dropped;
  }
  // Coordinates too far apart, or too many segments, for 32-bit ids: a comparison sort.
  struct Wide {
    u64 lo, hi, s;
  };
  std::vector<Wide> wide;
  wide.reserve(n);
  u64 s = 0;
  for (const auto& path : paths)
    for (std::size_t i = 0; i + 1 < path.size(); ++i, ++s) {
      u64 a = ids(path[i]), b = ids(path[i + 1]);
      if (a == b)
        dropped.push_back(s);
      else
        wide.push_back({std::min(a, b), std::max(a, b), s});
    }
  std::sort(wide.begin(), wide.end(), [](const Wide& a, const Wide& b) {
    return a.lo != b.lo ? a.lo < b.lo : a.hi != b.hi ? a.hi < b.hi : a.s < b.s;
  });
  for (std::size_t k = 1; k < wide.size(); ++k)
    if (wide[k].lo == wide[k - 1].lo && wide[k].hi == wide[k - 1].hi) dropped.push_back(wide[k].s);
  std::sort(dropped.begin(), dropped.end());
  return dropped;
}

// The ends of the paths to order in a uniform grid of cells, stored flat, for nearest-end
// queries; end 2j is the first point of path j, 2j + 1 its last.
class EndGrid {
 public:
  EndGrid(std::span<const DevicePoint> ends, DevicePoint start) : ends_(ends) {
    std::size_t n = ends.size() / 2;
    x0_ = x1_ = start.x, y0_ = y1_ = start.y;
    for (DevicePoint e : ends) {
      x0_ = std::min<long>(x0_, e.x), x1_ = std::max<long>(x1_, e.x);
      y0_ = std::min<long>(y0_, e.y), y1_ = std::max<long>(y1_, e.y);
    }
    long side = std::max<long>(1, static_cast<long>(std::sqrt(static_cast<double>(n))));
    long span = std::max<long>(x1_ - x0_, y1_ - y0_) + 1;
    cell_ = std::max<long>(1, (span + side - 1) / side);
    nx_ = (x1_ - x0_) / cell_ + 1, ny_ = (y1_ - y0_) / cell_ + 1;
    std::size_t cells = static_cast<std::size_t>(nx_ * ny_);
    first_.assign(cells + 1, 0);
    for (DevicePoint e : ends) ++first_[cell_of(e) + 1];
    for (std::size_t c = 0; c < cells; ++c) first_[c + 1] += first_[c];
    end_.assign(first_.begin(), first_.end() - 1);
    slot_.resize(ends.size());
    where_.resize(ends.size());
    for (std::size_t id = 0; id < ends.size(); ++id) {
      std::size_t w = end_[cell_of(ends[id])]++;
      slot_[w] = id, where_[id] = w;
    }
    next_.resize(n + 1), prev_.resize(n + 1);
    // A list of the paths not yet taken, for the queries that the grid would make slow.
    for (std::size_t i = 0; i <= n; ++i) next_[i] = (i + 1) % (n + 1), prev_[i] = (i + n) % (n + 1);
    left_ = n;
  }

  // The end nearest to q: smallest distance, then smallest id. Rings of cells around q's cell
  // until no nearer end can be left, or a plain search when the rings would take longer.
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
          std::size_t c = static_cast<std::size_t>(cx * ny_ + cy);
          for (std::size_t w = first_[c]; w < end_[c]; ++w) consider(best, q, slot_[w]);
          if (++scanned > budget) return brute(q);
        }
    }
    return best.id;
  }

  void take(std::size_t path) {
    for (std::size_t id : {2 * path, 2 * path + 1}) {
      std::size_t last = --end_[cell_of(ends_[id])], w = where_[id];
      slot_[w] = slot_[last], where_[slot_[w]] = w;
    }
    next_[prev_[path]] = next_[path];
    prev_[next_[path]] = prev_[path];
    --left_;
  }

 private:
  struct Best {
    double d2 = std::numeric_limits<double>::infinity();
    std::size_t id = none;
  };

  void consider(Best& best, DevicePoint q, std::size_t id) const {
    DevicePoint e = ends_[id];
    double dx = double(e.x) - q.x, dy = double(e.y) - q.y, d2 = dx * dx + dy * dy;
    if (d2 < best.d2 || (d2 == best.d2 && id < best.id)) best = {d2, id};
  }

  std::size_t brute(DevicePoint q) const {
    Best best;
    std::size_t n = ends_.size() / 2;
    for (std::size_t i = next_[n]; i != n; i = next_[i]) {
      consider(best, q, 2 * i);
      consider(best, q, 2 * i + 1);
    }
    return best.id;
  }

  std::size_t cell_of(DevicePoint p) const {
    return static_cast<std::size_t>((p.x - x0_) / cell_ * ny_ + (p.y - y0_) / cell_);
  }

  std::span<const DevicePoint> ends_;
  long x0_, x1_, y0_, y1_, cell_, nx_, ny_;
  std::vector<std::size_t> first_, end_;   // by cell: its slots, and the end of the live ones
  std::vector<std::size_t> slot_, where_;  // the ends by cell; the slot of each end
  std::vector<std::size_t> next_, prev_;
  std::size_t left_ = 0;
};

}  // namespace

double pen_up_travel(const std::vector<DevicePath>& paths, DevicePoint from, DevicePoint to) {
  const std::vector<Line> lines(paths.begin(), paths.end());
  return pen_up_travel(lines, from, to);
}

double pen_up_travel(std::span<const Line> lines, DevicePoint from, DevicePoint to) {
  double travel = 0;
  DevicePoint at = from;
  for (const Line& line : lines) {
    if (line.empty()) continue;
    travel += distance(at, line.front());
    at = line.back();
  }
  return travel + distance(at, to);
}

double pen_up_travel(const PlotOrder& order, std::span<const Line> lines, DevicePoint from,
                     DevicePoint to) {
  double travel = 0;
  DevicePoint at = from;
  for (std::size_t k = 0; k < order.size(); ++k) {
    travel += distance(at, order.strokes[order.starts[k]].begin(lines));
    at = order.strokes[order.starts[k + 1] - 1].end(lines);
  }
  return travel + distance(at, to);
}

void plot_order(std::span<const Line> paths, DevicePoint start, PlotOrder& out) {
  plot_order(paths, box_of(paths), start, out);
}

void plot_order(std::span<const Line> paths, const DeviceBox& box, DevicePoint start,
                PlotOrder& out) {
  out.strokes.clear();
  out.starts.assign(1, 0);
  const PointIds ids(box);
  const std::vector<std::size_t> dropped = not_drawn(paths, ids);

  // The pieces: runs of drawn segments within a path, cut where a segment is not drawn.
  std::vector<Piece> pieces;
  auto next = dropped.begin();
  for (std::size_t k = 0, s = 0; k < paths.size(); ++k) {
    const std::size_t segments = paths[k].empty() ? 0 : paths[k].size() - 1;
    std::size_t first = 0;
    for (; next != dropped.end() && *next < s + segments; ++next) {
      const std::size_t i = *next - s;
      if (i > first) pieces.push_back({k, first, i});
      first = i + 1;
    }
    if (segments > first) pieces.push_back({k, first, segments});
    s += segments;
  }
  if (pieces.empty()) return;
  // End e of the pieces: the first point of piece e / 2 when e is even, its last when odd.
  auto end_point = [&](std::size_t e) {
    const Piece& p = pieces[e / 2];
    return paths[p.path][e % 2 ? p.last : p.first];
  };

  // Pieces whose ends meet, two at a point and no more, are joined (a point where three or more
  // ends meet is left to the ordering): mate[e] is the one other end at e's point.
  const std::size_t n_ends = 2 * pieces.size();
  std::vector<std::size_t> mate(n_ends, none);
  {
    Buffer<Keyed> records(n_ends), scratch(n_ends);
    RadixSort sorter(ids.bits);
    for (std::size_t e = 0; e < n_ends; ++e) {
      records.data[e] = {ids(end_point(e)), e};
      sorter.add(records.data[e].key);
    }
    const Keyed* keyed =
        sorter.sort(records.begin(), scratch.begin(), n_ends, [](const Keyed& k) { return k.key; });
    for (std::size_t i = 0; i < n_ends;) {
      std::size_t j = i + 1;
      while (j < n_ends && keyed[j].key == keyed[i].key) ++j;
      if (j - i == 2)
        mate[keyed[i].value] = keyed[i + 1].value, mate[keyed[i + 1].value] = keyed[i].value;
      i = j;
    }
  }
  // The joined paths, each a run of refs: ref r is piece r / 2, reversed when r is odd (so its
  // first point is end_point(r) and its last end_point(r ^ 1)). Each starts at the earliest
  // piece not yet used, the pieces following its last point then those before its first.
  std::vector<std::size_t> refs, joined{0}, after, before;
  refs.reserve(pieces.size());
  std::vector<std::uint8_t> used(pieces.size(), 0);
  auto chain = [&](std::size_t p, std::size_t e, std::vector<std::size_t>& ids_out) {
    ids_out.clear();
    for (std::size_t other = mate[e]; other != none; other = mate[e]) {
      if (other / 2 == p || used[other / 2]) break;
      used[other / 2] = 1;
      ids_out.push_back(other);
      e = other ^ 1;
    }
  };
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (used[p]) continue;
    used[p] = 1;
    chain(p, 2 * p + 1, after);
    chain(p, 2 * p, before);
    // A piece before p is entered from p's side: drawn towards p, the other way round.
    for (std::size_t k = before.size(); k-- > 0;) refs.push_back(before[k] ^ 1);
    refs.push_back(2 * p);
    refs.insert(refs.end(), after.begin(), after.end());
    joined.push_back(refs.size());
  }
  std::vector<std::uint8_t>().swap(used);
  std::vector<std::size_t>().swap(mate);

  // The greedy order by nearest end over the joined paths.
  const std::size_t m = joined.size() - 1;
  std::vector<DevicePoint> ends(2 * m);
  for (std::size_t j = 0; j < m; ++j) {
    ends[2 * j] = end_point(refs[joined[j]]);
    ends[2 * j + 1] = end_point(refs[joined[j + 1] - 1] ^ 1);
  }
  EndGrid grid(ends, start);
  out.strokes.reserve(pieces.size());
  out.starts.reserve(m + 1);
  auto stroke = [&](std::size_t r) {
    const Piece& p = pieces[r / 2];
    out.strokes.push_back({p.path, p.first, p.last, r % 2 == 1});
  };
  bool drawn = false;
  DevicePoint at = start;
  for (std::size_t k = 0; k < m; ++k) {
    std::size_t id = grid.nearest(at), j = id / 2;
    grid.take(j);
    // Ends that meet make one path: the pen stays down.
    const bool goes_on = drawn && at == ends[id];
    if (!goes_on && drawn) out.starts.push_back(out.strokes.size());
    if (id % 2 == 0)
      for (std::size_t i = joined[j]; i < joined[j + 1]; ++i) stroke(refs[i]);
    else
      for (std::size_t i = joined[j + 1]; i-- > joined[j];) stroke(refs[i] ^ 1);
    at = ends[id ^ 1];
    drawn = true;
  }
  out.starts.push_back(out.strokes.size());
}

void plot_order(std::span<const DevicePath> paths, DevicePoint start, PathList& out) {
  out.clear();
  std::vector<Line> lines(paths.begin(), paths.end());
  PlotOrder order;
  plot_order(lines, start, order);
  for (std::size_t k = 0; k < order.size(); ++k) {
    for (std::size_t s = order.starts[k]; s < order.starts[k + 1]; ++s) {
      const Stroke& t = order.strokes[s];
      const Line line = lines[t.line];
      const bool skip = s > order.starts[k];
      if (!t.reversed)
        out.points.insert(out.points.end(), line.begin() + long(t.first + skip),
                          line.begin() + long(t.last + 1));
      else
        out.points.insert(out.points.end(),
                          std::make_reverse_iterator(line.begin() + long(t.last + 1 - skip)),
                          std::make_reverse_iterator(line.begin() + long(t.first)));
    }
    out.starts.push_back(out.points.size());
  }
}

std::vector<DevicePath> plot_order(const std::vector<DevicePath>& paths, DevicePoint start) {
  PathList list;
  plot_order(paths, start, list);
  std::vector<DevicePath> out;
  out.reserve(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) out.emplace_back(list[k].begin(), list[k].end());
  return out;
}

}  // namespace igds
