// LIST, ZOOM, the point numbers of DISPLAY INPUT and the REPLACED line of SAVE, WRITE, STORE
// FILE and EXPORT, driven through a scripted Context.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>

#include <fmt/format.h>

#include "commands/command.h"
#include "commands/pick.h"
#include "commands/picture.h"
#include "devices/layout.h"
#include "devices/render.h"
#include "tests/devices/support.h"
#include "tests/support/fake_context.h"
#include "tests/support/process.h"
#include "workspace/error.h"

namespace igds {
extern const Command build_command;
extern const Command change_command;
extern const Command display_command;
extern const Command store_command;
extern const Command save_command;
extern const Command write_command;
extern const Command export_command;
extern const Command list_command;
extern const Command zoom_command;
extern const Command pick_command;
}  // namespace igds

namespace igds::test {

namespace {

namespace fs = std::filesystem;

// A 3 x 3 saddle 20 x 20, with tangents at point 1 (as in commands_test.cpp).
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
  ctx.said.clear();
  ctx.prompts.clear();
}

// The lines LIST writes for `option`.
std::vector<std::string> listing(FakeContext& ctx, std::string_view option) {
  ctx.said.clear();
  ctx.run(list_command, option);
  return ctx.said;
}

bool has_line(const std::vector<std::string>& lines, std::string_view line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

}  // namespace

TEST_CASE("LIST POINTS: every input point with its number, curve and place, curve by curve") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, list_command, "POINTS") == "INPUT NOT FOUND");
  build_saddle(ctx);
  const auto lines = listing(ctx, "P");
  CHECK(lines ==
        std::vector<std::string>{"INPUT POINTS: 3 CURVES OF 3 POINTS",
                                 "    K CURVE PLACE             X             Y             Z",
                                 "    1     1     1             0             0             0",
                                 "    2     1     2             0            10             2",
                                 "    3     1     3             0            20             0", "",
                                 "    4     2     1            10             0             2",
                                 "    5     2     2            10            10             0",
                                 "    6     2     3            10            20             2", "",
                                 "    7     3     1            20             0             0",
                                 "    8     3     2            20            10             2",
                                 "    9     3     3            20            20             0"});
  // Nothing changed, nothing asked.
  CHECK(ctx.prompts.empty());
  CHECK(report_of(ctx, list_command, "POINTS", {"MORE"}) == "INCORRECT COMMAND OR PARAMETERS");
}

TEST_CASE("LIST TANGENTS: the border tangents with their points and directions") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  const auto lines = listing(ctx, "T");
  REQUIRE(lines.size() == 2 + 12 + 1);
  CHECK(lines[0] == "BORDER TANGENTS: 6 ALONG THE CURVES, 6 ALONG THE STRINGERS");
  // Point 1 along its curve: 0 1 0 as typed; along its stringer: 1 0 0.
  CHECK(lines[2] == "    1     1     1  CURVE                 0             1             0");
  CHECK(lines[3].starts_with("    3     1     3  CURVE    "));
  CHECK(lines[8].empty());  // the stringers' tangents after a blank line
  CHECK(lines[9] == "    1     1     1  STRINGER              1             0             0");
  CHECK(lines[10].starts_with("    7     3     1  STRINGER "));
  CHECK(lines.back().starts_with("    9     3     3  STRINGER "));
}

TEST_CASE("LIST SURFACE: sizes, tangent mode and twist mode") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, list_command, "SURFACE") == "INPUT NOT FOUND");
  build_saddle(ctx);
  CHECK(listing(ctx, "SU") == std::vector<std::string>{"NOCUR 3  NOSTR 3  INTCU 2  INTST 2",
                                                       "INPUT POINTS 9, BORDER TANGENTS 12",
                                                       "PATCHES 2 BY 2",
                                                       "INTERPOLATED GRID 7 BY 7 POINTS",
                                                       "TANGENTS: TYPED", "TWISTS: ZERO TWISTS"});
  // CHANGE TWISTS MARKS, then AUTO at CHANGE TANGENTS: both said.
  ctx.run(change_command, "TW", {"M"});
  ctx.type({"AUTO", "", "N"});
  ctx.run(change_command, "T");
  const auto modes = listing(ctx, "SU");
  REQUIRE(modes.size() == 6);
  CHECK(modes[4] == "TANGENTS: AUTO (MARKS'S RULE)");
  CHECK(modes[5] == "TWISTS: MARKS TWISTS (BIRKHOFF AND DE BOOR)");
}

