// BUILD, CHANGE, DISPLAY, STORE, END and HELP driven through a scripted Context.
#include <doctest/doctest.h>

#include <cmath>

#include "commands/command.h"
#include "commands/surface.h"
#include "commands/view.h"
#include "tests/support/fake_context.h"
#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/error.h"

namespace igds {
extern const Command build_command;
extern const Command change_command;
extern const Command display_command;
extern const Command store_command;
extern const Command end_command;
extern const Command help_command;
}  // namespace igds

namespace igds::test {

namespace {

const std::vector<std::string> saddle{"3 3",
                                      "1  0 0 0   0 10 2   0 20 0",
                                      "4  10 0 2  10 10 0  10 20 2",
                                      "7  20 0 0  20 10 2  20 20 0",
                                      "",
                                      "1 0 1 0 1",
                                      "1 1 0 0 0",
                                      "",
                                      "2 2"};

void build_saddle(FakeContext& ctx) {
  ctx.type(saddle);
  ctx.run(build_command, "");
  REQUIRE(ctx.ws.has_surface());
}

}  // namespace

TEST_CASE("BUILD asks its four questions and makes the surface") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  CHECK(ctx.prompts == std::vector<std::string>{"NUMBER OF CURVES AND STRINGERS?", "POINTS?",
                                                "POINTS?", "POINTS?", "POINTS?", "TANGENTS?",
                                                "TANGENTS?", "TANGENTS?",
                                                "INTERPOLATED CURVES AND STRINGERS?"});
  const Workspace& ws = ctx.ws;
  CHECK(ws.nocur == 3);
  CHECK(ws.nostr == 3);
  CHECK(ws.intcu == 2);
  CHECK(ws.intst == 2);
  CHECK(ws.inppn.shape == std::vector<std::size_t>{9, 3});
  CHECK(ws.inppn.ravel[3 * 4 + 2] == 0);  // point 5 is 10 10 0
  CHECK(ws.inppn.ravel[3 * 5 + 2] == 2);  // point 6 is 10 20 2
  CHECK(ws.inptg.shape == std::vector<std::size_t>{12, 4});
  CHECK(ws.inptg.ravel[0 * 4 + 1] == 1);  // point 1 along the curve: 0 1 0
  CHECK(ws.inptg.ravel[6 * 4 + 0] == 1);  // point 1 along the stringer: 1 0 0
  // The interpolation's PATCHES are not kept: made when they are read.
  CHECK(ws.patches.shape.empty());
  CHECK(given_patches(ws).shape == std::vector<std::size_t>{2, 2, 3, 4, 4});
  CHECK(ws.intpn.shape == std::vector<std::size_t>{7, 7, 3});
  // Input point 5 (curve 2, place 2) is grid point (3, 3), bit-exact.
  const double* p = ws.intpn.data() + (3 * 7 + 3) * 3;
  CHECK(p[0] == 10);
  CHECK(p[1] == 10);
  CHECK(p[2] == 0);
  CHECK(ctx.reports == 0);
}

TEST_CASE("BUILD: words after BUILD are refused") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, build_command, "", {"3", "3"}) == "INCORRECT COMMAND OR PARAMETERS");
  CHECK(ctx.prompts.empty());
}

TEST_CASE("BUILD: incorrect entries are reported, ignored, and the next one awaited") {
  TempDir dir;
  FakeContext ctx(dir.path());
  ctx.type({"0 3", "3 3 3", "2 x", "2 2", "5 1 1 1", "9 1 2", "4 1 2 3", "", "3 0 0", "2 1 0 0 0",
            "", "-1 0", "1 1"});
  ctx.run(build_command, "");
  CHECK(ctx.reports == 7);
  CHECK(ctx.said[0] == "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS, NOCUR AND NOSTR");
  CHECK(ctx.said[2] == "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS, NOCUR AND NOSTR");
  CHECK(ctx.said[3] == "INCORRECT ENTRY: THE POINT NUMBER MUST BE 1 TO 4");
  CHECK(ctx.said[4] == "INCORRECT ENTRY: A POINT ENTRY IS K X Y Z [X Y Z ...]");
  CHECK(ctx.ws.nocur == 2);
  CHECK(ctx.ws.inppn.ravel == Ravel{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3});
  CHECK(ctx.ws.inptg.ravel[6 * 4 + 0] == 1);  // point 2, f = 0: along stringer 2 at curve 1
  CHECK(ctx.ws.intpn.shape == std::vector<std::size_t>{3, 3, 3});
}

