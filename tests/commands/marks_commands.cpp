// Marks 1970 in the conversation (docs/marks.md): AUTO at TANGENTS?, CHANGE TWISTS, FIT, PUNCH,
// and the surface's modes kept by SAVE, RESTORE and the session.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "commands/command.h"
#include "commands/picture.h"
#include "tests/support/fake_context.h"
#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/session.h"
#include "workspace/error.h"
#include "workspace/exchange/marks_deck.h"
#include "workspace/exchange/marks_listing.h"
#include "workspace/exchange/mpdp_tape.h"
#include "workspace/images.h"
#include "workspace/kernels/marks.h"

namespace igds {
extern const Command build_command;
extern const Command change_command;
extern const Command fit_command;
extern const Command punch_command;
extern const Command help_command;
}  // namespace igds

namespace igds::test {

namespace {

namespace fs = std::filesystem;

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A 4 x 5 surface that is neither bilinear nor translational: its Marks twists are not zero.
constexpr int nocur = 4, nostr = 5;
Vec3 wavy_point(int i, int j) {
  return {10.0 * j, 10.0 * i + 0.5 * j, std::round(30 * std::sin(0.7 * j) * std::cos(0.4 * i))};
}

std::vector<std::string> point_lines() {
  std::vector<std::string> lines;
  for (int i = 0; i < nocur; ++i)
    for (int j = 0; j < nostr; ++j) {
      const Vec3 p = wavy_point(i, j);
      lines.push_back(fmt::format("{} {} {} {}", i * nostr + j + 1, p.x, p.y, p.z));
    }
  return lines;
}

// BUILD of the wavy surface with `tangents` typed at TANGENTS?.
void build_wavy(FakeContext& ctx, const std::vector<std::string>& tangents) {
  std::vector<std::string> lines{fmt::format("{} {}", nocur, nostr)};
  for (auto& l : point_lines()) lines.push_back(l);
  lines.emplace_back("");
  for (auto& t : tangents) lines.push_back(t);
  lines.insert(lines.end(), {"", "2 2"});
  ctx.type(lines);
  ctx.run(build_command, "");
  REQUIRE(ctx.ws.has_surface());
}

// The element (r, c) of coordinate k of patch p of PATCHES.
double element(const Array& patches, std::size_t p, int k, int r, int c) {
  return patches.ravel[48 * p + 16 * std::size_t(k) + 4 * std::size_t(r) + std::size_t(c)];
}

// Card images of a deck (docs/marks.md): MR NC, the keys 18 a card, then per point x y z and the
// given vectors, nine fields a card.
std::string deck_text(int rows, int columns, const std::vector<int>& keys,
                      const std::vector<std::vector<double>>& numbers) {
  std::string out = fmt::format("{:4}{:4}\n", rows, columns);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    out += fmt::format("{:4}.", keys[k]).substr(1);
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

struct Deck {
  std::vector<int> keys;
  std::vector<std::vector<double>> numbers;
  std::string text() const { return deck_text(nocur, nostr, keys, numbers); }
};

Deck wavy_deck() {
  Deck d;
  for (int i = 0; i < nocur; ++i)
    for (int j = 0; j < nostr; ++j) {
      const Vec3 p = wavy_point(i, j);
      d.keys.push_back(1);
      d.numbers.push_back({p.x, p.y, p.z});
    }
  return d;
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace

TEST_CASE("AUTO at TANGENTS? sets every border tangent by Marks's rule, per unit of chord") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_wavy(ctx, {"AUTO"});
  const Workspace& ws = ctx.ws;
  CHECK(ctx.reports == 0);
  CHECK(ws.auto_tangents());
  CHECK(!ws.marks_twists());
  CHECK(ws.inptg == marks_border_tangents(nocur, nostr, as_vec3(ws.inppn)));
  // PATCHES holds Marks's vectors themselves at the border: Pu at the first corner of patch 1.
  const GridTangents marks = marks_grid_tangents(nocur, nostr, as_vec3(ws.inppn));
  const Array patches = given_patches(ws);
  for (int k = 0; k < 3; ++k) {
    const double along_curve[3] = {marks.along_curves[0].x, marks.along_curves[0].y,
                                   marks.along_curves[0].z};
    const double along_stringer[3] = {marks.along_stringers[0].x, marks.along_stringers[0].y,
                                      marks.along_stringers[0].z};
    CHECK(element(patches, 0, k, 2, 0) == doctest::Approx(along_curve[k]).epsilon(1e-12));
    CHECK(element(patches, 0, k, 0, 2) == doctest::Approx(along_stringer[k]).epsilon(1e-12));
  }
  // Lowercase and a prefix are the same word; HELP and DISPLAY INPUT say so.
  FakeContext again(dir.path());
  build_wavy(again, {"au"});
  CHECK(again.ws.inptg == ws.inptg);
  ctx.said.clear();
  ctx.ws.status[0] = 0;
  ctx.run(help_command, "");
  CHECK(ctx.said.back() == "THE CURRENT SURFACE HAS TANGENTS AUTO (MARKS'S RULE).");
  const Image image = input_image(ws, View{Projection::orthogonal, {1, 0, 0}});
  const auto caption = picture_of(image).caption;
  CHECK(caption.back() == "TANGENTS AUTO");
  CHECK(image_line(image) == "IMAGE: INPUT, ORTHOGONAL XY, TANGENTS AUTO");  // the one-line text
  // Without AUTO there is no such line.
  FakeContext typed(dir.path());
  build_wavy(typed, {"1 1 0 0 1"});
  CHECK(!typed.ws.auto_tangents());
  CHECK(picture_of(input_image(typed.ws, View{Projection::orthogonal, {1, 0, 0}})).caption.back() !=
        "TANGENTS AUTO");
}

TEST_CASE("entries after AUTO override single tangents; CHANGE TANGENTS AUTO; CHANGE POINTS") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_wavy(ctx, {"AUTO", "1 5 6 7 1", "3 0 0 2"});
  const Array marks = marks_border_tangents(nocur, nostr, as_vec3(ctx.ws.inppn));
  const Array& inptg = ctx.ws.inptg;
  for (std::size_t row = 0; row < inptg.shape[0]; ++row) {
    CAPTURE(row);
    const std::size_t stringer_3 = 2 * nocur + 2 * 2;  // point 3 along stringer 3, curve 1
    if (row == 0) {
      CHECK(std::vector<double>(inptg.ravel.begin(), inptg.ravel.begin() + 4) ==
            std::vector<double>{5, 6, 7, 1});
    } else if (row == stringer_3) {
      CHECK(inptg.ravel[4 * row + 2] == 2);
      CHECK(inptg.ravel[4 * row + 3] == 3);
    } else {
      for (std::size_t c = 0; c < 4; ++c)
        CHECK(inptg.ravel[4 * row + c] == marks.ravel[4 * row + c]);
    }
  }
  CHECK(ctx.ws.auto_tangents());

  // CHANGE TANGENTS with typed entries only keeps the mark; AUTO there sets them all again.
  ctx.type({"1 1 1 1 1", "", "N"});
  ctx.run(change_command, "T");
  CHECK(ctx.ws.auto_tangents());
  ctx.type({"AUTO", "", "N"});
  ctx.run(change_command, "T");
  CHECK(ctx.ws.inptg == marks);

  // New points: the old AUTO tangents are kept as numbers but the mark goes, unless AUTO again.
  ctx.type({"7 10 10 40", "", "N", "N"});
  ctx.run(change_command, "P");
  CHECK(!ctx.ws.auto_tangents());
  CHECK(ctx.ws.inptg == marks);
  ctx.type({"7 10 10 45", "", "AUTO", "", "N"});
  ctx.run(change_command, "P");
  CHECK(ctx.ws.auto_tangents());
  CHECK(ctx.ws.inptg == marks_border_tangents(nocur, nostr, as_vec3(ctx.ws.inppn)));
  CHECK(ctx.reports == 0);
}

TEST_CASE("CHANGE TWISTS: ZERO or MARKS into PATCHES and the grid") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_wavy(ctx, {"AUTO"});
  const Array zero_patches = given_patches(ctx.ws), zero_grid = ctx.ws.intpn;
  for (std::size_t p = 0; p < 12; ++p)
    for (int k = 0; k < 3; ++k) CHECK(element(zero_patches, p, k, 2, 2) == 0);

