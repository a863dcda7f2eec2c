#include "workspace/kernels/surface.h"

#include <cassert>
#include <cmath>
#include <string>
#include <utility>

#include "workspace/kernels/coons.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"
#include "workspace/kernels/limits.h"
#include "workspace/kernels/marks.h"
#include "workspace/kernels/spline.h"

namespace igds {

namespace {

[[noreturn]] void refuse(DataError::Problem problem, std::size_t number) {
  DataError e(problem);
  e.number = number;
  throw e;
}

bool finite(const double* v, int n) {
  for (int k = 0; k < n; ++k)
    if (!std::isfinite(v[k])) return false;
  return true;
}

// Point number of INPTG row `row` (workspace/state.h order), 1-based.
std::size_t tangent_point(const SurfaceInput& in, std::size_t row) {
  const std::size_t nc = in.nocur, ns = in.nostr;
  if (row < 2 * nc) return (row / 2) * ns + (row % 2 == 0 ? 0 : ns - 1) + 1;
  const std::size_t j = (row - 2 * nc) / 2;
  return (row % 2 == 0 ? 0 : nc - 1) * ns + j + 1;
}

// What every interpolation needs: sizes, shapes, finite points (docs/kernels.md, "Data checks").
void check_grid(const SurfaceInput& in) {
  // One curve or one stringer is a surface too (manual 4.1: "two integer positive numbers").
  if (in.nocur < 1 || in.nostr < 1 || double(in.nocur) * in.nostr < 2)
    throw DataError(DataError::Problem::grid_too_small);
  if (in.intcu < 0 || in.intst < 0) throw DataError(DataError::Problem::negative_density);
  const double inputs = double(in.nocur) * in.nostr;
  const double points = grid_points(in.nocur, in.nostr, in.intcu, in.intst);
  if (inputs > double(max_input_points) || points > double(max_grid_points)) {
    DataError e(DataError::Problem::too_many_points);
    e.count = inputs > double(max_input_points) ? inputs : points;
    e.limit = double(inputs > double(max_input_points) ? max_input_points : max_grid_points);
    throw e;
  }
  const std::size_t n = std::size_t(in.nocur) * std::size_t(in.nostr);
  require_shape("INPPN", in.inppn, {n, 3});
  for (std::size_t k = 0; k < n; ++k) {
    if (!finite(in.inppn->data() + 3 * k, 3)) refuse(DataError::Problem::point_not_finite, k + 1);
  }
}

// Everything interpolate needs beyond check_grid: INPTG's shape and finite tangents.
void check_tangents(const SurfaceInput& in) {
  const std::size_t rows = 2 * (std::size_t(in.nocur) + std::size_t(in.nostr));
  require_shape("INPTG", in.inptg, {rows, 4});
  for (std::size_t r = 0; r < rows; ++r) {
    if (!finite(in.inptg->data() + 4 * r, 3))
      refuse(DataError::Problem::tangent_not_finite, tangent_point(in, r));
  }
}

// The error of a surface whose first number not finite is PATCHES' `kp` (of `patch_numbers`) or
// INTPN's `ki` (the array's size: none).
std::optional<DataError> not_finite(std::size_t patch_numbers, std::size_t kp, const Array& intpn,
                                    std::size_t ki) {
  if (kp < patch_numbers) {
    DataError e(DataError::Problem::patch_not_finite);
    e.number = kp / 48 + 1;
    return e;
  }
  if (ki < intpn.size()) {
    const std::size_t columns = intpn.rank() == 3 ? intpn.shape[1] : 1;
    DataError e(DataError::Problem::grid_point_not_finite);
    e.number = ki / 3 / columns + 1;
    e.column = ki / 3 % columns + 1;
    return e;
  }
  return std::nullopt;
}

void check_patches(const SurfaceInput& in, const Array& patches) {
  const std::size_t pr = in.nocur - 1, pc = in.nostr - 1;
  require_shape("PATCHES", &patches, {pr, pc, 3, 4, 4});
  for (std::size_t p = 0; p < pr * pc; ++p) {
    if (!finite(patches.data() + 48 * p, 48)) refuse(DataError::Problem::patch_not_finite, p + 1);
  }
}

// A single curve (NOCUR 1) or a single stringer (NOSTR 1): no patch; INTPN is the spline of its
// points, clamped by its two end tangents, at the parameters a/(INT+1) of every arc.
void interpolate_line(const SurfaceInput& in, Surface& out) {
  const LineSpline line = line_spline(in);
  const bool curve = line.curve;
  const std::size_t n = line.points.size(), inserted = line.inserted, count = line.count();
  const Vec3View points = line.points;
  const std::vector<Vec3>& tangents = line.tangents;
  out.patches = Array({std::size_t(in.nocur) - 1, std::size_t(in.nostr) - 1, 3, 4, 4});
  out.intpn =
      Array(curve ? std::vector<std::size_t>{1, count, 3} : std::vector<std::size_t>{count, 1, 3});
  MutableVec3View grid = as_vec3(out.intpn);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    for (std::size_t a = 1; a <= inserted; ++a) {
      const double s = double(a) / double(inserted + 1);
      grid[k * (inserted + 1) + a] =
          spline_arc_point(points[k], points[k + 1], tangents[k], tangents[k + 1], s);
    }
  }
  // The input points come out bit-exact (docs/kernels.md).
  for (std::size_t k = 0; k < n; ++k) grid[k * (inserted + 1)] = points[k];
}

}  // namespace

