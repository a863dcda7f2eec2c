// Workspaces with every variable filled, for the disk tests: values that a careless copy would
// change (-0.0, denormals, huge and tiny numbers) in every array.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include <doctest/doctest.h>

#include "tests/support/process.h"
#include "workspace/images.h"
#include "workspace/kernels/surface.h"
#include "workspace/state.h"

namespace igds::test {

// Deterministic values, a few of them special; NaNs only where `finite` is false (no variable of
// the workspace holds a number that is not finite: workspace/variables.h, finite_problem).
inline void fill(Array& a, std::uint64_t seed, bool finite = true) {
  std::uint64_t x = seed * 0x9E3779B97F4A7C15ull + 1;
  for (std::size_t i = 0; i < a.ravel.size(); ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    double v = static_cast<double>(x % 2000001) / 1000.0 - 1000.0;
    switch (i % 97) {
      case 3:
        v = -0.0;
        break;
      case 5:
        v = std::numeric_limits<double>::denorm_min() * 3;
        break;
      case 7:
        if (!finite) v = std::bit_cast<double>(0x7FF8000000000123ull);  // NaN with a payload
        break;
      case 11:
        v = 1e150;  // large, yet the surface of such points interpolates to finite numbers
        break;
      case 13:
        v = -1.0 / 3.0;
        break;
    }
    a.ravel[i] = v;
  }
}

inline Image make_image(int what, Projection projection, std::size_t curves, std::size_t rows,
                        std::uint64_t seed) {
  Image image;
  image.desim.what = what;
  image.desim.projection = projection;
  image.desim.parameters = {-0.0, 110.5, 1e-310};
  image.points = Array({curves, rows, 2});
  fill(image.points, seed);
  if (what == 0) {
    image.arrows = Array({3, 4});
    fill(image.arrows, seed + 1);
  }
  return image;
}

// A surface of NOCUR x NOSTR input points with INTCU, INTST: every array with its shape, PATCHES
// and INTPN not an interpolation of the inputs (as the APL environment may leave them: the
// session saves them then).
inline Workspace make_workspace(int nocur, int nostr, int intcu, int intst, bool images = true) {
  Workspace ws;
  ws.nocur = nocur;
  ws.nostr = nostr;
  ws.intcu = intcu;
  ws.intst = intst;
  auto cu = static_cast<std::size_t>(nocur), st = static_cast<std::size_t>(nostr);
  ws.inppn = Array({cu * st, 3});
  fill(ws.inppn, 1);
  ws.inptg = Array({2 * (cu + st), 4});
  fill(ws.inptg, 2);
  for (std::size_t r = 0; r < 2 * (cu + st); ++r)  // column 4: a point number
    ws.inptg.ravel[4 * r + 3] = double(r % (cu * st) + 1);
  ws.patches = Array({cu - 1, st - 1, 3, 4, 4});
  fill(ws.patches, 3);
  ws.intpn = Array({cu + static_cast<std::size_t>(intcu) * (cu - 1),
                    st + static_cast<std::size_t>(intst) * (st - 1), 3});
  fill(ws.intpn, 4);
  ws.changes.derived = false;
  if (images) {
    ws.image = std::make_shared<const Image>(
        make_image(1, Projection::conic, ws.intpn.shape[0], ws.intpn.shape[1], 5));
    ws.temp1 = std::make_shared<const Image>(make_image(0, Projection::isometric, cu, st, 6));
    ws.temp2 = std::make_shared<const Image>(make_image(1, Projection::assonometric, 2, 3, 7));
  }
  ws.status = {0, 2, 0, 0, 0, 0, 0, 0, 0, 7};
  return ws;
}

// A surface as BUILD makes it (PATCHES and INTPN its interpolation: the session does not save
// them, and PATCHES are not kept) with images drawn from it as DISPLAY draws them (recipes for the
// session).
inline Workspace make_interpolated(int nocur, int nostr, int intcu, int intst) {
  Workspace ws;
  ws.nocur = nocur;
  ws.nostr = nostr;
  ws.intcu = intcu;
  ws.intst = intst;
  auto cu = static_cast<std::size_t>(nocur), st = static_cast<std::size_t>(nostr);
  ws.inppn = Array({cu * st, 3});
  for (std::size_t i = 0; i < cu; ++i)
    for (std::size_t j = 0; j < st; ++j) {
      double* p = ws.inppn.data() + 3 * (i * st + j);
      p[0] = 10.0 * double(j);
      p[1] = 7.0 * double(i) + 0.1 * double(j);
      p[2] = std::sin(0.3 * double(i)) * std::cos(0.2 * double(j)) - 0.0;
    }
  ws.inptg = Array({2 * (cu + st), 4});
  for (std::size_t r = 0; r < 2 * cu; ++r) {  // along the curves at their ends
    ws.inptg.ravel[4 * r] = 1;
    ws.inptg.ravel[4 * r + 3] = double((r / 2) * st + (r % 2 ? st : 1));
  }
  for (std::size_t r = 0; r < 2 * st; ++r) {  // along the stringers at their ends
    ws.inptg.ravel[4 * (2 * cu + r) + 1] = 1;
    ws.inptg.ravel[4 * (2 * cu + r) + 3] = double((r % 2 ? (cu - 1) * st : 0) + r / 2 + 1);
  }
  Surface s;
  (void)interpolate_into({nocur, nostr, intcu, intst, &ws.inppn, &ws.inptg}, s,
                         PatchesOut::dropped);
  ws.patches = std::move(s.patches);
  ws.intpn = std::move(s.intpn);
  ws.image =
      std::make_shared<const Image>(image_of(ws, {1, Projection::assonometric, {110, 130, 120}}));
  ws.temp1 = ws.image;
  ws.temp2 = std::make_shared<const Image>(image_of(ws, {0, Projection::isometric, {3, 30, 0}}));
  ws.status = {1, 1, 0, 0, 0, 0, 0, 0, 0, 0};
  return ws;
}

inline bool same_bits(const Array& a, const Array& b) {
  return a.shape == b.shape && a.ravel.size() == b.ravel.size() &&
         (a.ravel.empty() ||
          std::memcmp(a.ravel.data(), b.ravel.data(), a.ravel.size() * sizeof(double)) == 0);
}

inline bool same_bits(const ImageRef& a, const ImageRef& b) {
  if (!a || !b) return !a && !b;
  return a->desim.what == b->desim.what && a->desim.projection == b->desim.projection &&
         std::memcmp(&a->desim.parameters, &b->desim.parameters, sizeof a->desim.parameters) == 0 &&
         same_bits(a->points, b->points) && same_bits(a->arrows, b->arrows);
}

// Replaces a file by removing it first: truncating one in place can make the file system
// flush it (ext4's auto_da_alloc), which would make the many-damaged-files tests slow.
inline void rewrite_file(const std::filesystem::path& path, std::string_view bytes) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
  write_file(path, bytes);
}

