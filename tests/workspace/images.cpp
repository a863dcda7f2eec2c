// workspace/images.h: what a copy of an image keeps.
#include "workspace/images.h"

#include <doctest/doctest.h>

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

}  // namespace
}  // namespace igds
