// The point, tangent and grid entries of BUILD and CHANGE, and the answers they share.
#include "commands/entries.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "commands/answers.h"
#include "workspace/error.h"

namespace igds::test {

namespace {

std::vector<std::string_view> words(std::initializer_list<const char*> list) {
  return {list.begin(), list.end()};
}

// The report an entry gets, "" when it is accepted.
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a point entry sets point k and the ones after it") {
  Array inppn({6, 3});
  apply_point_entry(words({"2", "1", "2", "3", "4", "5", "¯6"}), inppn);
  CHECK(inppn.ravel == Ravel{0, 0, 0, 1, 2, 3, 4, 5, -6, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  apply_point_entry(words({"6", "1E2", "2.5e-1", "-1.5E+03"}), inppn);
  CHECK(inppn.ravel[15] == 100);
  CHECK(inppn.ravel[16] == 0.25);
  CHECK(inppn.ravel[17] == -1500);
}

TEST_CASE(
    "a malformed or out-of-range point entry is refused with its reason and changes nothing") {
  Array inppn({4, 3});
  const Array before = inppn;
  auto entry = [&](std::initializer_list<const char*> w) {
    return refusal([&] { apply_point_entry(words(w), inppn); });
  };
  CHECK(entry({"1", "2", "3"}) == "INCORRECT ENTRY: A POINT ENTRY IS K X Y Z [X Y Z ...]");
  CHECK(entry({"1", "2", "3", "4", "5"}) ==
        "INCORRECT ENTRY: A POINT ENTRY IS K X Y Z [X Y Z ...]");
  CHECK(entry({"0", "1", "2", "3"}) == "INCORRECT ENTRY: THE POINT NUMBER MUST BE 1 TO 4");
  CHECK(entry({"5", "1", "2", "3"}) == "INCORRECT ENTRY: THE POINT NUMBER MUST BE 1 TO 4");
  CHECK(entry({"1.5", "1", "2", "3"}) == "INCORRECT ENTRY: THE POINT NUMBER MUST BE 1 TO 4");
  CHECK(entry({"x", "1", "2", "3"}) == "INCORRECT ENTRY: A POINT ENTRY IS K X Y Z [X Y Z ...]");
  CHECK(entry({"4", "1", "2", "3", "4", "5", "6"}) == "INCORRECT ENTRY: THERE ARE ONLY 4 POINTS");
  CHECK(entry({"1", "1", "2", "3x"}) == "INCORRECT ENTRY: 3x IS NOT A NUMBER");
  CHECK(entry({"2", "1", "2", "1E999"}) == "INCORRECT ENTRY: POINT 2 IS NOT A FINITE NUMBER");
  CHECK(entry({"2", "0", "0", "0", "1", "1E999", "1"}) ==
        "INCORRECT ENTRY: POINT 3 IS NOT A FINITE NUMBER");
  // A command typed where an entry is awaited says so.
  CHECK(entry({"DISPLAY", "SU"}) ==
        "INCORRECT ENTRY: DISPLAY IS A COMMAND: END THE ENTRIES WITH AN EMPTY LINE FIRST");
  CHECK(entry({"di", "1", "2", "3"}) ==
        "INCORRECT ENTRY: DISPLAY IS A COMMAND: END THE ENTRIES WITH AN EMPTY LINE FIRST");
  CHECK(inppn == before);
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

  apply_tangent_entry(words({"5", "1", "0", "0"}), nocur, nostr, inptg);  // curve end
  apply_tangent_entry(words({"10", "0", "¯1", "0"}), nocur, nostr, inptg);
  apply_tangent_entry(words({"12", "0", "0", "1", "1"}), nocur, nostr, inptg);
  apply_tangent_entry(words({"12", "0", "0", "2", "0"}), nocur, nostr, inptg);
  auto row = [&](std::size_t r) {
    return std::vector<double>(inptg.ravel.begin() + r * 4, inptg.ravel.begin() + r * 4 + 4);
  };
  CHECK(row(2) == std::vector<double>{1, 0, 0, 5});
  CHECK(row(9) == std::vector<double>{0, -1, 0, 10});
  CHECK(row(5) == std::vector<double>{0, 0, 1, 12});
  CHECK(row(13) == std::vector<double>{0, 0, 2, 12});
}

TEST_CASE("a single curve has tangents at its two ends only, and no corners") {
  // NOCUR 1, NOSTR 4: the curve's ends 1 and 4 take a tangent along the curve, without a flag.
  Array inptg = zero_tangents(1, 4);
  CHECK(tangent_row(1, true, 1, 4) == 0);
  CHECK(tangent_row(4, true, 1, 4) == 1);
  CHECK(tangent_row(2, false, 1, 4) == -1);
  apply_tangent_entry(words({"4", "1", "1", "0"}), 1, 4, inptg);
  CHECK(inptg.ravel[4 + 0] == 1);
  CHECK(refusal([&] {
          apply_tangent_entry(words({"2", "1", "0", "0"}), 1, 4, inptg);
        }) == "INCORRECT ENTRY: POINT 2 IS NOT ON THE BORDER");
  CHECK(refusal([&] {
          apply_tangent_entry(words({"1", "1", "0", "0", "1"}), 1, 4, inptg);
        }) == "INCORRECT ENTRY: POINT 1 IS NOT A CORNER: GIVE K TX TY TZ");
  // A single stringer likewise.
  CHECK(tangent_row(3, false, 3, 1) == 2 * 3 + 1);
  CHECK(tangent_row(3, true, 3, 1) == -1);
}

TEST_CASE("tangent entries that do not fit the point are refused") {
  const int nocur = 3, nostr = 4;
  Array inptg = zero_tangents(nocur, nostr);
  const Array before = inptg;
  auto entry = [&](std::initializer_list<const char*> w) {
    return refusal([&] { apply_tangent_entry(words(w), nocur, nostr, inptg); });
  };
  CHECK(entry({"6", "1", "0", "0"}) == "INCORRECT ENTRY: POINT 6 IS NOT ON THE BORDER");
  CHECK(entry({"1", "1", "0", "0"}).starts_with("INCORRECT ENTRY: POINT 1 IS A CORNER"));
  CHECK(entry({"5", "1", "0", "0", "1"}).starts_with("INCORRECT ENTRY: POINT 5 IS NOT A CORNER"));
  CHECK(entry({"1", "1", "0", "0", "2"}) ==
        "INCORRECT ENTRY: THE LAST NUMBER AT A CORNER MUST BE 1 (CURVE) OR 0 (STRINGER)");
  CHECK(entry({"13", "1", "0", "0"}) == "INCORRECT ENTRY: THE POINT NUMBER MUST BE 1 TO 12");
  CHECK(entry({"2", "1", "0"}) ==
        "INCORRECT ENTRY: A TANGENT ENTRY IS K TX TY TZ (AND 1 OR 0 AT A CORNER)");
  CHECK(entry({"2", "1", "1E400", "0"}) ==
        "INCORRECT ENTRY: THE TANGENT AT POINT 2 IS NOT A FINITE NUMBER");
  CHECK(entry({"SAVE", "X"}) ==
        "INCORRECT ENTRY: SAVE IS A COMMAND: END THE ENTRIES WITH AN EMPTY LINE FIRST");
  CHECK(inptg == before);
}

TEST_CASE("grid sizes and densities") {
  CHECK(parse_grid_size(words({"3", "4"})).nocur == 3);
  CHECK(parse_grid_size(words({"3", "4"})).nostr == 4);
  CHECK(parse_grid_size(words({"1", "4"})).nocur == 1);  // a single curve (manual 4.1)
  auto size = [](std::initializer_list<const char*> w) {
    return refusal([&] { parse_grid_size(words(w)); });
  };
  CHECK(size({"1", "1"}) == "INCORRECT ENTRY: A SURFACE NEEDS AT LEAST TWO POINTS");
  CHECK(size({"3"}) == "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS, NOCUR AND NOSTR");
  CHECK(size({"3", "4", "5"}) == "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS, NOCUR AND NOSTR");
  CHECK(size({"3", "4.5"}) == "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS, NOCUR AND NOSTR");
  CHECK(size({"0", "4"}) == "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS, NOCUR AND NOSTR");
  CHECK(size({"2000", "2000"}) == "INCORRECT ENTRY: 4000000 POINTS, AT MOST 1000000");

  Density d = parse_density(words({"0", "7"}), 3, 3);
  CHECK(d.intcu == 0);
  CHECK(d.intst == 7);
  auto density = [](std::initializer_list<const char*> w, int nc, int ns) {
    return refusal([&] { parse_density(words(w), nc, ns); });
  };
  CHECK(density({"¯1", "2"}, 3, 3) ==
        "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS >= 0, INTCU AND INTST");
  CHECK(density({"1"}, 3, 3) == "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS >= 0, INTCU AND INTST");
  CHECK(density({"1000", "1000"}, 10, 10) ==
        "INCORRECT ENTRY: THE GRID WOULD HAVE 81180100 POINTS, AT MOST 4000000");
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