TEST_CASE("LIST IMAGES: the current image, FIRST and SECOND") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(listing(ctx, "I") == std::vector<std::string>{"CURRENT IMAGE  NONE", "STORE FIRST    NONE",
                                                      "STORE SECOND   NONE"});
  build_saddle(ctx);
  ctx.run(display_command, "SURFACE", {"ORTHOGONAL", "XY"});
  ctx.run(store_command, "FIRST");
  ctx.run(display_command, "INPUT", {"ASSONOMETRIC", "110", "130", "120"});
  ctx.run(store_command, "SECOND");
  ctx.run(display_command, "FIRST");
  CHECK(listing(ctx, "IMAGES") ==
        std::vector<std::string>{"CURRENT IMAGE  SURFACE, ORTHOGONAL XY",
                                 "               7 BY 7 POINTS", "STORE FIRST    THE CURRENT IMAGE",
                                 "STORE SECOND   INPUT, ASSONOMETRIC 110 130 120",
                                 "               3 BY 3 POINTS, 2 ARROWS"});
  ctx.run(zoom_command, "", {"0", "0", "10", "5"});
  CHECK(has_line(listing(ctx, "IMAGES"), "               ZOOMED TO 0 0 10 5"));
  // FIRST keeps the image as it was: the zoom made a new current image.
  CHECK(has_line(listing(ctx, "IMAGES"), "STORE FIRST    SURFACE, ORTHOGONAL XY"));
}

TEST_CASE("LIST FILES: every type of file on the disk, by type, with sizes and dates") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.run(display_command, "INPUT", {"ORTHOGONAL", "XY"});
  ctx.run(save_command, "", {"HULL"});
  ctx.run(write_command, "", {"HULL"});
  ctx.run(store_command, "FILE", {"TOP"});
  for (std::string_view type : {"SVG", "TEK", "HPGL"}) ctx.run(export_command, type, {"HULL"});
  // The session's files, a plot and the history, as igds leaves them (contents do not matter).
  for (std::string_view file :
       {"BINSAVE.IGDSCONT", "B0000001.IGDSVARS", "B0000002.IGDSVIMG", "BINSAVE.IGDSLOCK",
        "BINSAVE.IGDSBAD", "HISTORY.IGDSHIST", "PLOT0001.HPGL", "NOTES.TXT"})
    write_file(dir.path() / file, "12345");
  // Not files of the disk: a folder, a link out of it, names that are not NAME.TYPE.
  fs::create_directory(dir.path() / "SUB.IGDSDATA");
  TempDir outside;
  write_file(outside.path() / "X.IGDSDATA", "x");
  fs::create_symlink(outside.path() / "X.IGDSDATA", dir.path() / "LINK.IGDSDATA");
  write_file(dir.path() / "HULL.IGDSDATA.IGDSTEMP", "x");
  write_file(dir.path() / "lower.igdsdata", "x");
  write_file(dir.path() / "NOTYPE", "x");
  // A known date.
  const auto when = std::chrono::sys_seconds{std::chrono::seconds{1700000000}};
  fs::last_write_time(dir.path() / "NOTES.TXT", std::chrono::file_clock::from_sys(when));
  const std::time_t t = 1700000000;
  std::tm tm{};
  localtime_r(&t, &tm);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M", &tm);

  const auto lines = listing(ctx, "F");
  REQUIRE(!lines.empty());
  CHECK(lines[0] == fmt::format("DISK {}: 14 FILES", fs::absolute(dir.path()).string()));
  std::vector<std::string> headings;
  for (const auto& l : lines)
    if (!l.empty() && l[0] != ' ' && &l != &lines[0]) headings.push_back(l);
  CHECK(headings ==
        std::vector<std::string>{
            "HPGL: EXPORT HPGL", "IGDSBAD: DAMAGED SESSIONS, KEPT ASIDE",
            "IGDSCHAR: CARD IMAGES (WRITE)", "IGDSCONT: THE SESSION",
            "IGDSDATA: SURFACES (SAVE, RESTORE)", "IGDSHIST: THE HISTORY OF TYPED LINES",
            "IGDSIMAG: IMAGES (STORE FILE, DISPLAY FILE)", "IGDSLOCK: THE LOCK OF THE SESSION",
            "IGDSVARS: PARTS OF THE SESSION", "IGDSVIMG: IMAGES OF THE SESSION", "SVG: EXPORT SVG",
            "TEK: EXPORT TEK", "TXT"});
  CHECK(has_line(lines, fmt::format("  NOTES               5 BYTES  {}", date)));
  const auto size = fs::file_size(dir.path() / "HULL.IGDSDATA");
  CHECK(std::any_of(lines.begin(), lines.end(), [&](const std::string& l) {
    return l.starts_with(fmt::format("  HULL     {:>12} BYTES  ", size));
  }));
  for (const auto& l : lines) {
    CHECK(l.find("LINK") == std::string::npos);
    CHECK(l.find("SUB") == std::string::npos);
    CHECK(l.find("lower") == std::string::npos);
    CHECK(l.find("NOTYPE") == std::string::npos);
  }
  // The disk's own listing: the same files, by type then name.
  const auto files = ctx.disk().files();
  REQUIRE(files.size() == 14);
  CHECK(files.front().type == "HPGL");
  CHECK(files.front().name == "HULL");
  CHECK(files[1].name == "PLOT0001");
}

