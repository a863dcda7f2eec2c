// workspace/images.h and state.h: a deferred image made once, at its first look.
#include "workspace/images.h"

#include <doctest/doctest.h>

#include <fmt/format.h>

#include "tests/workspace/disk_fixtures.h"
#include "workspace/kernels/curvature.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/project.h"

namespace igds {
namespace {

TEST_CASE("a deferred image is made once, at its first look; a failed make again") {
  int makes = 0;
  const Description desim{1, Projection::isometric, {3, 30, 0}};
  const ImageRef ref = ImageRef::deferred(
      [&] {
        if (++makes == 1) throw DataError(DataError::Problem::view_inside_box);
        Image image;
        image.desim = desim;
        image.points = Array({2, 2, 2});
        image.drawn_from = 5;
        return image;
      },
      5, desim);
  CHECK(!ref.made());
  CHECK(ref.recipe() == std::pair{std::uint64_t{5}, desim});  // known without making it
  CHECK(makes == 0);
  // A make that fails leaves the recipe: the next look tries again.
  CHECK_THROWS_AS(static_cast<void>(*ref), DataError);
  CHECK(!ref.made());
  const ImageRef shared = ref;  // STORE FIRST: the same image
  const Image* seen = &*ref;
  CHECK(makes == 2);
  CHECK(&*shared == seen);  // not made again
  CHECK(makes == 2);
  CHECK(shared.made());
  CHECK(ref.recipe() == std::pair{std::uint64_t{5}, desim});
}

// 274 x 274 points: more than threads_for makes one part of (six numbers a point), and more than
// DISPLAY COMBS takes at a time. The last curve zigzags: the highest points and the sharpest
// bends are in the last rows.
Workspace zigzag_surface() {
  Workspace ws = test::make_interpolated(40, 40, 6, 6);
  for (std::size_t j = 0; j < 40; ++j) ws.inppn.ravel[3 * (39 * 40 + j) + 2] += j % 2 ? 50 : 0;
  Surface s;
  REQUIRE(!interpolate_into(surface_input(ws), s, PatchesOut::dropped));
  ws.intpn = std::move(s.intpn);
  return ws;
}

TEST_CASE("DISPLAY COMBS of a grid made in parts: its scale and combs as one pass makes them") {
  const Workspace ws = zigzag_surface();
  const auto points = as_vec3(ws.intpn);
  REQUIRE(threads_for(6 * points.size()) == cores());
  const View view{Projection::isometric, {3, 30, 0}};
  const Image image = comb_image(ws, view);
  // One pass over the points: the box, the largest curvature, then each comb's end.
  Array made;
  Array bends = grid_curvature(surface_input(ws), patches_of(ws, made));
  Vec3 low = points[0], high = low;
  double most = 0;
  std::size_t where = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    low = {std::min(low.x, points[k].x), std::min(low.y, points[k].y),
           std::min(low.z, points[k].z)};
    high = {std::max(high.x, points[k].x), std::max(high.y, points[k].y),
            std::max(high.z, points[k].z)};
    for (std::size_t d = 0; d < 2; ++d) {
      const double bend = norm(Vec3::load(bends.data() + 6 * k + 3 * d));
      if (bend > most) most = bend, where = k;
    }
  }
  CHECK(where >= points.size() / 2);
  const Vec3 size = high - low;
  CHECK(image.comb_scale == comb_scale_for(std::max({size.x, size.y, size.z}), most));
  auto ends = as_vec3(bends);
  for (std::size_t k = 0; k < points.size(); ++k)
    for (std::size_t d = 0; d < 2; ++d)
      ends[2 * k + d] = points[k] - image.comb_scale * Vec3(ends[2 * k + d]);
  std::vector<double> xy(2 * ends.size());
  project(view, bounding_box_centre(as_vec3(ws.inppn)), as_vec3(std::as_const(bends)),
          MutablePoint2View(xy.data(), ends.size()));
  REQUIRE(image.combs.size() == xy.size());
  CHECK(std::equal(xy.begin(), xy.end(), image.combs.ravel.begin()));
}

TEST_CASE("DISPLAY COMBS CONIC refuses a view point among the combs, not only among the points") {
  const Workspace ws = zigzag_surface();
  const auto points = as_vec3(ws.intpn);
  Vec3 low = points[0], high = low;
  for (const Vec3& p : points) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  // Just above the highest point, over the first curve: outside the surface's box, inside the
  // box of the combs (those above the zigzag's crests reach higher), but in the box of none of
  // the rows DISPLAY COMBS projects at a time.
  const View view{Projection::conic,
                  {(low.x + high.x) / 2, low.y + 1, high.z + 1e-3 * (high.z - low.z)}};
  CHECK_NOTHROW((void)surface_image(ws, view));
  try {
    (void)comb_image(ws, view);
    FAIL("a view point among the combs was taken");
  } catch (const DataError& e) {
    CHECK(e.problem == DataError::Problem::view_inside_box);
  }
  // From far above, the same combs are drawn.
  const View above{Projection::conic, {view.parameters[0], view.parameters[1], 100 * high.z}};
  CHECK(comb_image(ws, above).combs.size() == 4 * points.size());
}

TEST_CASE("a projection that overflows is refused, naming the point, row or tangent it came from") {
  // Finite points near the largest numbers: the isometric view adds coordinates that overflow.
  Workspace ws = test::make_interpolated(3, 3, 1, 1);
  const View isometric{Projection::isometric, {3, 30, 0}};
  auto refused = [](auto&& make) {
    try {
      make();
    } catch (const DataError& e) {
      CHECK(e.problem == DataError::Problem::image_not_finite);
      return fmt::format("{} {} {}", e.variable, e.number, e.column);
    }
    return std::string("MADE");
  };
  CHECK(refused([&] { return input_image(ws, isometric); }) == "MADE");
  Workspace huge = ws;
  for (std::size_t c = 0; c < 3; ++c) huge.inppn.ravel[3 * 4 + c] = c == 1 ? -1.7e308 : 1.7e308;
  CHECK(refused([&] { return input_image(huge, isometric); }) == "INPPN 5 1");
  for (std::size_t c = 0; c < 3; ++c)
    huge.intpn.ravel[3 * (5 * 2 + 3) + c] = c == 1 ? -1.7e308 : 1.7e308;
  CHECK(refused([&] { return surface_image(huge, isometric); }) == "INTPN 3 4");
}

TEST_CASE("images drawn from the same surface with the same DESIM are the same, unmade, unread") {
  const Workspace ws = test::make_interpolated(3, 3, 1, 1);
  const auto source = std::make_shared<const Workspace>(ws);
  const Description desim{1, Projection::isometric, {3, 30, 0}};
  const ImageRef a = image_by_recipe(source, desim), b = image_by_recipe(source, desim);
  CHECK(same_image(a, b));
  CHECK_FALSE(a.made());  // known by the recipe alone
  CHECK_FALSE(b.made());
  const ImageRef c = image_by_recipe(source, {1, Projection::isometric, {3, 31, 0}});
  CHECK_FALSE(same_image(a, c));
  // The same image zoomed is another picture on the screen, the same made afresh is not.
  auto zoomed = std::make_shared<Image>(*a);
  zoomed->window = std::array<double, 4>{0, 0, 1, 1};
  CHECK_FALSE(same_image(a, ImageRef(zoomed)));
  CHECK(same_image(a, ImageRef(std::make_shared<const Image>(image_of(ws, desim)))));
  // An image with no recipe (read from a file, assigned in END APL) is compared by its points.
  auto kept = std::make_shared<Image>(*a);
  kept->drawn_from = 0;
  CHECK(same_image(a, ImageRef(kept)));
  kept->points.ravel[0] += 1;
  CHECK_FALSE(same_image(a, ImageRef(kept)));
}

}  // namespace
}  // namespace igds
