// What the files of DUCT pictures (duct_*.cpp) share, and no other file: a field trimmed, and the
// layout of a drawing as a picture, which duct_layout.cpp makes and duct_write.cpp writes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <vector>

#include "workspace/exchange/duct.h"

namespace igds::duct {

// `s` without the blanks and tabs on either side.
inline std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// A picture's pixels in file order, not copied: runs of a drawing's points (a polyline's, a
// Bézier chain's controls, a run of marks'), and the few the layout makes (a conic arc's pixels
// with their shape factors, a rational cubic's lines). The drawing must outlive it.
class PixelRuns {
 public:
  // Pixels from a drawing whose points have `dimension` coordinates (2: z is 0).
  explicit PixelRuns(std::size_t dimension) : dimension_(dimension) {}

  // `count` points of the drawing from `points`, `stride` doubles apart.
  void add(const double* points, std::size_t count, std::size_t stride) {
    if (count == 0) return;
    // Points packed right after those of the last run (marks one after another) lengthen it.
    if (!runs_.empty() && !runs_.back().made && stride == dimension_ &&
        runs_.back().stride == stride &&
        runs_.back().points + stride * (count_ - runs_.back().first) == points) {
      count_ += count;
      return;
    }
    runs_.push_back({count_, points, stride, false, 0});
    count_ += count;
  }
  // A pixel made by the layout, with its shape factor T.
  void add_made(Vec3 v, double shape) {
    if (runs_.empty() || !runs_.back().made)
      runs_.push_back({count_, nullptr, 4, true, made_.size() / 4});
    made_.insert(made_.end(), {v.x, v.y, v.z, shape});
    ++count_;
  }

  std::size_t size() const { return count_; }

  // Calls f(xyz, shape) for pixels [first, last) in order, xyz its three coordinates.
  template <class F>
  void each(std::size_t first, std::size_t last, const F& f) const {
    if (first >= last) return;
    // The run that holds `first`: the last one starting at or before it.
    auto run = std::upper_bound(runs_.begin(), runs_.end(), first,
                                [](std::size_t k, const Run& r) { return k < r.first; }) -
               1;
    for (std::size_t k = first; k < last;) {
      const std::size_t end = std::min(last, run + 1 == runs_.end() ? count_ : (run + 1)->first);
      const double* points = run->made ? made_.data() + 4 * run->made_first : run->points;
      for (; k < end; ++k) {
        const double* p = points + run->stride * (k - run->first);
        const double xyz[3] = {p[0], p[1], dimension_ == 3 || run->made ? p[2] : 0.0};
        f(xyz, run->made ? p[3] : 0.0);
      }
      ++run;
    }
  }

 private:
  struct Run {
    std::size_t first;       // its first pixel
    const double* points;    // the drawing's, when not made
    std::size_t stride;      // doubles from one pixel to the next
    bool made;               // its pixels are made_'s (x y z T each)
    std::size_t made_first;  // when made: its first pixel in made_
  };
  std::size_t dimension_;
  std::vector<Run> runs_;
  std::vector<double> made_;
  std::size_t count_ = 0;
};

// The picture of a drawing (a drawing in the plane at z = 0) as duct_picture makes it, but for
// its pixels (xyz and tu are left empty), which `pixels` holds. Throws DataError for a point that
// is not finite (duct_picture).
struct Layout {
  DuctPicture picture;
  PixelRuns pixels;
};
template <class P>
Layout lay_out(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view);

// What an image's picture says of its view.
DuctView image_view(Projection projection);

}  // namespace igds::duct
