// Marks's files (workspace/exchange/): the fitting deck NAME.CADADATA, the listing NAME.CADALIST
// and the MPDP paper tape NAME.MPDPTAPE, checked against docs/marks.md field by field (the
// FORTRAN fields themselves: tests/numbers/fortran.cpp).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "workspace/exchange/marks_deck.h"
#include "workspace/exchange/marks_listing.h"
#include "workspace/exchange/mpdp_tape.h"
#include "workspace/kernels/marks.h"
#include "workspace/numbers/fortran.h"

using namespace igds;
using namespace igds::exchange;

namespace {

// Card images of a deck: MR NC, the keys (18 a card), then per point x y z and given vectors.
struct DeckText {
  int rows, columns;
  std::vector<int> keys;
  std::vector<std::vector<double>> numbers;  // per point: x y z and the given vectors
  std::string text() const {
    std::string out = fmt::format("{:4}{:4}\n", rows, columns);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      out += fmt::format("{:4}.", keys[k]).substr(1);  // F4.0 as "  1."
      if (k % 18 == 17 || k + 1 == keys.size()) out += '\n';
    }
    for (const auto& point : numbers) {
      for (std::size_t v = 0; v < point.size(); ++v) {
        out += fmt::format("{:7.1f}", point[v]);
        if (v % 9 == 8 || v + 1 == point.size()) out += '\n';
      }
    }
    return out;
  }
};

// A deck of MR x NC points of a wavy surface, position only.
DeckText wavy_deck(int rows, int columns, double scale = 10) {
  DeckText d{rows, columns, {}, {}};
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      d.keys.push_back(1);
      d.numbers.push_back({scale * j, scale * i + 0.5 * j,
                           std::round(10 * scale * std::sin(0.7 * j) * std::cos(0.4 * i)) / 10});
    }
  }
  return d;
}

DeckError deck_error(std::string_view text) {
  try {
    read_deck(text);
  } catch (const DeckError& e) {
    return e;
  }
  FAIL("the deck was accepted");
  return DeckError(DeckError::Problem::bad_number);
}

TapeError tape_error(std::string_view frames) {
  try {
    read_tape(frames);
  } catch (const TapeError& e) {
    return e;
  }
  FAIL("the tape was accepted");
  return TapeError(TapeError::Problem::shape);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return lines;
}

}  // namespace

TEST_CASE("a deck is read: sizes, keys, positions and given vectors") {
  DeckText d = wavy_deck(3, 4);
  // Point 2: horizontal given; point 7: vertical and twist; point 12: all three (two cards).
  d.keys[1] = 1 + 2;
  d.numbers[1].insert(d.numbers[1].end(), {5, 0.5, -1});
  d.keys[6] = 1 + 4 + 8;
  d.numbers[6].insert(d.numbers[6].end(), {0.5, 7, 0, 1, 2, 3});
  d.keys[11] = 15;
  d.numbers[11].insert(d.numbers[11].end(), {1, 0, 0, 0, 1, 0, 0.5, 0.5, -0.5});
  const MarksDeck deck = read_deck(d.text());
  CHECK(deck.rows == 3);
  CHECK(deck.columns == 4);
  CHECK(deck.keys == d.keys);
  REQUIRE(deck.points.shape == std::vector<std::size_t>{12, 3});
  for (std::size_t k = 0; k < 12; ++k) {
    CHECK(as_vec3(deck.points)[k] == Vec3{d.numbers[k][0], d.numbers[k][1], d.numbers[k][2]});
  }
  CHECK(as_vec3(deck.horizontal)[1] == Vec3{5, 0.5, -1});
  CHECK(as_vec3(deck.vertical)[6] == Vec3{0.5, 7, 0});
  CHECK(as_vec3(deck.twists)[6] == Vec3{1, 2, 3});
  CHECK(as_vec3(deck.horizontal)[11] == Vec3{1, 0, 0});
  CHECK(as_vec3(deck.vertical)[11] == Vec3{0, 1, 0});
  CHECK(as_vec3(deck.twists)[11] == Vec3{0.5, 0.5, -0.5});
  CHECK(as_vec3(deck.horizontal)[0] == Vec3{});
  CHECK(as_vec3(deck.twists)[1] == Vec3{});
  // Point 12's numbers take two cards: 9 then 3.
  CHECK(d.text().find("   -0.5\n") != std::string::npos);
}