TEST_CASE("BUILD: Ctrl-C or the end of the input leaves the workspace as it was") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  const Workspace before = ctx.ws;
  ctx.type({"2 2", "1 5 5 5", "^C"});
  CHECK_THROWS_AS(ctx.run(build_command, ""), Interrupted);
  CHECK(ctx.ws == before);
  ctx.type({"2 2", "1 5 5 5", "", ""});
  CHECK_THROWS_AS(ctx.run(build_command, ""), EndOfInput);
  CHECK(ctx.ws == before);
}

TEST_CASE("BUILD and CHANGE interpolate into the old surface's memory, kept when refused") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  const Workspace before = ctx.ws;
  const double* intpn = ctx.ws.intpn.data();
  // A point that is not finite (the APL environment can put one in INPPN): refused with the
  // kernel's report, PATCHES and INTPN given back as they were.
  Array inppn = ctx.ws.inppn;
  inppn.ravel[4] = std::nan("");
  const SurfaceInput bad{3, 3, 2, 2, &inppn, &ctx.ws.inptg};
  try {
    interpolate_surface(ctx.ws, bad);
    FAIL("a point that is not finite was interpolated");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).ends_with("; THE SURFACE IS NOT CHANGED"));
  }
  CHECK(ctx.ws == before);
  CHECK(ctx.ws.intpn.data() == intpn);
  // A new surface of the same size is written where the old one was.
  ctx.type(saddle);
  ctx.run(build_command, "");
  CHECK(same_patches(ctx.ws, before));
  CHECK(ctx.ws.intpn.data() == intpn);
}

TEST_CASE("CHANGE needs a surface") {
  TempDir dir;
  FakeContext ctx(dir.path());
  for (std::string_view option : {"GRID", "TANGENTS", "POINTS"})
    CHECK(report_of(ctx, change_command, option) == "INPUT NOT FOUND");
}

TEST_CASE("CHANGE GRID refits the same patches") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  const Array patches = given_patches(ctx.ws);
  ctx.type({"x", "4 0"});
  ctx.run(change_command, "GRID");
  CHECK(ctx.reports == 1);
  CHECK(ctx.ws.intcu == 4);
  CHECK(ctx.ws.intst == 0);
  CHECK(ctx.ws.intpn.shape == std::vector<std::size_t>{11, 3, 3});
  CHECK(given_patches(ctx.ws) == patches);
}

TEST_CASE("CHANGE TANGENTS, then the grid as two numbers or Y/N") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  const Array patches = given_patches(ctx.ws);
  ctx.type({"3 0 5 0 1", "", "maybe", "1 1"});
  ctx.run(change_command, "TANGENTS");
  CHECK(ctx.reports == 1);
  CHECK(ctx.prompts.back() == "CHANGE GRID TOO? (Y OR N)");
  CHECK(ctx.said.back() == "INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS >= 0, INTCU AND INTST");
  CHECK(ctx.ws.inptg.ravel[1 * 4 + 1] == 5);  // point 3 along curve 1
  CHECK(ctx.ws.intcu == 1);
  CHECK(ctx.ws.intpn.shape == std::vector<std::size_t>{5, 5, 3});
  CHECK(given_patches(ctx.ws) != patches);

  ctx.type({"", "N"});
  ctx.run(change_command, "TANGENTS");
  CHECK(ctx.ws.intcu == 1);
  ctx.type({"", "Y", "3 3"});
  ctx.run(change_command, "TANGENTS");
  CHECK(ctx.ws.intpn.shape == std::vector<std::size_t>{9, 9, 3});
}

