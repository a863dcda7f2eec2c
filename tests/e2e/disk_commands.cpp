// RESTORE, SAVE and WRITE with the real binary (manual 4.3, 4.6, 4.7; docs/disk.md): the
// dialogue, every report, and what reaches the disk.
#include <doctest/doctest.h>

#include <filesystem>
#include <regex>

#include <fmt/format.h>

#include "commands/command.h"
#include "tests/support/fake_context.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/small_disk.h"
#include "workspace/disk/session.h"
#include "workspace/error.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

const char* const build_3x3 =
    "BUILD\n3 3\n1 0 0 0 1 0 1 2 0 2\n4 0 1 0 1 1 1 2 1 1\n7 0 2 0 1 2 0 2 2 0\n\n1 1 0 0 1\n\n"
    "1 1\n";

// Runs igds on `disk` with `commands` as its command file.
test::RunResult igds_on(const fs::path& disk, const std::string& commands) {
  test::TempDir files;
  test::write_file(files.path() / "commands.igds", commands);
  return test::run_igds(
      {"--disk", disk.string(), "--term", "none", (files.path() / "commands.igds").string()});
}

Workspace session_on(const fs::path& dir, std::vector<std::string>* notices = nullptr) {
  Disk disk(dir);
  Session session(disk);
  Workspace ws = session.load();
  if (notices) *notices = session.notices();
  return ws;
}

bool has(const std::string& out, const std::string& part) {
  return out.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("RESTORE, SAVE, WRITE: the dialogue and the reports") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir disk;

  SUBCASE("no surface: INPUT NOT FOUND before any name is asked") {
    auto r = igds_on(disk.path(), "SAVE\nSA HULL\nWRITE\nWRITE HULL\n");
    CHECK(r.out ==
          "READY\nSAVE\nINPUT NOT FOUND\nREADY\nSA HULL\nINPUT NOT FOUND\nREADY\nWRITE\nINPUT NOT "
          "FOUND\nREADY\nWRITE HULL\nINPUT NOT FOUND\nREADY\n");
  }
  SUBCASE("names that are not CMS names, and files that are not there") {
    auto r = igds_on(disk.path(),
                     "RESTORE ../X\nRESTORE /tmp/X\nRESTORE A.B\nRESTORE TOOLONGNAME\nRESTORE "
                     "CAF\xc3\xa9\nRESTORE A B\nRESTORE\n\nNONE\n");
    const std::string bad = "INCORRECT PARAMETER: A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - _";
    CHECK(r.out == "READY\nRESTORE ../X\n" + bad + "\nREADY\nRESTORE /tmp/X\n" + bad +
                       "\nREADY\nRESTORE A.B\n" + bad + "\nREADY\nRESTORE TOOLONGNAME\n" + bad +
                       "\nREADY\nRESTORE CAF\xc3\xa9\n" + bad + "\nREADY\nRESTORE A B\n" + bad +
                       "\nREADY\nRESTORE\nFILE NAME?\nFILE NAME? NONE\nFILE NOT FOUND\nREADY\n");
    // Typed at the question, a bad name is asked for again; on the command line it ends the
    // command.
    auto s = igds_on(disk.path(), std::string(build_3x3) + "SAVE ../X\nWRITE\nA.B\nOK\n");
    CHECK(has(s.out, "SAVE ../X\n" + bad + "\nREADY\n"));
    CHECK(has(s.out, "WRITE\nFILE NAME? A.B\n" + bad + "\nFILE NAME? OK\nREADY\n"));
    for (const auto& e : fs::directory_iterator(disk.path())) {
      std::string name = e.path().filename().string();
      CHECK((name == "BINSAVE.IGDSCONT" || name.ends_with(".IGDSVARS") || name == "OK.IGDSCHAR"));
    }
  }
}

TEST_CASE("SAVE then RESTORE with the binary: the surface back, images and STATUS kept") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir disk;
  auto r = igds_on(disk.path(), std::string(build_3x3) + "SAVE hull\nWRITE\nhull\n");
  CHECK(has(r.out, "SAVE hull\nREADY\nWRITE\nFILE NAME? hull\nREADY\n"));
  CHECK(fs::exists(disk.path() / "HULL.IGDSDATA"));
  CHECK(fs::exists(disk.path() / "HULL.IGDSCHAR"));
  Workspace saved = session_on(disk.path());

  auto c = igds_on(disk.path(),
                   "CHANGE GRID 4 2\nDISPLAY SURFACE ORTHOGONAL XY\nSTORE FIRST\n"
                   "HELP SHORT\n");
  CHECK(c.status == 0);
  Workspace changed = session_on(disk.path());
  REQUIRE(changed.intcu == 4);
  REQUIRE(changed.image);

  auto back = igds_on(disk.path(), "RESTORE\nHULL\n");
  CHECK(back.out == "READY\nRESTORE\nFILE NAME? HULL\nNOCUR 3 NOSTR 3 INTCU 1 INTST 1\nREADY\n");
  Workspace restored = session_on(disk.path());
  test::check_same_surface(restored, saved);
  CHECK(test::same_bits(restored.image, changed.image));
  CHECK(test::same_bits(restored.temp1, changed.temp1));
  CHECK(restored.status == changed.status);
}

