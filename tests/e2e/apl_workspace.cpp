// END APL's own workspace through a real igds: the user's variables and functions survive a new
// start on the same disk, and )SAVE )CLEAR )LOAD )COPY act on them with the surface.
#include <doctest/doctest.h>

#include <signal.h>

#include <filesystem>
#include <string>

#include "tests/e2e/e2e_support.h"
#include "tests/support/pty.h"
#include "workspace/disk/frame.h"

namespace igds::test {

namespace {

// The transcript holds `lines` one after the other.
bool shows(const std::string& out, std::string_view lines) {
  return out.find(lines) != std::string::npos;
}

}  // namespace

TEST_CASE("END APL: the user's variables and functions are there after a new start") {
  TempDir disk;
  auto first = run_commands(disk, std::string(saddle_build) + R"(END APL
V←2 3⍴⍳6
T←'HELLO ⍴'
E←0 3⍴0
∇Z←DOUBLE X
Z←2×X
∇
)OFF
)");
  REQUIRE(first.status == 0);
  auto second = run_commands(disk, "END APL\nV\nT\n⍴E\nDOUBLE V\n)VARS\n)FNS\n)OFF\n");
  CHECK(second.status == 0);
  CHECK(second.err == "");
  CHECK(shows(second.out, R"(READY
END APL
      V
1 2 3
4 5 6
      T
HELLO ⍴
      ⍴E
0 3
      DOUBLE V
2  4  6
8 10 12
      )VARS
E T V
IGDS: INPPN INPTG INTCU INTPN INTST NOCUR NOSTR PATCHES STATUS
      )FNS
DOUBLE
IGDS: )"));

  // Erased, they stay erased.
  REQUIRE(run_commands(disk, "END APL\n)ERASE V DOUBLE\n)OFF\n").status == 0);
  auto third = run_commands(disk, "END APL\n)VARS\n)FNS\n)OFF\n");
  CHECK(shows(third.out, "      )VARS\nE T\nIGDS: "));
  CHECK(shows(third.out, "      )FNS\nIGDS: "));
}

TEST_CASE("END APL: what a line defined is on the disk when igds is killed after it") {
  TempDir disk, home;
  {
    PtySession igds({igds_binary().string(), "--term", "none", "--disk", disk.path().string()},
                    {{"TERM", "dumb"},
                     {"INPUTRC", "/dev/null"},
                     {"HOME", home.path().string()},
                     {"IGDS_DISK", ""}});
    REQUIRE(igds.expect("READY"));
    igds.send("END APL\r");
    igds.send(
        "V\xE2\x86\x90\xE2\x8D\xB3"
        "3\r");  // V←⍳3
    igds.send(
        "\xE2\x88\x87Z\xE2\x86\x90"
        "F X\r");                                 // ∇Z←F X
    igds.send("Z\xE2\x86\x90X+V\xE2\x88\x87\r");  // Z←X+V∇
    // The lines are read one after the other: this one's answer comes after the others' saves.
    igds.send("'DONE'\r");
    REQUIRE(igds.expect("DONE\r\n"));
    ::kill(igds.pid(), SIGKILL);
    igds.wait();
  }
  auto after = run_commands(disk, "END APL\nF 10\n)OFF\n");
  CHECK(shows(after.out, "      F 10\n11 12 13\n"));
}

TEST_CASE("END APL: )SAVE, )CLEAR, )LOAD and )COPY on the whole APL workspace") {
  TempDir disk;
  auto r = run_commands(disk, std::string(saddle_build) + R"(END APL
V←2 3⍴⍳6
T←'HELLO'
∇Z←DOUBLE X
Z←2×X
∇
)SAVE WS1
)CLEAR
)VARS
V←7
INPPN[1;1]←99
)LOAD WS1
V
INPPN[1;1]
START
END APL
INPPN[1;1]
V←0
T←1
)ERASE DOUBLE
)COPY WS1 T DOUBLE NOPE
V
T
DOUBLE 1
)COPY WS9
)LOAD WS9
)OFF
)");
  CHECK(r.status == 0);
  CHECK(r.err == "");
  CHECK(shows(r.out, R"(
      )SAVE WS1
SAVED WS1
      )CLEAR
CLEAR WS
      )VARS
IGDS: INPPN INPTG INTCU INTPN INTST NOCUR NOSTR PATCHES STATUS
      V←7
      INPPN[1;1]←99
      )LOAD WS1
NOCUR 3 NOSTR 3 INTCU 2 INTST 2
LOADED WS1
      V
1 2 3
4 5 6
      INPPN[1;1]
0
      START
READY
END APL
      INPPN[1;1]
0
      V←0
      T←1
      )ERASE DOUBLE
      )COPY WS1 T DOUBLE NOPE
NOT FOUND: NOPE
COPIED WS1
      V
0
      T
HELLO
      DOUBLE 1
2
      )COPY WS9
FILE NOT FOUND
      )LOAD WS9
FILE NOT FOUND
      )OFF
)"));
  for (const char* file : {"WS1.IGDSAPLW", "WS1.IGDSDATA"})
    CHECK(std::filesystem::is_regular_file(disk.path() / file));

  // What )LOAD and )COPY put in the session is there at the next start.
  auto again = run_commands(disk, "END APL\nV\nT\nDOUBLE 2\n)OFF\n");
  CHECK(shows(again.out, "      V\n0\n      T\nHELLO\n      DOUBLE 2\n4\n"));

  // A damaged WS1.IGDSAPLW changes nothing, surface included.
  std::string bytes = read_file(disk.path() / "WS1.IGDSAPLW");
  bytes[disk::frame_header_bytes] ^= 1;
  std::filesystem::remove(disk.path() / "WS1.IGDSAPLW");
  write_file(disk.path() / "WS1.IGDSAPLW", bytes);
  auto damaged = run_commands(disk,
                              "END APL\nINPPN[1;1]←5\n)LOAD WS1\nV\nSTART\nEND APL\n"
                              "INPPN[1;1]\n)OFF\n");
  CHECK(shows(damaged.out, R"(      )LOAD WS1
FILE DAMAGED: WS1.IGDSAPLW (CHECKSUM); NOTHING LOADED
      V
0
      START
READY
END APL
      INPPN[1;1]
5
)"));
}

}  // namespace igds::test