TEST_CASE("CHANGE POINTS offers CHANGE TANGENTS and CHANGE GRID") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.type({"5 10 10 7", "", "9 0 1 0 1", "", "N"});
  ctx.run(change_command, "POINTS");
  CHECK(ctx.ws.inppn.ravel[4 * 3 + 2] == 7);
  CHECK(ctx.ws.inptg.ravel[5 * 4 + 1] == 1);  // the tangent entry typed at CHANGE TANGENTS TOO?
  CHECK(ctx.ws.intpn.shape == std::vector<std::size_t>{7, 7, 3});
  // The grid point of input point 5 follows it.
  CHECK(ctx.ws.intpn.ravel[(3 * 7 + 3) * 3 + 2] == 7);

  ctx.type({"", "Y", "1 0 0 0 1", "", "Y", "0 0"});
  ctx.run(change_command, "POINTS");
  CHECK(ctx.ws.inptg.ravel[0] == 0);
  CHECK(ctx.ws.intpn.shape == std::vector<std::size_t>{3, 3, 3});
  CHECK(ctx.reports == 0);
}

TEST_CASE("DISPLAY reports what is missing") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, display_command, "INPUT") == "INPUT NOT FOUND");
  CHECK(report_of(ctx, display_command, "SURFACE") == "SURFACE NOT FOUND");
  CHECK(report_of(ctx, display_command, "FIRST") == "IMAGE NOT FOUND");
  CHECK(report_of(ctx, display_command, "SECOND") == "IMAGE NOT FOUND");
  const std::string bad_name =
      "INCORRECT PARAMETER: A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - _";
  CHECK(report_of(ctx, display_command, "FILE", {"a/b"}) == bad_name);
  CHECK(report_of(ctx, display_command, "FILE", {"TOOLONGNAME"}) == bad_name);
  CHECK(report_of(ctx, display_command, "FILE", {"NOSUCH"}) == "FILE NOT FOUND");
  // Extra words after DISPLAY FIRST: the manual's INCORRECT PARAMETER (4.4).
  CHECK(report_of(ctx, display_command, "FIRST", {"X"}) == "INCORRECT PARAMETER");
  CHECK(ctx.shown.empty());
}

TEST_CASE("DISPLAY projection parameters are checked") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"PERSPECTIVE"}, "THE PROJECTION IS CONIC, ISOMETRIC, ASSONOMETRIC OR ORTHOGONAL"},
      {{"O", "XX"}, "THE PLANE IS XY, YZ OR XZ"},
      {{"O", "X"}, "THE PLANE IS XY, YZ OR XZ"},
      {{"I", "4", "30"}, "THE AXIS IS 1, 2 OR 3 (X, Y, Z)"},
      {{"I", "1", "95"}, "THE ANGLE MUST BE 0 TO 90"},
      {{"I", "1.5", "30"}, "THE AXIS IS 1, 2 OR 3 (X, Y, Z)"},
      {{"A", "90", "130", "140"}, "EACH ANGLE MUST BE BETWEEN 90 AND 180"},
      {{"A", "110", "130", "121"}, "THE THREE ANGLES MUST ADD UP TO 360"},
      {{"A", "120", "120"}, "GIVE THREE ANGLES"},
      {{"C", "10", "10", "1"}, "THE VIEW POINT IS INSIDE THE SURFACE'S BOX"},
      {{"C", "1", "2"}, "GIVE THE VIEW POINT AS X Y Z"},
      {{"C", "x", "1", "2"}, "x IS NOT A NUMBER"},
      {{"C", "15", "10", "2.5"}, "A POINT IS BEHIND THE EYE"}};
  for (const auto& c : cases) {
    CAPTURE(c.first.front());
    CHECK(report_of(ctx, display_command, "SURFACE", c.first) ==
          "INCORRECT PARAMETER: " + c.second);
  }
  CHECK(ctx.shown.empty());
  CHECK_FALSE(ctx.ws.image);
  // Typed at the question, a bad answer gets its report and the question again.
  ctx.prompts.clear();
  ctx.said.clear();
  ctx.type({"PERSPECTIVE", "A", "110 130 121", "110 130 120"});
  ctx.run(display_command, "SURFACE");
  CHECK(ctx.prompts ==
        std::vector<std::string>{"PROJECTION?", "PROJECTION?", "THREE ANGLES?", "THREE ANGLES?"});
  CHECK(ctx.said.size() == 2);
  REQUIRE(ctx.ws.image);
  CHECK(ctx.ws.image->desim.parameters == std::array<double, 3>{110, 130, 120});
}

