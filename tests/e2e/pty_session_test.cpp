// igds at a terminal (a pseudo-terminal): Readline, abbreviations, HELP at an entry prompt,
// INCORRECT ENTRY, Ctrl-C in the middle of BUILD, completion, the disk's lock, Ctrl-D, and the
// session and history coming back at the next start.
#include <doctest/doctest.h>

#include "tests/e2e/e2e_support.h"
#include "tests/support/process.h"
#include "tests/support/pty.h"

namespace igds::test {

namespace {

std::map<std::string, std::string> terminal_env(const TempDir& home) {
  return {{"TERM", "dumb"},
          {"INPUTRC", "/dev/null"},
          {"HOME", home.path().string()},
          {"XTERM_VERSION", ""},
          {"IGDS_DISK", ""}};
}

}  // namespace

TEST_CASE("an interactive session through a pseudo-terminal") {
  TempDir disk, home;
  const std::vector<std::string> argv{igds_binary().string(), "--term", "none", "--disk",
                                      disk.path().string()};
  {
    PtySession igds(argv, terminal_env(home));
    REQUIRE(igds.expect("READY"));
    igds.send("b\r");  // BUILD
    REQUIRE(igds.expect("NUMBER OF CURVES AND STRINGERS?"));
    igds.send("2 2\r");
    REQUIRE(igds.expect("POINTS?"));
    igds.send("h s\r");  // HELP SHORT at a point entry, then the same prompt again
    REQUIRE(igds.expect("A point number k and x y z"));
    REQUIRE(igds.expect("POINTS?"));
    igds.send("1 0 0\r");
    REQUIRE(igds.expect("INCORRECT ENTRY"));
    REQUIRE(igds.expect("POINTS?"));
    igds.send("1 0 0 0  0 10 0  10 0 0  10 10 5\r");
    REQUIRE(igds.expect("POINTS?"));
    igds.send("\r");
    REQUIRE(igds.expect("TANGENTS?"));
    igds.send("\r");
    REQUIRE(igds.expect("INTERPOLATED CURVES AND STRINGERS?"));
    igds.send("3 3\r");
    REQUIRE(igds.expect("READY"));

    // Ctrl-C in the middle of a second BUILD: the first surface stays.
    igds.send("BU\r");
    REQUIRE(igds.expect("NUMBER OF CURVES AND STRINGERS?"));
    igds.send("4 4\r");
    REQUIRE(igds.expect("POINTS?"));
    igds.send("1 1 1 1");
    igds.send("\x03");
    if (!igds.expect("READY")) FAIL(igds.output() << "\nstatus " << igds.wait(1));

    // TAB completes commands and options.
    igds.send("DI\tSU\tO XY\r");
    REQUIRE(igds.expect("DISPLAY SURFACE O XY"));
    REQUIRE(igds.expect("IMAGE: SURFACE, ORTHOGONAL XY"));
    REQUIRE(igds.expect("READY"));

    // Only one igds per disk.
    auto second =
        run_igds({"--term", "none", "--disk", disk.path().string()}, with_input("END CMS\n"));
    CHECK(second.status == 1);
    CHECK_FALSE(second.err.empty());

    igds.send("e c\r");  // END CMS
    CHECK(igds.wait() == 0);
  }
  {
    PtySession igds(argv, terminal_env(home));
    REQUIRE(igds.expect("READY"));
    // The history of the first session is there: Ctrl-P brings back its last line.
    igds.send("\x10");
    CHECK(igds.expect("e c"));
    igds.send("\x15");  // Ctrl-U: forget it
    igds.send("END APL\r");
    REQUIRE(igds.expect("      "));
    igds.send("NOCUR\r");
    CHECK(igds.expect("\n2\r\n"));
    igds.send("\xE2\x8D\xB4INTPN\r");  // ⍴INTPN
    CHECK(igds.expect("\n5 5 3\r\n"));
    // Without an APL keyboard: ` then r is ⍴, ` then - is ×.
    igds.send("`r`rINTPN\r");
    CHECK(igds.expect("\n3\r\n"));
    igds.send("NOCUR`-NOSTR\r");
    CHECK(igds.expect("\n4\r\n"));
    igds.send("START\r");
    REQUIRE(igds.expect("READY"));
    igds.send("\x04");  // Ctrl-D at READY is END
    CHECK(igds.wait() == 0);
  }
  const std::string history = read_file(disk.path() / "HISTORY.IGDSHIST");
  CHECK(history.find("1 0 0 0  0 10 0  10 0 0  10 10 5") != std::string::npos);
  CHECK(history.find("END APL") != std::string::npos);
}

TEST_CASE("Ctrl-D in the middle of a command abandons it and ends the session") {
  TempDir disk, home;
  PtySession igds({igds_binary().string(), "--term", "none", "--disk", disk.path().string()},
                  terminal_env(home));
  REQUIRE(igds.expect("READY"));
  igds.send("BUILD\r");
  REQUIRE(igds.expect("NUMBER OF CURVES AND STRINGERS?"));
  igds.send("\x04");
  CHECK(igds.expect("END OF INPUT: BUILD ABANDONED"));
  CHECK(igds.wait() == 0);
}

}  // namespace igds::test

