// Values and igds's workspace arrays.
#include "interp/apl/array_bridge.h"

#include <doctest/doctest.h>

#include <algorithm>

namespace igds::apl::test {

TEST_CASE("an igds Array as an APL value and back") {
  igds::Array scalar;
  scalar.ravel = {3};
  CHECK(to_value(scalar) == Value::number(3));
  CHECK(to_array(Value::number(3)) == scalar);
  igds::Array empty;  // igds's variables before BUILD: shape 0 in APL
  CHECK(to_value(empty).shape() == Shape{0});
  igds::Array m({2, 3});
  m.ravel = {1, 2, 3, 4, 5, 6};
  Value v = to_value(m);
  CHECK(v.shape() == Shape{2, 3});
  CHECK(v.numbers()[5] == 6);
  CHECK(to_array(v) == m);
  CHECK_THROWS_AS(to_array(Value::text("AB")), Error);
}

TEST_CASE("values share their ravel until one is changed") {
  Value a = Value::vector({1, 2, 3});
  Value b = a;
  CHECK(!a.unique());
  b.mutable_numbers()[0] = 9;
  CHECK(a.numbers()[0] == 1);
  CHECK(b.numbers()[0] == 9);
  CHECK(a.unique());
  Value r = a.reshaped({3, 1});
  CHECK(r.numbers().data() == a.numbers().data());
  Value big = Value::zeros({3000, 1000});  // a large block: zeros, though the allocator writes none
  CHECK(std::all_of(big.numbers().begin(), big.numbers().end(), [](double x) { return x == 0; }));
  big.mutable_numbers()[2999999] = 1;
  CHECK(big.numbers()[2999999] == 1);
}

}  // namespace igds::apl::test
