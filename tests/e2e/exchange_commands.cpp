// EXPORT DUCT, IGES and STEP and DISPLAY PICTURE (commands/export.cpp, display.cpp): the golden
// files of a small surface written by the command, a hand-written DUCT picture displayed and
// decoded, the round trip EXPORT DUCT then DISPLAY PICTURE, damaged pictures refused with their
// line, a picture image kept by STORE FILE and by the session, and the IGES file of the real igds
// read by OpenCASCADE.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/picture.h"
#include "devices/render.h"
#include "devices/tek_stream.h"
#include "tests/e2e/e2e_support.h"
#include "tests/support/fake_context.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "tests/support/tek_decoder.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/exchange_support.h"
#include "tests/workspace/occt_support.h"
#include "workspace/disk/session.h"
#include "workspace/drawing/project.h"
#include "workspace/error.h"
#include "workspace/exchange/duct.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/step.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/images.h"
#include "workspace/variables.h"

namespace igds {
extern const Command export_command;
extern const Command import_command;
extern const Command display_command;
extern const Command store_command;
}  // namespace igds

namespace igds::test::exchange {

namespace {

namespace fs = std::filesystem;

// 22 SEP 1987 09:55:50 UTC, the date of the golden files.
constexpr const char* golden_epoch = "559302950";
const Timestamp golden_date{1987, 9, 22, 9, 55, 50};

// SOURCE_DATE_EPOCH set while it lives.
struct FixedDate {
  FixedDate() { setenv("SOURCE_DATE_EPOCH", golden_epoch, 1); }
  ~FixedDate() { unsetenv("SOURCE_DATE_EPOCH"); }
};

template <class F>
std::string report_of(F f) {
  try {
    f();
  } catch (const Error& r) {
    return r.what();
  }
  return "";
}

// The workspace of the golden surface, as BUILD leaves it.
Workspace workspace_of(const TestSurface& t) {
  Workspace ws;
  ws.nocur = t.input.nocur;
  ws.nostr = t.input.nostr;
  ws.intcu = t.input.intcu;
  ws.intst = t.input.intst;
  ws.inppn = t.inppn;
  ws.inptg = t.inptg;
  ws.patches = t.surface.patches;
  ws.intpn = t.surface.intpn;
  ws.changes.replaced();
  return ws;
}

fs::path hand_written() {
  return source_dir() / "tests/workspace/data/hand_written.ductpic";
}

// The shortest distance from `p` to the polyline.
double distance_to(DevicePoint p, std::span<const DevicePoint> path) {
  double best = INFINITY;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const double ax = path[k].x, ay = path[k].y, bx = path[k + 1].x, by = path[k + 1].y;
    const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - ax) * dx + (p.y - ay) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    best = std::min(best, std::hypot(p.x - (ax + t * dx), p.y - (ay + t * dy)));
  }
  if (path.size() == 1) best = std::hypot(p.x - path[0].x, p.y - path[0].y);
  return best;
}

// The largest distance of a vertex of either path from the other path.
double path_gap(std::span<const DevicePoint> a, std::span<const DevicePoint> b) {
  double gap = 0;
  for (DevicePoint p : a) gap = std::max(gap, distance_to(p, b));
  for (DevicePoint p : b) gap = std::max(gap, distance_to(p, a));
  return gap;
}

}  // namespace

TEST_CASE("EXPORT DUCT, IGES and STEP of a small surface: the golden files, the reports") {
  const FixedDate date;
  const TestSurface t = golden_surface();
  TempDir dir;
  FakeContext ctx(dir.path(), workspace_of(t));
  ctx.run(export_command, "DUCT", {"hull"});
  ctx.run(export_command, "IGES", {"HULL"});
  ctx.type({"hull"});
  ctx.run(export_command, "STEP");
  CHECK(ctx.prompts == std::vector<std::string>{"FILE NAME?"});
  const std::string duct = read_file(dir.path() / "HULL.DUCTPIC");
  const std::string iges = read_file(dir.path() / "HULL.IGS");
  const std::string step = read_file(dir.path() / "HULL.STP");
  check_golden("export_5x4.ductpic", duct);
  check_golden("export_5x4.igs", iges);
  check_golden("export_5x4.stp", step);
  // What the libraries write for the same surface, name and date.
  CHECK(duct == write_duct(duct_picture(
                    surface_curves(t.input, t.surface),
                    {"HULL", duct_date(golden_date), "SURFACE 5 X 4, INTCU 2, INTST 2"})));
  CHECK(iges == write_iges(t.input, t.surface.patches, {"HULL", "HULL.IGS", golden_date, "", ""}));
  CHECK(step == write_step(t.input, t.surface.patches, {"HULL", "HULL.STP", golden_date, "", ""}));
  CHECK(duct.starts_with("IGDS PICTURE FILE HULL 22 SEP 1987 09:55:50\n"));
  CHECK(iges.find("15H19870922.095550") != std::string::npos);
  CHECK(ctx.said == std::vector<std::string>{
                        fmt::format("HULL.DUCTPIC: THE SURFACE IN SPACE, {} BYTES", duct.size()),
                        fmt::format("HULL.IGS: {} BYTES", iges.size()),
                        fmt::format("HULL.STP: {} BYTES", step.size())});
  // FACES and a unit after the name, in any order, abbreviated (F is FACES, M metres).
  ctx.run(export_command, "IGES", {"PATCHES", "F", "in"});
  CHECK(read_file(dir.path() / "PATCHES.IGS") ==
        write_iges(t.input, t.surface.patches,
                   {"PATCHES", "PATCHES.IGS", golden_date, "", "", LengthUnit::inch},
                   SurfaceForm::patches));
  ctx.run(export_command, "STEP", {"METRES", "M"});
  CHECK(read_file(dir.path() / "METRES.STP") ==
        write_step(t.input, t.surface.patches,
                   {"METRES", "METRES.STP", golden_date, "", "", LengthUnit::m}));
  ctx.run(export_command, "STEP", {"NONE", "NONE", "FACES"});
  CHECK(read_file(dir.path() / "NONE.STP") ==
        write_step(t.input, t.surface.patches,
                   {"NONE", "NONE.STP", golden_date, "", "", LengthUnit::none},
                   SurfaceForm::patches));

  // An image of the current surface changes nothing: the surface is written in space.
  ctx.ws.image = std::make_shared<const Image>(
      surface_image(ctx.ws, {Projection::assonometric, {110, 130, 120}}));
  ctx.run(export_command, "DU", {"AGAIN"});
  const std::string again = read_file(dir.path() / "AGAIN.DUCTPIC");
  CHECK(again.substr(again.find('\n')) == duct.substr(duct.find('\n')));
}