TEST_CASE("WRITE says how many values did not fit F10.3, and the file agrees") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir disk;
  auto r =
      igds_on(disk.path(), "BUILD\n2 2\n1 0 0 0 0 1 0 1 0 0 1 1 12345678\n\n\n1 1\nWRITE BIG\n");
  std::smatch m;
  REQUIRE(std::regex_search(r.out, m,
                            std::regex("\n([0-9]+) VALUES DO NOT FIT F10.3: WRITTEN AS "
                                       "\\*\\*\\*\\*\\*\\*\\*\\*\\*\\*\nREADY\n")));
  std::string text = test::read_file(disk.path() / "BIG.IGDSCHAR");
  std::size_t stars = 0;
  for (std::size_t at = text.find("**********"); at != std::string::npos;
       at = text.find("**********", at + 10))
    ++stars;
  CHECK(std::to_string(stars) == m[1].str());
  CHECK(stars >= 2);  // INPPN and INTPN hold the point itself
}

TEST_CASE("a damaged file is reported word for word and the surface is kept") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir disk;
  igds_on(disk.path(), std::string(build_3x3) + "SAVE HULL\nCHANGE GRID 2 2\n");
  std::string good = test::read_file(disk.path() / "HULL.IGDSDATA");
  std::string bad = good;
  bad[bad.size() - 30] ^= 1;
  test::rewrite_file(disk.path() / "HULL.IGDSDATA", bad);
  Workspace before = session_on(disk.path());
  auto r = igds_on(disk.path(), "RESTORE HULL\nRESTORE\nHULL\n");
  CHECK(r.out ==
        "READY\nRESTORE HULL\nFILE DAMAGED: HULL.IGDSDATA (CHECKSUM); CURRENT SURFACE KEPT\n"
        "READY\nRESTORE\nFILE NAME? HULL\nFILE DAMAGED: HULL.IGDSDATA (CHECKSUM); CURRENT "
        "SURFACE KEPT\nREADY\n");
  test::check_same_workspace(session_on(disk.path()), before);
  test::rewrite_file(disk.path() / "HULL.IGDSDATA", good.substr(0, good.size() / 2));
  CHECK(has(igds_on(disk.path(), "RESTORE HULL\n").out,
            "FILE DAMAGED: HULL.IGDSDATA (TRUNCATED); CURRENT SURFACE KEPT\n"));
}

TEST_CASE("a damaged session at start: said before READY, kept aside, igds goes on") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir disk;
  igds_on(disk.path(), build_3x3);
  std::string good = test::read_file(disk.path() / "BINSAVE.IGDSCONT");
  test::rewrite_file(disk.path() / "BINSAVE.IGDSCONT", good.substr(0, good.size() - 3));
  auto r = igds_on(disk.path(), "SAVE HULL\n");
  CHECK(r.status == 0);
  CHECK(r.out ==
        "SESSION FILE BINSAVE.IGDSCONT DAMAGED (TRUNCATED): KEPT AS BINSAVE.IGDSBAD; THE "
        "WORKSPACE STARTS EMPTY\nREADY\nSAVE HULL\nINPUT NOT FOUND\nREADY\n");
  CHECK(test::read_file(disk.path() / "BINSAVE.IGDSBAD") == good.substr(0, good.size() - 3));
  // The next start is quiet again.
  CHECK(igds_on(disk.path(), "").out == "READY\n");
}