TEST_CASE("DISPLAY INPUT projects the points and the tangents") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.run(display_command, "INPUT", {"ORTHOGONAL", "xy"});
  REQUIRE(ctx.ws.image);
  const Image& image = *ctx.ws.image;
  CHECK(image.desim == Description{0, Projection::orthogonal, {1, 0, 0}});
  CHECK(image.points.shape == std::vector<std::size_t>{3, 3, 2});
  CHECK(image.points.ravel[4 * 2 + 0] == 10);  // point 5: x 10 y 10
  CHECK(image.points.ravel[5 * 2 + 1] == 20);  // point 6: y 20
  // Two tangents at point 1: 0 1 0 along the curve, 1 0 0 along the stringer.
  REQUIRE(image.arrows.shape == std::vector<std::size_t>{2, 6});
  // Each row: base x y, direction dx dy, the point, 1 along the curve or 0 the stringer.
  for (std::size_t i = 0; i < 6; ++i) {
    CHECK(image.arrows.ravel[i] == doctest::Approx(std::vector<double>{0, 0, 0, 1, 1, 1}[i]));
    CHECK(image.arrows.ravel[6 + i] == doctest::Approx(std::vector<double>{0, 0, 1, 0, 1, 0}[i]));
  }
  REQUIRE(ctx.shown.size() == 1);
  CHECK(ctx.shown[0] == image);
}

TEST_CASE("DISPLAY SURFACE asks the projection and its parameters") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.type({"", "ass", "110 130 120"});
  ctx.run(display_command, "SURFACE");
  CHECK(ctx.prompts.back() == "THREE ANGLES?");
  REQUIRE(ctx.ws.image);
  CHECK(ctx.ws.image->desim == Description{1, Projection::assonometric, {110, 130, 120}});
  CHECK(ctx.ws.image->points.shape == std::vector<std::size_t>{7, 7, 2});
  CHECK(ctx.ws.image->arrows.empty());

  ctx.run(display_command, "SURFACE", {"AXONOMETRIC", "120", "120", "120"});
  CHECK(ctx.ws.image->desim.projection == Projection::assonometric);
  ctx.run(display_command, "SURFACE", {"I", "3", "30"});
  CHECK(ctx.ws.image->desim == Description{1, Projection::isometric, {3, 30, 0}});
  ctx.run(display_command, "SURFACE", {"C", "100", "¯50", "80"});
  CHECK(ctx.ws.image->desim == Description{1, Projection::conic, {100, -50, 80}});
  CHECK(ctx.shown.size() == 4);
}