TEST_CASE("EXPORT DUCT writes the surface whatever the image, with IMAGE the image as projected") {
  const FixedDate date;
  const TestSurface t = golden_surface();
  TempDir dir;
  FakeContext ctx(dir.path(), workspace_of(t));
  const View view{Projection::assonometric, {110, 130, 120}};
  Image image = surface_image(ctx.ws, view);
  ctx.ws.image = std::make_shared<const Image>(image);
  ctx.ws.changes.replaced();  // the surface changed since the image was drawn
  ctx.run(export_command, "DUCT", {"SURFACE"});
  CHECK(read_duct(read_file(dir.path() / "SURFACE.DUCTPIC")).counters[6] == 3);  // I7: in space
  CHECK(ctx.said.at(0).starts_with("SURFACE.DUCTPIC: THE SURFACE IN SPACE, "));
  ctx.run(export_command, "DUCT", {"IMAGE", "IM"});
  const DuctPicture p = read_duct(read_file(dir.path() / "IMAGE.DUCTPIC"));
  CHECK(p.counters[6] == 2);                                           // I7: in the plane
  CHECK(p.counters[7] == static_cast<int>(Projection::assonometric));  // I8: DESIM[2]
  CHECK(p.header.at(1) == "SURFACE ASSONOMETRIC 110 130 120");
  // One straight-line instruction per curve and per stringer of the image, as it is drawn.
  CHECK(p.instructions.size() == picture_of(ctx.ws.image).drawing.size());
  CHECK(ctx.said.at(1).starts_with("IMAGE.DUCTPIC: THE IMAGE AS PROJECTED, "));
  // The name asked for: IMAGE may follow it there too.
  ctx.type({"ASKED IMAGE"});
  ctx.run(export_command, "DUCT");
  CHECK(read_duct(read_file(dir.path() / "ASKED.DUCTPIC")).counters[6] == 2);
  CHECK(report_of([&] {
          ctx.run(export_command, "DUCT", {"X", "SURFACE"});
        }) == "INCORRECT PARAMETER: AFTER THE NAME ONLY IMAGE (THE CURRENT IMAGE AS PROJECTED)");
  // No surface: the image only when asked for.
  ctx.ws = Workspace{};
  ctx.ws.image = std::make_shared<const Image>(image);
  CHECK(report_of([&] { ctx.run(export_command, "DUCT", {"ALONE"}); }) ==
        "SURFACE NOT FOUND: EXPORT DUCT NAME IMAGE WRITES THE CURRENT IMAGE AS PROJECTED");
  CHECK(!fs::exists(dir.path() / "ALONE.DUCTPIC"));
  ctx.run(export_command, "DUCT", {"ALONE", "IMAGE"});
  CHECK(read_file(dir.path() / "ALONE.DUCTPIC").find("SURFACE ASSONOMETRIC") != std::string::npos);
  // No image: IMAGE NOT FOUND.
  FakeContext bare(dir.path(), workspace_of(t));
  CHECK(report_of([&] {
          bare.run(export_command, "DUCT", {"NONE", "IMAGE"});
        }) == reports::image_not_found);
  CHECK(!fs::exists(dir.path() / "NONE.DUCTPIC"));
}

TEST_CASE("EXPORT DUCT of a million pixels or more says its counts do not fit DUCT's fields" *
          doctest::test_suite("slow")) {
  const FixedDate date;
  TempDir dir;
  // 711 x 711 interpolated points: an image of as many vertices on its curves and on its
  // stringers, 1,011,042 pixels, more than I5's six columns hold.
  FakeContext ctx(dir.path(), test::make_interpolated(143, 143, 4, 4));
  ctx.ws.image =
      std::make_shared<const Image>(surface_image(ctx.ws, {Projection::orthogonal, {1, 0, 0}}));
  ctx.run(export_command, "DUCT", {"LARGE", "IMAGE"});
  const DuctPicture p = read_duct(read_file(dir.path() / "LARGE.DUCTPIC"));
  CHECK(p.pixel_count() >= 1000000);
  CHECK(!duct_counts_fit(p));
  REQUIRE(ctx.said.size() == 2);
  CHECK(ctx.said[1] ==
        "LARGE.DUCTPIC: A MILLION PIXELS OR MORE: ITS COUNTS DO NOT FIT DUCT'S I6 FIELDS AND ARE "
        "WRITTEN FREE-FORM");
  // A smaller picture: nothing more said.
  ctx.said.clear();
  ctx.ws = test::make_interpolated(6, 6, 2, 2);
  ctx.run(export_command, "DUCT", {"SMALL"});
  CHECK(ctx.said.size() == 1);
  CHECK(duct_counts_fit(read_duct(read_file(dir.path() / "SMALL.DUCTPIC"))));
}

