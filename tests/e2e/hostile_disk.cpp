// The real igds on a disk where someone put things in its way: a link at the name of its history,
// a FIFO there or as the plotter. Nothing outside the disk is written, nothing holds the
// conversation.
#include <doctest/doctest.h>
#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <string>

#include <fmt/format.h>

#include "tests/e2e/e2e_support.h"
#include "tests/support/process.h"
#include "tests/support/pty.h"

namespace igds::test {

namespace {

namespace fs = std::filesystem;

std::map<std::string, std::string> terminal_env(const TempDir& home) {
  return {{"TERM", "dumb"},
          {"INPUTRC", "/dev/null"},
          {"HOME", home.path().string()},
          {"XTERM_VERSION", ""},
          {"IGDS_DISK", ""}};
}

// igds at a terminal on `disk`: HELP typed, then END CMS; its exit status.
int type_help_and_end(const TempDir& disk, const TempDir& home) {
  PtySession igds({igds_binary().string(), "--term", "none", "--disk", disk.path().string()},
                  terminal_env(home));
  if (!igds.expect("READY")) {
    FAIL_CHECK("no READY: " << igds.output());
    return -1;
  }
  igds.send("HELP\r");
  CHECK(igds.expect("READY"));
  igds.send("e c\r");
  return igds.wait();
}

}  // namespace

TEST_CASE("the history is never written through a link at its name") {
  TempDir disk, home, elsewhere;
  const fs::path history = disk.path() / "HISTORY.IGDSHIST";
  SUBCASE("a link to someone's file") {
    const fs::path file = elsewhere.path() / "notes";
    write_file(file, "someone's notes\n");
    fs::create_symlink(file, history);
    CHECK(type_help_and_end(disk, home) == 0);
    CHECK(read_file(file) == "someone's notes\n");
    CHECK(fs::is_symlink(history));
  }
  SUBCASE("a link to nothing yet") {
    const fs::path made = elsewhere.path() / "made";
    fs::create_symlink(made, history);
    CHECK(type_help_and_end(disk, home) == 0);
    CHECK(!fs::exists(made));
    CHECK(fs::is_empty(elsewhere.path()));
  }
  SUBCASE("igds's own file: kept, and read back at the next start") {
    CHECK(type_help_and_end(disk, home) == 0);
    CHECK(fs::is_regular_file(fs::symlink_status(history)));
    CHECK(read_file(history) == "HELP\ne c\n");
  }
}

TEST_CASE("a FIFO at the name of the history holds nothing") {
  TempDir disk, home;
  const fs::path history = disk.path() / "HISTORY.IGDSHIST";
  REQUIRE(::mkfifo(history.c_str(), 0600) == 0);
  CHECK(type_help_and_end(disk, home) == 0);
  struct stat st;
  REQUIRE(::lstat(history.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
}

TEST_CASE("PLOT to a plotter FIFO without a reader: said, and READY") {
  TempDir disk, elsewhere;
  const fs::path fifo = elsewhere.path() / "plotter";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const RunResult r = run_commands(
      disk, std::string(saddle_build) + "DISPLAY SURFACE ORTHOGONAL XY\nPLOT SELECTRIC\nEND CMS\n",
      {"--plotter", fifo.string()});
  CHECK(r.status == 0);  // a report is no failure of the session
  CHECK(r.out.find(fmt::format("PLOTTER {} DOES NOT ANSWER; NOTHING PLOTTED\nREADY",
                               fifo.string())) != std::string::npos);
}

}  // namespace igds::test