TEST_CASE("the deck's given vectors are honoured, Marks's elsewhere, into PATCHES unscaled") {
  DeckText d = wavy_deck(4, 5);
  d.keys[6] = 1 + 2 + 4 + 8;  // an interior point (row 2, column 2)
  d.numbers[6].insert(d.numbers[6].end(), {3, 1, 0, -1, 4, 0.5, 1.5, -0.5, 2});
  d.keys[0] = 1 + 4;  // a corner, vertical only
  d.numbers[0].insert(d.numbers[0].end(), {0, 20, 1});
  const MarksDeck deck = read_deck(d.text());
  const MarksFit fit = fit_deck(deck);
  const auto points = as_vec3(deck.points);
  const GridTangents marks = marks_grid_tangents(4, 5, points);
  const Array twists = marks_twists(4, 5, points);
  CHECK(fit.tangents.units == TangentUnits::per_parameter);
  for (std::size_t k = 0; k < 20; ++k) {
    CAPTURE(k);
    CHECK(fit.tangents.along_curves[k] == (k == 6 ? Vec3{3, 1, 0} : marks.along_curves[k]));
    CHECK(fit.tangents.along_stringers[k] == (k == 6   ? Vec3{-1, 4, 0.5}
                                              : k == 0 ? Vec3{0, 20, 1}
                                                       : marks.along_stringers[k]));
    CHECK(as_vec3(fit.twists)[k] == (k == 6 ? Vec3{1.5, -0.5, 2} : Vec3(as_vec3(twists)[k])));
  }
  // Point 7 (row 1, column 1 from 0) is corner P(0,0) of patch (1, 1) = patch 5: Pv at M[0][2],
  // Pu at M[2][0], the twist at M[2][2], as given.
  auto m = [&](std::size_t p, int r, int c) {
    const double* a = fit.patches.data() + 48 * p + 4 * r + c;
    return Vec3{a[0], a[16], a[32]};
  };
  CHECK(m(5, 0, 2) == Vec3{-1, 4, 0.5});
  CHECK(m(5, 2, 0) == Vec3{3, 1, 0});
  CHECK(m(5, 2, 2) == Vec3{1.5, -0.5, 2});
  // ... and corner P(1,1) of patch (0, 0): Pv at M[1][3], Pu at M[3][1], the twist at M[3][3].
  CHECK(m(0, 1, 3) == Vec3{-1, 4, 0.5});
  CHECK(m(0, 3, 1) == Vec3{3, 1, 0});
  CHECK(m(0, 3, 3) == Vec3{1.5, -0.5, 2});
  // Point 1's vertical vector is stored in INPTG per unit of chord (stringer 1, first end: row
  // 2 NOCUR = 8), so that COONS would put it back.
  const double chord = norm(Vec3(points[5]) - points[0]);
  const Vec3 stored = Vec3::load(fit.inptg.data() + 4 * 8);
  CHECK(norm(chord * stored - Vec3{0, 20, 1}) < 1e-13);
}

TEST_CASE("a deck with a missing point is refused, the point named") {
  DeckText d = wavy_deck(3, 4);
  d.keys[5] = 0;  // point 6
  d.numbers.erase(d.numbers.begin() + 5);
  DeckError e = deck_error(d.text());
  CHECK(e.problem == DeckError::Problem::missing_point);
  CHECK(e.point == 6);
  CHECK(e.line == 2);
  CHECK(std::string(e.what()).find("point 6") != std::string::npos);
  // A key that gives vectors but no position is a missing point too.
  d = wavy_deck(3, 4);
  d.keys[9] = 2;
  e = deck_error(d.text());
  CHECK(e.problem == DeckError::Problem::missing_point);
  CHECK(e.point == 10);
}