TEST_CASE("SAVE, WRITE, STORE FILE and EXPORT say when they replace a file") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.run(display_command, "INPUT", {"ORTHOGONAL", "XY"});
  ctx.said.clear();
  ctx.run(save_command, "", {"hull"});
  ctx.run(write_command, "", {"HULL"});
  ctx.run(store_command, "FILE", {"HULL"});
  ctx.run(export_command, "SVG", {"HULL"});
  const auto svg_bytes = fs::file_size(dir.path() / "HULL.SVG");
  CHECK(ctx.said == std::vector<std::string>{fmt::format("HULL.SVG: {} BYTES", svg_bytes)});
  const auto data = read_file(dir.path() / "HULL.IGDSDATA");
  ctx.said.clear();
  ctx.run(save_command, "", {"HULL"});
  ctx.run(write_command, "", {"hull"});
  ctx.run(store_command, "FILE", {"HULL"});
  ctx.run(export_command, "SVG", {"HULL"});
  CHECK(ctx.said == std::vector<std::string>{"HULL.IGDSDATA REPLACED", "HULL.IGDSCHAR REPLACED",
                                             "HULL.IGDSIMAG REPLACED",
                                             fmt::format("HULL.SVG: {} BYTES", svg_bytes),
                                             "HULL.SVG REPLACED"});
  // The same surface, the same bytes: nothing else changed.
  CHECK(read_file(dir.path() / "HULL.IGDSDATA") == data);
  // Another type of the same name is another file.
  ctx.said.clear();
  ctx.run(export_command, "TEK", {"HULL"});
  CHECK(ctx.said.size() == 1);
}