namespace igds::test {

TEST_CASE("Ctrl-C while END APL computes: INTERRUPT, the function suspended, the workspace kept") {
  TempDir disk, home;
  PtySession igds({igds_binary().string(), "--term", "none", "--disk", disk.path().string()},
                  terminal_env(home));
  REQUIRE(igds.expect("READY"));
  igds.send("END APL\r");
  REQUIRE(igds.expect("      "));
  // Each function says when it has begun: Ctrl-C is sent then, never while the line is still
  // being read (where it would only abandon the line).
  igds.send("\xE2\x88\x87LOOP\r");  // ∇LOOP
  REQUIRE(igds.expect("[1] "));
  igds.send("'LOOPING'\r");
  REQUIRE(igds.expect("[2] "));
  igds.send("L:\xE2\x86\x92L\xE2\x88\x87\r");  // L:→L∇
  REQUIRE(igds.expect("\n      "));
  igds.send(
      "X\xE2\x86\x90"
      "42\r");  // X←42
  REQUIRE(igds.expect("\n      "));
  igds.send("LOOP\r");
  REQUIRE(igds.expect("LOOPING"));
  igds.send("\x03");
  REQUIRE(igds.expect("INTERRUPT"));
  REQUIRE(igds.expect("LOOP[2] L:"));
  igds.send(")SI\r");
  CHECK(igds.expect("LOOP[2] *"));
  // A long product, stopped between its blocks.
  igds.send("\xE2\x88\x87P;A\r");  // ∇P;A
  REQUIRE(igds.expect("[1] "));
  igds.send(
      "A\xE2\x86\x90"
      "2500 2500\xE2\x8D\xB4\xE2\x8D\xB3"
      "7\r");  // A←2500 2500⍴⍳7
  REQUIRE(igds.expect("[2] "));
  igds.send("'MULTIPLYING'\r");
  REQUIRE(igds.expect("[3] "));
  igds.send(
      "A\xE2\x86\x90"
      "A+.\xC3\x97"
      "A\xE2\x88\x87\r");  // A←A+.×A∇
  REQUIRE(igds.expect("\n      "));
  igds.send("P\r");
  REQUIRE(igds.expect("MULTIPLYING"));
  igds.send("\x03");
  REQUIRE(igds.expect("INTERRUPT"));
  REQUIRE(igds.expect("P[3] A"));
  igds.send("X\r");
  CHECK(igds.expect("\n42\r\n"));
  igds.send(")OFF\r");
  CHECK(igds.wait() == 0);
}

}  // namespace igds::test