  ctx.run(change_command, "TW", {"MARKS"});
  const Workspace& ws = ctx.ws;
  CHECK(ws.marks_twists());
  CHECK(ws.status[2] == 1);  // STATUS[3]
  CHECK(ws.auto_tangents());
  SurfaceInput input = surface_input(ws);
  CHECK(input.marks_twists);
  const Surface expected = interpolate(input);
  const Array patches = given_patches(ws);
  CHECK(patches == expected.patches);
  CHECK(ws.intpn == expected.intpn);
  CHECK(ws.intpn != zero_grid);
  // The twist of point 7 (curve 2, place 2) is Marks's, unscaled, at M[2][2] of patch (1, 1).
  const Array twists = marks_twists(nocur, nostr, as_vec3(ws.inppn));
  const Vec3 t7 = as_vec3(twists)[6];
  CHECK(t7 != Vec3{});
  CHECK(element(patches, 5, 0, 2, 2) == t7.x);
  CHECK(element(patches, 5, 2, 2, 2) == t7.z);
  // Everything but the twist block is as before.
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const std::size_t r = (i / 4) % 4, c = i % 4;
    if (r < 2 || c < 2) CHECK(patches.ravel[i] == zero_patches.ravel[i]);
  }
  // Asked when not on the line; a wrong answer is asked again; back to ZERO.
  ctx.type({"SOME", "Z"});
  ctx.run(change_command, "TW");
  CHECK(ctx.prompts.back() == "TWISTS? (ZERO OR MARKS)");
  CHECK(ctx.said.back() == "INCORRECT ENTRY: ANSWER ZERO OR MARKS");
  CHECK(!ctx.ws.marks_twists());
  CHECK(given_patches(ctx.ws) == zero_patches);
  // A wrong word on the command line ends the command.
  CHECK(report_of(ctx, change_command, "TW", {"ONE"}) == "INCORRECT ENTRY: ANSWER ZERO OR MARKS");
  // A new surface has the manual's zero twists again.
  ctx.run(change_command, "TW", {"M"});
  build_wavy(ctx, {});
  CHECK(!ctx.ws.marks_twists());
  CHECK(!ctx.ws.auto_tangents());
}

