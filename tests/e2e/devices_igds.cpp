// The devices through the real igds binary: a whole --term tek session is a 4013 stream that
// tek2plot renders without complaint, and EXPORT and PLOT write what the devices make.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <regex>

#include "tests/devices/support.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "tests/support/tek_decoder.h"

namespace igds::test::devices {

namespace {

// A 3 x 3 surface with two border tangents, shown three ways, erased once, exported, plotted.
constexpr std::string_view session = R"(BUILD
3 3
1 0 0 0  1 0 0.2  2 0 0
4 0 1 0.3  1 1 0.5  2 1 0.3
7 0 2 0  1 2 0.2  2 2 0

1 1 0 0 1
2 0 1 0

2 2
DISPLAY INPUT ASSONOMETRIC 110 130 120
DISPLAY SURFACE ORTHOGONAL XY
ERASE
DISPLAY SURFACE ISOMETRIC 3 30
EXPORT SVG HULL
EXPORT TEK HULL
EXPORT HPGL HULL
PLOT SELECTRIC
END CMS
)";

RunResult run_session(const TempDir& disk, std::vector<std::string> options) {
  write_file(disk.path() / "session.igds", session);
  std::vector<std::string> args{"--disk", disk.path().string()};
  args.insert(args.end(), options.begin(), options.end());
  args.push_back((disk.path() / "session.igds").string());
  RunOptions run_options;
  run_options.timeout_seconds = 60;
  return run_igds(args, run_options);
}

RunResult tek2plot(const std::filesystem::path& file) {
  RunOptions options;
  options.timeout_seconds = 60;
  return run({"tek2plot", "-T", "svg", file.string()}, options);
}

}  // namespace

TEST_CASE("igds --term tek: the whole session is a 4013 stream tek2plot renders") {
  IGDS_SKIP_UNLESS(have_program("tek2plot"), "tek2plot (plotutils) is not installed");
  TempDir disk;
  RunResult r = run_session(disk, {"--term", "tek"});
  INFO(r.out, r.err);
  REQUIRE(r.status == 0);
  write_file(disk.path() / "out.tek", r.out);
  RunResult t = tek2plot(disk.path() / "out.tek");
  CHECK(t.status == 0);
  CHECK(t.err == "");
  // Page by page, nothing over anything, nothing off the screen.
  const TekDrawing pages = test::decode_tek(r.out);
  RunOptions options;
  options.timeout_seconds = 60;
  RunResult last_page =
      run({"tek2plot", "-T", "svg", "--page-number", std::to_string(pages.pages.size() - 1),
           (disk.path() / "out.tek").string()},
          options);
  CHECK(last_page.status == 0);
  CHECK(!svg_paths(last_page.out).empty());
  CHECK(pages.errors.empty());
  for (const auto& page : pages.pages)
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
  // The last DISPLAY is the one EXPORT TEK wrote, in the square of the screen that keeps the
  // dialogue below it: the same picture, drawn by the same code, smaller.
  std::string exported = read_file(disk.path() / "HULL.TEK");
  auto image = decode_tek(exported, 10);
  CHECK(image.pages == 1);
  CHECK(!image.paths.empty());
  const auto& last = pages.pages.back();
  CHECK(!last.segments.empty());
  for (const auto& s : last.segments)
    for (const TekPoint& p : {s.a, s.b}) CHECK((p.x <= 583 && p.y >= 184 && p.y <= 767));
  CHECK(r.out.find("SURFACE") != std::string::npos);
  CHECK(r.out.find("ISOMETRIC") != std::string::npos);
  RunResult e = tek2plot(disk.path() / "HULL.TEK");
  CHECK(e.status == 0);
  CHECK(e.err == "");
  // READY after a DISPLAY comes in the dialogue below the picture; the caption beside it.
  CHECK(std::any_of(last.texts.begin(), last.texts.end(), [](const TekText& t) {
    return t.text == "READY" && t.at.x == 0 && t.at.y <= 160;
  }));
  CHECK(std::any_of(last.texts.begin(), last.texts.end(),
                    [](const TekText& t) { return t.text == "ISOMETRIC" && t.at.x == 600; }));
}