TEST_CASE("igds: EXPORT DUCT after RESTORE, CHANGE GRID and ERASE writes the surface in space") {
  TempDir disk;
  const RunResult run =
      run_commands(disk, std::string(saddle_build) +
                             "DISPLAY SURFACE ASSONOMETRIC 110 130 120\nSAVE HULL\nRESTORE HULL\n"
                             "EXPORT DUCT RESTORED\nCHANGE GRID 3 3\nEXPORT DUCT CHANGED\nERASE\n"
                             "EXPORT DUCT ERASED\nEXPORT DUCT FLAT IMAGE\n");
  INFO(run.out);
  CHECK(run.status == 0);
  for (const char* name : {"RESTORED", "CHANGED", "ERASED"}) {
    CAPTURE(name);
    CHECK(run.out.find(fmt::format("{}.DUCTPIC: THE SURFACE IN SPACE, ", name)) !=
          std::string::npos);
    const DuctPicture p = read_duct(read_file(disk.path() / fmt::format("{}.DUCTPIC", name)));
    CHECK(p.counters[6] == 3);  // I7: in space
    CHECK(p.counters[7] == 0);  // not projected
    CHECK(p.header.at(1).starts_with("SURFACE 3 X 3, "));
  }
  // CHANGE GRID's surface: 3 x 3 input points interpolated 3 x 3, 7 curves and 7 stringers.
  CHECK(read_duct(read_file(disk.path() / "CHANGED.DUCTPIC")).header.at(1) ==
        "SURFACE 3 X 3, INTCU 3, INTST 3");
  CHECK(run.out.find("FLAT.DUCTPIC: THE IMAGE AS PROJECTED, ") != std::string::npos);
  CHECK(read_duct(read_file(disk.path() / "FLAT.DUCTPIC")).counters[6] == 2);
}

TEST_CASE("EXPORT DUCT, IGES, STEP: SURFACE NOT FOUND, INCORRECT PARAMETER, nothing written") {
  TempDir dir;
  FakeContext ctx(dir.path());
  for (const char* option : {"DUCT", "IGES", "STEP"})
    CHECK(report_of([&] { ctx.run(export_command, option, {"A"}); }) == reports::surface_not_found);
  // An image is enough for EXPORT DUCT name IMAGE, never for IGES and STEP.
  FakeContext with_image(dir.path());
  with_image.ws.image = std::make_shared<const Image>(
      surface_image(workspace_of(golden_surface()), {Projection::orthogonal, {1, 0, 0}}));
  CHECK(report_of([&] { with_image.run(export_command, "IGES", {"A"}); }) ==
        reports::surface_not_found);
  FakeContext surface(dir.path(), workspace_of(golden_surface()));
  CHECK(report_of([&] { surface.run(export_command, "IGES", {"A.B"}); }) ==
        "INCORRECT PARAMETER: A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - _");
  CHECK(report_of([&] {
          surface.run(export_command, "IGES", {"A", "YARDS"});
        }) ==
        "INCORRECT PARAMETER: YARDS: FACES OR A UNIT (M, MM, CM, INCH, FOOT, NONE) MAY FOLLOW THE "
        "NAME");
  CHECK(report_of([&] {
          surface.run(export_command, "STEP", {"A", "M", "FOOT"});
        }) == "INCORRECT PARAMETER: TWO UNITS");
  CHECK(report_of([&] {
          surface.run(export_command, "STEP", {"A", "FA", "FACES"});
        }) == "INCORRECT PARAMETER: FACES TWICE");

  CHECK(ctx.prompts.empty());
  CHECK(fs::is_empty(dir.path()));
}

namespace {

// The largest difference of two arrays of numbers relative to the largest number of `a`.
double relative_gap(const Array& a, const Array& b) {
  REQUIRE(a.ravel.size() == b.ravel.size());
  double gap = 0, largest = 0;
  for (std::size_t k = 0; k < a.ravel.size(); ++k) {
    gap = std::max(gap, std::abs(a.ravel[k] - b.ravel[k]));
    largest = std::max(largest, std::abs(a.ravel[k]));
  }
  return gap / largest;
}

}  // namespace

TEST_CASE("IMPORT IGES and STEP: a surface EXPORT wrote comes back, its points and tangents") {
  const TestSurface t = golden_surface();
  TempDir dir;
  FakeContext ctx(dir.path(), workspace_of(t));
  ctx.run(export_command, "IGES", {"HULL"});
  ctx.run(export_command, "STEP", {"HULL"});
  for (const std::string kind : {"IGES", "STEP"}) {
    CAPTURE(kind);
    ctx.ws = Workspace{};
    ctx.said.clear();
    ctx.prompts.clear();
    // The grid asked with the surface's own as the default (an empty line), then the density.
    ctx.type({"", "2 2"});
    ctx.run(import_command, kind, {"HULL"});
    CHECK(ctx.prompts == std::vector<std::string>{"NUMBER OF CURVES AND STRINGERS?",
                                                  "INTERPOLATED CURVES AND STRINGERS?"});
    CHECK(ctx.said == std::vector<std::string>{"NOCUR 5 NOSTR 4 INTCU 2 INTST 2"});
    REQUIRE(ctx.ws.nocur == 5);
    REQUIRE(ctx.ws.nostr == 4);
    CHECK(relative_gap(t.inppn, ctx.ws.inppn) < 1e-14);
    // The tangents (column 4, the point number, is not read: docs/kernels.md).
    Array given = t.inptg, imported = ctx.ws.inptg;
    for (std::size_t row = 0; row < given.ravel.size() / 4; ++row)
      given.ravel[4 * row + 3] = imported.ravel[4 * row + 3] = 0;
    CHECK(relative_gap(given, imported) < 1e-13);
    CHECK(relative_gap(t.surface.intpn, ctx.ws.intpn) < 1e-13);
  }
  // A finer sampling of the same surface, on the line: the input points among them.
  ctx.type({"0 0"});
  ctx.run(import_command, "S", {"HULL", "9", "7"});
  REQUIRE(ctx.ws.nocur == 9);
  for (int i = 0; i < 9; i += 2)
    for (int j = 0; j < 7; j += 2)
      for (int c = 0; c < 3; ++c)
        CHECK(std::abs(ctx.ws.inppn.ravel[3 * std::size_t(i * 7 + j) + c] -
                       t.inppn.ravel[3 * std::size_t((i / 2) * 4 + j / 2) + c]) < 1e-12);
  // Refusals: the reason, the surface kept.
  const Workspace before = ctx.ws;
  CHECK(report_of([&] { ctx.run(import_command, "IGES", {"NONE"}); }) == reports::file_not_found);
  write_file(dir.path() / "BAD.STP", "ISO-10303-21;\nDATA;\n#1=CARTESIAN_POINT('',(1.,2.,3.));\n");
  CHECK(report_of([&] { ctx.run(import_command, "STEP", {"BAD"}); }) ==
        "FILE REFUSED: BAD.STP (NO B-SPLINE SURFACE (B_SPLINE_SURFACE_WITH_KNOTS) IN THE FILE); "
        "CURRENT SURFACE KEPT");
  CHECK(report_of([&] {
          ctx.run(import_command, "IGES", {"HULL", "1", "4"});
        }) == "INCORRECT ENTRY: A SURFACE NEEDS AT LEAST 2 CURVES AND 2 STRINGERS");
  CHECK(ctx.ws == before);
}

