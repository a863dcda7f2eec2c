#include "workspace/kernels/marks.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <vector>

#include "workspace/kernels/parallel.h"
#include "workspace/kernels/spline.h"

namespace igds {

namespace {

// One grid line read in place: a row of the grid (stride 3) or a column (stride 3 NOSTR).
struct Line {
  const double* data;
  std::size_t stride, size;
  Vec3 operator[](std::size_t k) const { return Vec3::load(data + k * stride); }
};

Line curve(Vec3View points, std::size_t nostr, std::size_t i) {
  return {points.data() + 3 * i * nostr, 3, nostr};
}
Line stringer(Vec3View points, std::size_t nocur, std::size_t nostr, std::size_t j) {
  return {points.data() + 3 * j, 3 * nostr, nocur};
}

// The first point after k that differs from point k (line.size if none): runs of equal
// consecutive points are merged (docs/kernels.md, "Choices").
std::size_t next_run(const Line& p, std::size_t k) {
  const Vec3 here = p[k];
  while (++k < p.size && p[k] == here) {
  }
  return k;
}

// The last point before k that differs from point k (line.size if none).
std::size_t previous_run(const Line& p, std::size_t k) {
  const Vec3 here = p[k];
  while (k-- > 0) {
    if (!(p[k] == here)) return k;
  }
  return p.size;
}

// Forrest's F-mesh rule between `previous` and `next` (docs/marks.md): the direction of next -
// previous, the length of the shorter of the chords `back` and `ahead` to the point between them;
// no direction when the line turns back onto the previous point.
Vec3 f_mesh(Vec3 previous, Vec3 next, double back, double ahead) {
  const double across = chord_length(previous, next);
  if (!(across > 0)) return {};
  return (std::min(back, ahead) / across) * (next - previous);
}

// Marks's end rule, "computed to make ends parabolas": P'(1) = 2(P(2) - P(1)) - P'(2).
Vec3 parabolic_end(Vec3 end, Vec3 neighbour, Vec3 neighbour_tangent) {
  return 2 * (neighbour - end) - neighbour_tangent;
}

template <class Set>
void fill(std::size_t first, std::size_t last, Vec3 t, const Set& set) {
  for (std::size_t k = first; k < last; ++k) set(k, t);
}

// Marks's tangents along one line, set(k, tangent) for every point: the rules of marks.h on the
// runs of equal points, s0 < s1 < s2 the first points of three consecutive runs.
template <class Set>
void tangents_on(const Line& p, const Set& set) {
  const std::size_t n = p.size;
  if (n == 0) return;
  std::size_t s0 = 0, s1 = next_run(p, s0);
  if (s1 == n) {
    fill(0, n, Vec3{}, set);  // one point, or all coincide: no direction
    return;
  }
  std::size_t s2 = next_run(p, s1);
  if (s2 == n) {
    fill(0, n, p[s1] - p[s0], set);  // two distinct points: the chord at both
    return;
  }
  // Each chord is computed once: `back` from run s0 to s1, `ahead` from s1 to s2.
  double back = chord_length(p[s0], p[s1]), ahead = chord_length(p[s1], p[s2]);
  Vec3 t1 = f_mesh(p[s0], p[s2], back, ahead);
  fill(s0, s1, parabolic_end(p[s0], p[s1], t1), set);
  for (;;) {
    fill(s1, s2, t1, set);
    const std::size_t s3 = next_run(p, s2);
    if (s3 == n) {
      fill(s2, n, 2 * (p[s2] - p[s1]) - t1, set);  // P'(m) = 2(P(m) - P(m-1)) - P'(m-1)
      return;
    }
    back = ahead;
    ahead = chord_length(p[s2], p[s3]);
    t1 = f_mesh(p[s1], p[s3], back, ahead);
    s0 = s1, s1 = s2, s2 = s3;
  }
}

// Marks's tangent at one end of a line and the chord of its end arc (0 when all points coincide),
// computed from the three distinct points nearest that end: O(1) without repeated points.
struct End {
  Vec3 tangent;
  double chord = 0;
};

End first_end(const Line& p) {
  const std::size_t n = p.size;
  if (n == 0) return {};
  const std::size_t s1 = next_run(p, 0);
  if (s1 == n) return {};
  const double chord = chord_length(p[0], p[s1]);
  const std::size_t s2 = next_run(p, s1);
  if (s2 == n) return {p[s1] - p[0], chord};
  const Vec3 t1 = f_mesh(p[0], p[s2], chord, chord_length(p[s1], p[s2]));
  return {parabolic_end(p[0], p[s1], t1), chord};
}

// The same expressions as tangents_on's last run, so that both give the same bits.
End last_end(const Line& p) {
  const std::size_t n = p.size;
  if (n == 0) return {};
  const std::size_t e0 = n - 1, e1 = previous_run(p, e0);
  if (e1 == n) return {};
  const double chord = chord_length(p[e1], p[e0]);
  const std::size_t e2 = previous_run(p, e1);
  if (e2 == n) return {p[e0] - p[e1], chord};
  const Vec3 t1 = f_mesh(p[e2], p[e0], chord_length(p[e2], p[e1]), chord);
  return {2 * (p[e0] - p[e1]) - t1, chord};
}

// A tangent per unit of patch parameter as IGDS stores it, per unit of chord (docs/kernels.md);
// divided, not multiplied by 1/chord, so that COONS's product by the chord comes back within an
// ulp.
Vec3 per_chord(Vec3 t, double chord) {
  return chord > 0 ? Vec3{t.x / chord, t.y / chord, t.z / chord} : Vec3{};
}

struct Pair {
  Vec3 first, last;
};

// INPTG with the point numbers of workspace/state.h in column 4 and the tangents row(curve?, k)
// gives for the ends of curve or stringer k.
template <class Row>
Array border_array(std::size_t nc, std::size_t ns, const Row& row) {
  Array inptg({2 * (nc + ns), 4});
  double* r = inptg.data();
  auto put = [&r](Vec3 t, std::size_t point) {
    t.store(r);
    r[3] = double(point);
    r += 4;
  };
  for (std::size_t i = 0; i < nc; ++i) {
    const auto [first, last] = row(true, i);
    put(first, i * ns + 1);
    put(last, i * ns + ns);
  }
  for (std::size_t j = 0; j < ns; ++j) {
    const auto [first, last] = row(false, j);
    put(first, j + 1);
    put(last, (nc - 1) * ns + j + 1);
  }
  return inptg;
}

}  // namespace

void marks_tangents(Vec3View points, std::span<Vec3> out) {
  assert(out.size() == points.size());
  tangents_on(Line{points.data(), 3, points.size()}, [&out](std::size_t k, Vec3 t) { out[k] = t; });
}

GridTangents marks_grid_tangents(int nocur, int nostr, Vec3View points) {
  const std::size_t nc = nocur, ns = nostr;
  assert(points.size() == nc * ns);
  GridTangents t;
  t.units = TangentUnits::per_parameter;
  // Each family's tangents are made on a thread of its own, which also writes them first.
  auto curves = [&] {
    t.along_curves.resize(nc * ns);
    for (std::size_t i = 0; i < nc; ++i) {
      Vec3* out = t.along_curves.data() + i * ns;
      tangents_on(curve(points, ns, i), [out](std::size_t k, Vec3 v) { out[k] = v; });
    }
  };
  // A column's points are 24 NOSTR bytes apart: copied side by side (stringer_tangents).
  auto stringers = [&] {
    stringer_tangents(nc, ns, points, t.along_stringers,
                      [&](std::size_t, std::size_t width, const double* columns, Vec3* out) {
                        for (std::size_t c = 0; c < width; ++c) {
                          Vec3* column = out + c * nc;
                          tangents_on(Line{columns + 3 * c * nc, 3, nc},
                                      [column](std::size_t k, Vec3 v) { column[k] = v; });
                        }
                      });
  };
  // The two families are independent: one thread each when the grid is large (as grid_tangents).
  parallel_for(2, threads_for(nc * ns * 12) > 1 ? 2 : 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t task = first; task < last; ++task) task == 0 ? curves() : stringers();
  });
  return t;
}

