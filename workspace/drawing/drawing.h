// A drawing: what a picture is made of, whatever shows it (a display list). Items in drawing
// order: polylines, rational or polynomial Bézier curves, marks and texts, each with its style
// (pen, dash, weight) and its identity (point k, curve i, ...) for picks, listings and zooms.
// Drawing3 is in space (a DUCT picture, a surface's exact curves), Drawing2 in the plane (what
// is shown); workspace/drawing/project.h makes the one from the other. The devices draw any
// Drawing2 and know nothing of grids or IMAGE.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/kernels/memory.h"
#include "workspace/kernels/vec3.h"

namespace igds {

// The dash patterns a drawing may ask for; each device says what it makes of them
// (docs/devices.md).
enum class Dash : std::uint8_t { solid, dashed, chain, dotted };

// How a stroke looks. Pen 1 is the ordinary black pen; DUCT colours and plotter pens count from
// 1 too. Weight 1 is a normal line, 2 a bold one.
struct Style {
  int pen = 1;
  Dash dash = Dash::solid;
  int weight = 1;
  friend bool operator==(Style, Style) = default;
};

// Marks drawn at a point, sized in device units (half the side of the square they fill).
enum class MarkShape : std::uint8_t { dot, cross, plus, square, circle, diamond };

// What an item stands for.
enum class Role : std::uint8_t {
  none,
  border,    // the border of the input grid
  curve,     // curve `index` (1-based)
  stringer,  // stringer `index`
  tangent,   // the tangent arrow at point `index`; `detail` 1 along the curve, 0 the stringer
  point,     // input point `index`
  label,     // a text written beside something (a point number: `index` is the point)
  menu,      // menu item `index` of the 2250 workspace
  line,      // any other line (a DUCT instruction: `index` is its number)
  comb,      // the curvature comb of curve `index` (`detail` 1) or stringer `index` (`detail` 0)
};
struct Identity {
  Role role = Role::none;
  int index = 0;
  int detail = 0;
  friend bool operator==(Identity, Identity) = default;
};

template <class P>
class Drawing {
 public:
  static constexpr std::size_t n = P::dimension;
  static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();
  using View = PointsView<P, const double>;

  enum class Kind : std::uint8_t { polyline, curve, mark, text };

  struct Item {
    Kind kind = Kind::polyline;
    Style style;
    Identity id;
    bool closed = false;                  // polyline: back to its first point
    std::uint8_t degree = 0;              // curve: 2 or 3 (spans of degree+1 controls)
    MarkShape shape = MarkShape::square;  // mark
    std::uint32_t pool = 0;               // where its points are (0: the drawing's own)
    std::size_t first = 0;                // its first point, in doubles from the pool's start
    std::size_t count = 0;                // points: polyline points, curve controls, 1 else
    std::size_t stride = n;               // doubles between consecutive points
    std::size_t weights = npos;           // curve: its first weight in the own weights; npos 1s
    double size = 0;                      // mark: half side; text: character height (device)
    std::size_t text = 0;                 // text: its string
  };

  // The lowest then the highest coordinate of each axis (x0 y0 x1 y1 in the plane).
  using Extent = std::array<double, 2 * n>;
  // Points that stay with their owner (an image's projected grid): items may refer to them
  // without copying; `owner` keeps them alive as long as the drawing. `extent`: the box of all
  // `doubles / n` points, every one finite, when the owner knows it.
  std::uint32_t share(std::shared_ptr<const void> owner, const double* data, std::size_t doubles,
                      std::optional<Extent> extent = {});
  // A shared pool's size in doubles, and the box it was shared with.
  std::size_t pool_size(std::uint32_t pool) const { return pools_[pool - 1].size; }
  const std::optional<Extent>& pool_extent(std::uint32_t pool) const {
    return pools_[pool - 1].extent;
  }

  // A polyline of copies of `points`.
  void add_polyline(View points, Style style = {}, Identity id = {}, bool closed = false);
  // A polyline of `count` shared points of `pool`, from double `first`, `stride` doubles apart.
  void add_polyline(std::uint32_t pool, std::size_t first, std::size_t count, std::size_t stride,
                    Style style = {}, Identity id = {});
  // A chain of Bézier spans of `degree` 2 or 3: degree × spans + 1 control points, the last of a
  // span the first of the next. `weights` empty: polynomial; else one positive weight per control
  // point (rational: conic arcs are degree 2 with a middle weight).
  void add_curve(int degree, View controls, std::span<const double> weights = {}, Style style = {},
                 Identity id = {});
  void add_mark(P at, MarkShape shape, double size, Style style = {}, Identity id = {});
  void add_text(P at, std::string_view text, double size = 1, Style style = {}, Identity id = {});
  // Room for `items` more items and `points` more points of the drawing's own, made at once
  // before a drawing of millions of points is added item by item.
  void reserve(std::size_t items, std::size_t points);

  std::span<const Item> items() const { return items_; }
  std::size_t size() const { return items_.size(); }
  bool empty() const { return items_.empty(); }
  // The points of an item: a polyline's points, a curve's control points, a mark's or a text's
  // place.
  View points(const Item& item) const {
    return View(pool_data(item.pool) + item.first, item.count, item.stride);
  }
  std::span<const double> weights(const Item& item) const {
    if (item.weights == npos) return {};
    return std::span<const double>(weights_).subspan(item.weights, item.count);
  }
  const std::string& text(const Item& item) const { return texts_[item.text]; }

 private:
  struct Pool {
    const double* data = nullptr;
    std::size_t size = 0;
    std::shared_ptr<const void> owner;
    std::optional<Extent> extent;
  };
  const double* pool_data(std::uint32_t pool) const {
    return pool == 0 ? own_.data() : pools_[pool - 1].data;
  }
  std::size_t own_point(P p);
  std::size_t own_points(View points);  // copies at the end of own_; where they start

  std::vector<Item> items_;
  std::vector<double, UnwrittenAllocator<double>> own_;  // the points the drawing holds itself
  std::vector<double> weights_;
  std::vector<std::string> texts_;
  std::vector<Pool> pools_;  // shared points, pool k at pools_[k - 1]
};

using Drawing2 = Drawing<Point2>;
using Drawing3 = Drawing<Vec3>;

// A point of a drawing as a point in space: a point in the plane at z = 0.
inline Vec3 in_space(Vec3 v) {
  return v;
}
inline Vec3 in_space(Point2 p) {
  return {p.x, p.y, 0};
}

// What DISPLAY shows: a drawing and the lines of its description (written beside it by every
// device: the column right of the image on the Tek screen, labels on a plot).
struct Picture {
  Drawing2 drawing;
  std::vector<std::string> caption;
};

extern template class Drawing<Point2>;
extern template class Drawing<Vec3>;

}  // namespace igds