TEST_CASE("DISPLAY PICTURE: a hand-written picture with every curve, pen code, mark and dash") {
  TempDir dir;
  fs::copy_file(hand_written(), dir.path() / "HAND.DUCTPIC");
  FakeContext ctx(dir.path());
  ctx.type({"ORTHOGONAL", "XY"});
  ctx.run(display_command, "PI", {"hand"});
  CHECK(ctx.prompts == std::vector<std::string>{"PROJECTION?", "PLANE XY, YZ OR XZ?"});
  REQUIRE(ctx.shown.size() == 1);
  REQUIRE(ctx.ws.image);
  const Image& image = *ctx.ws.image;
  CHECK(image.desim.what == 2);
  CHECK(image.desim.projection == Projection::orthogonal);
  CHECK(!image_problem(image));
  REQUIRE(image.picture);
  CHECK(image.picture->name == "HAND");
  const Picture picture = picture_of(ctx.ws.image);
  // The drawing of the picture, seen from above: 21 items (tests/workspace/exchange_duct.cpp).
  const Drawing3 space = duct_drawing(read_duct(read_file(hand_written())));
  CHECK(picture.drawing.size() == space.size());
  CHECK(picture.drawing.size() == 21);
  CHECK(picture.caption ==
        std::vector<std::string>{"PICTURE", "HAND", "ORTHOGONAL", "XY", "COLOURS 1 2 3 4 5"});
  CHECK(describe_line(image.desim) == "IMAGE: PICTURE, ORTHOGONAL XY");

  // The 4013 stream: dashed (ESC c) and chain-dashed (ESC b) vectors besides solid ones, the
  // texts at their pixels, nothing off the screen.
  const std::string stream = tek_stream(picture, {});
  CHECK(stream.find("\x1b"
                    "c") != std::string::npos);
  CHECK(stream.find("\x1b"
                    "b") != std::string::npos);
  const TekDrawing decoded = decode_tek(stream);
  CHECK(decoded.errors.empty());
  REQUIRE(decoded.pages.size() == 2);  // before and after the stream's ESC FF
  const TekPage& page = decoded.pages[1];
  CHECK(page.segments.size() > 50);
  std::vector<std::string> texts;
  for (const TekText& text : page.texts) texts.push_back(text.text);
  // The title (51 characters at x = 164) is cut before the description's column, which says so.
  for (const char* expected : {"IGDS HAND-WRITTEN DUCT PICTURE FOR THE READ", "ORIGIN", "%mm",
                               "PICTURE", "HAND", "COLOURS 1 2 3 4 5", "TEXTS CUT"})
    CHECK(std::find(texts.begin(), texts.end(), expected) != texts.end());
  for (const TekSegment& s : page.segments) {
    CHECK(s.a.x >= 0);
    CHECK(s.b.x <= 1023);
  }

  // STORE, then DISPLAY FIRST: the same picture.
  ctx.run(store_command, "FIRST");
  ctx.run(display_command, "FIRST");
  CHECK(same_image(ctx.ws.image, ctx.ws.temp1));
}

TEST_CASE("DISPLAY PICTURE: the projection on the line, CONIC, and its refusals") {
  TempDir dir;
  fs::copy_file(hand_written(), dir.path() / "HAND.DUCTPIC");
  FakeContext ctx(dir.path());
  ctx.run(display_command, "PICTURE", {"HAND", "CONIC", "100", "-50", "80"});
  REQUIRE(ctx.ws.image);
  CHECK(ctx.ws.image->desim.projection == Projection::conic);
  CHECK(ctx.prompts.empty());
  // A view point inside the picture's box is refused at the question, and asked again.
  ctx.type({"20 10 2", "200 100 80"});
  ctx.run(display_command, "PICTURE", {"HAND", "CONIC"});
  CHECK(ctx.reports == 1);
  CHECK(ctx.ws.image->desim.parameters == std::array<double, 3>{200, 100, 80});
}