// PATCHES as the workspace gives them (made from the inputs when it keeps none).
inline Array given_patches(const Workspace& ws) {
  Array made;
  return patches_of(ws, made);
}

// PATCHES and INTPN made the workspace's own, as END APL leaves them when one of them is assigned:
// PATCHES kept first (state.h), then another surface whose arrays the session keeps.
inline void own_surface(Workspace& ws) {
  keep_patches(ws);
  ws.changes.surface = new_generation();
  ws.changes.derived = false;
}

// PATCHES as each workspace gives them, bit for bit.
inline bool same_patches(const Workspace& a, const Workspace& b) {
  return same_bits(given_patches(a), given_patches(b));
}

// Every variable, bit for bit, as one answer (for searching a list of states).
inline bool same_workspace(const Workspace& a, const Workspace& b) {
  return a.nocur == b.nocur && a.nostr == b.nostr && a.intcu == b.intcu && a.intst == b.intst &&
         same_bits(a.inppn, b.inppn) && same_bits(a.inptg, b.inptg) && same_patches(a, b) &&
         same_bits(a.intpn, b.intpn) && same_bits(a.image, b.image) &&
         same_bits(a.temp1, b.temp1) && same_bits(a.temp2, b.temp2) && a.status == b.status;
}

// Every variable, bit for bit (operator== would call -0.0 and 0.0 equal and NaN unequal).
inline void check_same_surface(const Workspace& a, const Workspace& b) {
  CHECK(a.nocur == b.nocur);
  CHECK(a.nostr == b.nostr);
  CHECK(a.intcu == b.intcu);
  CHECK(a.intst == b.intst);
  CHECK(same_bits(a.inppn, b.inppn));
  CHECK(same_bits(a.inptg, b.inptg));
  CHECK(same_patches(a, b));
  CHECK(same_bits(a.intpn, b.intpn));
}

// The tangents and twists the workspace keeps with its surface: there, and those of its inputs
// (the PATCHES made from them are those made from nothing kept).
inline void check_kept_splines(const Workspace& ws) {
  const auto kept = kept_splines(ws);
  REQUIRE(kept != nullptr);
  const SurfaceInput input = surface_input(ws);
  CHECK(surface_patches(input, kept) == surface_patches(input));
}

inline void check_same_workspace(const Workspace& a, const Workspace& b) {
  check_same_surface(a, b);
  CHECK(same_bits(a.image, b.image));
  CHECK(same_bits(a.temp1, b.temp1));
  CHECK(same_bits(a.temp2, b.temp2));
  CHECK(a.status == b.status);
  CHECK(a.functions == b.functions);
  CHECK(a.apl_variables == b.apl_variables);
}

}  // namespace igds::test
