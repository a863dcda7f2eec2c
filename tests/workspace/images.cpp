// workspace/images.h and state.h: a deferred image made once, at its first look.
#include "workspace/images.h"

#include <doctest/doctest.h>

#include <fmt/format.h>

#include <optional>

#include "tests/workspace/disk_fixtures.h"
#include "workspace/kernels/curvature.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/fit.h"
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

// The report of an image refused (none when it was made).
std::optional<DataError> refusal(const auto& make) {
  try {
    (void)make();
  } catch (const DataError& e) {
    return e;
  }
  return std::nullopt;
}

// `ws` with INTPN made again from its inputs, as BUILD makes it (PATCHES not kept).
Workspace interpolated_again(Workspace ws) {
  Surface s;
  REQUIRE(!interpolate_into(surface_input(ws), s, PatchesOut::dropped));
  ws.intpn = std::move(s.intpn);
  return ws;
}

// 274 x 274 points: more than threads_for makes one part of (six numbers a point), and more than
// DISPLAY COMBS takes at a time. Input curve `curve` zigzags (by default the last: the highest
// points and the sharpest bends are in the last rows).
Workspace zigzag_surface(std::size_t curve = 39) {
  Workspace ws = test::make_interpolated(40, 40, 6, 6);
  for (std::size_t j = 0; j < 40; ++j) ws.inppn.ravel[3 * (curve * 40 + j) + 2] += j % 2 ? 50 : 0;
  return interpolated_again(std::move(ws));
}

// DISPLAY COMBS of `ws` in four views (the last CONIC, from far above) against one pass over the
// whole grid: the box, the largest curvature, each comb's end p - s k.
void check_combs(const Workspace& ws) {
  const auto points = as_vec3(ws.intpn);
  Array made;
  const Array bends = grid_curvature(surface_input(ws), patches_of(ws, made));
  const auto bend = as_vec3(bends);  // two a point: the curve's, the stringer's
  Box3 box;
  double most = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    box.add(points[k]);
    for (std::size_t d = 0; d < 2; ++d) most = std::max(most, norm(bend[2 * k + d]));
  }
  REQUIRE(most > 0);
  const Vec3 size = box.hi - box.lo;
  const double scale = comb_scale_for(std::max({size.x, size.y, size.z}), most);
  std::vector<double> ends(bends.size());
  for (std::size_t k = 0; k < bend.size(); ++k)
    (points[k / 2] - scale * Vec3(bend[k])).store(ends.data() + 3 * k);
  const Vec3 centre = bounding_box_centre(as_vec3(ws.inppn));
  auto seen = [&](const View& view, const double* in) {
    std::vector<double> xy(2 * bend.size());
    project(view, centre, Vec3View(in, bend.size()), MutablePoint2View(xy.data(), bend.size()));
    return xy;
  };
  const double extent = std::max({size.x, size.y, size.z});
  const View far_above{Projection::conic,
                       {box.centre().x, box.centre().y, box.hi.z + 100 * extent}};
  for (const View& view :
       {View{Projection::isometric, {3, 30, 0}}, View{Projection::assonometric, {110, 130, 120}},
        View{Projection::orthogonal, {2, 0, 0}}, far_above}) {
    CAPTURE(int(view.projection));
    const Image image = comb_image(ws, view);
    CHECK(image.comb_scale == scale);
    const std::vector<double> xy = seen(view, ends.data());
    REQUIRE(image.combs.size() == xy.size());
    if (view.projection == Projection::conic) {
      CHECK(std::equal(xy.begin(), xy.end(), image.combs.ravel.begin()));
      continue;
    }
    // A parallel projection is linear: each comb is the image of its point less s times the
    // image of its curvature vector (by the projection's map), the same as the image of its end
    // within rounding.
    const ProjectiveMap map = projection_map(view, {});
    const double within = 1e-12 * extent;
    std::size_t same = 0, near = 0;
    for (std::size_t k = 0; k < xy.size(); ++k) {
      const double bent = map.apply(bend[k / 2])[k % 2];
      const double comb = image.points.ravel[(k >> 2) * 2 + (k & 1)] - scale * bent;
      same += image.combs.ravel[k] == comb;
      near += std::abs(image.combs.ravel[k] - xy[k]) <= within;
    }
    CHECK(same == xy.size());
    CHECK(near == xy.size());
  }
}

TEST_CASE("DISPLAY COMBS of a grid made in parts: its scale and combs as one pass makes them") {
  const Workspace ws = zigzag_surface();
  REQUIRE(threads_for(6 * ws.intpn.size() / 3) == cores());
  // The sharpest bends are in the last rows: not in the first part.
  Array made;
  const Array bends = grid_curvature(surface_input(ws), patches_of(ws, made));
  const auto bend = as_vec3(bends);
  std::size_t where = 0;
  for (std::size_t k = 0; k < bend.size(); ++k)
    if (norm(bend[k]) > norm(bend[where])) where = k;
  CHECK(where >= bend.size() / 2);
  check_combs(ws);
}