TEST_CASE("DISPLAY PICTURE: damaged, foreign and missing pictures refused, the image kept") {
  TempDir dir;
  fs::copy_file(hand_written(), dir.path() / "HAND.DUCTPIC");
  std::string text = read_file(hand_written());
  // Line 7, the second instruction: IARC 1536 does not decompose.
  const std::size_t at = text.find("        2072      2");
  REQUIRE(at != std::string::npos);
  text.replace(at, 19, "        3584      2");
  write_file(dir.path() / "BAD.DUCTPIC", text);
  write_file(dir.path() / "FOREIGN.DUCTPIC", "<svg xmlns=\"http://www.w3.org/2000/svg\"/>\n");
  FakeContext ctx(dir.path());
  ctx.run(display_command, "PICTURE", {"HAND", "ORTHOGONAL", "XY"});
  const Workspace before = ctx.ws;
  CHECK(report_of([&] {
          ctx.run(display_command, "PICTURE", {"BAD", "ORTHOGONAL", "XY"});
        }) ==
        "FILE DAMAGED: BAD.DUCTPIC (LINE 7: INSTRUCTION CODE 3584 DOES NOT DECOMPOSE); "
        "CURRENT IMAGE KEPT");
  const std::string foreign = report_of([&] {
    ctx.run(display_command, "PICTURE", {"FOREIGN", "ORTHOGONAL", "XY"});
  });
  CHECK(foreign.starts_with("FILE DAMAGED: FOREIGN.DUCTPIC (LINE 2: "));
  CHECK(foreign.ends_with("); CURRENT IMAGE KEPT"));
  CHECK(report_of([&] { ctx.run(display_command, "PICTURE", {"NONE"}); }) ==
        reports::file_not_found);
  CHECK(ctx.ws == before);
  CHECK(ctx.shown.size() == 1);
  CHECK(ctx.prompts.empty());
}

TEST_CASE("round trip: EXPORT DUCT then DISPLAY PICTURE draws the surface's own vectors") {
  const TestSurface t = golden_surface();
  TempDir dir;
  FakeContext ctx(dir.path(), workspace_of(t));
  ctx.run(export_command, "DUCT", {"HULL"});
  ctx.run(display_command, "PICTURE", {"HULL", "ASSONOMETRIC", "110", "130", "120"});
  REQUIRE(ctx.ws.image);
  const Drawing2 read_back = picture_of(ctx.ws.image).drawing;
  const View view{Projection::assonometric, {110, 130, 120}};
  const Drawing3 exact = surface_curves(t.input, t.surface);
  const Drawing2 expected = project(exact, view, bounding_box(exact).centre());
  REQUIRE(read_back.size() == expected.size());
  // Both placed as the screen places the exact one: every vector within the flattening
  // tolerance (and the rounding to device units) of the other's.
  const Box screen{0, 0, 4095, 3119};
  const Placement at = fit(expected, screen, 12);
  const Rendering rendering{1, 0.2};
  const Placed a = place(expected, at, screen, rendering);
  const Placed b = place(read_back, at, screen, rendering);
  REQUIRE(a.paths.size() == b.paths.size());
  REQUIRE(a.paths.size() > 40);
  double worst = 0;
  for (std::size_t k = 0; k < a.paths.size(); ++k) {
    CHECK(a.styles[k] == b.styles[k]);
    worst = std::max(worst, path_gap(a.paths[k], b.paths[k]));
  }
  MESSAGE(
      fmt::format("round trip: {} paths, largest gap {:.3f} device units", a.paths.size(), worst));
  // Each side flattened within 0.2 of its curve, each vertex rounded by up to 0.71.
  CHECK(worst <= 2 * 0.2 + std::sqrt(2.0));
}

TEST_CASE("a picture image is kept by STORE FILE and by the session, and cannot be assigned") {
  TempDir dir;
  fs::copy_file(hand_written(), dir.path() / "HAND.DUCTPIC");
  Workspace saved;
  {
    FakeContext ctx(dir.path());
    ctx.run(display_command, "PICTURE", {"HAND", "ASSONOMETRIC", "110", "130", "120"});
    ctx.run(store_command, "FILE", {"KEPT"});
    ctx.run(store_command, "SECOND");
    ctx.run(display_command, "FILE", {"KEPT"});
    REQUIRE(ctx.ws.image->picture);
    CHECK(same_image(ctx.ws.image, ctx.ws.temp2));
    CHECK(picture_of(ctx.ws.image).drawing.size() == 21);
    saved = ctx.ws;
  }
  // The session: written, then read back by a new igds (the file itself set aside first, so that
  // the images must come from the session's own files).
  const Disk disk(dir.path());
  {
    Session session(disk);
    session.load();
    session.save(saved);
  }
  fs::rename(dir.path() / "KEPT.IGDSIMAG", dir.path() / "KEPT.OLD");
  fs::remove(dir.path() / "HAND.DUCTPIC");
  {
    Session session(disk);
    Workspace back = session.load();
    CHECK(session.notices().empty());
    REQUIRE(back.image);
    REQUIRE(back.temp2);
    CHECK(*back.image == *saved.image);
    CHECK(*back.temp2 == *saved.temp2);
    REQUIRE(back.temp2->picture);
    CHECK(picture_of(back.temp2).drawing.size() == 21);
  }
  // An IGDSIMAG file whose picture does not read (written whole, so its checksum is right).
  Image bad;
  bad.desim = {2, Projection::orthogonal, {1, 0, 0}};
  bad.picture =
      std::make_shared<const ImagePicture>(ImagePicture{"BAD", "NOT A PICTURE\n", {}, {}});
  store_image(disk, "BADPIC", bad);
  CHECK(report_of([&] { (void)load_image(disk, "BADPIC"); }) ==
        "FILE DAMAGED: BADPIC.IGDSIMAG (PICTURE LINE 2: NO LINE HOLDING ONLY '*' ENDS THE HEADER); "
        "CURRENT IMAGE KEPT");
  // END APL may not give a picture image other points or another view.
  Image moved = *saved.image;
  moved.desim.projection = Projection::orthogonal;
  CHECK(image_problem(moved));
  Image plain;
  plain.desim = {2, Projection::orthogonal, {1, 0, 0}};
  CHECK(image_problem(plain));
}

