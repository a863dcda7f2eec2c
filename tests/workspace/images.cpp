// workspace/images.h and state.h: what a copy of an image keeps; a deferred image made once.
#include "workspace/images.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include <fmt/format.h>

#include "tests/workspace/disk_fixtures.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/large_array.h"

namespace igds {
namespace {

TEST_CASE("copy_of keeps every member of an image, its points too") {
  Image image;
  image.desim = {1, Projection::conic, {30, -20, 15}};
  image.points = Array({3, 4, 2});
  for (std::size_t k = 0; k < image.points.size(); ++k) image.points.ravel[k] = 0.5 * k - 3;
  image.arrows = Array({1, 6});
  image.arrows.ravel = {1, 2, 3, 4, 5, 1};
  image.drawn_from = 7;
  image.file = "ONE.IGDSIMAG";
  image.file_sum = 99;
  image.window = std::array<double, 4>{0, 0, 1, 1};
  image.auto_tangents = true;
  const Image copy = copy_of(image);
  CHECK(copy == image);
  CHECK(copy.points.shape == image.points.shape);
  CHECK(copy.drawn_from == 7);
  CHECK(copy.file == image.file);
  CHECK(copy.file_sum == 99);
  CHECK(copy.auto_tangents);
  CHECK(copy.picture == image.picture);
  CHECK(copy.points.data() != image.points.data());
}

TEST_CASE("large_copy copies large arrays and small ones alike") {
  for (std::size_t n : {std::size_t(6), std::size_t(3) << 20}) {
    Array a({n / 2, 2});
    for (std::size_t k = 0; k < a.size(); ++k) a.ravel[k] = double(k % 977);
    const Array b = large_copy(a, 2);
    CHECK(b == a);
  }
}

TEST_CASE("a deferred image is made once, by whichever thread looks first; a failed make again") {
  // The session makes the current image on a thread of its own while a command may look at it.
  using namespace std::chrono_literals;
  std::atomic<int> makes = 0;
  std::atomic<bool> started = false;
  const Description desim{1, Projection::isometric, {3, 30, 0}};
  const ImageRef ref = ImageRef::deferred(
      [&] {
        const int k = ++makes;
        if (k == 1) throw DataError(DataError::Problem::view_inside_box);
        if (k == 2) {
          // Long enough for the other look to come while this make runs.
          started = true;
          std::this_thread::sleep_for(100ms);
        }
        Image image;
        image.desim = desim;
        image.points = Array({2, 2, 2});
        image.drawn_from = 5;
        return image;
      },
      5, desim);
  // A make that fails leaves the recipe: the next look tries again.
  CHECK_THROWS_AS(static_cast<void>(*ref), DataError);
  CHECK(!ref.made());
  CHECK(ref.recipe() == std::pair{std::uint64_t{5}, desim});
  const Image* seen[2] = {};
  std::thread first([&] { seen[0] = &*ref; });
  while (!started) std::this_thread::yield();
  seen[1] = &*ref;  // waits for the make under way instead of making another
  first.join();
  CHECK(makes == 2);
  CHECK(seen[0] == seen[1]);
  CHECK(ref.made());
  CHECK(ref.recipe() == std::pair{std::uint64_t{5}, desim});
  ref.make_ahead();  // made already: nothing
  CHECK(makes == 2);
  CHECK(!ref.made_ahead());
}

TEST_CASE("an image made ahead is taken by its first look, or given up") {
  std::atomic<int> makes = 0;
  auto deferred = [&] {
    return ImageRef::deferred(
        [&] {
          ++makes;
          Image image;
          image.points = Array({1, 1, 2});
          image.points.ravel = {1, 2};
          return image;
        },
        0, {});
  };
  const ImageRef taken = deferred();
  taken.make_ahead();
  CHECK(makes == 1);
  CHECK(taken.made_ahead());
  CHECK(!taken.made());
  taken.make_ahead();  // once
  CHECK(makes == 1);
  CHECK(taken->points.ravel == std::vector<double>{1, 2});
  CHECK(makes == 1);
  CHECK(taken.made());
  CHECK(!taken.made_ahead());

  const ImageRef given_up = deferred();
  given_up.make_ahead();
  CHECK(makes == 2);
  given_up.drop_ahead();
  CHECK(!given_up.made_ahead());
  given_up.make_ahead();  // given up for good: not made ahead again
  CHECK(makes == 2);
  CHECK(given_up->points.ravel == std::vector<double>{1, 2});
  CHECK(makes == 3);
  CHECK(given_up.made());
}

TEST_CASE("an image given up while it is being made ahead is not kept when the make ends") {
  // The session gives the image up (a command replaced it) while its thread still makes it: the
  // give-up does not wait for the make, and what the make ends with goes.
  std::atomic<int> makes = 0;
  std::atomic<bool> started = false, go_on = false;
  const ImageRef ref = ImageRef::deferred(
      [&] {
        if (++makes == 1) {
          started = true;
          while (!go_on) std::this_thread::yield();
        }
        Image image;
        image.points = Array({1, 1, 2});
        image.points.ravel = {3, 4};
        return image;
      },
      0, {});
  std::thread ahead([&] { ref.make_ahead(); });
  while (!started) std::this_thread::yield();
  ref.drop_ahead();  // while the make runs
  go_on = true;
  ahead.join();
  CHECK(makes == 1);
  CHECK(!ref.made_ahead());
  CHECK(!ref.made());
  CHECK(ref->points.ravel == std::vector<double>{3, 4});  // made again when looked at
  CHECK(makes == 2);
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

}  // namespace
}  // namespace igds