// The largest curvature on the rows of comb_guess_rows (the guess of DISPLAY COMBS CONIC), then
// the whole grid's.
std::pair<double, double> guessed_and_whole(const Workspace& ws) {
  Array made;
  const Array bends = grid_curvature(surface_input(ws), patches_of(ws, made));
  const auto bend = as_vec3(bends);
  const std::size_t cols = intpn_shape(ws.nocur, ws.nostr, ws.intcu, ws.intst).cols;
  const std::vector<std::size_t> rows = comb_guess_rows(ws);
  double most = 0, sampled = 0;
  for (std::size_t k = 0; k < bend.size(); ++k) {
    most = std::max(most, norm(bend[k]));
    if (std::binary_search(rows.begin(), rows.end(), k / 2 / cols))
      sampled = std::max(sampled, norm(bend[k]));
  }
  return {sampled, most};
}

// The scale of the combs of `ws` with the largest curvature `most`.
double scale_of(const Workspace& ws, double most) {
  const Box3 box = bounding_box(as_vec3(ws.intpn));
  const Vec3 size = box.hi - box.lo;
  return comb_scale_for(std::max({size.x, size.y, size.z}), most);
}

TEST_CASE("DISPLAY COMBS CONIC guesses its scale from some rows, made again if it was wrong") {
  // Every eighth row of patches (7 lines each), and those on either side of input curve 20: its
  // zigzag bends both its curve and the stringers that cross it most sharply there.
  const Workspace zigzag = zigzag_surface(20);
  std::vector<std::size_t> expected;
  for (const std::size_t q : {0, 8, 16, 19, 20, 24, 32})
    for (std::size_t row = 7 * q; row < 7 * q + 7; ++row) expected.push_back(row);
  CHECK(comb_guess_rows(zigzag) == expected);
  // Its first curve made a pole (every point one): no circle passes through three of its
  // points, and the search along the curves goes on past them to the zigzag; the stringers bend
  // most as they leave the pole, in the first two rows of patches.
  Workspace pole = zigzag;
  for (std::size_t j = 1; j < 40; ++j)
    for (std::size_t c = 0; c < 3; ++c) pole.inppn.ravel[3 * j + c] = pole.inppn.ravel[c];
  pole = interpolated_again(std::move(pole));
  std::vector<std::size_t> with_pole = expected;
  for (std::size_t row = 7; row < 14; ++row) with_pole.push_back(row);
  std::sort(with_pole.begin(), with_pole.end());
  CHECK(comb_guess_rows(pole) == with_pole);
  // Its sharpest bends are near the curve, and the guess is the whole's.
  const auto [sampled, most] = guessed_and_whole(zigzag);
  CHECK(scale_of(zigzag, sampled) == scale_of(zigzag, most));
  check_combs(zigzag);
  // Stringer 20 made to end upright on the last curve: it bends most in the last row of patches,
  // not among those rows (its input points are the same), and the combs are made again.
  Workspace upright = test::make_interpolated(40, 40, 6, 6);
  const std::size_t end = 2 * 40 + 2 * 20 + 1;  // INPTG: the curves' ends, then the stringers'
  upright.inptg.ravel[4 * end] = 0, upright.inptg.ravel[4 * end + 1] = 0;
  upright.inptg.ravel[4 * end + 2] = 1;
  upright = interpolated_again(std::move(upright));
  CHECK(comb_guess_rows(upright).back() < 38 * 7);
  const auto [upright_sampled, upright_most] = guessed_and_whole(upright);
  CHECK(scale_of(upright, upright_sampled) != scale_of(upright, upright_most));
  check_combs(upright);
}

TEST_CASE("DISPLAY COMBS of a single curve or stringer: the combs of its spline") {
  Workspace curve = test::make_interpolated(1, 30, 1, 4);
  for (std::size_t j = 0; j < 30; ++j) curve.inppn.ravel[3 * j + 2] = std::sin(0.4 * double(j));
  check_combs(interpolated_again(std::move(curve)));
  Workspace stringer = test::make_interpolated(30, 1, 4, 1);
  for (std::size_t i = 0; i < 30; ++i) stringer.inppn.ravel[3 * i + 2] = std::cos(0.3 * double(i));
  check_combs(interpolated_again(std::move(stringer)));
}