namespace {

// BUILD typed for a test surface: one point a line, the tangents in INPTG's row order (corners
// say along the curve, 1, or the stringer, 0), then INTCU and INTST.
std::string build_commands(const TestSurface& t) {
  const int nc = t.input.nocur, ns = t.input.nostr;
  std::string s = fmt::format("BUILD\n{} {}\n", nc, ns);
  for (int k = 0; k < nc * ns; ++k) {
    const double* p = t.inppn.data() + 3 * k;
    s += fmt::format("{} {:.15f} {:.15f} {:.15f}\n", k + 1, p[0], p[1], p[2]);
  }
  s += "\n";
  auto corner = [&](int k) { return k == 1 || k == ns || k == (nc - 1) * ns + 1 || k == nc * ns; };
  for (int r = 0; r < 2 * (nc + ns); ++r) {
    const double* tg = t.inptg.data() + 4 * r;
    const bool along_curve = r < 2 * nc;
    const int k = along_curve ? (r / 2) * ns + (r % 2 ? ns : 1)
                              : ((r - 2 * nc) % 2 ? (nc - 1) * ns : 0) + (r - 2 * nc) / 2 + 1;
    s += fmt::format("{} {:.15f} {:.15f} {:.15f}", k, tg[0], tg[1], tg[2]);
    s += corner(k) ? fmt::format(" {}\n", along_curve ? 1 : 0) : "\n";
  }
  s += fmt::format("\n{} {}\n", t.input.intcu, t.input.intst);
  return s;
}

}  // namespace

TEST_CASE("igds: EXPORT IGES and STEP read by OpenCASCADE, every INTPN point found again") {
  TempDir disk;
  const auto draw = find_draw(disk.path());
  IGDS_SKIP_UNLESS(draw.has_value(),
                   "OpenCASCADE's DRAW (occt-draw or DRAWEXE) is not installed: scripts/setup "
                   "--test installs it");
  const TestSurface t = golden_surface();
  const RunResult run =
      run_commands(disk, build_commands(t) +
                             "EXPORT IGES HULL\nEXPORT STEP HULL\nEXPORT DUCT HULL\n"
                             "EXPORT IGES FACES FACES\nEXPORT STEP FACES FACES\n");
  INFO(run.out);
  CHECK(run.status == 0);
  CHECK(run.out.find("INCORRECT") == std::string::npos);
  REQUIRE(fs::exists(disk.path() / "HULL.IGS"));
  REQUIRE(fs::exists(disk.path() / "HULL.STP"));
  CHECK(run.out.find("HULL.DUCTPIC: THE SURFACE IN SPACE, ") != std::string::npos);
  for (SurfaceForm form : {SurfaceForm::one, SurfaceForm::patches}) {
    for (bool step : {false, true}) {
      CAPTURE(step);
      CAPTURE(form == SurfaceForm::one);
      const std::string name = form == SurfaceForm::one ? "HULL" : "FACES";
      const std::vector<Probe> probes = probes_of(t, form, 1);
      const Result r = run_draw(*draw, disk.path(), disk.path() / (name + (step ? ".STP" : ".IGS")),
                                step, probes);
      INFO(r.all.substr(0, 4000));
      // IGES's one surface is C0 across its patch borders, which the reader says (iges.h).
      if (!step && form == SurfaceForm::one)
        CHECK(r.transfer_checks.find("Nb Total:1  for 1 items") != std::string::npos);
      else
        CHECK(no_messages(r.transfer_checks));
      CHECK(no_messages(r.model_checks));
      CHECK(r.shape_check.find("This shape seems to be valid") != std::string::npos);
      check_topology(t, form, r);
      const double worst = worst_error(t, probes, r);
      MESSAGE(fmt::format("igds EXPORT {} {}: {} probes, largest relative error {:.2e}",
                          step ? "STEP" : "IGES", name, probes.size(), worst));
      CHECK(worst <= 1e-9);
    }
  }
}

TEST_CASE("igds: IMPORT makes a new surface, and UNDO gives the old one back") {
  TempDir disk;
  const TestSurface t = golden_surface();
  const RunResult run = run_commands(disk, build_commands(t) +
                                               "SAVE HULL\nEXPORT STEP HULL\n"
                                               "IMPORT STEP HULL 3 3\n0 0\nSAVE COARSE\n"
                                               "UNDO\nSAVE AGAIN\n");
  INFO(run.out);
  CHECK(run.out.find("NOCUR 3 NOSTR 3 INTCU 0 INTST 0\n") != std::string::npos);
  CHECK(run.out.find("UNDONE: IMPORT STEP\n") != std::string::npos);
  Disk d(disk.path());
  Workspace hull, coarse, again;
  restore_surface(d, "HULL", hull);
  restore_surface(d, "COARSE", coarse);
  restore_surface(d, "AGAIN", again);
  CHECK(coarse.nocur == 3);
  CHECK(again.inppn == hull.inppn);
  CHECK(again.intpn == hull.intpn);
}