TEST_CASE("ZOOM: a window by its corners, by a factor and a centre, by picks; ZOOM alone") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, zoom_command, "") == "IMAGE NOT FOUND");
  build_saddle(ctx);
  ctx.run(display_command, "INPUT", {"ORTHOGONAL", "XY"});
  const Image whole = ctx.ws.image.shared() ? *ctx.ws.image : Image{};
  REQUIRE(!whole.window);

  SUBCASE("two corners, in either order") {
    ctx.run(zoom_command, "", {"10", "5", "0", "0"});
    REQUIRE(ctx.shown.size() == 2);
    CHECK(ctx.shown.back().window == std::array<double, 4>{0, 0, 10, 5});
    CHECK(ctx.shown.back().points == whole.points);
    CHECK(ctx.erases == 1);  // on a clean screen
    CHECK(image_line(ctx.shown.back()) == "IMAGE: INPUT, ORTHOGONAL XY, ZOOMED TO 0 0 10 5");
    CHECK(image_caption(ctx.shown.back(), caption_width).back() == "ZOOMED");
    ctx.run(zoom_command, "");
    CHECK(!ctx.shown.back().window);
    CHECK(ctx.shown.back() == whole);
  }
  SUBCASE("a factor, and a centre") {
    ctx.run(zoom_command, "", {"4", "20", "10"});
    CHECK(ctx.shown.back().window == std::array<double, 4>{17.5, 7.5, 22.5, 12.5});
    // A factor alone keeps the centre of what is shown.
    ctx.run(zoom_command, "", {"2"});
    CHECK(ctx.shown.back().window == std::array<double, 4>{15, 5, 25, 15});
  }
  SUBCASE("two cross-hair picks, in screen addresses") {
    // Where the screen (the full square: --term none and the Tek window of xterm) shows the
    // image's points 0 0 and 10 10.
    const TekLayout l = full_layout();
    const double m = tek_screen::image_margin;
    const Placement at =
        fit(picture_of(whole).drawing,
            {l.image.x0 + m, l.image.y0 + m, l.image.x1 - m, l.image.y1 - m}, tek_screen::mark);
    const Point2 a = at.apply({0, 0}), b = at.apply({10, 10});
    ctx.type({"NOT A PICK", fmt::format("{} {}", std::lround(a.x), std::lround(a.y)),
              fmt::format("{} {}", std::lround(b.x), std::lround(b.y))});
    ctx.run(zoom_command, "", {"PICK"});
    CHECK(ctx.prompts ==
          std::vector<std::string>{"FIRST CORNER?", "FIRST CORNER?", "SECOND CORNER?"});
    CHECK(ctx.reports == 1);
    const auto w = ctx.shown.back().window;
    REQUIRE(w);
    const double tolerance = 1 / at.scale;  // one screen point
    CHECK(std::abs((*w)[0] - 0) <= tolerance);
    CHECK(std::abs((*w)[1] - 0) <= tolerance);
    CHECK(std::abs((*w)[2] - 10) <= tolerance);
    CHECK(std::abs((*w)[3] - 10) <= tolerance);
  }
  SUBCASE("what is refused") {
    CHECK(report_of(ctx, zoom_command, "", {"1", "2"}) ==
          "INCORRECT PARAMETER: GIVE X0 Y0 X1 Y1, A FACTOR [X Y], OR PICK");
    CHECK(report_of(ctx, zoom_command, "", {"0", "0", "0", "5"}) ==
          "INCORRECT PARAMETER: THE TWO CORNERS MUST DIFFER IN X AND IN Y");
    CHECK(report_of(ctx, zoom_command, "", {"0"}) ==
          "INCORRECT PARAMETER: THE FACTOR MUST BE GREATER THAN 0");
    CHECK(report_of(ctx, zoom_command, "", {"A", "B", "C", "D"}) ==
          "INCORRECT PARAMETER: A IS NOT A NUMBER");
    CHECK(ctx.shown.size() == 1);
    CHECK(ctx.ws.image->window == std::nullopt);
  }
}

namespace {

// The address of image point p of the current image in layout `l`: by default the page (the
// full square of EXPORT TEK, of --term none and xterm, and of every command file's X Y).
std::string address_of(FakeContext& ctx, Point2 p, const TekLayout& l = full_layout()) {
  const double m = tek_screen::image_margin;
  const Placement at =
      fit(picture_of(*ctx.ws.image).drawing,
          {l.image.x0 + m, l.image.y0 + m, l.image.x1 - m, l.image.y1 - m}, tek_screen::mark);
  const Point2 a = at.apply(p);
  return fmt::format("{} {}", std::lround(a.x), std::lround(a.y));
}

}  // namespace

TEST_CASE(
    "PICK names the input point nearest the cross-hair, on an input, surface or combs image") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, pick_command, "") == "INPUT NOT FOUND");
  build_saddle(ctx);
  CHECK(report_of(ctx, pick_command, "") == "IMAGE NOT FOUND");
  CHECK(report_of(ctx, pick_command, "", {"5"}) == "INCORRECT COMMAND OR PARAMETERS");
  for (const char* what : {"INPUT", "SURFACE", "COMBS"}) {
    CAPTURE(what);
    ctx.run(display_command, what, {"ORTHOGONAL", "XY"});
    ctx.said.clear();
    ctx.type({"NOT A PICK", address_of(ctx, {10.4, 19.2})});
    ctx.run(pick_command, "");
    CHECK(ctx.prompts.back() == "POINT?");
    CHECK(ctx.said ==
          std::vector<std::string>{"INCORRECT ENTRY: A CROSS-HAIR PICK OR X Y (0..1023 0..779)",
                                   "POINT 6 AT 10 20 2"});
  }
  // Zoomed: the pick is read through the window.
  ctx.run(zoom_command, "", {"15", "0", "25", "10"});
  ctx.said.clear();
  ctx.type({address_of(ctx, {19, 9})});
  ctx.run(pick_command, "");
  CHECK(ctx.said == std::vector<std::string>{"POINT 8 AT 20 10 2"});
  // An image of another shape than the surface's (after CHANGE GRID) shows none of its points.
  ctx.type({"3 3"});
  ctx.run(change_command, "GRID");
  CHECK(report_of(ctx, pick_command, "") ==
        "THE CURRENT IMAGE SHOWS NO INPUT POINTS OF THE SURFACE (DISPLAY INPUT OR SURFACE FIRST)");
}