Array marks_border_tangents(int nocur, int nostr, Vec3View points) {
  const std::size_t nc = nocur, ns = nostr;
  assert(points.size() == nc * ns);
  return border_array(nc, ns, [&](bool along_curve, std::size_t k) {
    const Line line = along_curve ? curve(points, ns, k) : stringer(points, nc, ns, k);
    const End first = first_end(line), last = last_end(line);
    return Pair{per_chord(first.tangent, first.chord), per_chord(last.tangent, last.chord)};
  });
}

Array border_tangents_of(int nocur, int nostr, Vec3View points, const GridTangents& tangents) {
  const std::size_t nc = nocur, ns = nostr;
  assert(points.size() == nc * ns);
  const bool scaled = tangents.units == TangentUnits::per_parameter;
  return border_array(nc, ns, [&](bool along_curve, std::size_t k) {
    const Line line = along_curve ? curve(points, ns, k) : stringer(points, nc, ns, k);
    const auto& t = along_curve ? tangents.along_curves : tangents.along_stringers;
    const std::size_t k0 = along_curve ? k * ns : k;
    const std::size_t k1 = along_curve ? k * ns + ns - 1 : (nc - 1) * ns + k;
    if (!scaled) return Pair{t[k0], t[k1]};
    return Pair{per_chord(t[k0], first_end(line).chord), per_chord(t[k1], last_end(line).chord)};
  });
}

Array marks_twists(int nocur, int nostr, Vec3View points) {
  const std::size_t nc = nocur, ns = nostr;
  assert(points.size() == nc * ns);
  Array twists({nc * ns, 3});
  auto out = as_vec3(twists);
  // Border points keep zero (marks.h); the interior has all four diagonal neighbours.
  for (std::size_t i = 1; i + 1 < nc; ++i) {
    for (std::size_t j = 1; j + 1 < ns; ++j) {
      const std::size_t k = i * ns + j;
      // Differences of neighbours first, so that a surface far from the origin loses nothing.
      const Vec3 below = Vec3(points[k + ns + 1]) - points[k + ns - 1];
      const Vec3 above = Vec3(points[k - ns + 1]) - points[k - ns - 1];
      out[k] = 0.25 * (below - above);
    }
  }
  return twists;
}

}  // namespace igds