TEST_CASE("DISPLAY COMBS in another view takes the scale of combs drawn from the same surface") {
  Workspace ws = zigzag_surface();
  const View far_above{Projection::conic, {140, 140, 1000}};
  const View views[] = {
      {Projection::isometric, {3, 30, 0}}, {Projection::assonometric, {110, 130, 120}}, far_above};
  // Each view alone, then after the combs of another: the same image, bit for bit.
  for (const View& view : views)
    for (const View& before : views) {
      CAPTURE(int(view.projection));
      CAPTURE(int(before.projection));
      ws.image = nullptr;
      const Image alone = comb_image(ws, view);
      ws.image = std::make_shared<const Image>(comb_image(ws, before));
      const Image after = comb_image(ws, view);
      CHECK(after.comb_scale == alone.comb_scale);
      CHECK(after.combs == alone.combs);
      CHECK(after.points == alone.points);
    }
  // The scale is read from IMAGE, FIRST or SECOND when they hold combs of this surface, made: a
  // kept image given a scale of its own shows which one is read.
  ws.image = nullptr;
  const Image made = comb_image(ws, views[0]);
  auto kept = [&](double scale, int what, std::uint64_t drawn_from) {
    auto image = std::make_shared<Image>(made);
    image->comb_scale = scale, image->desim.what = what, image->drawn_from = drawn_from;
    return ImageRef(std::shared_ptr<const Image>(std::move(image)));
  };
  const std::uint64_t surface = ws.changes.surface;
  const double half = made.comb_scale / 2, quarter = made.comb_scale / 4;
  ws.temp1 = kept(half, 3, surface);
  CHECK(comb_image(ws, views[1]).comb_scale == half);
  ws.temp1 = nullptr, ws.temp2 = kept(quarter, 3, surface);
  CHECK(comb_image(ws, far_above).comb_scale == quarter);
  // Not from a surface image, nor from combs of another surface, nor from one not made yet (it is
  // not made for this).
  ws.temp2 = nullptr;
  ws.image = kept(half, 1, surface);
  CHECK(comb_image(ws, views[1]).comb_scale == made.comb_scale);
  ws.image = kept(half, 3, surface + 1);
  CHECK(comb_image(ws, views[1]).comb_scale == made.comb_scale);
  int makes = 0;
  ws.image = ImageRef::deferred(
      [&] {
        ++makes;
        return *kept(half, 3, surface);
      },
      surface, made.desim);
  CHECK(comb_image(ws, views[1]).comb_scale == made.comb_scale);
  CHECK(makes == 0);
  // A surface changed has its own scale: ten times as large, a hundred times the scale.
  ws.image = kept(made.comb_scale, 3, surface);
  for (double& x : ws.inppn.ravel) x *= 10;
  ws = interpolated_again(std::move(ws));
  ws.changes.replaced();
  CHECK(comb_image(ws, views[1]).comb_scale == 100 * made.comb_scale);
}

TEST_CASE("DISPLAY COMBS CONIC refuses a view point among the combs, not only among the points") {
  const Workspace ws = zigzag_surface();
  const auto points = as_vec3(ws.intpn);
  const Box3 box = bounding_box(points);
  const Vec3 low = box.lo, high = box.hi;
  // Just above the highest point: outside the surface's box, inside the box of the combs (those
  // above the zigzag's crests reach higher). Over the first curve, in the box of none of the rows
  // DISPLAY COMBS projects at a time; over the middle, looking down, the combs that reach above
  // the eye are behind it too, and the report is still the box's.
  const double z = high.z + 1e-3 * (high.z - low.z);
  for (double y : {low.y + 1, (low.y + high.y) / 2}) {
    const View view{Projection::conic, {(low.x + high.x) / 2, y, z}};
    CHECK_NOTHROW((void)surface_image(ws, view));
    const std::optional<DataError> e = refusal([&] { return comb_image(ws, view); });
    REQUIRE(e);
    CHECK(e->problem == DataError::Problem::view_inside_box);
  }
  // From far above, the same combs are drawn.
  const View view{Projection::conic, {(low.x + high.x) / 2, low.y + 1, z}};
  const View above{Projection::conic, {view.parameters[0], view.parameters[1], 100 * high.z}};
  CHECK(comb_image(ws, above).combs.size() == 4 * points.size());
}

// A bowl, 9 x 9 points 10 apart, z = r^2 / 40 about its middle: every comb stands below it and,
// at the rim, out beyond its points.
Workspace bowl_surface() {
  Workspace ws = test::make_interpolated(9, 9, 4, 4);
  auto height = [](double x, double y) { return ((x - 40) * (x - 40) + (y - 40) * (y - 40)) / 40; };
  for (std::size_t i = 0; i < 9; ++i)
    for (std::size_t j = 0; j < 9; ++j) {
      const double x = 10.0 * double(j), y = 10.0 * double(i);
      Vec3{x, y, height(x, y)}.store(ws.inppn.data() + 3 * (i * 9 + j));
    }
  // The border tangents of the paraboloid: slope (x - 40) / 20 along x, likewise along y.
  for (std::size_t r = 0; r < 36; ++r) {
    const bool curve = r < 18, end = r % 2 == 1;
    const double slope = end ? 2 : -2;
    const Vec3 t = (1 / std::sqrt(5.0)) * (curve ? Vec3{1, 0, slope} : Vec3{0, 1, slope});
    t.store(ws.inptg.data() + 4 * r);
  }
  return interpolated_again(std::move(ws));
}