TEST_CASE("a deck that cannot be read says where") {
  const std::string good = wavy_deck(3, 4).text();
  auto lines = lines_of(good);
  REQUIRE(lines.size() == 1 + 1 + 12);
  auto join = [](const std::vector<std::string>& ls) {
    std::string s;
    for (const auto& l : ls) s += l + "\n";
    return s;
  };
  SUBCASE("a number that does not parse, with its line and column") {
    auto bad = lines;
    bad[4].replace(7, 7, "  1..5 ");
    const DeckError e = deck_error(join(bad));
    CHECK(e.problem == DeckError::Problem::bad_number);
    CHECK(e.line == 5);
    CHECK(e.column == 8);
  }
  SUBCASE("a key out of range or not whole") {
    for (const char* key : {"16.", " -1.", " 1.5"}) {
      auto bad = lines;
      bad[1].replace(8, 4, key);
      const DeckError e = deck_error(join(bad));
      CHECK(e.problem == DeckError::Problem::bad_key);
      CHECK(e.point == 3);
      CHECK(e.line == 2);
      CHECK(e.column == 9);
    }
  }
  SUBCASE("counts that disagree: too few cards, cards after the last point") {
    auto shorter = lines;
    shorter.pop_back();
    DeckError e = deck_error(join(shorter));
    CHECK(e.problem == DeckError::Problem::ends_early);
    CHECK(e.line == 14);
    e = deck_error(join(lines) + "   1.0\n");
    CHECK(e.problem == DeckError::Problem::extra_cards);
    CHECK(e.line == 15);
    // Blank cards after the last point are nothing; the keys need their cards.
    CHECK_NOTHROW(read_deck(join(lines) + "\n   \n"));
    e = deck_error(lines[0] + "\n");
    CHECK(e.problem == DeckError::Problem::ends_early);
    CHECK(e.line == 2);
    CHECK(deck_error("").problem == DeckError::Problem::ends_early);
  }
  SUBCASE("sizes below 2 or above the limits") {
    DeckError e = deck_error("   1   5\n");
    CHECK(e.problem == DeckError::Problem::too_small);
    CHECK(e.rows == 1);
    CHECK(deck_error("\n").problem == DeckError::Problem::too_small);
    e = deck_error("2000 600\n");  // 1.2 million points, more than max_input_points
    CHECK(e.problem == DeckError::Problem::too_large);
    CHECK(e.columns == 600);
    CHECK(deck_error(" 2x   5\n").problem == DeckError::Problem::bad_number);
  }
  SUBCASE("short cards, CR LF, sequence numbers past the fields") {
    std::string text;
    for (auto l : lines) {
      while (!l.empty() && l.back() == ' ') l.pop_back();
      text += l + std::string(72 - l.size(), ' ') + "SEQ00001\r\n";
    }
    const MarksDeck deck = read_deck(text);
    CHECK(deck.points == read_deck(good).points);
  }
}