TEST_CASE(
    "a pick on the page is read in the full square; on tek mode's screen, above the dialogue") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.run(display_command, "INPUT", {"ORTHOGONAL", "XY"});
  // Points 1 (0 0), 5 (10 10) and 6 (10 20) on the page and on tek mode's screen.
  const std::vector<std::string> on_page{address_of(ctx, {0, 0}), address_of(ctx, {10, 10}),
                                         address_of(ctx, {10, 20})};
  const std::vector<std::string> on_screen{address_of(ctx, {0, 0}, dialogue_layout()),
                                           address_of(ctx, {10, 10}, dialogue_layout()),
                                           address_of(ctx, {10, 20}, dialogue_layout())};
  // PICK at point 6, then ZOOM PICK from point 1 to point 5: what was named, and the window.
  auto picked = [&](TermMode term, bool by_person, const std::vector<std::string>& address) {
    ctx.opts.term = term;
    ctx.picks_on_screen = by_person;
    ctx.said.clear();
    ctx.type({address[2]});
    ctx.run(pick_command, "");
    ctx.type({address[0], address[1]});
    ctx.run(zoom_command, "", {"PICK"});
    const auto window = ctx.ws.image->window;
    ctx.run(zoom_command, "");  // the whole image again, for the next picks
    REQUIRE(ctx.said.size() == 1);
    REQUIRE(window);
    return std::pair{ctx.said[0], *window};
  };
  const double point = 20.0 / 700;  // a screen point in image units, at most
  auto near = [&](std::array<double, 4> w, std::array<double, 4> want) {
    for (std::size_t k = 0; k < 4; ++k)
      if (std::abs(w[k] - want[k]) > 1.5 * point) return false;
    return true;
  };
  // A command file's addresses name the same point and window under every terminal mode.
  const auto none = picked(TermMode::none, false, on_page);
  CHECK(none.first == "POINT 6 AT 10 20 2");
  CHECK(near(none.second, {0, 0, 10, 10}));
  for (const TermMode term : {TermMode::tek, TermMode::xterm}) {
    CAPTURE(int(term));
    CHECK(picked(term, false, on_page) == none);
  }
  // A person's are on the screen they see: above the dialogue in tek mode, the full square in
  // the Tek window of xterm.
  const auto tek_screen = picked(TermMode::tek, true, on_screen);
  CHECK(tek_screen.first == "POINT 6 AT 10 20 2");
  CHECK(near(tek_screen.second, {0, 0, 10, 10}));
  CHECK(!near(picked(TermMode::tek, true, on_page).second, {0, 0, 10, 10}));
  CHECK(picked(TermMode::xterm, true, on_page) == none);
}

