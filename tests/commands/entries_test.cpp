// The point, tangent and grid entries of BUILD and CHANGE.
#include "commands/entries.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "workspace/error.h"

namespace igds::test {

namespace {

std::vector<std::string> words(std::initializer_list<const char*> list) {
  return {list.begin(), list.end()};
}

}  // namespace

TEST_CASE("a point entry sets point k and the ones after it") {
  Array inppn({6, 3});
  CHECK_FALSE(apply_point_entry(words({"2", "1", "2", "3", "4", "5", "¯6"}), inppn));
  CHECK(inppn.ravel == std::vector<double>{0, 0, 0, 1, 2, 3, 4, 5, -6, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  CHECK_FALSE(apply_point_entry(words({"6", "1E2", "2.5e-1", "-1.5E+03"}), inppn));
  CHECK(inppn.ravel[15] == 100);
  CHECK(inppn.ravel[16] == 0.25);
  CHECK(inppn.ravel[17] == -1500);
}

TEST_CASE("a malformed or out-of-range point entry is refused and changes nothing") {
  Array inppn({4, 3});
  const Array before = inppn;
  for (auto entry :
       {words({"1", "2", "3"}), words({"1", "2", "3", "4", "5"}), words({"0", "1", "2", "3"}),
        words({"5", "1", "2", "3"}), words({"1.5", "1", "2", "3"}), words({"x", "1", "2", "3"}),
        words({"4", "1", "2", "3", "4", "5", "6"}), words({"1", "1", "2", "3x"}),
        words({"2", "1", "2", "1E999"})}) {
    auto error = apply_point_entry(entry, inppn);
    REQUIRE(error);
    CHECK(error->starts_with(reports::incorrect_entry));
  }
  CHECK(inppn == before);
  CHECK(*apply_point_entry(words({"2", "0", "0", "0", "1", "1E999", "1"}), inppn) ==
        "INCORRECT ENTRY: POINT 3 IS NOT A FINITE NUMBER");
  CHECK(*apply_point_entry(words({"1", "2", "3"}), inppn) == "INCORRECT ENTRY");
}

TEST_CASE("border tangents go to their INPTG rows") {
  // 3 curves x 4 stringers: points 1..12, curve c holds 4(c-1)+1 .. 4c.
  const int nocur = 3, nostr = 4;
  Array inptg = zero_tangents(nocur, nostr);
  REQUIRE(inptg.shape == std::vector<std::size_t>{14, 4});
  // Point numbers: curve ends first (1 4, 5 8, 9 12), then stringer ends (1 9, 2 10, 3 11, 4 12).
  std::vector<double> numbers;
  for (std::size_t r = 0; r < 14; ++r) numbers.push_back(inptg.ravel[r * 4 + 3]);
  CHECK(numbers == std::vector<double>{1, 4, 5, 8, 9, 12, 1, 9, 2, 10, 3, 11, 4, 12});

  CHECK(tangent_row(5, true, nocur, nostr) == 2);
  CHECK(tangent_row(5, false, nocur, nostr) == -1);
  CHECK(tangent_row(2, false, nocur, nostr) == 8);
  CHECK(tangent_row(6, true, nocur, nostr) == -1);

  CHECK_FALSE(apply_tangent_entry(words({"5", "1", "0", "0"}), nocur, nostr, inptg));  // curve end
  CHECK_FALSE(apply_tangent_entry(words({"10", "0", "¯1", "0"}), nocur, nostr, inptg));
  CHECK_FALSE(apply_tangent_entry(words({"12", "0", "0", "1", "1"}), nocur, nostr, inptg));
  CHECK_FALSE(apply_tangent_entry(words({"12", "0", "0", "2", "0"}), nocur, nostr, inptg));
  auto row = [&](std::size_t r) {
    return std::vector<double>(inptg.ravel.begin() + r * 4, inptg.ravel.begin() + r * 4 + 4);
  };
  CHECK(row(2) == std::vector<double>{1, 0, 0, 5});
  CHECK(row(9) == std::vector<double>{0, -1, 0, 10});
  CHECK(row(5) == std::vector<double>{0, 0, 1, 12});
  CHECK(row(13) == std::vector<double>{0, 0, 2, 12});
}

TEST_CASE("tangent entries that do not fit the point are refused") {
  const int nocur = 3, nostr = 4;
  Array inptg = zero_tangents(nocur, nostr);
  const Array before = inptg;
  CHECK(*apply_tangent_entry(words({"6", "1", "0", "0"}), nocur, nostr, inptg) ==
        "INCORRECT ENTRY: POINT 6 IS NOT ON THE BORDER");
  CHECK(apply_tangent_entry(words({"1", "1", "0", "0"}), nocur, nostr, inptg)
            ->starts_with("INCORRECT ENTRY: POINT 1 IS A CORNER"));
  CHECK(apply_tangent_entry(words({"5", "1", "0", "0", "1"}), nocur, nostr, inptg)
            ->starts_with("INCORRECT ENTRY: POINT 5 IS NOT A CORNER"));
  CHECK(apply_tangent_entry(words({"1", "1", "0", "0", "2"}), nocur, nostr, inptg));
  CHECK(apply_tangent_entry(words({"13", "1", "0", "0"}), nocur, nostr, inptg));
  CHECK(apply_tangent_entry(words({"2", "1", "0"}), nocur, nostr, inptg));
  CHECK(*apply_tangent_entry(words({"2", "1", "1E400", "0"}), nocur, nostr, inptg) ==
        "INCORRECT ENTRY: THE TANGENT AT POINT 2 IS NOT A FINITE NUMBER");
  CHECK(inptg == before);
}

TEST_CASE("grid sizes and densities") {
  CHECK(parse_grid_size(words({"3", "4"}))->nocur == 3);
  CHECK(parse_grid_size(words({"3", "4"}))->nostr == 4);
  CHECK_FALSE(parse_grid_size(words({"1", "4"})));
  CHECK_FALSE(parse_grid_size(words({"3"})));
  CHECK_FALSE(parse_grid_size(words({"3", "4", "5"})));
  CHECK_FALSE(parse_grid_size(words({"3", "4.5"})));
  CHECK_FALSE(parse_grid_size(words({"2000", "2000"})));  // more than max_input_points

  Density d;
  CHECK_FALSE(parse_density(words({"0", "7"}), 3, 3, d));
  CHECK(d.intcu == 0);
  CHECK(d.intst == 7);
  CHECK(parse_density(words({"¯1", "2"}), 3, 3, d));
  CHECK(parse_density(words({"1"}), 3, 3, d));
  CHECK(
      parse_density(words({"1000", "1000"}), 10, 10, d)->starts_with("INCORRECT ENTRY: THE GRID"));
}

TEST_CASE("integers, yes and no") {
  CHECK(parse_integer("3", 0, 5) == 3);
  CHECK(parse_integer("3.0", 0, 5) == 3);
  CHECK(parse_integer("¯2", -5, 5) == -2);
  CHECK_FALSE(parse_integer("6", 0, 5));
  CHECK_FALSE(parse_integer("2.5", 0, 5));
  CHECK_FALSE(parse_integer("1E400", 0, 5));
  CHECK(parse_yes_no(words({"y"})) == true);
  CHECK(parse_yes_no(words({"YES"})) == true);
  CHECK(parse_yes_no(words({"n"})) == false);
  CHECK_FALSE(parse_yes_no(words({"maybe"})));
  CHECK_FALSE(parse_yes_no(words({"Y", "N"})));
}

}  // namespace igds::test