TEST_CASE("a disk that fills up: the command's report, and the last session kept") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir scratch;
  test::SmallDisk small(scratch.path() / "disk", 96);
  IGDS_SKIP_UNLESS(small.mounted(), "cannot mount a tmpfs here (root can)");
  igds_on(small.path(), build_3x3);
  Workspace before = session_on(small.path());
  // A grid made finer is not stored (the session and SAVE make it again from the inputs): the
  // session and HULL.IGDSDATA fit. Then a BUILD of 4900 points (118 KB of inputs) cannot be
  // saved, in the session or by SAVE.
  std::string commands = "CHANGE GRID 40 40\nSAVE HULL\nBUILD\n70 70\n";
  for (int k = 1; k <= 4900; ++k) commands += fmt::format("{} {} {} 0\n", k, k % 70, k / 70);
  commands += "\n\n0 0\nSAVE BIG\n";
  auto r = igds_on(small.path(), commands);
  CHECK(has(r.out, "CHANGE GRID 40 40\nREADY\nSAVE HULL\nREADY\n"));
  CHECK(has(r.out,
            "CANNOT SAVE THE SESSION IN BINSAVE.IGDSCONT (NO SPACE LEFT ON DEVICE); THE LAST "
            "SAVED SESSION IS KEPT\nREADY\n"));
  CHECK(has(r.out,
            "SAVE BIG\nCANNOT WRITE BIG.IGDSDATA (NO SPACE LEFT ON DEVICE); NO FILE CHANGED\n"));
  CHECK(fs::exists(small.path() / "HULL.IGDSDATA"));
  CHECK(!fs::exists(small.path() / "BIG.IGDSDATA"));
  before.intcu = before.intst = 40;
  before.intpn = session_on(small.path()).intpn;
  test::check_same_workspace(session_on(small.path()), before);
  for (const auto& e : fs::directory_iterator(small.path()))
    CHECK(!e.path().filename().string().ends_with(".IGDSTEMP"));
}

TEST_CASE("a disk that is not there") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir scratch;
  auto r = test::run_igds({"--disk", (scratch.path() / "none").string(), "--term", "none"});
  CHECK(r.status == 1);
  CHECK(r.err == fmt::format("DISK {} NOT FOUND\n", (scratch.path() / "none").string()));
  CHECK(fs::is_empty(scratch.path()));
}

namespace igds {
extern const Command restore_command, save_command, write_command;
}  // namespace igds

TEST_CASE("the commands through the Context alone") {
  test::TempDir dir;
  Disk disk(dir.path());
  Workspace ws = test::make_workspace(2, 2, 1, 0, false);
  for (double& v : ws.inppn.ravel) v = 1;
  for (double& v : ws.inptg.ravel) v = 1;
  for (double& v : ws.patches.ravel) v = 1;
  for (double& v : ws.intpn.ravel) v = 1;
  ws.intpn.ravel[4] = -123456.5;  // the only value too wide for F10.3

  test::FakeContext write(dir.path(), ws);
  write.type({"", "one"});
  write.run(write_command, "");
  CHECK(write.prompts == std::vector<std::string>{"FILE NAME?", "FILE NAME?"});
  CHECK(write.said ==
        std::vector<std::string>{"1 VALUE DOES NOT FIT F10.3: WRITTEN AS **********"});
  CHECK(fs::exists(dir.path() / "ONE.IGDSCHAR"));

  test::FakeContext save(dir.path(), ws);
  save.type({"keep"});
  save.run(save_command, "");
  CHECK(save.said.empty());

  test::FakeContext restore(dir.path());
  restore.type({"KEEP"});
  restore.run(restore_command, "");
  CHECK(restore.said == std::vector<std::string>{"NOCUR 2 NOSTR 2 INTCU 1 INTST 0"});
  test::check_same_surface(restore.workspace(), ws);

  // A bad name typed at the question: the reason, and the question again.
  test::FakeContext two(dir.path(), ws);
  two.type({"A B", "ok"});
  two.run(save_command, "");
  CHECK(two.said == std::vector<std::string>{
                        "INCORRECT PARAMETER: A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - _"});
  CHECK(fs::exists(dir.path() / "OK.IGDSDATA"));
  // On the command line: the report ends the command.
  test::FakeContext line(dir.path(), ws);
  CHECK_THROWS_WITH_AS(line.run(save_command, "", {"A.B"}),
                       "INCORRECT PARAMETER: A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - _",
                       Error);
  test::FakeContext empty(dir.path());
  empty.type({"X"});
  CHECK_THROWS_WITH_AS(empty.run(write_command, ""), "INPUT NOT FOUND", Report);
  CHECK(empty.prompts.empty());
  // Ctrl-D at the prompt: the command ends, nothing written.
  test::FakeContext ended(dir.path(), ws);
  CHECK_THROWS_AS(ended.run(save_command, ""), EndOfInput);
  CHECK(!save_command.long_help.empty());
}
