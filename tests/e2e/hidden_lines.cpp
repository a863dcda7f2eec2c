// DISPLAY HIDDEN on the real igds: the picture PLOT and every EXPORT make of it, the same after
// UNDO and REDO and after a restart (the image kept by its recipe), and a part of DISPLAY
// SURFACE's picture of the same view.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "tests/support/process.h"
#include "tests/support/tek_decoder.h"

using namespace igds;
using namespace igds::test;
namespace fs = std::filesystem;

namespace {

// The wave of the manual's figure 6 (scripts/examples/fig6-multipatch.igds), with a finer grid.
const std::string wave =
    "BUILD\n4 5\n"
    "1  0 0 0   10 0 5.657   20 0 8   30 0 5.657   40 0 0\n"
    "6  0 10 0   10 10 4.333   20 10 6.128   30 10 4.333   40 10 0\n"
    "11  0 20 0   10 20 0.982   20 20 1.389   30 20 0.982   40 20 0\n"
    "16  0 30 0   10 30 -2.828   20 30 -4   30 30 -2.828   40 30 0\n\n"
    "1 0.847 0 0.532 1\n5 0.847 0 -0.532 1\n6 0.901 0 0.434\n10 0.901 0 -0.434\n"
    "11 0.994 0 0.108\n15 0.994 0 -0.108\n16 0.954 0 -0.3 1\n20 0.954 0 0.3 1\n"
    "1 0 1 0 0\n16 0 1 0 0\n2 0 1 0\n17 0 0.946 -0.324\n3 0 1 0\n18 0 0.9 -0.435\n"
    "4 0 1 0\n19 0 0.946 -0.324\n5 0 1 0 0\n20 0 1 0 0\n\n"
    "4 4\n";

RunResult igds_on(const fs::path& disk, const std::string& commands) {
  const fs::path file = disk / "commands.igds";
  write_file(file, commands + "END CMS\n");
  return run_igds({"--disk", disk.string(), "--term", "none", file.string()});
}

double ink(const std::vector<TekSegment>& segments) {
  double sum = 0;
  for (const auto& s : segments) sum += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
  return sum;
}

}  // namespace

TEST_CASE("DISPLAY HIDDEN: its picture is kept by PLOT and EXPORT, UNDO, REDO and a restart") {
  TempDir dir;
  const fs::path disk = dir.path();
  auto first = igds_on(disk, wave +
                                 "D H CONIC 80 -20 14\n"
                                 "EXPORT TEK HID\nEXPORT SVG HID\nEXPORT HPGL HID\nPLOT S\n"
                                 "DISPLAY SURFACE CONIC 80 -20 14\nEXPORT TEK ALL\n"
                                 "UNDO\nEXPORT TEK UNDONE\nREDO\nUNDO\n");
  REQUIRE(first.status == 0);
  CHECK(first.out.find("IMAGE: SURFACE HIDDEN, CONIC, VIEW POINT 80 ¯20 14") != std::string::npos);
  const std::string hidden = read_file(disk / "HID.TEK");
  // Each file is a clean page (ESC FF) and the picture on it.
  const auto seen = decode_tek(hidden).pages.back().segments;
  const auto all = decode_tek(read_file(disk / "ALL.TEK")).pages.back().segments;
  REQUIRE(!all.empty());
  // The surface hides a part of itself from that low eye, and what is drawn lies on its lines.
  CHECK(ink(seen) < 0.9 * ink(all));
  CHECK(ink(seen) > 0.5 * ink(all));
  for (const auto& s : seen)
    for (const TekPoint p : {s.a, s.b}) {
      double nearest = 1e9;
      for (const auto& t : all) nearest = std::min(nearest, distance(p, t));
      CHECK(nearest <= 1.0);
    }
  // UNDO put the hidden-line image back, and it draws the same.
  CHECK(read_file(disk / "UNDONE.TEK") == hidden);
  // The SVG's description says what it is; PLOT draws what EXPORT HPGL writes.
  const std::string svg = read_file(disk / "HID.SVG");
  CHECK(svg.find(">HIDDEN<") != std::string::npos);
  const std::string plot = read_file(disk / "PLOT0001.HPGL");
  CHECK(read_file(disk / "HID.HPGL") == plot);

  // A restart: the current image is the hidden one, made again from its recipe, the same.
  auto second = igds_on(disk, "EXPORT TEK AGAIN\nEXPORT SVG AGAIN\nLIST IMAGES\n");
  REQUIRE(second.status == 0);
  CHECK(read_file(disk / "AGAIN.TEK") == hidden);
  CHECK(read_file(disk / "AGAIN.SVG") == svg);
  CHECK(second.out.find("CURRENT IMAGE  SURFACE HIDDEN, CONIC, VIEW POINT 80 ¯20 14\n") !=
        std::string::npos);
}

TEST_CASE("DISPLAY HIDDEN: SURFACE NOT FOUND without a surface, and a projection's report") {
  TempDir dir;
  auto r = igds_on(dir.path(), "D H CONIC 80 -20 14\n" + wave + "D H CONIC 20 15 0\n");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("D H CONIC 80 -20 14\nSURFACE NOT FOUND\n") != std::string::npos);
  // A view point inside the surface's box: refused as DISPLAY SURFACE refuses it.
  CHECK(r.out.find("D H CONIC 20 15 0\nINCORRECT PARAMETER: THE VIEW POINT IS INSIDE THE "
                   "SURFACE'S BOX\n") != std::string::npos);
}

TEST_CASE(
    "DISPLAY SURFACE HIDDEN draws what DISPLAY HIDDEN draws; H alone there is no projection") {
  TempDir dir;
  const fs::path disk = dir.path();
  auto r = igds_on(disk, wave +
                             "D H ASSONOMETRIC 110 130 120\nEXPORT TEK ONE\n"
                             "DISPLAY SURFACE HIDDEN ASSONOMETRIC 110 130 120\nEXPORT TEK TWO\n"
                             "D SU HI\nASSONOMETRIC 110 130 120\nEXPORT TEK THREE\n"
                             "D SU ASSONOMETRIC 110 130 120\nEXPORT TEK ALL\nD SU H\n");
  REQUIRE(r.status == 0);
  const std::string hidden = read_file(disk / "ONE.TEK");
  CHECK(read_file(disk / "TWO.TEK") == hidden);
  CHECK(read_file(disk / "THREE.TEK") == hidden);
  CHECK(read_file(disk / "ALL.TEK") != hidden);
  CHECK(r.out.find("D SU H\nINCORRECT PARAMETER: THE PROJECTION IS CONIC, ISOMETRIC, ASSONOMETRIC "
                   "OR ORTHOGONAL\n") != std::string::npos);
}
