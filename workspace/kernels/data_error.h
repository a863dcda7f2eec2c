// Data a kernel cannot work with. Kernels say what is wrong with typed fields, never in words
// meant for the user: the commands layer words the report (commands/reports.h).
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <exception>
#include <string>
#include <vector>

namespace igds {

struct DataError : std::exception {
  enum class Problem {
    point_not_finite,       // `number`: the point (1-based)
    tangent_not_finite,     // `number`: the border point of the tangent
    patch_not_finite,       // `number`: the patch, row by row from 1
    twist_not_finite,       // `number`: the point
    shape,                  // `variable` has `shape`, not `expected`
    missing,                // `variable` is not there
    grid_too_small,         // NOCUR or NOSTR below 1, or a grid of one point
    negative_density,       // INTCU or INTST below 0
    too_many_points,        // `count` points, more than `limit`
    projection_parameters,  // parameters out of range for the projection
    behind_eye,             // CONIC: a point behind (or beside) the eye
    view_at_centre,         // CONIC: the view point is the centre
    view_inside_box,        // CONIC: the view point is inside the points' bounding box
    // A result that overflowed (finite inputs near the largest numbers): `number` and `column`
    // the row and column of INTPN (1-based) whose point is not finite.
    grid_point_not_finite,
    // A projected image that overflowed: the image of `variable`'s point `number` (INPPN), of
    // the tangent at point `number` (INPTG), of INTPN's row `number` and `column`, or of item
    // `number` of a picture's drawing (DRAWING).
    image_not_finite,
  };

  Problem problem;
  std::size_t number = 0, column = 0;
  std::string variable;
  std::vector<std::size_t> shape, expected;
  double count = 0, limit = 0;

  explicit DataError(Problem p) : problem(p) {}
  // A developer's account of the problem, in English (not a report).
  const char* what() const noexcept override;

 private:
  mutable std::string text_;
};

struct Array;

// The first of `n` numbers at `v` that is not finite (a NaN or an infinity), or n when all are:
// the check of every result before it is kept (docs/kernels.md, "Data checks"). Reads the numbers
// at the speed of memory, a large array on the machine's cores as the kernels make it.
std::size_t first_not_finite(const double* v, std::size_t n);

// The same for `n` points x y (2n numbers at `xy`), in the same one pass: the first number that is
// not finite (2n: none) and, when every one is, the box of the points, x0 y0 x1 y1.
struct FinitePoints {
  std::size_t not_finite = 0;
  std::array<double, 4> box{};
};
FinitePoints finite_points(const double* xy, std::size_t n);

// `least` made `k` when k is less: the first index that the parts of a loop split between threads
// (workspace/kernels/parallel.h) report, each its own.
inline void keep_least(std::atomic<std::size_t>& least, std::size_t k) {
  for (std::size_t seen = least.load(); k < seen && !least.compare_exchange_weak(seen, k);) {
  }
}

// Throws DataError missing (no array) or shape (`a` is not of shape `expected`), naming
// `variable`: the check every kernel makes of the arrays it is given.
void require_shape(const char* variable, const Array* a, std::vector<std::size_t> expected);

}  // namespace igds