TEST_CASE("igds: IMPORT of surfaces OpenCASCADE wrote, and igds's own sent through it") {
  TempDir disk;
  const auto draw = find_draw(disk.path());
  IGDS_SKIP_UNLESS(draw.has_value(),
                   "OpenCASCADE's DRAW (occt-draw or DRAWEXE) is not installed: scripts/setup "
                   "--test installs it");
  const TestSurface t = golden_surface();
  const RunResult out =
      run_commands(disk, build_commands(t) + "SAVE HULL\nEXPORT IGES HULL\nEXPORT STEP HULL\n");
  REQUIRE(out.status == 0);
  // DRAW reads igds's files and writes them again, and writes a quarter of a cylinder of radius
  // 10 and height 20 converted to a rational B-spline surface.
  const std::string tcl = fmt::format(
      "pload MODELING DATAEXCHANGEKERNEL\n"
      "igesread {{{0}/HULL.IGS}} a *\nexplode a F\nbrepiges a_1 {{{0}/BACK.IGS}}\n"
      "stepread {{{0}/HULL.STP}} b *\nrenamevar b_1 bb\nexplode bb F\n"
      "stepwrite a bb_1 {{{0}/BACK.STP}}\n"
      "cylinder c 0 0 0 10\ntrim tc c 0 1.5 0 20\nconvert bc tc\nmkface f bc\n"
      "brepiges f {{{0}/CYL.IGS}}\nstepwrite a f {{{0}/CYL.STP}}\nexit\n",
      disk.path().string());
  write_file(disk.path() / "back.tcl", tcl);
  RunOptions options;
  options.env = draw->env;
  options.cwd = disk.path();
  options.timeout_seconds = 600;
  const RunResult r =
      igds::test::run({draw->program, "-b", "-f", (disk.path() / "back.tcl").string()}, options);
  INFO(r.out);
  for (const char* file : {"BACK.IGS", "BACK.STP", "CYL.IGS", "CYL.STP"})
    REQUIRE(fs::exists(disk.path() / file));
  const RunResult in = run_commands(disk,
                                    "IMPORT IGES BACK\n\n2 2\nSAVE BACKI\n"
                                    "IMPORT STEP BACK\n\n2 2\nSAVE BACKS\n"
                                    "IMPORT IGES CYL 5 6\n1 1\nSAVE CYLI\n"
                                    "IMPORT STEP CYL 5 6\n1 1\nSAVE CYLS\n");
  INFO(in.out);
  CHECK(in.out.find("INCORRECT") == std::string::npos);
  CHECK(in.out.find("REFUSED") == std::string::npos);
  Disk d(disk.path());
  Workspace hull;
  restore_surface(d, "HULL", hull);
  // igds -> IGES or STEP -> OpenCASCADE -> IGES or STEP -> igds: every point, tangent and grid
  // point kept.
  for (const char* name : {"BACKI", "BACKS"}) {
    CAPTURE(name);
    Workspace back;
    restore_surface(d, name, back);
    REQUIRE(back.nocur == hull.nocur);
    REQUIRE(back.nostr == hull.nostr);
    CHECK(relative_gap(hull.inppn, back.inppn) < 1e-9);
    CHECK(relative_gap(hull.inptg, back.inptg) < 1e-9);
    CHECK(relative_gap(hull.intpn, back.intpn) < 1e-9);
  }
  // The cylinder: every input point on it, the tangents along the curves (around) tangent to
  // the circle, those along the stringers vertical.
  for (const char* name : {"CYLI", "CYLS"}) {
    CAPTURE(name);
    Workspace cyl;
    restore_surface(d, name, cyl);
    REQUIRE(cyl.nocur * cyl.nostr == 30);
    for (std::size_t k = 0; k < 30; ++k) {
      const Vec3 p = Vec3::load(cyl.inppn.data() + 3 * k);
      CHECK(std::abs(std::hypot(p.x, p.y) - 10) < 1e-9 * 20);
    }
    for (std::size_t row = 0; row < cyl.inptg.size() / 4; ++row) {
      const Vec3 tg = Vec3::load(cyl.inptg.data() + 4 * row);
      const auto k = static_cast<std::size_t>(cyl.inptg.ravel[4 * row + 3]) - 1;
      const Vec3 p = Vec3::load(cyl.inppn.data() + 3 * k);
      CHECK(norm(tg) > 0.5);
      if (row < std::size_t(2 * cyl.nocur))
        CHECK(std::abs(dot(tg, {p.x, p.y, 0})) < 1e-9 * 10);
      else
        CHECK(std::hypot(tg.x, tg.y) < 1e-9);
    }
  }
}