TEST_CASE("DISPLAY COMBS: the surface and a comb at every point, its scale said") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, display_command, "COMBS") == "SURFACE NOT FOUND");
  build_saddle(ctx);
  ctx.run(display_command, "COMBS", {"O", "XZ"});
  REQUIRE(ctx.ws.image);
  const Image image = *ctx.ws.image;  // a copy: DISPLAY SURFACE below replaces the current image
  CHECK(image.desim == Description{3, Projection::orthogonal, {2, 0, 0}});
  CHECK(image.points.shape == std::vector<std::size_t>{7, 7, 2});
  CHECK(image.combs.shape == std::vector<std::size_t>{7, 7, 4});
  // The saddle's lines are parabola-like arcs 20 long and 2 high: a comb of the largest
  // curvature is at most a fifth of 20, and a scale of 1, 2 or 5 times a power of ten.
  CHECK(image.comb_scale > 0);
  const double mantissa = image.comb_scale / std::pow(10, std::floor(std::log10(image.comb_scale)));
  CHECK((std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
         std::abs(mantissa - 5) < 1e-9));
  // Point 1 of the grid (0 0 0) in XZ: its curve (along y, bending up to z 2 at y 10) bends
  // towards +z, so its comb stands below it, in the plane x = 0.
  CHECK(image.combs.ravel[0] == doctest::Approx(0));
  CHECK(image.combs.ravel[1] < 0);
  REQUIRE(ctx.shown.size() == 1);
  CHECK(ctx.shown[0] == image);
  // STORE FILE and DISPLAY FILE keep the combs.
  ctx.run(store_command, "FILE", {"COMBS"});
  ctx.run(display_command, "SURFACE", {"O", "XY"});
  ctx.run(display_command, "FILE", {"COMBS"});
  CHECK(*ctx.ws.image == image);
  CHECK(ctx.ws.image->combs == image.combs);
}

TEST_CASE("STORE and DISPLAY FIRST, SECOND and FILE") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, store_command, "FIRST") == "IMAGE NOT FOUND");
  CHECK(report_of(ctx, store_command, "FILE", {"X"}) == "IMAGE NOT FOUND");
  build_saddle(ctx);
  ctx.run(display_command, "SURFACE", {"O", "XY"});
  const Image xy = *ctx.ws.image;
  ctx.run(store_command, "FIRST");
  ctx.run(display_command, "SURFACE", {"O", "YZ"});
  const Image yz = *ctx.ws.image;
  ctx.run(store_command, "SECOND");
  CHECK(report_of(ctx, store_command, "FILE", {"a.b"}) ==
        "INCORRECT PARAMETER: A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - _");
  ctx.run(store_command, "FILE", {"view"});
  CHECK(std::filesystem::exists(dir.path() / "VIEW.IGDSIMAG"));
  CHECK(report_of(ctx, store_command, "SECOND", {"2"}) == "INCORRECT COMMAND OR PARAMETERS");
  CHECK(*ctx.ws.temp1 == xy);
  CHECK(*ctx.ws.temp2 == yz);

  ctx.run(display_command, "FIRST");
  CHECK(*ctx.ws.image == xy);
  ctx.type({"VIEW"});
  ctx.run(display_command, "FILE");
  CHECK(ctx.prompts.back() == "FILE NAME?");
  CHECK(*ctx.ws.image == yz);
  ctx.run(display_command, "SECOND");
  CHECK(ctx.shown.size() == 5);
}

TEST_CASE("END and HELP") {
  TempDir dir;
  FakeContext ctx(dir.path());
  ctx.run(end_command, "APL");
  CHECK(ctx.ends == 1);
  ctx.run(end_command, "CMS");
  CHECK(ctx.ends == 0);
  CHECK(report_of(ctx, end_command, "CMS", {"NOW"}) == "INCORRECT COMMAND OR PARAMETERS");

  CHECK(ctx.ws.status[0] == 1);
  ctx.run(help_command, "SHORT");
  CHECK(ctx.ws.status[0] == 0);
  CHECK(ctx.said.size() == 2);
  CHECK(ctx.said[0].starts_with("Type a command: BUILD CHANGE RESTORE DISPLAY"));
  ctx.said.clear();
  ctx.run(help_command, "");
  CHECK(ctx.said.size() == 2);
  ctx.said.clear();
  ctx.run(help_command, "LONG");
  CHECK(ctx.ws.status[0] == 1);
  CHECK(ctx.said.size() > 20);
  ctx.said.clear();
  ctx.run(help_command, "");
  CHECK(ctx.said.size() > 20);
}

}  // namespace igds::test