TEST_CASE("FIT makes a deck the current surface and writes its listing") {
  TempDir dir;
  FakeContext ctx(dir.path());
  Deck d = wavy_deck();
  d.keys[6] = 1 + 2 + 4 + 8;  // given vectors at an interior point
  d.numbers[6].insert(d.numbers[6].end(), {3, 1, 0, -1, 4, 0.5, 1.5, -0.5, 2});
  d.keys[0] = 1 + 2;  // a given tangent along the first curve at its corner
  d.numbers[0].insert(d.numbers[0].end(), {12, 0, 1});
  write_text(dir.path() / "WAVY.CADADATA", d.text());
  ctx.type({"3 1"});
  ctx.run(fit_command, "", {"wavy"});
  CHECK(ctx.reports == 0);
  CHECK(ctx.prompts == std::vector<std::string>{"INTERPOLATED CURVES AND STRINGERS?"});
  CHECK(ctx.said ==
        std::vector<std::string>{"NOCUR 4 NOSTR 5 INTCU 3 INTST 1",
                                 "WAVY.CADALIST: 20 POINTS, 12 PATCHES, 4 GIVEN VECTORS"});
  const exchange::MarksDeck deck = exchange::read_deck(d.text());
  const exchange::MarksFit fit = exchange::fit_deck(deck);
  const Workspace& ws = ctx.ws;
  CHECK(ws.nocur == 4);
  CHECK(ws.nostr == 5);
  CHECK(ws.inppn == deck.points);
  CHECK(ws.inptg == fit.inptg);
  CHECK(ws.patches == fit.patches);
  CHECK(ws.marks_twists());
  CHECK(ws.auto_tangents());
  CHECK(!ws.changes.derived);  // Marks's interior tangents: the session keeps PATCHES
  CHECK(ws.intpn == refit({4, 5, 3, 1, &deck.points, &fit.inptg, true}, fit.patches));
  // The given vectors are in PATCHES as given (point 7 is corner P(0,0) of patch 5).
  CHECK(element(ws.patches, 5, 0, 2, 0) == 3);
  CHECK(element(ws.patches, 5, 1, 0, 2) == 4);
  CHECK(element(ws.patches, 5, 2, 2, 2) == 2);
  CHECK(element(ws.patches, 0, 0, 2, 0) == 12);
  CHECK(element(ws.patches, 0, 2, 2, 0) == 1);
  CHECK(file_text(dir.path() / "WAVY.CADALIST") == exchange::cada_listing(deck, fit));
  // The name is asked when not on the line; no such deck is FILE NOT FOUND.
  ctx.type({"NONE"});
  CHECK(report_of(ctx, fit_command, "") == "FILE NOT FOUND");
  CHECK(ctx.ws.patches == fit.patches);
}