TEST_CASE(
    "CHANGE POINTS takes a picked point: a new place typed, or picked in an orthogonal view") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.type({"PICK", "", "N", "N"});
  ctx.run(change_command, "POINTS");
  CHECK(ctx.reports == 1);  // no image to pick on: the entry refused, the next one awaited
  ctx.run(display_command, "INPUT", {"ORTHOGONAL", "XZ"});
  const Image xz = *ctx.ws.image;
  // Point 4 (10 0 2) picked and moved to x 5, z 3 in the XZ view: y kept. Then point 7 (20 0
  // 0) picked and given a new place typed.
  ctx.said.clear();
  ctx.type({"PICK", address_of(ctx, {10, 2}), "PICK", address_of(ctx, {5, 3}), "PICK",
            address_of(ctx, {19.5, 0.3}), "1 2", "1 2 3", "", "N", "N"});
  ctx.run(change_command, "POINTS");
  REQUIRE(ctx.said.size() == 5);
  CHECK(ctx.said[0] == "POINT 4 AT 10 0 2");
  CHECK(ctx.said[1].starts_with("POINT 4 AT "));
  CHECK(ctx.said[2] == "POINT 7 AT 20 0 0");
  CHECK(ctx.said[3] == "INCORRECT ENTRY: GIVE X Y Z, OR PICK IN AN ORTHOGONAL VIEW");
  CHECK(ctx.said[4] == "POINT 7 AT 1 2 3");
  CHECK(ctx.reports == 2);  // "1 2": three coordinates wanted
  const double* p4 = ctx.ws.inppn.data() + 3 * 3;
  CHECK(std::abs(p4[0] - 5) < 0.1);
  CHECK(p4[1] == 0);
  CHECK(std::abs(p4[2] - 3) < 0.1);
  const double* p7 = ctx.ws.inppn.data() + 3 * 6;
  CHECK(std::array<double, 3>{p7[0], p7[1], p7[2]} == std::array<double, 3>{1, 2, 3});
  CHECK(ctx.ws.image->desim == xz.desim);

  // In another projection the new place is typed, not picked.
  ctx.run(display_command, "SURFACE", {"ASSONOMETRIC", "110", "130", "120"});
  ctx.said.clear();
  ctx.type({"PICK", address_of(ctx, {0, 0}), "PICK", "", "", "N", "N"});
  const std::size_t reports = ctx.reports;
  const Array before = ctx.ws.inppn;
  ctx.run(change_command, "POINTS");
  CHECK(ctx.reports == reports + 1);
  REQUIRE(ctx.said.size() == 2);
  CHECK(ctx.said[0].starts_with("POINT "));
  CHECK(ctx.said[1] == "INCORRECT ENTRY: A PLACE IS PICKED IN AN ORTHOGONAL VIEW ONLY: TYPE X Y Z");
  CHECK(ctx.ws.inppn == before);  // an empty line at NEW X Y Z? leaves the point
}

TEST_CASE("placed_in_view: the plane's two coordinates set, the third kept; other views none") {
  const std::array<double, 3> p{1, 2, 3};
  auto in = [](double plane) { return Description{0, Projection::orthogonal, {plane, 0, 0}}; };
  CHECK(placed_in_view(in(1), p, {7, 8}) == std::array<double, 3>{7, 8, 3});
  CHECK(placed_in_view(in(2), p, {7, 8}) == std::array<double, 3>{7, 2, 8});
  CHECK(placed_in_view(in(3), p, {7, 8}) == std::array<double, 3>{1, 7, 8});
  CHECK(!placed_in_view(in(4), p, {7, 8}));
  CHECK(!placed_in_view({0, Projection::conic, {100, 0, 0}}, p, {7, 8}));
}

TEST_CASE("a zoomed picture: the window scaled to the square, the rest cut away") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.run(display_command, "SURFACE", {"ORTHOGONAL", "XY"});
  ctx.run(zoom_command, "", {"5", "5", "15", "10"});
  const Picture pic = picture_of(ctx.ws.image);
  // Everything inside the window, and the window is what fits the square.
  const Box b = bounds(pic.drawing);
  CHECK(b.x0 == 5);
  CHECK(b.y0 == 5);
  CHECK(b.x1 == 15);
  CHECK(b.y1 == 10);
  // Curve 2 (x = 10) is cut at the window's edges: from y 5 to y 10.
  bool curve_2 = false;
  for (const auto& item : pic.drawing.items()) {
    if (item.id != Identity{Role::curve, 4}) continue;  // INTCU 2: input curve 2 is grid curve 4
    const auto p = pic.drawing.points(item);
    REQUIRE(p.size() >= 2);
    CHECK(p[0].y == doctest::Approx(5));
    CHECK(p[p.size() - 1].y == doctest::Approx(10));
    curve_2 = true;
  }
  CHECK(curve_2);
  CHECK(pic.caption.back() == "ZOOMED");
}