TEST_CASE("the listing of a small surface, field by field") {
  // A plane grid, 2 rows x 3 columns 10 apart, a given twist at point 5: every vector is known.
  DeckText d{2, 3, {1, 1, 1, 1, 9, 1}, {}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) d.numbers.push_back({10.0 * j, 10.0 * i, 0});
  d.numbers[4].insert(d.numbers[4].end(), {1, -2, 0.5});
  const MarksDeck deck = read_deck(d.text());
  const MarksFit fit = fit_deck(deck);
  std::size_t overflow = 99;
  const std::string listing = cada_listing(deck, fit, &overflow);
  CHECK(overflow == 0);
  const auto lines = lines_of(listing);
  REQUIRE(lines.size() == 6 + 1 + 2 * 5);
  // Point 1: key, position, H = (10 0 0), V = (0 10 0), T = 0; groups three blanks apart.
  CHECK(lines[0] ==
        "  1.    0.0    0.0    0.0      10.0    0.0    0.0       0.0   10.0    0.0"
        "       0.0    0.0    0.0");
  CHECK(lines[4] ==
        "  9.   10.0   10.0    0.0      10.0    0.0    0.0       0.0   10.0    0.0"
        "       1.0   -2.0    0.5");
  for (int k = 0; k < 6; ++k) CHECK(lines[k].size() == 97);
  CHECK(lines[6].empty());
  // Patch 2 (columns 2-3): C = point 2 (10 0 0), S = point 5, E = point 3, SE = point 6.
  // Rows of B side by side for x, y, z: C_c S_c C_V S_V / E_c SE_c E_V SE_V / C_H S_H C_T S_T /
  // E_H SE_H E_T SE_T, the twist of point 5 at S_T.
  CHECK(lines[12] ==
        "   10.0   10.0    0.0    0.0       0.0   10.0   10.0   10.0       0.0    0.0    0.0"
        "    0.0");
  CHECK(lines[13] ==
        "   20.0   20.0    0.0    0.0       0.0   10.0   10.0   10.0       0.0    0.0    0.0"
        "    0.0");
  CHECK(lines[14] ==
        "   10.0   10.0    0.0    1.0       0.0    0.0    0.0   -2.0       0.0    0.0    0.0"
        "    0.5");
  CHECK(lines[15] ==
        "   10.0   10.0    0.0    0.0       0.0    0.0    0.0    0.0       0.0    0.0    0.0"
        "    0.0");
  CHECK(lines[16].empty());
  // Every B field reads back (with BINARY's widths) as PATCHES to the listing's one decimal.
  for (std::size_t p = 0; p < 2; ++p) {
    for (int r = 0; r < 4; ++r) {
      const std::string& line = lines[7 + 5 * p + r];
      CHECK(line.size() == 90);
      std::size_t column = 0;
      for (int k = 0; k < 3; ++k) {
        for (int c = 0; c < 4; ++c) {
          const std::size_t width = k > 0 && c == 0 ? 10 : 7;
          const auto value = fortran::read_f(line, column, width, 0);
          REQUIRE(value);
          CHECK(*value ==
                doctest::Approx(fit.patches.ravel[48 * p + 16 * k + 4 * r + c]).epsilon(0.05 / 20));
          column += width;
        }
      }
    }
  }
  // A value too wide for F7.1 is asterisks, and counted.
  MarksDeck wide = deck;
  as_vec3(wide.points)[0] = Vec3{-123456.0, 0, 0};
  cada_listing(wide, fit_deck(wide), &overflow);
  CHECK(overflow > 0);
  // A value that is not finite is asterisks too (gfortran would write NaN), and counted.
  MarksFit odd = fit;
  as_vec3(odd.twists)[0] = Vec3{std::nan(""), 0, INFINITY};
  const auto odd_lines = lines_of(cada_listing(deck, odd, &overflow));
  CHECK(odd_lines[0].substr(73) == "**********    0.0*******");
  CHECK(overflow == 2);
}

TEST_CASE("the tape: frames of one number, the end mark") {
  Array patches({1, 1, 3, 4, 4});
  patches.ravel[0] = 131071;   // x, C_c
  patches.ravel[1] = -131072;  // x, S_c
  patches.ravel[2] = -1;       // x, C_V: the end mark's bits, inside a patch
  patches.ravel[3] = -2.5;     // x, S_V: reversed on the tape, 2.5 rounds to 3
  patches.ravel[16] = 0.49;    // y, C_c
  patches.ravel[47] = 1e-300;  // z, SE_T
  const std::string tape = write_tape(patches);
  REQUIRE(tape.size() == 54 * 3 + 3);
  auto frames = [&](std::size_t number) {
    return std::vector<int>{static_cast<unsigned char>(tape[3 * number]),
                            static_cast<unsigned char>(tape[3 * number + 1]),
                            static_cast<unsigned char>(tape[3 * number + 2])};
  };
  CHECK(frames(0) == std::vector<int>{0300, 0300, 0301});  // patch 1
  CHECK(frames(1) == std::vector<int>{0300, 0300, 0300});
  CHECK(frames(6) == std::vector<int>{0337, 0377, 0377});   // 131071 = 377777 octal
  CHECK(frames(7) == std::vector<int>{0340, 0300, 0300});   // -131072 = 400000 octal
  CHECK(frames(8) == std::vector<int>{0377, 0377, 0377});   // -1
  CHECK(frames(9) == std::vector<int>{0300, 0300, 0303});   // 3
  CHECK(frames(54) == std::vector<int>{0377, 0377, 0377});  // 777777 octal, the end
  for (char f : tape) CHECK((static_cast<unsigned char>(f) & 0300) == 0300);
  const auto read = read_tape(tape);
  REQUIRE(read.size() == 1);
  CHECK(read[0].number == 1);
  CHECK(read[0].b[0] == 131071);
  CHECK(read[0].b[1] == -131072);
  CHECK(read[0].b[2] == -1);
  CHECK(read[0].b[3] == 3);
  CHECK(read[0].b[16] == 0);
  CHECK(read[0].b[47] == 0);
}

