#include "workspace/drawing/drawing.h"

#include <algorithm>
#include <stdexcept>

namespace igds {

template <class P>
std::uint32_t Drawing<P>::share(std::shared_ptr<const void> owner, const double* data,
                                std::size_t doubles, std::optional<Extent> extent) {
  pools_.push_back({data, doubles, std::move(owner), extent});
  return static_cast<std::uint32_t>(pools_.size());
}

template <class P>
std::size_t Drawing<P>::own_point(P p) {
  const std::size_t at = own_.size();
  own_.resize(at + n);
  p.store(own_.data() + at);
  return at;
}

template <class P>
std::size_t Drawing<P>::own_points(View points) {
  const std::size_t at = own_.size(), need = at + n * points.size();
  // Room grown by half at least: many small items (the pieces of a zoomed grid) must not each
  // move all the points before them.
  if (need > own_.capacity()) own_.reserve(std::max(need, own_.capacity() + own_.capacity() / 2));
  own_.resize(need);
  double* w = own_.data() + at;
  for (P p : points) {
    p.store(w);
    w += n;
  }
  return at;
}

template <class P>
void Drawing<P>::reserve(std::size_t items, std::size_t points) {
  items_.reserve(items_.size() + items);
  reserve_large(own_, own_.size() + n * points);
}

template <class P>
void Drawing<P>::add_polyline(View points, Style style, Identity id, bool closed) {
  Item item{.kind = Kind::polyline, .style = style, .id = id, .closed = closed};
  item.first = own_points(points);
  item.count = points.size();
  items_.push_back(item);
}

template <class P>
void Drawing<P>::add_polyline(std::uint32_t pool, std::size_t first, std::size_t count,
                              std::size_t stride, Style style, Identity id) {
  if (pool == 0 || pool > pools_.size()) throw std::out_of_range("drawing: no such pool");
  const Pool& p = pools_[pool - 1];
  // The last point's last coordinate must lie in the pool.
  if (count > 0 && (first + stride * (count - 1) + n > p.size))
    throw std::out_of_range("drawing: points outside their pool");
  Item item{.kind = Kind::polyline, .style = style, .id = id};
  item.pool = pool;
  item.first = first;
  item.count = count;
  item.stride = stride;
  items_.push_back(item);
}

template <class P>
void Drawing<P>::add_curve(int degree, View controls, std::span<const double> weights, Style style,
                           Identity id) {
  if (degree != 2 && degree != 3)
    throw std::invalid_argument("drawing: curves are of degree 2 or 3");
  if (controls.size() < static_cast<std::size_t>(degree) + 1 ||
      (controls.size() - 1) % static_cast<std::size_t>(degree) != 0)
    throw std::invalid_argument("drawing: a curve has degree x spans + 1 control points");
  if (!weights.empty() && weights.size() != controls.size())
    throw std::invalid_argument("drawing: one weight per control point");
  Item item{.kind = Kind::curve, .style = style, .id = id};
  item.degree = static_cast<std::uint8_t>(degree);
  item.first = own_points(controls);
  item.count = controls.size();
  if (!weights.empty()) {
    item.weights = weights_.size();
    weights_.insert(weights_.end(), weights.begin(), weights.end());
  }
  items_.push_back(item);
}

template <class P>
void Drawing<P>::add_mark(P at, MarkShape shape, double size, Style style, Identity id) {
  Item item{.kind = Kind::mark, .style = style, .id = id};
  item.shape = shape;
  item.size = size;
  item.first = own_point(at);
  item.count = 1;
  items_.push_back(item);
}

template <class P>
void Drawing<P>::add_text(P at, std::string_view text, double size, Style style, Identity id) {
  Item item{.kind = Kind::text, .style = style, .id = id};
  item.size = size;
  item.first = own_point(at);
  item.count = 1;
  item.text = texts_.size();
  texts_.emplace_back(text);
  items_.push_back(item);
}

template class Drawing<Point2>;
template class Drawing<Vec3>;

}  // namespace igds
