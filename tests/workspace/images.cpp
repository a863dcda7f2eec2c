// workspace/images.h and state.h: a deferred image made once, at its first look.
#include "workspace/images.h"

#include <doctest/doctest.h>

#include "workspace/kernels/data_error.h"

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

}  // namespace
}  // namespace igds