TEST_CASE("igds: EXPORT and PLOT files read by xmllint and hp2xx, the PLOT summary") {
  IGDS_SKIP_UNLESS(have_program("hp2xx"), "hp2xx is not installed");
  IGDS_SKIP_UNLESS(have_program("xmllint"), "xmllint (libxml2-utils) is not installed");
  TempDir disk;
  RunResult r = run_session(disk, {"--term", "none", "--paper", "a3"});
  INFO(r.out, r.err);
  REQUIRE(r.status == 0);
  std::string plot = read_file(disk.path() / "PLOT0001.HPGL");
  CHECK(read_file(disk.path() / "HULL.HPGL") == plot);
  std::smatch m;
  REQUIRE(std::regex_search(
      r.out, m,
      std::regex(
          R"(PLOT0001\.HPGL: ([0-9]+) VECTORS, ([0-9]+) PEN LIFTS, PEN-UP TRAVEL ([0-9]+) MM, ([0-9]+) BYTES)")));
  CHECK(std::stoul(m[4]) == plot.size());
  CHECK(std::stoul(m[1]) > 0);
  RunOptions options;
  options.timeout_seconds = 60;
  RunResult h = run(
      {"hp2xx", "-t", "-m", "hpgl", "-f", "-", (disk.path() / "PLOT0001.HPGL").string()}, options);
  CHECK(h.status == 0);
  Hp2xxLog log = read_hp2xx_log(h.err);
  CHECK(log.commands > 0);
  CHECK(log.x1 <= 16158);  // A3 on the 7475A
  CHECK(log.y1 <= 11040);
  CHECK(log.x1 > 11040);  // larger than A4 allows
  RunResult x = run({"xmllint", "--noout", (disk.path() / "HULL.SVG").string()}, options);
  CHECK(x.status == 0);
  CHECK(x.err == "");
}

TEST_CASE("igds --tek 4014: 12-bit addresses, still read by tek2plot") {
  IGDS_SKIP_UNLESS(have_program("tek2plot"), "tek2plot (plotutils) is not installed");
  TempDir disk;
  RunResult r = run_session(disk, {"--term", "tek", "--tek", "4014"});
  REQUIRE(r.status == 0);
  write_file(disk.path() / "out.tek", r.out);
  RunResult t = tek2plot(disk.path() / "out.tek");
  CHECK(t.status == 0);
  CHECK(t.err == "");
  auto image = decode_tek(read_file(disk.path() / "HULL.TEK"), 12);
  int largest = 0;
  for (const auto& p : image.paths)
    for (auto q : p) largest = std::max({largest, q.x, q.y});
  CHECK(largest > 1023);
  // The session at 12 bits is the session at 10 bits, four times finer (on a disk of its own:
  // on this one EXPORT would say REPLACED, and the dialogue would differ).
  TempDir disk10;
  RunResult r10 = run_session(disk10, {"--term", "tek", "--tek", "4013"});
  const auto fine = decode_tek(r.out, 12), coarse = decode_tek(r10.out, 10);
  REQUIRE(fine.paths.size() == coarse.paths.size());
  for (std::size_t i = 0; i < fine.paths.size(); ++i) {
    REQUIRE(fine.paths[i].size() == coarse.paths[i].size());
    for (std::size_t k = 0; k < fine.paths[i].size(); ++k) {
      CHECK(std::abs(fine.paths[i][k].x - 4 * coarse.paths[i][k].x) <= 4);
      CHECK(std::abs(fine.paths[i][k].y - 4 * coarse.paths[i][k].y) <= 4);
    }
  }
}

TEST_CASE("igds --term xterm and --plotter tty: the wrappings on the terminal") {
  TempDir disk;
  RunResult r = run_session(disk, {"--term", "xterm", "--plotter", "tty"});
  REQUIRE(r.status == 0);
  CHECK(r.out.find("\x1B[?38h\x1D") != std::string::npos);
  CHECK(r.out.find("\x1F\x1B\x03") != std::string::npos);
  CHECK(r.out.find("\x1B[?38h\x1B\x0C") != std::string::npos);  // ERASE
  auto start = r.out.find("\x1B.(IN;SP1;");
  REQUIRE(start != std::string::npos);
  auto end = r.out.find("PU;SP0;\x1B.)", start);
  REQUIRE(end != std::string::npos);
  CHECK(r.out.substr(start + 3, end + 7 - start - 3) == read_file(disk.path() / "HULL.HPGL"));
  CHECK(!std::filesystem::exists(disk.path() / "PLOT0001.HPGL"));
}

}  // namespace igds::test::devices