TEST_CASE("a tape written and read back holds PATCHES number by number, MPDP's signs") {
  const MarksDeck deck = read_deck(wavy_deck(4, 5, 100).text());
  const MarksFit fit = fit_deck(deck);
  const std::string tape = write_tape(fit.patches);
  CHECK(tape.size() == 12 * 162 + 3);
  const auto patches = read_tape(tape);
  REQUIRE(patches.size() == 12);
  for (std::size_t p = 0; p < 12; ++p) {
    CAPTURE(p);
    CHECK(patches[p].number == int(p + 1));
    CHECK(patches[p].internal_lines == 0);
    CHECK(patches[p].links == std::array<std::int32_t, 4>{});
    int nonzero = 0;
    for (int k = 0; k < 3; ++k) {
      for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
          // S_V (row 0, col 3), SE_V (1, 3), E_H (3, 0), SE_H (3, 1) change sign on the tape.
          const bool mpdp = (r < 2 && c == 3) || (r == 3 && c < 2);
          const double value = fit.patches.ravel[48 * p + 16 * k + 4 * r + c];
          const double expected = std::round(mpdp ? -value : value);
          CHECK(patches[p].b[16 * k + 4 * r + c] == expected);
          nonzero += expected != 0;
        }
      }
    }
    CHECK(nonzero > 20);
  }
  // The text of a decoded tape lists the same numbers.
  const std::string text = tape_text(patches);
  CHECK(text.starts_with("PATCH 1 LINES 0 LINKS 0 0 0 0\n"));
  CHECK(text.ends_with("\nEND\n"));
}

TEST_CASE("a number out of 18 bits is refused, naming its patch") {
  Array patches({2, 2, 3, 4, 4});
  patches.ravel[48 * 2 + 20] = 131071.5;  // patch 3, rounds to 131072
  TapeError e(TapeError::Problem::shape);
  try {
    write_tape(patches);
    FAIL("written");
  } catch (const TapeError& caught) {
    e = caught;
  }
  CHECK(e.problem == TapeError::Problem::out_of_range);
  CHECK(e.patch == 3);
  CHECK(e.value == 131071.5);
  patches.ravel[48 * 2 + 20] = -131072.4;  // rounds to -131072: fits
  CHECK_NOTHROW(write_tape(patches));
  // Reversed on the tape: -(-131072) does not fit.
  patches.ravel[48 * 1 + 3] = -131072;  // patch 2, x S_V
  CHECK_THROWS_AS(write_tape(patches), TapeError);
  patches.ravel[48 * 1 + 3] = 0;
  patches.ravel[48 * 3 + 47] = std::nan("");
  try {
    write_tape(patches);
    FAIL("written");
  } catch (const TapeError& caught) {
    CHECK(caught.problem == TapeError::Problem::out_of_range);
    CHECK(caught.patch == 4);
  }
  CHECK_THROWS_AS(write_tape(Array({2, 3})), TapeError);
}