LineSpline line_spline(const SurfaceInput& in) {
  LineSpline line;
  line.curve = in.nocur == 1;
  line.inserted = std::size_t(line.curve ? in.intst : in.intcu);
  line.points = as_vec3(*in.inppn);
  const std::size_t first_row = line.curve ? 0 : 2 * std::size_t(in.nocur);
  line.tangents.resize(line.points.size());
  spline_tangents(line.points, border_tangent(*in.inptg, first_row),
                  border_tangent(*in.inptg, first_row + 1), line.tangents);
  return line;
}

Surface interpolate(const SurfaceInput& input) {
  Surface s;
  (void)interpolate_into(input, s);  // returned as it is: the caller checks or refuses it
  return s;
}

std::optional<DataError> interpolate_into(const SurfaceInput& input, Surface& out,
                                          PatchesOut patches) {
  if (input.nocur == 1 || input.nostr == 1) {
    check_grid(input);
    check_tangents(input);
    Surface line;
    interpolate_line(input, line);
    out = std::move(line);
    return not_finite(0, 0, out.intpn, first_not_finite(out.intpn.data(), out.intpn.size()));
  }
  if (&out.patches == input.inppn || &out.patches == input.inptg || &out.intpn == input.inppn ||
      &out.intpn == input.inptg) {
    // The output would overwrite the input while it is read: compute apart.
    Surface apart;
    auto error = interpolate_into(input, apart, patches);
    out = std::move(apart);
    return error;
  }
  const PatchMaker maker(input);  // checks the inputs first
  const PatchSource& source = maker.source();
  out.tangents = maker.tangents();
  const std::size_t patch_numbers =
      std::size_t(input.nocur - 1) * std::size_t(input.nostr - 1) * 48;
  if (patches == PatchesOut::dropped) {
    out.patches = Array();
    const FitResult made = fit(input.intcu, input.intst, source, out.intpn);
    return not_finite(patch_numbers, made.patch_not_finite, out.intpn, made.intpn_not_finite);
  }
  const std::size_t kp = coons_patches(input.nocur, input.nostr, source.points, *source.tangents,
                                       out.patches, source.twists);
  const std::size_t ki = fit(input.nocur, input.nostr, input.intcu, input.intst, out.patches,
                             source.points, out.intpn);
  return not_finite(patch_numbers, kp, out.intpn, ki);
}

PatchMaker::PatchMaker(const SurfaceInput& input, std::shared_ptr<const SplineTangents> made)
    : made_(std::move(made)) {
  check_grid(input);
  check_tangents(input);
  assert(input.nocur > 1 && input.nostr > 1);
  const auto points = as_vec3(*input.inppn);
  if (!made_) {
    auto splines = std::make_shared<SplineTangents>();
    // Marks's twists (docs/marks.md, Birkhoff and de Boor) or the manual's zero block.
    if (input.marks_twists) splines->twists = marks_twists(input.nocur, input.nostr, points);
    splines->tangents = grid_tangents(input.nocur, input.nostr, points, *input.inptg);
    made_ = std::move(splines);
  }
  source_ = {std::size_t(input.nocur), std::size_t(input.nostr), points, &made_->tangents,
             as_vec3(made_->twists)};
}

Array surface_patches(const SurfaceInput& input, std::shared_ptr<const SplineTangents> made) {
  if (input.nocur == 1 || input.nostr == 1) {
    check_grid(input);
    check_tangents(input);
    return Array({std::size_t(input.nocur) - 1, std::size_t(input.nostr) - 1, 3, 4, 4});
  }
  const PatchMaker maker(input, std::move(made));  // checks the inputs first
  const PatchSource& source = maker.source();
  Array patches({std::size_t(input.nocur) - 1, std::size_t(input.nostr) - 1, 3, 4, 4});
  // Finite: they were when the surface was made.
  (void)coons_patches(input.nocur, input.nostr, source.points, *source.tangents, patches,
                      source.twists);
  return patches;
}

Array refit(const SurfaceInput& input, const Array& patches) {
  Array intpn;
  (void)refit_into(input, patches, intpn);  // returned as it is: the caller checks or refuses it
  return intpn;
}

std::optional<DataError> refit_into(const SurfaceInput& input, const Array& patches, Array& intpn) {
  check_grid(input);
  if (input.nocur == 1 || input.nostr == 1) {
    // A line has no patches: its grid comes from its points and end tangents.
    check_tangents(input);
    Surface line;
    interpolate_line(input, line);
    intpn = std::move(line.intpn);
    return not_finite(0, 0, intpn, first_not_finite(intpn.data(), intpn.size()));
  }
  check_patches(input, patches);
  if (&intpn == input.inppn || &intpn == &patches) {
    Array apart;
    auto error = refit_into(input, patches, apart);
    intpn = std::move(apart);
    return error;
  }
  // PATCHES are finite (check_patches): INTPN alone can overflow.
  return not_finite(0, 0, intpn,
                    fit(input.nocur, input.nostr, input.intcu, input.intst, patches,
                        as_vec3(*input.inppn), intpn));
}

}  // namespace igds