TEST_CASE("DISPLAY COMBS CONIC refuses a comb behind the eye, the eye outside every box") {
  // The eye beside the rim, beyond the points but among the combs' ends in x, above the highest
  // end and below the highest point: in neither box, the points in front of it, the combs that
  // stand out beyond it behind it. Only the combs' report can refuse the image.
  const Workspace ws = bowl_surface();
  const auto points = as_vec3(ws.intpn);
  Array made;
  const Array bends = grid_curvature(surface_input(ws), patches_of(ws, made));
  const double scale = comb_image(ws, {Projection::isometric, {3, 30, 0}}).comb_scale;
  Box3 ends;
  for (std::size_t k = 0; k < 2 * points.size(); ++k)
    ends.add(points[k / 2] - scale * Vec3::load(bends.data() + 3 * k));
  const Box3 box = bounding_box(points);
  REQUIRE(ends.hi.x > box.hi.x);
  REQUIRE(ends.hi.z < box.hi.z);
  const Vec3 eye{(box.hi.x + ends.hi.x) / 2, 40, (ends.hi.z + box.hi.z) / 2};
  CHECK_FALSE(ends.contains(eye));
  const View view{Projection::conic, {eye.x, eye.y, eye.z}};
  CHECK_NOTHROW((void)surface_image(ws, view));
  const std::optional<DataError> e = refusal([&] { return comb_image(ws, view); });
  REQUIRE(e);
  CHECK(e->problem == DataError::Problem::behind_eye);
}

TEST_CASE("DISPLAY COMBS CONIC from the origin, the surface away from it") {
  Workspace ws = test::make_interpolated(3, 3, 1, 1);
  for (double& x : ws.inppn.ravel) x += 100;
  ws = interpolated_again(std::move(ws));
  const View origin{Projection::conic, {0, 0, 0}};
  CHECK(comb_image(ws, origin).combs.size() == 4 * ws.intpn.size() / 3);
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

TEST_CASE("DISPLAY COMBS refuses a comb whose image overflows, naming its point") {
  // Coordinates near the largest numbers and a peak at the middle point: the points' images are
  // finite, the combs standing above the peak reach beyond the largest number.
  Workspace ws = test::make_interpolated(3, 3, 3, 3);
  for (double& x : ws.inppn.ravel) x *= 1e306;
  ws.inppn.ravel[3 * 4 + 2] = 1.7e308;
  ws = interpolated_again(std::move(ws));
  const std::size_t cols = ws.intpn.shape[1];
  // The first comb whose end is not finite, as one pass over the whole grid finds it.
  Array made;
  const Array bends = grid_curvature(surface_input(ws), patches_of(ws, made));
  const auto points = as_vec3(ws.intpn);
  const auto bend = as_vec3(bends);
  const Box3 box = bounding_box(points);
  double most = 0;
  for (std::size_t k = 0; k < bend.size(); ++k) most = std::max(most, norm(bend[k]));
  const Vec3 size = box.hi - box.lo;
  const double scale = comb_scale_for(std::max({size.x, size.y, size.z}), most);
  std::size_t first = bend.size();
  for (std::size_t k = 0; k < bend.size() && first == bend.size(); ++k)
    if (!std::isfinite((points[k / 2] - scale * Vec3(bend[k])).z)) first = k;
  REQUIRE(first < bend.size());
  const View xz{Projection::orthogonal, {2, 0, 0}};
  CHECK_NOTHROW((void)surface_image(ws, xz));
  // Refused alike when the scale is read from combs of the surface drawn before.
  auto combs_before = std::make_shared<Image>(surface_image(ws, xz));
  combs_before->desim.what = 3, combs_before->comb_scale = scale;
  for (const ImageRef& before : {ImageRef(), ImageRef(std::move(combs_before))}) {
    ws.image = before;
    const std::optional<DataError> e = refusal([&] { return comb_image(ws, xz); });
    REQUIRE(e);
    CHECK(e->problem == DataError::Problem::image_not_finite);
    CHECK(e->variable == "INTPN");
    CHECK(e->number == first / 2 / cols + 1);
    CHECK(e->column == first / 2 % cols + 1);
  }
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
