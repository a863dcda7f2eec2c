// igds on command files: transcripts, the error reports, exit statuses, the saved session.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "devices/tek_screen.h"
#include "devices/tek_stream.h"
#include "tests/e2e/e2e_support.h"
#include "tests/support/tek_decoder.h"
#include "tests/workspace/live_igds.h"

namespace igds::test {

namespace {

std::size_t count(const std::string& text, std::string_view what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("a command file gives the transcript of the session") {
  TempDir disk;
  auto r = run_commands(disk, R"(* A saddle, typed the 1975 way.
b
3,3
1  0 0 0   0 10 2   0 20 0
⍝ a comment does not end the entries
4  10 0 2  10 10 0  10 20 2
7  20 0 0  20 10 2  20 20 0 ⍝ the third curve
H S

1 0 1 0 1
1 1 0 0
1 1 0 0 0

x 2
2 2
d su a 110 130 120
D I O XY
S FI
C G
1 1
END CMS
)");
  CHECK(r.status == 0);
  CHECK(r.err == "");
  CHECK(r.out == R"(READY
b
NUMBER OF CURVES AND STRINGERS? 3,3
POINTS? 1  0 0 0   0 10 2   0 20 0
POINTS? 4  10 0 2  10 10 0  10 20 2
POINTS? 7  20 0 0  20 10 2  20 20 0 ⍝ the third curve
POINTS? H S
A point number k and x y z (more triplets go to k+1, k+2, ...); an empty line
ends the points.
POINTS?
TANGENTS? 1 0 1 0 1
TANGENTS? 1 1 0 0
INCORRECT ENTRY: POINT 1 IS A CORNER: GIVE 1 (CURVE) OR 0 (STRINGER)
TANGENTS? 1 1 0 0 0
TANGENTS?
INTERPOLATED CURVES AND STRINGERS? x 2
INCORRECT ENTRY: GIVE TWO WHOLE NUMBERS >= 0, INTCU AND INTST
INTERPOLATED CURVES AND STRINGERS? 2 2
READY
d su a 110 130 120
IMAGES ARE NOT DRAWN ON THIS TERMINAL. TO SEE THEM RUN IGDS IN AN XTERM
(xterm -t -e igds), OR WRITE THEM TO FILES WITH EXPORT SVG, TEK OR HPGL.
IMAGE: SURFACE, ASSONOMETRIC 110 130 120
READY
D I O XY
IMAGE: INPUT, ORTHOGONAL XY
READY
S FI
READY
C G
INTERPOLATED CURVES AND STRINGERS? 1 1
READY
END CMS
)");
}

TEST_CASE("the session comes back at the next start") {
  TempDir disk;
  auto first = run_commands(
      disk, std::string(saddle_build) + "D SU O XZ\nSTORE SECOND\nHELP SHORT\nEND CMS\n");
  REQUIRE(first.status == 0);
  auto second = run_commands(disk, "END APL\nNOCUR\n⍴INTPN\nDEST2\nSTATUS\n)VARS\n)OFF\n");
  CHECK(second.status == 0);
  CHECK(second.out == R"(READY
END APL
      NOCUR
3
      ⍴INTPN
7 7 3
      DEST2
1 4 2 0 0
      STATUS
0 0 0 0 0 0 0 0 0 0
      )VARS
IGDS: DESIM DEST2 IMAGE INPPN INPTG INTCU INTPN INTST NOCUR NOSTR PATCHES STATUS
      TEMP2
      )OFF
)");
}

TEST_CASE("END APL: START goes back to READY, errors in APL style") {
  TempDir disk;
  auto r = run_commands(disk, "E A\nIMAGE\nINPPN\n2+2\n)H S\nH←2\n* 1\nSTART\nH S\nEND CMS\n");
  CHECK(r.status == 0);
  CHECK(
      r.out.find("      IMAGE\nVALUE ERROR\n      IMAGE\n      ^\n      INPPN\n\n      2+2\n4\n") !=
      std::string::npos);
  CHECK(r.out.find("      )H S\nType an APL statement") != std::string::npos);
  // HELP and a CMS comment are IGDS's: in APL, H is a name and * a function.
  CHECK(r.out.find("      H←2\n      * 1\n2.718281828\n") != std::string::npos);
  CHECK(r.out.find("      START\nREADY\nH S\nType a command:") != std::string::npos);
}

TEST_CASE("every error report of the manual") {
  TempDir disk;
  auto r = run_commands(disk, R"(FROBNICATE
BUILD 3 3
CHANGE
SIDEWAYS
GRID
CHANGE GRID
DISPLAY INPUT
DISPLAY SURFACE
DISPLAY FIRST
STORE FIRST
DISPLAY FILE NOSUCH
DISPLAY FILE ../ETC
RESTORE NOSUCH
SAVE
)" + std::string(saddle_build) + R"(DISPLAY SURFACE PERSPECTIVE
DISPLAY SURFACE CONIC 10 10 1
BUILD
1 1
)");
  CHECK(r.status == 0);
  const std::string expected[] = {
      "FROBNICATE\nINCORRECT COMMAND OR PARAMETERS\nREADY\n",
      "BUILD 3 3\nINCORRECT COMMAND OR PARAMETERS\nREADY\n",
      // A word that is no option, typed at the question: the report, and the question again.
      "GRID, TANGENTS, POINTS OR TWISTS? SIDEWAYS\nINCORRECT CHOICE OF PARAMETERS\nGRID, "
      "TANGENTS, POINTS OR TWISTS? GRID\nINPUT NOT FOUND\nREADY\n",
      "CHANGE GRID\nINPUT NOT FOUND\nREADY\n",
      "DISPLAY INPUT\nINPUT NOT FOUND\nREADY\n",
      "DISPLAY SURFACE\nSURFACE NOT FOUND\nREADY\n",
      "DISPLAY FIRST\nIMAGE NOT FOUND\nREADY\n",
      "STORE FIRST\nIMAGE NOT FOUND\nREADY\n",
      "DISPLAY FILE NOSUCH\nFILE NOT FOUND\nREADY\n",
      "DISPLAY FILE ../ETC\nINCORRECT PARAMETER: A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - "
      "_\nREADY\n",
      "RESTORE NOSUCH\nFILE NOT FOUND\nREADY\n",
      "SAVE\nINPUT NOT FOUND\nREADY\n",
      "DISPLAY SURFACE PERSPECTIVE\nINCORRECT PARAMETER: THE PROJECTION IS CONIC, ISOMETRIC, "
      "ASSONOMETRIC OR ORTHOGONAL\nREADY\n",
      "DISPLAY SURFACE CONIC 10 10 1\nINCORRECT PARAMETER: THE VIEW POINT IS INSIDE THE SURFACE'S "
      "BOX\nREADY\n",
      "NUMBER OF CURVES AND STRINGERS? 1 1\nINCORRECT ENTRY: A SURFACE NEEDS AT LEAST TWO POINTS\n",
  };
  for (const auto& e : expected) {
    CAPTURE(e);
    CHECK(r.out.find(e) != std::string::npos);
  }
  // The input ended inside BUILD: the command is abandoned, the surface kept.
  CHECK(r.out.ends_with("END OF INPUT: BUILD ABANDONED\n"));
  auto after = run_commands(disk, "E A\nNOCUR\n");
  CHECK(after.out.find("NOCUR\n3\n") != std::string::npos);
}

TEST_CASE("HELP at every kind of prompt, SHORT and LONG") {
  TempDir disk;
  auto r = run_commands(disk, std::string(R"(CHANGE
H
HELP SHORT
GRID
)") + R"(BUILD
H
HELP LONG
2 2
H S

H S

H S
1 1
DISPLAY
H S
INPUT
H S
ISOMETRIC
H S
3 30
STORE FILE
H S
NAME
CHANGE TANGENTS

H S
N
END
H S
CMS
)");
  CHECK(r.status == 0);
  // HELP alone at the very first session is LONG: the command's explanation.
  CHECK(r.out.find("GRID, TANGENTS, POINTS OR TWISTS? H\nCHANGE modifies the current surface") !=
        std::string::npos);
  CHECK(r.out.find("GRID, TANGENTS, POINTS OR TWISTS? HELP SHORT\nGRID: new numbers") !=
        std::string::npos);
  CHECK(r.out.find("NUMBER OF CURVES AND STRINGERS? H\nTwo whole numbers: NOCUR") !=
        std::string::npos);
  CHECK(r.out.find("NUMBER OF CURVES AND STRINGERS? HELP LONG\nBUILD defines a new current "
                   "surface") != std::string::npos);
  CHECK(r.out.find("POINTS? H S\nA point number k") != std::string::npos);
  CHECK(r.out.find("TANGENTS? H S\nA border point k") != std::string::npos);
  CHECK(r.out.find("INTERPOLATED CURVES AND STRINGERS? H S\nTwo whole numbers >= 0") !=
        std::string::npos);
  CHECK(r.out.find("FIRST, SECOND, FILE, INPUT, SURFACE, PICTURE, HIDDEN OR COMBS? H S\nINPUT, "
                   "SURFACE, HIDDEN") != std::string::npos);
  CHECK(r.out.find("PROJECTION? H S\nCONIC, ISOMETRIC") != std::string::npos);
  CHECK(r.out.find("AXIS AND ANGLE? H S\nThe axis to drop") != std::string::npos);
  CHECK(r.out.find("FILE NAME? H S\nA name for the image file") != std::string::npos);
  CHECK(r.out.find("CHANGE GRID TOO? (Y OR N) H S\nY to give new numbers") != std::string::npos);
  CHECK(r.out.find("APL OR CMS? H S\nAPL: look at") != std::string::npos);
  CHECK(r.out.find("\nINCORRECT") == std::string::npos);
  // HELP SHORT was the last setting: it is kept for the next session.
  auto next = run_commands(disk, "HELP\n");
  CHECK(next.out.find("HELP\nType a command: BUILD CHANGE") != std::string::npos);
}

TEST_CASE("END APL is APL: a point changed by indexed assignment, START, and the surface follows") {
  TempDir disk;
  auto r = run_commands(disk, std::string(saddle_build) +
                                  "END APL\n"
                                  "⍝ Raise the middle point and look at the grid's highest point.\n"
                                  "INPPN[5;3]←7\n"
                                  "∇Z←TOP A\n"
                                  "Z←⌈/,A[;;3]\n"
                                  "∇\n"
                                  "∇Z←COUNT A;I\n"
                                  "Z←I←0\n"
                                  "L:I←I+1\n"
                                  "Z←Z+A[I]>5\n"
                                  "→(I<⍴A)/L\n"
                                  "∇\n"
                                  "START\n"
                                  "DISPLAY SURFACE ORTHOGONAL XZ\n"
                                  "END APL\n"
                                  "⌈/,IMAGE[;;2]\n"
                                  "COUNT ,INTPN[;;3]\n"
                                  "+/,INTPN[;;3]>5\n"
                                  "TOP INTPN\n"
                                  "⍴FIT\n"
                                  "COMDIS 'SURFACE ORTHOGONAL XY'\n"
                                  "DESCR DESIM\n"
                                  "NOCUR←5\n"
                                  "START\n"
                                  "NOCUR←3\n"
                                  ")OFF\n");
  CHECK(r.status == 0);
  // START made INTPN again: its highest point is the raised one.
  CHECK(r.out.find("      TOP INTPN\n7\n") != std::string::npos);
  // DISPLAY drew the raised surface: the highest point of its XZ view is the raised one.
  CHECK(r.out.find("      ⌈/,IMAGE[;;2]\n7\n") != std::string::npos);
  // A function that loops over INTPN agrees with APL's own reduction.
  const auto loop = r.out.find("      COUNT ,INTPN[;;3]\n");
  const auto reduction = r.out.find("      +/,INTPN[;;3]>5\n");
  REQUIRE(loop != std::string::npos);
  REQUIRE(reduction != std::string::npos);
  const auto value_after = [&](std::size_t at) {
    const auto from = r.out.find('\n', at) + 1;
    return r.out.substr(from, r.out.find('\n', from) - from);
  };
  CHECK(value_after(loop) == value_after(reduction));
  CHECK(value_after(loop) != "0");
  const auto comdis = r.out.find("      COMDIS 'SURFACE ORTHOGONAL XY'\n");
  CHECK(r.out.find("IMAGE: SURFACE, ORTHOGONAL XY\n", comdis) != std::string::npos);
  CHECK(r.out.find("      DESCR DESIM\nIMAGE: SURFACE, ORTHOGONAL XY\n") != std::string::npos);
  CHECK(r.out.find("      START\nCANNOT START: INPPN IS 9 BY 3, NOT 15 BY 3\n") !=
        std::string::npos);
  // The change and the function are the session's: the next start has them.
  auto again = run_commands(disk, "END APL\nINPPN[5;3]\nTOP INTPN\n)FNS\n)OFF\n");
  CHECK(again.out.find("      INPPN[5;3]\n7\n") != std::string::npos);
  CHECK(again.out.find("      TOP INTPN\n7\n") != std::string::npos);
  CHECK(again.out.find(" TOP\n") != std::string::npos);
}

TEST_CASE("--strict stops at the first error report of a command file") {
  TempDir disk;
  auto r = run_commands(disk, "HELP SHORT\nBUILD NOW\nHELP SHORT\n", {"--strict"});
  CHECK(r.status == 3);
  CHECK(r.out.find("INCORRECT COMMAND OR PARAMETERS") != std::string::npos);
  CHECK(count(r.out, "Type a command") == 1);
  // An entry error counts too.
  auto entry = run_commands(disk, "BUILD\n1 1\n2 2\n\n\n0 0\nHELP\n", {"--strict"});
  CHECK(entry.status == 3);
  CHECK(entry.out.ends_with("INCORRECT ENTRY: A SURFACE NEEDS AT LEAST TWO POINTS\n"));
  // And an APL error.
  auto apl = run_commands(disk, "END APL\nNOSUCH\nSTART\nHELP SHORT\n", {"--strict"});
  CHECK(apl.status == 3);
  CHECK(apl.out.ends_with("VALUE ERROR\n      NOSUCH\n      ^\n"));
  // Without --strict everything runs and the status is 0.
  CHECK(run_commands(disk, "BUILD NOW\nHELP SHORT\n").status == 0);
}

TEST_CASE("standard input that is not a terminal is a command file; - continues with it") {
  TempDir disk, files;
  auto r = run_igds({"--term", "none", "--disk", disk.path().string()},
                    with_input("HELP SHORT\nEND CMS\nHELP SHORT\n"));
  CHECK(r.status == 0);
  CHECK(r.out ==
        "READY\nHELP SHORT\nType a command: BUILD CHANGE RESTORE DISPLAY PLOT STORE "
        "SAVE WRITE END HELP\nERASE EXPORT FIT PUNCH LIST UNDO REDO ZOOM IMPORT PICK.\nA first "
        "letter is enough (S is STORE); HELP LONG explains them all.\nREADY\nEND CMS\n");

  write_file(files.path() / "one.igds", "* first file\nHELP SHORT\n");
  auto chained = run_igds(
      {"--term", "none", "--disk", disk.path().string(), (files.path() / "one.igds").string(), "-"},
      with_input("END APL\nSTATUS\n"));
  CHECK(chained.status == 0);
  CHECK(chained.out.find("READY\nEND APL\n      STATUS\n0 0 0") != std::string::npos);

  // Without -, igds ends after the files and does not read standard input.
  auto alone = run_igds(
      {"--term", "none", "--disk", disk.path().string(), (files.path() / "one.igds").string()},
      with_input("END APL\n"));
  CHECK(alone.out.find("END APL") == std::string::npos);
}

TEST_CASE("the disk: --disk, else IGDS_DISK, else the current folder") {
  TempDir disk, other;
  auto r = run_igds({"--term", "none"}, with_input(std::string(saddle_build) + "SAVE HULL\n",
                                                   {{"IGDS_DISK", disk.path().string()}}));
  CHECK(r.status == 0);
  CHECK(std::filesystem::exists(disk.path() / "HULL.IGDSDATA"));
  CHECK(std::filesystem::exists(disk.path() / "BINSAVE.IGDSCONT"));
  auto here =
      run_igds({"--term", "none"}, with_input("HELP SHORT\n", {{"IGDS_DISK", ""}}, other.path()));
  CHECK(here.status == 0);
  CHECK(std::filesystem::exists(other.path() / "BINSAVE.IGDSCONT"));
}

TEST_CASE("exit statuses of the command line") {
  TempDir disk;
  auto unknown = run_igds({"--frobnicate"});
  CHECK(unknown.status == 2);
  CHECK(unknown.err.find("usage: igds") != std::string::npos);
  CHECK(unknown.out.empty());
  auto missing = run_igds({"--disk", disk.path().string(), "/nonexistent/x.igds"});
  CHECK(missing.status == 1);
  CHECK(missing.err.find("/nonexistent/x.igds") != std::string::npos);
  auto folder = run_igds({"--disk", disk.path().string(), disk.path().string()});
  CHECK(folder.status == 1);
  auto light_pen = run_igds({"2250"});
  CHECK(light_pen.status != 0);
  CHECK(light_pen.err.find("2250") != std::string::npos);
  auto bad_disk = run_igds({"--disk", "/nonexistent/disk"}, with_input("HELP\n"));
  CHECK(bad_disk.status == 1);
  CHECK_FALSE(bad_disk.err.empty());
  auto help = run_igds({"--help"});
  CHECK(help.status == 0);
  CHECK(help.out.starts_with("usage: igds"));
  auto version = run_igds({"--version"});
  CHECK(version.status == 0);
  CHECK(version.out.starts_with("igds "));
  auto device =
      run_igds({"4013", "--term", "none", "--disk", disk.path().string()}, with_input("END CMS\n"));
  CHECK(device.status == 0);
  CHECK(device.out == "READY\nEND CMS\n");
  // Output nobody can take: a full device, or a reader that leaves. igds ends, saves the
  // session, leaves no lock, and the status says it did not go as it should.
  if (std::filesystem::exists("/dev/full")) {
    auto full = run({"sh", "-c",
                     fmt::format("'{}' --term none --disk '{}' >/dev/full", igds_binary().string(),
                                 disk.path().string())},
                    with_input("CHANGE GRID 2 2\nHELP LONG\n"));
    CHECK(full.status == 1);
    CHECK(!std::filesystem::exists(disk.path() / "BINSAVE.IGDSLOCK"));
  }
  std::string many;
  for (int i = 0; i < 2000; ++i) many += "HELP LONG\n";
  write_file(disk.path() / "many.igds", many);
  auto cut = run({"bash", "-c",
                  fmt::format("'{}' --term none --disk '{}' '{}' | head -c 5; "
                              "exit ${{PIPESTATUS[0]}}",
                              igds_binary().string(), disk.path().string(),
                              (disk.path() / "many.igds").string())});
  CHECK(cut.out == "READY");
  CHECK(cut.status == 1);
  CHECK(!std::filesystem::exists(disk.path() / "BINSAVE.IGDSLOCK"));
}

TEST_CASE("tek mode: the output is what a 4013 receives") {
  TempDir disk, files;
  write_file(files.path() / "a.igds", std::string(saddle_build) + "DISPLAY SURFACE O XY\n");
  auto r = run_igds({"--disk", disk.path().string(), (files.path() / "a.igds").string()});
  CHECK(r.status == 0);
  // Standard output is not a terminal: tek mode, graph mode (GS) in the stream, no note.
  CHECK(r.out.find('\x1d') != std::string::npos);
  CHECK(r.out.find("NOT DRAWN") == std::string::npos);
  // The dialogue starts at the top left of the screen, without erasing it.
  const std::string home = TekScreen({}, true).begin();
  CHECK(r.out.starts_with(home + "READY"));
  CHECK(home.starts_with('\x1d'));
  CHECK(home.ends_with('\x1f'));
  // Every line is placed where it goes: no line end reaches the 4013 (a pty would add CR to LF).
  CHECK(r.out.find('\n') == std::string::npos);
  CHECK(r.out.find('\r') == std::string::npos);
  // A 4013 is a 7-bit terminal: APL characters reach it as strokes, the rest as text.
  write_file(files.path() / "apl.igds", "C P\n1 ¯1 0 0 ⍝ note\n\nN\nN\nE A\n⍴INPPN\n)OFF\n");
  auto apl = run_igds({"--disk", disk.path().string(), (files.path() / "apl.igds").string()});
  CHECK(apl.status == 0);
  CHECK(std::none_of(apl.out.begin(), apl.out.end(),
                     [](char c) { return static_cast<unsigned char>(c) >= 0x80; }));
  const TekDrawing d = test::decode_tek(apl.out);
  std::vector<std::string> texts;
  for (const auto& page : d.pages) {
    for (const auto& t : page.texts) texts.push_back(t.text);
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
  }
  auto shown = [&](std::string_view text) {
    return std::find(texts.begin(), texts.end(), text) != texts.end();
  };
  CHECK(shown("POINTS? 1 "));  // then the high minus, drawn
  CHECK(shown("1 0 0 "));      // then the lamp
  CHECK(shown(" note"));
  CHECK(shown("INPPN"));
  CHECK(shown("9 3"));
  auto none = run_commands(disk, "D SU O XY\nD SU O YZ\n");
  CHECK(none.out.find('\x1d') == std::string::npos);
  CHECK(count(none.out, "NOT DRAWN") == 1);
}

}  // namespace igds::test