TEST_CASE("igds: the crease angles of the manual's figure 6, measured by OpenCASCADE") {
  TempDir disk;
  const auto draw = find_draw(disk.path());
  IGDS_SKIP_UNLESS(draw.has_value(),
                   "OpenCASCADE's DRAW (occt-draw or DRAWEXE) is not installed: scripts/setup "
                   "--test installs it");
  // The example's BUILD, then the patches as faces (docs/exchange.md, "Crease angles").
  const std::string example =
      read_file(source_dir() / "scripts" / "examples" / "fig6-multipatch.igds");
  const std::size_t display = example.find("\nDISPLAY INPUT");
  REQUIRE(display != std::string::npos);
  const RunResult run =
      run_commands(disk, example.substr(0, display + 1) + "EXPORT STEP WAVE FACES\n");
  INFO(run.out);
  REQUIRE(fs::exists(disk.path() / "WAVE.STP"));
  // Across every inner border of the 3 x 4 patches, 33 places: the angle between the normals of
  // the two faces there (Su x Sv of each; the faces share their parameters, docs/exchange.md).
  constexpr int rows = 3, columns = 4, places = 32;
  // DRAW's commands are not used inside Tcl procedures (svalue fails there): the normals' cross
  // product and the angle are written out at each place.
  std::string tcl = fmt::format(
      "pload MODELING DATAEXCHANGEKERNEL\n"
      "stepread {{{}}} r *\nrenamevar r_1 shape\nexplode shape F\n"
      "for {{set k 1}} {{$k <= {}}} {{incr k}} {{ mksurface g$k shape_$k }}\n",
      (disk.path() / "WAVE.STP").string(), rows * columns);
  // Borders u = j + 1 between patches (i, j) and (i, j + 1), v = i + 1 between (i, j) and
  // (i + 1, j); patch (i, j) is face i * columns + j + 1.
  tcl += fmt::format(
      "for {{set i 0}} {{$i < {0}}} {{incr i}} {{\n"
      "  for {{set j 0}} {{$j < {1}}} {{incr j}} {{\n"
      "    set here [expr {{$i * {1} + $j + 1}}]\n"
      "    foreach across {{0 1}} {{\n"
      "      if {{$across == 0 && $j + 1 == {1}}} continue\n"
      "      if {{$across == 1 && $i + 1 == {0}}} continue\n"
      "      set there [expr {{$across == 0 ? $here + 1 : $here + {1}}}]\n"
      "      for {{set s 0}} {{$s <= {2}}} {{incr s}} {{\n"
      "        set t [expr {{double($s) / {2}}}]\n"
      "        if {{$across == 0}} {{ set u [expr {{$j + 1}}]; set v [expr {{$i + $t}}] }} else "
      "{{\n"
      "          set u [expr {{$j + $t}}]; set v [expr {{$i + 1}}] }}\n"
      "        set n {{}}\n"
      "        foreach g [list g$here g$there] {{\n"
      "          svalue $g $u $v x y z ux uy uz vx vy vz\n"
      "          set a [dval ux]; set b [dval uy]; set c [dval uz]\n"
      "          set d [dval vx]; set e [dval vy]; set f [dval vz]\n"
      "          lappend n [expr {{$b*$f - $c*$e}}] [expr {{$c*$d - $a*$f}}] [expr {{$a*$e - "
      "$b*$d}}]\n"
      "        }}\n"
      "        lassign $n a b c d e f\n"
      "        set x [expr {{$b*$f - $c*$e}}]; set y [expr {{$c*$d - $a*$f}}]\n"
      "        set z [expr {{$a*$e - $b*$d}}]\n"
      "        set degrees [expr {{atan2(sqrt($x*$x + $y*$y + $z*$z), $a*$d + $b*$e + $c*$f) * "
      "180 / acos(-1)}}]\n"
      "        puts \"CREASE [expr {{$s == 0 || $s == {2}}}] $degrees\"\n"
      "      }}\n"
      "    }}\n"
      "  }}\n"
      "}}\n"
      "exit\n",
      rows, columns, places);
  write_file(disk.path() / "crease.tcl", tcl);
  INFO(tcl);
  RunOptions options;
  options.env = draw->env;
  options.cwd = disk.path();
  options.timeout_seconds = 600;
  const RunResult r =
      igds::test::run({draw->program, "-b", "-f", (disk.path() / "crease.tcl").string()}, options);
  INFO(r.out);
  INFO(r.err);
  std::istringstream lines(r.out);
  double worst = 0, worst_at_node = 0;
  std::size_t measured = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("CREASE ", 0) != 0) continue;
    int node = 0;
    double degrees = NAN;
    std::istringstream(line.substr(7)) >> node >> degrees;
    REQUIRE(std::isfinite(degrees));
    (node ? worst_at_node : worst) = std::max(node ? worst_at_node : worst, degrees);
    ++measured;
  }
  // 3 inner borders across 3 rows and 2 across 4 columns, 33 places each.
  CHECK(measured == (rows * (columns - 1) + (rows - 1) * columns) * (places + 1));
  MESSAGE(fmt::format("figure 6: largest crease {:.3f} degrees between the nodes, {:.1e} at them",
                      worst, worst_at_node));
  // The tangent planes of neighbouring patches agree at the grid's nodes (docs/kernels.md).
  CHECK(worst_at_node < 1e-9);
}

TEST_CASE("igds: DISPLAY PICTURE on the 4013, kept by the session for the next igds") {
  TempDir disk;
  fs::copy_file(hand_written(), disk.path() / "HAND.DUCTPIC");
  write_file(disk.path() / "first.igds", "DISPLAY PICTURE HAND ORTHOGONAL XY\nSTORE FIRST\n");
  RunOptions options;
  options.timeout_seconds = 60;
  const RunResult first = run_igds(
      {"--term", "tek", "--disk", disk.path().string(), (disk.path() / "first.igds").string()},
      options);
  CHECK(first.status == 0);
  // The whole session is a 4013 stream: the picture's dashed (ESC c) and chain-dashed (ESC b)
  // vectors, its texts, and the description.
  CHECK(first.out.find("\x1b"
                       "c") != std::string::npos);
  CHECK(first.out.find("\x1b"
                       "b") != std::string::npos);
  const TekDrawing decoded = decode_tek(first.out);
  CHECK(decoded.errors.empty());
  std::string texts;
  for (const TekPage& page : decoded.pages)
    for (const TekText& text : page.texts) texts += text.text + "\n";
  CHECK(texts.find("ORIGIN\n") != std::string::npos);
  CHECK(texts.find("COLOURS 1 2 3 4 5\n") != std::string::npos);
  // The next igds has the picture as IMAGE and TEMP1; EXPORT DUCT ... IMAGE writes it as
  // projected.
  fs::remove(disk.path() / "HAND.DUCTPIC");
  const RunResult next = run_commands(disk, "DISPLAY FIRST\nEXPORT DUCT AGAIN IMAGE\n");
  INFO(next.out);
  // The --term none line says what the caption says: the name, the colours.
  CHECK(next.out.find("IMAGE: PICTURE HAND, ORTHOGONAL XY, COLOURS 1 2 3 4 5\n") !=
        std::string::npos);
  CHECK(next.out.find("AGAIN.DUCTPIC: THE IMAGE AS PROJECTED, ") != std::string::npos);
  const DuctPicture again = read_duct(read_file(disk.path() / "AGAIN.DUCTPIC"));
  CHECK(again.counters[6] == 2);
  CHECK(again.texts.size() == 3);
}

}  // namespace igds::test::exchange