TEST_CASE("FIT refuses a deck with a missing point, naming it, and keeps the surface") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_wavy(ctx, {"AUTO"});
  ctx.prompts.clear();
  const Workspace before = ctx.ws;
  Deck d = wavy_deck();
  d.keys[5] = 0;  // point 6
  d.numbers.erase(d.numbers.begin() + 5);
  write_text(dir.path() / "HOLE.CADADATA", d.text());
  CHECK(report_of(ctx, fit_command, "", {"HOLE"}) ==
        "DECK REFUSED: HOLE.CADADATA (POINT 6 HAS NO POSITION, KEY ON LINE 2; IGDS NEEDS EVERY "
        "POINT); CURRENT SURFACE KEPT");
  write_text(dir.path() / "BAD.CADADATA", "   4   5\n  1.  x.\n");
  CHECK(report_of(ctx, fit_command, "", {"BAD"}) ==
        "DECK REFUSED: BAD.CADADATA (LINE 2 COLUMN 5: NOT A NUMBER); CURRENT SURFACE KEPT");
  CHECK(ctx.ws == before);
  CHECK(ctx.prompts.empty());
  CHECK(!fs::exists(dir.path() / "HOLE.CADALIST"));
}

TEST_CASE("PUNCH writes the tape; read back it is PATCHES number by number, MPDP's signs") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, punch_command, "", {"T"}) == "INPUT NOT FOUND");
  build_wavy(ctx, {"AUTO"});
  ctx.run(change_command, "TW", {"MARKS"});
  ctx.run(punch_command, "", {"wavy"});
  REQUIRE(ctx.said.size() >= 2);
  CHECK(ctx.said[ctx.said.size() - 2] == "WAVY.MPDPTAPE: 12 PATCHES, 1947 FRAMES");
  CHECK(ctx.said.back() == "MPDP HOLDS ABOUT 10 PATCHES AT A TIME");
  const std::string tape = file_text(dir.path() / "WAVY.MPDPTAPE");
  CHECK(tape.size() == 12 * 162 + 3);
  const auto patches = exchange::read_tape(tape);
  REQUIRE(patches.size() == 12);
  const Array m = given_patches(ctx.ws);
  bool some_negative = false, some_twist = false;
  for (std::size_t p = 0; p < 12; ++p) {
    CAPTURE(p);
    CHECK(patches[p].number == int(p + 1));
    CHECK(patches[p].internal_lines == 0);
    CHECK(patches[p].links == std::array<std::int32_t, 4>{});
    for (int k = 0; k < 3; ++k)
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
          // S_V, SE_V, E_H and SE_H change sign on the tape (docs/marks.md).
          const bool reversed =
              (r == 0 && c == 3) || (r == 1 && c == 3) || (r == 3 && c == 0) || (r == 3 && c == 1);
          const double value = element(m, p, k, r, c);
          const long expected = std::lround(reversed ? -value : value);
          CHECK(patches[p].b[std::size_t(16 * k + 4 * r + c)] == expected);
          some_negative = some_negative || expected < 0;
          some_twist = some_twist || (r >= 2 && c >= 2 && expected != 0);
        }
  }
  CHECK(some_negative);
  CHECK(some_twist);
  // A value beyond 18 bits is refused, the patch named, and nothing written.
  ctx.type({"7 10 10 200000", "", "N", "N"});
  ctx.run(change_command, "P");
  const std::string refused = report_of(ctx, punch_command, "", {"BIG"});
  CHECK(refused.starts_with("PATCH 1 HOLDS "));
  CHECK(refused.ends_with(", OUTSIDE THE TAPE'S 18 BITS (-131072 TO 131071); NO FILE WRITTEN"));
  CHECK(!fs::exists(dir.path() / "BIG.MPDPTAPE"));
  // A single curve has no patches.
  ctx.type({"1 3", "1 0 0 0 1 0 0 2 0 1", "", "", "1 1"});
  ctx.run(build_command, "");
  CHECK(report_of(ctx, punch_command, "", {"LINE"}) ==
        "A SINGLE CURVE OR STRINGER HAS NO PATCHES TO PUNCH");
}