TEST_CASE("DISPLAY INPUT writes each point's number beside it, clear of the lines") {
  TempDir dir;
  FakeContext ctx(dir.path());
  build_saddle(ctx);
  ctx.run(display_command, "INPUT", {"ORTHOGONAL", "XY"});
  const Picture pic = picture_of(ctx.ws.image);
  std::vector<int> numbers;
  for (const auto& item : pic.drawing.items()) {
    if (item.kind != Drawing2::Kind::text) continue;
    CHECK(item.id.role == Role::label);
    CHECK(pic.drawing.text(item) == std::to_string(item.id.index));
    numbers.push_back(item.id.index);
    // Beside its own point (k in point-number order: curve by curve).
    const int k = item.id.index;
    const Point2 p{10.0 * ((k - 1) / 3), 10.0 * ((k - 1) % 3)};
    const Point2 at = pic.drawing.points(item)[0];
    CHECK(std::abs(at.x - p.x) < 2);
    CHECK(std::abs(at.y - p.y) < 2);
  }
  CHECK(numbers == std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9});
  // Drawn on the 4013 screen, no number's cell meets a line or another number.
  const TekLayout l = dialogue_layout();
  const double m = tek_screen::image_margin;
  const Box box{l.image.x0 + m, l.image.y0 + m, l.image.x1 - m, l.image.y1 - m};
  const Placed placed =
      place(pic.drawing, fit(pic.drawing, box, tek_screen::mark), {0, 0, 1023, 779}, {});
  REQUIRE(placed.texts.size() == 9);
  std::vector<Box> cells;
  for (const auto& t : placed.texts) {
    const Box cell{double(t.at.x), t.at.y - 4.0, t.at.x + 14.0 * t.text.size(), t.at.y + 16.0};
    CHECK(cell.x0 >= box.x0);
    CHECK(cell.x1 <= box.x1);
    for (const Box& c : cells)
      CHECK((c.x1 < cell.x0 || cell.x1 < c.x0 || c.y1 < cell.y0 || cell.y1 < c.y0));
    cells.push_back(cell);
    for (std::size_t k = 0; k < placed.paths.size(); ++k)
      for (std::size_t i = 0; i + 1 < placed.paths[k].size(); ++i) {
        const auto path = placed.paths[k];
        Point2 a{double(path[i].x), double(path[i].y)};
        Point2 e{double(path[i + 1].x), double(path[i + 1].y)};
        CHECK_MESSAGE(!clip_segment(a, e, cell), "number " << t.text << " over a line");
      }
  }
}

TEST_CASE("the README's dome in a conic view: every point has its number, the lowest too") {
  TempDir dir;
  FakeContext ctx(dir.path());
  ctx.type({"3 3", "1 0 0 0  10 0 2  20 0 0", "4 0 10 2  10 10 4  20 10 2",
            "7 0 20 0  10 20 2  20 20 0", "", "4 1 0 0.4", "6 1 0 \u00AF0.4", "2 0 1 0.4",
            "8 0 1 \u00AF0.4", "", "3 3"});
  ctx.run(build_command, "");
  REQUIRE(ctx.ws.has_surface());
  ctx.run(display_command, "INPUT", {"CONIC", "60", "\u00AF40", "30"});
  const Picture pic = picture_of(ctx.ws.image);
  std::vector<int> numbers;
  for (const auto& item : pic.drawing.items())
    if (item.kind == Drawing2::Kind::text) numbers.push_back(item.id.index);
  std::sort(numbers.begin(), numbers.end());
  // Point 3, the V of two border lines at the bottom of the picture, gets its number above it.
  CHECK(numbers == std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9});
}

TEST_CASE("a grid too dense for its numbers gets none; zoomed into, its points have them") {
  auto numbers = [](const Image& im) {
    const Picture pic = picture_of(im);
    return std::count_if(pic.drawing.items().begin(), pic.drawing.items().end(),
                         [](const auto& item) { return item.kind == Drawing2::Kind::text; });
  };
  Image dense = devices::input_image(70, 70);
  REQUIRE(70 * 70 > max_numbered_points);
  CHECK(numbers(dense) == 0);
  // A window around a few of its points.
  const double* p = dense.points.data();
  const double x = p[2 * (35 * 70 + 35)], y = p[2 * (35 * 70 + 35) + 1];
  const double dx = std::abs(p[2 * (36 * 70 + 35)] - x) * 2.5 + 1e-9;
  const double dy = std::abs(p[2 * (35 * 70 + 36) + 1] - y) * 2.5 + 1e-9;
  dense.window = std::array<double, 4>{x - dx, y - dy, x + dx, y + dy};
  CHECK(numbers(dense) > 0);
}

}  // namespace igds::test
