#include "workspace/kernels/coons.h"

#include <atomic>
#include <cassert>

#include "workspace/kernels/data_error.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/spline.h"

namespace igds {

Vec3 border_tangent(const Array& inptg, std::size_t row) {
  const double* r = inptg.data() + 4 * row;
  return {r[0], r[1], r[2]};
}

GridTangents grid_tangents(int nocur, int nostr, Vec3View points, const Array& inptg) {
  const std::size_t nc = nocur, ns = nostr;
  GridTangents t;
  // Each family's tangents are made on a thread of its own, which also writes them first.
  // INPTG rows (workspace/state.h): curve i's ends at 2i and 2i+1.
  auto curves = [&] {
    reserve_large(t.along_curves, nc * ns);
    t.along_curves.resize(nc * ns);
    SplineScratch scratch;
    std::vector<SplineLine> lines(nc);
    for (std::size_t i = 0; i < nc; ++i)
      lines[i] = {points.subspan(i * ns, ns), border_tangent(inptg, 2 * i),
                  border_tangent(inptg, 2 * i + 1),
                  std::span<Vec3>(t.along_curves).subspan(i * ns, ns)};
    spline_tangents(lines, scratch);
  };
  // Stringer j's ends at rows 2NOCUR+2j and 2NOCUR+2j+1, its points copied side by side with
  // its neighbours' (stringer_tangents).
  auto stringers = [&] {
    SplineScratch scratch;
    std::vector<SplineLine> lines;
    stringer_tangents(nc, ns, points, t.along_stringers,
                      [&](std::size_t j0, std::size_t width, const double* columns, Vec3* out) {
                        lines.clear();
                        for (std::size_t c = 0; c < width; ++c)
                          lines.push_back({Vec3View(columns + 3 * c * nc, nc),
                                           border_tangent(inptg, 2 * nc + 2 * (j0 + c)),
                                           border_tangent(inptg, 2 * nc + 2 * (j0 + c) + 1),
                                           std::span<Vec3>(out + c * nc, nc)});
                        spline_tangents(lines, scratch);
                      });
  };
  // The two families are independent: one thread each when the grid is large.
  parallel_for(2, threads_for(nc * ns * 12) > 1 ? 2 : 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t task = first; task < last; ++task) task == 0 ? curves() : stringers();
  });
  return t;
}

std::size_t coons_patch_row(const PatchSource& source, std::size_t i, double* out) {
  const std::size_t ns = source.nostr;
  const Vec3View points = source.points;
  const auto& tu = source.tangents->along_curves;
  const auto& tv = source.tangents->along_stringers;
  const bool per_chord = source.tangents->units == TangentUnits::per_chord;
  // The factor of the tangents of an arc: its chord (docs/kernels.md), or 1 for tangents per unit
  // of parameter, 0 on a zero-length arc either way so that the arc is its point.
  auto scale = [per_chord](double chord) { return per_chord ? chord : chord > 0 ? 1.0 : 0.0; };
  auto twist = [&](std::size_t k) {
    return source.twists.empty() ? Vec3{} : Vec3(source.twists[k]);
  };
  std::size_t not_finite = (ns - 1) * 48;
  double* m = out;
  // P(a,b) = P[i+b][j+a]; Pu(a,b) is scaled by the chord of curve i+b's arc j, Pv(a,b) by the
  // chord of stringer j+a's arc i (docs/kernels.md), the same chords the splines used: stringer
  // j+1's is the next patch's first.
  double lv1 = scale(chord_length(points[i * ns], points[i * ns + ns]));
  for (std::size_t j = 0; j + 1 < ns; ++j, m += 48) {
    const std::size_t k00 = i * ns + j, k10 = k00 + 1, k01 = k00 + ns, k11 = k01 + 1;
    const double lu0 = scale(chord_length(points[k00], points[k10]));
    const double lu1 = scale(chord_length(points[k01], points[k11]));
    const double lv0 = lv1;
    lv1 = scale(chord_length(points[k10], points[k11]));
    // The twists T(a,b) of corner P(a,b) fill the lower right block (docs/marks.md).
    const Vec3 rows[4][4] = {
        {points[k00], points[k01], lv0 * tv[k00], lv0 * tv[k01]},
        {points[k10], points[k11], lv1 * tv[k10], lv1 * tv[k11]},
        {lu0 * tu[k00], lu1 * tu[k01], twist(k00), twist(k01)},
        {lu0 * tu[k10], lu1 * tu[k11], twist(k10), twist(k11)},
    };
    // x * 0 is 0 for a finite x, NaN for the rest (docs/kernels.md, "Data checks"), summed in
    // four independent lanes.
    double seen[4] = {0, 0, 0, 0};
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        m[0 * 16 + r * 4 + c] = rows[r][c].x;
        m[1 * 16 + r * 4 + c] = rows[r][c].y;
        m[2 * 16 + r * 4 + c] = rows[r][c].z;
        seen[c] += rows[r][c].x * 0.0 + rows[r][c].y * 0.0 + rows[r][c].z * 0.0;
      }
    }
    if (seen[0] + seen[1] + seen[2] + seen[3] != 0 && not_finite == (ns - 1) * 48)
      not_finite = std::size_t(m - out) + first_not_finite(m, 48);
  }
  return not_finite;
}

std::size_t coons_patches(int nocur, int nostr, Vec3View points, const GridTangents& tangents,
                          Array& patches, Vec3View twists) {
  const std::size_t nc = nocur, ns = nostr;
  const std::size_t count = (nc - 1) * (ns - 1) * 48;
  patches.reshape_for_output({nc - 1, ns - 1, 3, 4, 4});
  assert(twists.empty() || twists.size() == nc * ns);
  const PatchSource source{nc, ns, points, &tangents, twists};
  std::atomic<std::size_t> not_finite{count};
  parallel_for(nc - 1, threads_for(count), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      double* row = patches.data() + i * (ns - 1) * 48;
      const std::size_t k = coons_patch_row(source, i, row);
      if (k < (ns - 1) * 48) keep_least(not_finite, std::size_t(row - patches.data()) + k);
    }
  });
  return not_finite.load();
}

}  // namespace igds