TEST_CASE("the tape reader refuses garbage and says where") {
  Array patches({1, 2, 3, 4, 4});
  for (std::size_t k = 0; k < patches.size(); ++k) patches.ravel[k] = double(k) - 40;
  const std::string tape = write_tape(patches);
  REQUIRE(tape.size() == 2 * 162 + 3);
  CHECK(read_tape(tape).size() == 2);
  // Blank leader and trailer, as a punch adds them, are tape too.
  CHECK(read_tape(std::string(20, '\0') + tape + std::string(8, '\0')).size() == 2);

  std::string bad = tape;
  bad[100] = 077;
  TapeError e = tape_error(bad);
  CHECK(e.problem == TapeError::Problem::no_holes);
  CHECK(e.frame == 101);
  bad[100] = 0;  // blank tape inside a patch is not leader
  CHECK(tape_error(bad).problem == TapeError::Problem::no_holes);

  e = tape_error(tape.substr(0, tape.size() - 1));
  CHECK(e.problem == TapeError::Problem::truncated_number);
  CHECK(e.frame == 2 * 162 + 1);
  e = tape_error(tape.substr(0, 162 + 30));
  CHECK(e.problem == TapeError::Problem::truncated_patch);
  CHECK(e.patch == 2);
  e = tape_error(tape.substr(0, 2 * 162));
  CHECK(e.problem == TapeError::Problem::no_end_mark);
  CHECK(e.patch == 2);
  CHECK(tape_error("").problem == TapeError::Problem::no_end_mark);
  CHECK(tape_error(std::string(5, '\0')).problem == TapeError::Problem::no_end_mark);
  e = tape_error(tape + "\300");
  CHECK(e.problem == TapeError::Problem::after_end);
  CHECK(e.frame == tape.size() + 1);
  CHECK(read_tape("\377\377\377").empty());
}

TEST_CASE("the readers are total: damaged decks and tapes are refused, never more") {
  // Deterministic mutations of a good tape and a good deck (SplitMix64): every outcome is a
  // result or the reader's own error.
  std::uint64_t state = 42;
  auto next = [&state] {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  Array patches({2, 2, 3, 4, 4});
  for (std::size_t k = 0; k < patches.size(); ++k) patches.ravel[k] = double(k % 17) * 100 - 800;
  const std::string tape = write_tape(patches);
  DeckText d = wavy_deck(3, 3);
  d.keys[4] = 15;
  d.numbers[4].insert(d.numbers[4].end(), 9, 1.5);
  const std::string deck = d.text();
  const char alphabet[] = " 0123456789.+-EeD\n\r\t\0x\300\377";
  int tapes_read = 0, decks_read = 0;
  for (int round = 0; round < 4000; ++round) {
    std::string t = tape, k = deck;
    const int edits = 1 + int(next() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::uint64_t r = next();
      switch (r % 4) {
        case 0:
          if (!t.empty()) t[r / 4 % t.size()] = char(r >> 32);
          if (!k.empty()) k[r / 4 % k.size()] = alphabet[(r >> 32) % (sizeof alphabet - 1)];
          break;
        case 1:
          t.resize(r / 4 % (t.size() + 1));
          k.resize(r / 4 % (k.size() + 1));
          break;
        case 2:
          t.insert(r / 4 % (t.size() + 1), 1, char(r >> 40));
          k.insert(r / 4 % (k.size() + 1), 1, alphabet[(r >> 40) % (sizeof alphabet - 1)]);
          break;
        default:
          t.erase(r / 4 % (t.size() + 1), 3);
          k.erase(r / 4 % (k.size() + 1), 1 + r % 9);
          break;
      }
    }
    try {
      tapes_read += read_tape(t).size() <= t.size() / 162;
    } catch (const TapeError&) {
    }
    try {
      const MarksDeck m = read_deck(k);
      decks_read += m.points.size() == 3 * m.keys.size();
    } catch (const DeckError&) {
    }
  }
  MESSAGE("mutated tapes read: ", tapes_read, ", decks read: ", decks_read);
  CHECK(tapes_read + decks_read > 0);
}
