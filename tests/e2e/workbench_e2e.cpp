// LIST, ZOOM, the point numbers, the REPLACED lines and END APL's indexing on the real igds:
// transcripts of command files, and ZOOM decoded from the 4013 streams igds writes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "tests/e2e/e2e_support.h"
#include "tests/support/process.h"
#include "tests/support/tek_decoder.h"
#include "tests/support/tek_terminal.h"

namespace igds::test {

namespace {

namespace fs = std::filesystem;

// The 3 x 3 saddle of e2e_support.h (x and y 0 to 20), seen from above: image x y = x y.
const std::string seen_from_above = std::string(saddle_build) + "DISPLAY INPUT ORTHOGONAL XY\n";

bool has(const std::string& out, const std::string& part) {
  return out.find(part) != std::string::npos;
}

// Runs igds --term MODE on `commands` as a command file.
RunResult run_in(const TempDir& disk, const std::string& mode, const std::string& commands) {
  write_file(disk.path() / "commands.igds", commands);
  return run_igds(
      {"--term", mode, "--disk", disk.path().string(), (disk.path() / "commands.igds").string()},
      with_input(""));
}

}  // namespace

TEST_CASE("LIST, ZOOM and END APL's indexing: the transcript") {
  TempDir disk;
  const RunResult r = run_commands(disk, seen_from_above + R"(LIST POINTS
L T
LIST SURFACE
ZOOM 0 0 10 10
LIST IMAGES
Z 4 20 20
ZOOM
ZOOM 1 2
END APL
INPPN[3;]
INTPN[1;2;]
⍴INPPN
⍴INTPN[;1;]
)OFF
)");
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK(has(r.out, R"(READY
LIST POINTS
INPUT POINTS: 3 CURVES OF 3 POINTS
    K CURVE PLACE             X             Y             Z
    1     1     1             0             0             0
    2     1     2             0            10             2
    3     1     3             0            20             0

    4     2     1            10             0             2
)"));
  CHECK(has(r.out, "    9     3     3            20            20             0\nREADY\n"));
  CHECK(has(r.out, R"(L T
BORDER TANGENTS: 6 ALONG THE CURVES, 6 ALONG THE STRINGERS
    K CURVE PLACE  ALONG                 X             Y             Z
    1     1     1  CURVE                 0             1             0
)"));
  CHECK(has(r.out, "    1     1     1  STRINGER              1             0             0\n"));
  CHECK(has(r.out, R"(LIST SURFACE
NOCUR 3  NOSTR 3  INTCU 2  INTST 2
INPUT POINTS 9, BORDER TANGENTS 12
PATCHES 2 BY 2
INTERPOLATED GRID 7 BY 7 POINTS
TANGENTS: TYPED
TWISTS: ZERO TWISTS
READY
)"));
  CHECK(has(r.out, R"(ZOOM 0 0 10 10
IMAGE: INPUT, ORTHOGONAL XY, ZOOMED TO 0 0 10 10
READY
LIST IMAGES
CURRENT IMAGE  INPUT, ORTHOGONAL XY
               3 BY 3 POINTS, 2 ARROWS
               ZOOMED TO 0 0 10 10
STORE FIRST    NONE
STORE SECOND   NONE
READY
Z 4 20 20
IMAGE: INPUT, ORTHOGONAL XY, ZOOMED TO 17.5 17.5 22.5 22.5
READY
ZOOM
IMAGE: INPUT, ORTHOGONAL XY
READY
ZOOM 1 2
INCORRECT PARAMETER: GIVE X0 Y0 X1 Y1, A FACTOR [X Y], OR PICK
READY
)"));
  // APL indexing of the workspace variables, index origin 1.
  CHECK(has(r.out, "      INPPN[3;]\n0 20 0\n"));
  CHECK(has(r.out, "      INTPN[1;2;]\n0 3.181154653 0.5185185185\n"));
  CHECK(has(r.out, "      ⍴INPPN\n9 3\n"));
  CHECK(has(r.out, "      ⍴INTPN[;1;]\n7 3\n"));
}

TEST_CASE("ZOOM is not kept on the disk: the next session shows the whole image") {
  TempDir disk;
  const RunResult first = run_commands(disk, seen_from_above + "ZOOM 0 0 10 10\nSTORE FIRST\n");
  REQUIRE(first.status == 0);
  const RunResult next = run_commands(disk, "LIST IMAGES\n");
  CHECK(next.out == R"(READY
LIST IMAGES
CURRENT IMAGE  INPUT, ORTHOGONAL XY
               3 BY 3 POINTS, 2 ARROWS
STORE FIRST    THE CURRENT IMAGE
STORE SECOND   NONE
READY
)");
}

TEST_CASE("SAVE, WRITE, STORE FILE and EXPORT over an existing file say REPLACED") {
  TempDir disk;
  const RunResult first = run_commands(disk, seen_from_above + R"(SAVE HULL
WRITE HULL
STORE FILE HULL
EXPORT HPGL HULL
)");
  CHECK(first.status == 0);
  CHECK(!has(first.out, "REPLACED"));
  const std::string data = read_file(disk.path() / "HULL.IGDSDATA");
  const auto hpgl_bytes = fs::file_size(disk.path() / "HULL.HPGL");
  const RunResult again = run_commands(disk, R"(SA HULL
WRITE hull
S FIL HULL
EX H HULL
EX S HULL
)");
  CHECK(again.out == fmt::format(R"(READY
SA HULL
HULL.IGDSDATA REPLACED
READY
WRITE hull
HULL.IGDSCHAR REPLACED
READY
S FIL HULL
HULL.IGDSIMAG REPLACED
READY
EX H HULL
HULL.HPGL: {} BYTES
HULL.HPGL REPLACED
READY
EX S HULL
HULL.SVG: {} BYTES
READY
)",
                                 hpgl_bytes, fs::file_size(disk.path() / "HULL.SVG")));
  // The file is replaced by the same surface: nothing else changed.
  CHECK(read_file(disk.path() / "HULL.IGDSDATA") == data);
}

TEST_CASE("LIST FILES on a disk with every type of file") {
  TempDir disk;
  // Files igds reads but did not write in this session.
  write_file(disk.path() / "OLD.IGDSBAD", "kept aside");
  write_file(disk.path() / "PLOT0001.HPGL", "IN;");
  write_file(disk.path() / "HISTORY.IGDSHIST", "LIST FILES\n");
  write_file(disk.path() / "README.TXT", "a file of the designer's");
  fs::create_directory(disk.path() / "FOLDER.IGDSDATA");
  const RunResult r = run_commands(disk, seen_from_above + R"(SAVE HULL
WRITE HULL
STORE FILE HULL
DISPLAY FILE HULL
EXPORT SVG HULL
EXPORT TEK HULL
EXPORT HPGL HULL
LIST FILES
)");
  INFO(r.out);
  CHECK(r.status == 0);
  const auto at = r.out.find("LIST FILES\n");
  REQUIRE(at != std::string::npos);
  const std::string listing = r.out.substr(at);
  CHECK(has(listing, fmt::format("DISK {}: ", fs::absolute(disk.path()).string())));
  std::vector<std::string> types;
  for (std::size_t p = 0; (p = listing.find("\n\n", p)) != std::string::npos; p += 2)
    types.push_back(listing.substr(p + 2, listing.find('\n', p + 2) - p - 2));
  CHECK(types == std::vector<std::string>{
                     "HPGL: EXPORT HPGL", "IGDSBAD: DAMAGED SESSIONS, KEPT ASIDE",
                     "IGDSCHAR: CARD IMAGES (WRITE)", "IGDSCONT: THE SESSION",
                     "IGDSDATA: SURFACES (SAVE, RESTORE)", "IGDSHIST: THE HISTORY OF TYPED LINES",
                     "IGDSIMAG: IMAGES (STORE FILE, DISPLAY FILE)",
                     "IGDSLOCK: THE LOCK OF THE SESSION", "IGDSVIMG: IMAGES OF THE SESSION",
                     "SVG: EXPORT SVG", "TEK: EXPORT TEK", "TXT"});
  CHECK(has(listing, fmt::format("  HULL     {:>12} BYTES  ",
                                 fs::file_size(disk.path() / "HULL.IGDSDATA"))));
  CHECK(has(listing, "  PLOT0001            3 BYTES  "));
  CHECK(!has(listing, "FOLDER"));
  CHECK(!has(listing, "COMMANDS"));  // commands.igds: not a NAME.TYPE of the disk
}

TEST_CASE("ZOOM decoded from the 4013 stream: the window's content scaled, the rest cut away") {
  TempDir disk;
  const RunResult r = run_commands(disk, seen_from_above + R"(EXPORT TEK WHOLE
ZOOM 0 0 10 10
EXPORT TEK ZOOMED
)");
  REQUIRE(r.status == 0);
  const TekDrawing whole = decode_tek(read_file(disk.path() / "WHOLE.TEK"));
  const TekDrawing zoomed = decode_tek(read_file(disk.path() / "ZOOMED.TEK"));
  CHECK(zoomed.errors.empty());
  // A clean screen first (ESC FF), then the picture.
  REQUIRE(!whole.pages.empty());
  REQUIRE(!zoomed.pages.empty());
  const TekPage& w = whole.pages.back();
  const TekPage& z = zoomed.pages.back();
  for (const auto& fault : screen_faults(z)) FAIL_CHECK(fault);
  // The full square of an exported picture: 16 to 751 inside its margins, 3 more for the marks.
  // The window 0..10 fills it: point 1 (0 0) at 19 19, point 5 (10 10) at 748 748.
  for (const auto& s : z.segments)
    for (const TekPoint& p : {s.a, s.b}) {
      CHECK(p.x >= 16);
      CHECK(p.x <= 751);
      CHECK(p.y >= 16);
      CHECK(p.y <= 751);
    }
  // The border is drawn first, from point 1 up curve 1 to point 2 (0 10): the whole image puts
  // it where its arrow heads leave room; zoomed, it spans the square.
  REQUIRE(!w.segments.empty());
  REQUIRE(!z.segments.empty());
  const TekSegment& up_whole = w.segments[0];
  const TekSegment& up_zoomed = z.segments[0];
  CHECK(up_zoomed.a.x == 19);
  CHECK(up_zoomed.a.y == 19);
  CHECK(up_zoomed.b.x == 19);
  CHECK(up_zoomed.b.y == 748);
  CHECK(up_whole.a.x == up_whole.b.x);
  const double whole_length = up_whole.b.y - up_whole.a.y;
  CHECK(whole_length > 300);
  CHECK(729 / whole_length > 2);  // 2 times the image's side, and the arrow heads left out
  // The bottom border, cut at the window's right edge: 19 19 to 748 19.
  CHECK(std::any_of(z.segments.begin(), z.segments.end(), [](const TekSegment& s) {
    return s.a.y == 19 && s.b.y == 19 && std::min(s.a.x, s.b.x) == 19 &&
           std::max(s.a.x, s.b.x) == 748;
  }));
  // The points inside the window keep their numbers; the others are cut away with them.
  auto numbers = [](const TekPage& page) {
    std::vector<std::string> out;
    for (const auto& t : page.texts)
      if (t.at.x < 768 && std::all_of(t.text.begin(), t.text.end(), ::isdigit))
        out.push_back(t.text);
    std::sort(out.begin(), out.end());
    return out;
  };
  CHECK(numbers(w) == std::vector<std::string>{"1", "2", "3", "4", "5", "6", "7", "8", "9"});
  CHECK(numbers(z) == std::vector<std::string>{"1", "2", "4", "5"});
  CHECK(std::any_of(z.texts.begin(), z.texts.end(),
                    [](const TekText& t) { return t.text == "ZOOMED" && t.at.x == 780; }));
}

namespace {

// Where the saddle seen from above is drawn, from the first vector of its border: point 1 (0 0)
// up to point 2 (0 10).
struct SaddlePlaced {
  TekPoint origin;
  double unit = 0;  // points per image unit
  std::string at(double x, double y) const {
    return fmt::format("{} {}", std::lround(origin.x + unit * x), std::lround(origin.y + unit * y));
  }
  std::array<int, 2> address(double x, double y) const {
    return {int(std::lround(origin.x + unit * x)), int(std::lround(origin.y + unit * y))};
  }
};

SaddlePlaced placed_on(const TekDrawing& d) {
  REQUIRE(!d.pages.empty());
  const auto& border = d.pages.back().segments;
  REQUIRE(border.size() > 3);
  SaddlePlaced s{border[0].a, (border[0].b.y - border[0].a.y) / 10};
  REQUIRE(s.unit > 20);
  return s;
}

// On tek mode's screen, in the square above the dialogue: where a person sees it.
SaddlePlaced saddle_on_screen(const TempDir& disk) {
  const RunResult shown = run_in(disk, "tek", seen_from_above);
  REQUIRE(shown.status == 0);
  return placed_on(decode_tek(shown.out));
}

// On the page (EXPORT TEK's full square): where a command file's X Y are read in every mode.
SaddlePlaced saddle_on_page() {
  TempDir disk;
  REQUIRE(run_in(disk, "none", seen_from_above + "EXPORT TEK PAGE\n").status == 0);
  return placed_on(decode_tek(read_file(disk.path() / "PAGE.TEK")));
}

// The dialogue of a run under `mode`: the texts of the 4013 stream in tek mode (after checking
// that nothing on a page is written over anything), else the output as it is.
std::string dialogue_of(const std::string& mode, const RunResult& r) {
  if (mode != "tek") return r.out;
  const TekDrawing d = decode_tek(r.out);
  CHECK(d.errors.empty());
  std::string said;
  for (const auto& page : d.pages) {
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
    for (const auto& t : page.texts) said += t.text + "\n";
  }
  return said;
}

// The x y z of the first line `POINT k AT x y z` after `from` in `out`.
std::array<double, 3> point_at(const std::string& out, int k, std::size_t from = 0) {
  const std::string start = fmt::format("POINT {} AT ", k);
  const auto at = out.find(start, from);
  REQUIRE(at != std::string::npos);
  std::array<double, 3> p{};
  REQUIRE(std::sscanf(out.c_str() + at + start.size(), "%lf %lf %lf", &p[0], &p[1], &p[2]) == 3);
  return p;
}

const char* const every_mode[] = {"none", "tek", "xterm"};

}  // namespace

TEST_CASE("ZOOM PICK from a command file: the same window under --term none, tek and xterm") {
  // The corners at points 1 (0 0) and 5 (10 10) of the page.
  const SaddlePlaced page = saddle_on_page();
  const std::string first = page.at(0, 0), second = page.at(10, 10);
  std::string window_none;
  for (const std::string mode : every_mode) {
    CAPTURE(mode);
    TempDir disk;
    const RunResult r =
        run_in(disk, mode,
               seen_from_above + "ZOOM PICK\n" + first + "\n" + second + "\nLIST IMAGES\nERASE\n");
    REQUIRE(r.status == 0);
    const std::string said = dialogue_of(mode, r);
    CHECK(has(said, "FIRST CORNER? " + first + "\n"));
    CHECK(has(said, "SECOND CORNER? " + second + "\n"));
    // The corners come back in image units, within a point of 0 0 and 10 10, the same in
    // every mode.
    const auto at = said.find(" ZOOMED TO ");
    REQUIRE(at != std::string::npos);
    const std::string window = said.substr(at, said.find('\n', at) - at);
    double x0 = 1, y0 = 1, x1 = 0, y1 = 0;
    REQUIRE(std::sscanf(window.c_str(), " ZOOMED TO %lf %lf %lf %lf", &x0, &y0, &x1, &y1) == 4);
    CHECK(std::abs(x0) <= 1 / page.unit);
    CHECK(std::abs(y0) <= 1 / page.unit);
    CHECK(std::abs(x1 - 10) <= 1 / page.unit);
    CHECK(std::abs(y1 - 10) <= 1 / page.unit);
    if (window_none.empty()) window_none = window;
    CHECK(window == window_none);
  }
}

TEST_CASE(
    "PICK and CHANGE POINTS from a command file: the same points, moved alike, in every mode") {
  // A pick a little off point 5 (10 10) names it; at CHANGE POINTS, point 9 (20 20) is picked
  // and put at 15 5 (z kept, the view is XY); point 4 is typed a new place.
  const SaddlePlaced page = saddle_on_page();
  const std::string commands = seen_from_above + "PICK\n" + page.at(10.2, 9.7) +
                               "\nCHANGE POINTS\nPICK\nNOT A PICK\n" + page.at(19.8, 20) +
                               "\nPICK\n" + page.at(15, 5) + "\nPICK\n" + page.at(10, 0) +
                               "\n10 ¯1 2.5\n\nN\nN\nLIST POINTS\nWRITE SADDLE\n";
  std::string cards_none;
  for (const std::string mode : every_mode) {
    CAPTURE(mode);
    TempDir disk;
    const RunResult r = run_in(disk, mode, commands);
    REQUIRE(r.status == 0);
    const std::string said = dialogue_of(mode, r);
    CHECK(has(said, "POINT 5 AT 10 10 0\n"));
    CHECK(has(said, "INCORRECT ENTRY: A CROSS-HAIR PICK OR X Y (0..1023 0..779)"));
    CHECK(has(said, "POINT 9 AT 20 20 0\n"));
    // The new place within a point, rounded to what a pick can tell; z kept.
    const auto moved = point_at(said, 9, said.find("NEW PLACE?"));
    CHECK(std::abs(moved[0] - 15) <= 1 / page.unit + 0.01);
    CHECK(std::abs(moved[1] - 5) <= 1 / page.unit + 0.01);
    CHECK(moved[2] == 0);
    CHECK(std::abs(moved[0] * 100 - std::round(moved[0] * 100)) < 1e-6);
    CHECK(has(said, "POINT 4 AT 10 0 2\n"));
    CHECK(has(said, "POINT 4 AT 10 -1 2.5\n"));
    // LIST POINTS shows the surface changed.
    CHECK(has(said,
              fmt::format("    9     3     3 {:>13} {:>13}             0", moved[0], moved[1])));
    // The surface after it, card for card, is the same in every mode.
    const std::string cards = read_file(disk.path() / "SADDLE.IGDSCHAR");
    REQUIRE(!cards.empty());
    if (cards_none.empty()) cards_none = cards;
    CHECK(cards == cards_none);
  }
}

TEST_CASE("PICK and CHANGE POINTS through the pty: clicked, or typed as X Y, on the screen seen") {
  TempDir disk;
  const SaddlePlaced screen = saddle_on_screen(disk);
  TempDir home;
  XtermPty term({igds_binary().string(), "--term", "tek", "--disk", disk.path().string()},
                {{"TERM", "tek4014"},
                 {"INPUTRC", "/dev/null"},
                 {"HOME", home.path().string()},
                 {"XTERM_VERSION", ""},
                 {"IGDS_DISK", ""}});
  PtySession& igds = term.pty();
  REQUIRE(term.expect("READY", 60));
  // The session's image is the saddle seen from above, drawn again at start.
  igds.send("ERASE\r");
  REQUIRE(term.expect("READY"));
  igds.send("DISPLAY INPUT ORTHOGONAL XY\r");
  REQUIRE(term.expect("READY"));
  igds.send("PICK\r");
  REQUIRE(term.expect("POINT?"));
  REQUIRE(term.expect_gin());
  auto [x5, y5] = screen.address(9.8, 10.1);
  term.click('l', x5, y5);
  if (!term.expect("POINT 5 AT 10 10 0")) FAIL(term.transcript());
  REQUIRE(term.expect("READY"));

  // CHANGE POINTS with the point picked at image (x, y) by `pick` (a click, or X Y typed at the
  // cross-hair), named as `named`, and its new place picked at `to`; the empty line then ends the
  // points, the tangents and the grid left as they are. Point `number` as the last NEW PLACE?
  // lists it (the screen may start a new page and write the dialogue's end again).
  auto change_by_picks = [&](auto pick, std::array<double, 2> from, const std::string& named,
                             int number, std::array<double, 2> to) {
    igds.send("CHANGE POINTS\r");
    REQUIRE(term.expect("POINTS?"));
    igds.send("PICK\r");
    REQUIRE(term.expect_gin());
    pick(from);
    REQUIRE_MESSAGE(term.expect(named), term.transcript());
    REQUIRE(term.expect("NEW X Y Z?"));
    igds.send("PICK\r");
    REQUIRE(term.expect("NEW PLACE?"));
    REQUIRE(term.expect_gin());
    pick(to);
    REQUIRE(term.expect(fmt::format("POINT {} AT ", number)));
    REQUIRE(term.expect("POINTS?"));
    igds.send("\r");
    REQUIRE(term.expect("CHANGE TANGENTS TOO?"));
    igds.send("N\r");
    REQUIRE(term.expect("CHANGE GRID TOO?"));
    igds.send("N\r");
    REQUIRE(term.expect("READY"));
    return point_at(igds.output(), number, igds.output().rfind("NEW PLACE?"));
  };
  auto click = [&](std::array<double, 2> at) {
    const auto [x, y] = screen.address(at[0], at[1]);
    term.click('l', x, y);
  };
  const auto moved = change_by_picks(click, {0.2, 0.3}, "POINT 1 AT 0 0 0", 1, {3, 4});
  CHECK(std::abs(moved[0] - 3) <= 1 / screen.unit + 0.01);
  CHECK(std::abs(moved[1] - 4) <= 1 / screen.unit + 0.01);
  CHECK(moved[2] == 0);

  // X Y typed by the person at the cross-hair are read on the screen too, as a click would be:
  // point 9 (20 20), which on the page would be nearer point 6, and its new place.
  auto type = [&](std::array<double, 2> at) { term.type(screen.at(at[0], at[1]) + "\r"); };
  const auto typed = change_by_picks(type, {20, 20}, "POINT 9 AT 20 20 0", 9, {6, 8});
  CHECK(std::abs(typed[0] - 6) <= 1 / screen.unit + 0.01);
  CHECK(std::abs(typed[1] - 8) <= 1 / screen.unit + 0.01);
  CHECK(typed[2] == 0);
  igds.send("END CMS\r");
  CHECK(igds.wait(60) == 0);
}

}  // namespace igds::test
