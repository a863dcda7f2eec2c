// Marks 1970 with the real binary (docs/marks.md): AUTO, CHANGE TWISTS, FIT, PUNCH, the
// transcript word for word, the files on the disk, and the modes kept by the session.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "tests/support/process.h"
#include "workspace/exchange/marks_deck.h"
#include "workspace/exchange/mpdp_tape.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

test::RunResult igds_on(const fs::path& disk, const std::string& commands) {
  test::TempDir files;
  test::write_file(files.path() / "commands.igds", commands);
  return test::run_igds(
      {"--disk", disk.string(), "--term", "none", (files.path() / "commands.igds").string()});
}

// A 3 x 3 deck, positions only, and the same with point 5 missing.
const char* const deck =
    "   3   3\n"
    "  1.  1.  1.  1.  1.  1.  1.  1.  1.\n"
    "    0.0    0.0    0.0\n   10.0    0.0    2.0\n   20.0    0.0    0.0\n"
    "    0.0   10.0    2.0\n   10.0   10.0    4.0\n   20.0   10.0    2.0\n"
    "    0.0   20.0    0.0\n   10.0   20.0    2.0\n   20.0   20.0    0.0\n";
const char* const hole =
    "   3   3\n"
    "  1.  1.  1.  1.  0.  1.  1.  1.  1.\n"
    "    0.0    0.0    0.0\n   10.0    0.0    2.0\n   20.0    0.0    0.0\n"
    "    0.0   10.0    2.0\n   20.0   10.0    2.0\n"
    "    0.0   20.0    0.0\n   10.0   20.0    2.0\n   20.0   20.0    0.0\n";

}  // namespace

TEST_CASE("AUTO, CHANGE TWISTS, FIT and PUNCH: the transcript and the files") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir disk;
  test::write_file(disk.path() / "DOME.CADADATA", deck);
  test::write_file(disk.path() / "HOLE.CADADATA", hole);
  auto r = igds_on(disk.path(),
                   "BUILD\n3 3\n1 0 0 0 10 0 2 20 0 0\n4 0 10 2 10 10 4 20 10 2\n"
                   "7 0 20 0 10 20 2 20 20 0\n\nAUTO\n4 1 0 0\n\n2 2\n"
                   "C TW\nSOME\nM\nPU DOME\nWRITE DOME\nFIT HOLE\nF DOME\n1 1\nHELP SHORT\n");
  CHECK(r.status == 0);
  CHECK(r.err == "");
  CHECK(r.out ==
        "READY\nBUILD\nNUMBER OF CURVES AND STRINGERS? 3 3\nPOINTS? 1 0 0 0 10 0 2 20 0 0\n"
        "POINTS? 4 0 10 2 10 10 4 20 10 2\nPOINTS? 7 0 20 0 10 20 2 20 20 0\nPOINTS?\n"
        "TANGENTS? AUTO\nTANGENTS? 4 1 0 0\nTANGENTS?\nINTERPOLATED CURVES AND STRINGERS? 2 2\n"
        "READY\nC TW\nTWISTS? (ZERO OR MARKS) SOME\nINCORRECT ENTRY: ANSWER ZERO OR MARKS\n"
        "TWISTS? (ZERO OR MARKS) M\nREADY\nPU DOME\nDOME.MPDPTAPE: 4 PATCHES, 651 FRAMES\n"
        "READY\nWRITE DOME\nREADY\nFIT HOLE\n"
        "DECK REFUSED: HOLE.CADADATA (POINT 5 HAS NO POSITION, KEY ON LINE 2; IGDS NEEDS EVERY "
        "POINT); CURRENT SURFACE KEPT\nREADY\nF DOME\nINTERPOLATED CURVES AND STRINGERS? 1 1\n"
        "NOCUR 3 NOSTR 3 INTCU 1 INTST 1\nDOME.CADALIST: 9 POINTS, 4 PATCHES, 0 GIVEN VECTORS\n"
        "READY\nHELP SHORT\n"
        "Type a command: BUILD CHANGE RESTORE DISPLAY PLOT STORE SAVE WRITE END HELP\n"
        "ERASE EXPORT FIT PUNCH LIST UNDO REDO ZOOM IMPORT PICK.\n"
        "A first letter is enough (S is STORE); HELP LONG explains them all.\n"
        "THE CURRENT SURFACE HAS TANGENTS AUTO (MARKS'S RULE) AND TWISTS MARKS.\nREADY\n");
  // The tape decodes to 4 patches, 162 frames each and the end mark.
  const std::string tape = test::read_file(disk.path() / "DOME.MPDPTAPE");
  CHECK(tape.size() == 4 * 162 + 3);
  const auto patches = exchange::read_tape(tape);
  REQUIRE(patches.size() == 4);
  // Point 1 is the corner C of patch 1; x of C_c is 0, z of E_c (point 2) is 2.
  CHECK(patches[0].b[0] == 0);
  CHECK(patches[0].b[32 + 4] == 2);
  // IGDSCHAR's STATUS card shows the twists (STATUS[3]) and AUTO (STATUS[4]).
  const std::string cards = test::read_file(disk.path() / "DOME.IGDSCHAR");
  CHECK(cards.substr(0, 20) == "    1    0    1    1");
  // The listing has a line per point and the four B rows of each patch.
  const std::string listing = test::read_file(disk.path() / "DOME.CADALIST");
  CHECK(std::count(listing.begin(), listing.end(), '\n') == 9 + 1 + 4 * 5);
  CHECK(!fs::exists(disk.path() / "HOLE.CADALIST"));

  // The next start has the FIT surface with its modes and its patches.
  auto again = igds_on(disk.path(), "HELP SHORT\nPU AGAIN\n");
  CHECK(again.out.find("THE CURRENT SURFACE HAS TANGENTS AUTO (MARKS'S RULE) AND TWISTS MARKS.") !=
        std::string::npos);
  const auto fitted = exchange::read_tape(test::read_file(disk.path() / "AGAIN.MPDPTAPE"));
  const auto fit = exchange::fit_deck(exchange::read_deck(deck));
  REQUIRE(fitted.size() == 4);
  for (std::size_t p = 0; p < 4; ++p)
    for (int k = 0; k < 3; ++k)
      for (int e = 0; e < 16; ++e) {
        const int r = e / 4, c = e % 4;
        const bool reversed = (c == 3 && r < 2) || (r == 3 && c < 2);
        const double v = fit.patches.ravel[48 * p + 16 * std::size_t(k) + std::size_t(e)];
        CHECK(fitted[p].b[std::size_t(16 * k + e)] == std::lround(reversed ? -v : v));
      }
}