TEST_CASE("the twists and AUTO mark are kept by SAVE and RESTORE and by the session") {
  TempDir dir;
  const Disk disk(dir.path());
  Workspace saved;
  {
    Session session(disk);
    FakeContext ctx(dir.path(), session.load());
    build_wavy(ctx, {"AUTO"});
    ctx.run(change_command, "TW", {"MARKS"});
    // An image drawn from the MARKS surface, kept after CHANGE TWISTS ZERO, comes back from
    // its own record of the session, with Marks's twists.
    ctx.ws.temp1 = std::make_shared<const Image>(
        surface_image(ctx.ws, View{Projection::assonometric, {110, 130, 120}}));
    session.save(ctx.ws);
    ctx.run(change_command, "TW", {"ZERO"});
    ctx.ws.image = std::make_shared<const Image>(
        surface_image(ctx.ws, View{Projection::assonometric, {110, 130, 120}}));
    CHECK(!(*ctx.ws.image == *ctx.ws.temp1));
    session.save(ctx.ws);
    ctx.run(change_command, "TW", {"MARKS"});
    ctx.ws.status[0] = 0;
    save_surface(disk, "MODES", ctx.ws);
    session.save(ctx.ws);
    saved = ctx.ws;
  }
  {
    Session session(disk);
    Workspace ws = session.load();
    CHECK(!ws.temp1.made());  // a recipe, made from its record when looked at
    CHECK(ws.marks_twists());
    CHECK(ws.auto_tangents());
    CHECK(ws.changes.derived);
    CHECK(ws == saved);
    CHECK(given_patches(ws) == interpolate(surface_input(saved)).patches);
    CHECK(*ws.temp1 == *saved.temp1);
    CHECK(*ws.image == *saved.image);
    // RESTORE into a workspace without the modes gives them back with the patches.
    Workspace other;
    restore_surface(disk, "MODES", other);
    CHECK(other.marks_twists());
    CHECK(other.auto_tangents());
    CHECK(same_patches(other, saved));
    CHECK(other.changes.derived);
    CHECK(other.status[0] == 1);  // the HELP setting is not the surface's
  }
}

TEST_CASE("a FIT surface's patches are kept by the session and by CHANGE GRID") {
  TempDir dir;
  const Disk disk(dir.path());
  write_text(dir.path() / "WAVY.CADADATA", wavy_deck().text());
  Workspace saved;
  {
    Session session(disk);
    FakeContext ctx(dir.path(), session.load());
    ctx.type({"1 1"});
    ctx.run(fit_command, "", {"WAVY"});
    const Array patches = ctx.ws.patches;
    ctx.type({"2 3"});
    ctx.run(change_command, "G");
    CHECK(ctx.ws.patches == patches);
    CHECK(!ctx.ws.changes.derived);
    session.save(ctx.ws);
    saved = ctx.ws;
  }
  Session session(disk);
  Workspace ws = session.load();
  CHECK(ws == saved);
  CHECK(ws.marks_twists());
}

}  // namespace igds::test
