// Ctrl-C (SIGINT) as a returning user meets it, in the program that ships: igds started on a disk
// that holds a surface, in every terminal mode, at READY, at a question, during a long command
// and at a cross-hair question, goes on at READY with the session as it was; a command file
// stopped by Ctrl-C ends with the session saved and the disk's lock given back; and no thread of
// igds can ever receive SIGINT (docs/interp.md, "Ctrl-C and Ctrl-D").
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "tests/e2e/e2e_support.h"
#include "tests/support/pty.h"
#include "tests/support/tek_terminal.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/live_igds.h"
#include "workspace/disk/disk.h"

namespace igds::test {

namespace {

namespace fs = std::filesystem;

// The threads of process `pid` now, and how many of them do not block SIGINT
// (/proc/PID/task/TID/status, SigBlk: bit SIGINT - 1). Before main's first line (between fork
// and exec, in the loader) the process is not yet igds's: nothing is counted then.
struct Threads {
  int seen = 0, receiving = 0;
};
// Whether the thread whose status file this is blocks SIGINT; a thread that has ended (its file
// gone, or read as it went, or its state dead or zombie: the kernel then shows no signal blocked)
// is not counted.
bool blocks_interrupts(const fs::path& status_file) {
  std::ifstream status(status_file);
  for (std::string line; std::getline(status, line);) {
    if (line.starts_with("State:") && line.find_first_of("XZ", 6) != std::string::npos) return true;
    if (line.starts_with("SigBlk:"))
      return std::stoull(line.substr(7), nullptr, 16) & (1ull << (SIGINT - 1));
  }
  return true;
}
Threads threads_of(pid_t pid) {
  Threads t;
  const fs::path tasks = fs::path("/proc") / std::to_string(pid) / "task";
  if (!blocks_interrupts(tasks / std::to_string(pid) / "status")) return t;
  std::error_code ec;
  for (const auto& task : fs::directory_iterator(tasks, ec)) {
    ++t.seen;
    if (!blocks_interrupts(task.path() / "status")) ++t.receiving;
  }
  return t;
}

// A returning user's disk: a session whose surface (a 100 x 100 grid interpolated 9 x 9, about a
// million points) and image igds makes again at start, and that grid as BIG.IGDSDATA.
struct ReturningDisk {
  TempDir disk;
  ReturningDisk() {
    save_surface(Disk(disk.path()), "BIG", make_interpolated(100, 100, 0, 0));
    const auto made = run_commands(disk,
                                   "RESTORE BIG\nCHANGE GRID\n9 9\n"
                                   "DISPLAY SURFACE ASSONOMETRIC 110 130 120\nEND CMS\n");
    REQUIRE(made.status == 0);
  }
  fs::path path(const std::string& file) const { return disk.path() / file; }
};

std::map<std::string, std::string> terminal_env(const TempDir& home, const char* term) {
  return {{"TERM", term},
          {"INPUTRC", "/dev/null"},
          {"HOME", home.path().string()},
          {"XTERM_VERSION", ""},
          {"IGDS_DISK", ""}};
}

// Waits (a minute at most) until `file` exists, looking at the threads of `pid` meanwhile.
bool appears(const fs::path& file, pid_t pid, Threads& most) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!fs::exists(file)) {
    const Threads t = threads_of(pid);
    most.seen = std::max(most.seen, t.seen);
    most.receiving = std::max(most.receiving, t.receiving);
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::yield();
  }
  return true;
}

}  // namespace

TEST_CASE("Ctrl-C on a returning user's disk, in every terminal mode: READY, the session kept") {
  const ReturningDisk disk;
  const fs::path duct = disk.path("BIG.DUCTPIC"), writing = disk.path("BIG.DUCTPIC.IGDSTEMP");
  for (const char* mode : {"none", "xterm", "tek"}) {
    CAPTURE(mode);
    TempDir home;
    // A terminal that answers as xterm's Tek window does (the tek mode's cross-hair).
    // At the lowest priority, so that on a busy machine the Ctrl-C during EXPORT still comes
    // while the file is being written.
    XtermPty term({"/usr/bin/nice", "-n", "19", igds_binary().string(), "--term", mode, "--disk",
                   disk.disk.path().string()},
                  terminal_env(home, std::string_view(mode) == "tek" ? "tek4014" : "xterm"));
    PtySession& igds = term.pty();
    REQUIRE(term.expect("READY", 60));
    CHECK(threads_of(igds.pid()).receiving == 0);

    igds.send("\x03");  // at READY
    REQUIRE(term.expect("READY"));
    igds.send("CHANGE GRID\r");  // at a question
    REQUIRE(term.expect("INTERPOLATED CURVES AND STRINGERS?"));
    igds.send("\x03");
    REQUIRE(term.expect("READY"));

    // During a long command, once its file is being written: abandoned, no file left. The
    // threads that make the file's text are looked at while it is written: none receives SIGINT.
    Threads during;
    igds.send("EXPORT DUCT BIG\r");
    REQUIRE(appears(writing, igds.pid(), during));
    igds.send("\x03");
    if (!term.expect("INTERRUPTED: EXPORT ABANDONED", 60)) FAIL(igds.output());
    REQUIRE(term.expect("READY"));
    CHECK(!fs::exists(duct));
    CHECK(!fs::exists(writing));
    CHECK(during.receiving == 0);
    CHECK(threads_of(igds.pid()).receiving == 0);

    if (std::string_view(mode) != "none") {
      // At a cross-hair question (GIN mode in the Tek window).
      igds.send("ZOOM PICK\r");
      REQUIRE(term.expect("FIRST CORNER?"));
      if (std::string_view(mode) == "tek") {
        // Ctrl-C with the cross-hair up: xterm reports it as the key pressed, the tty makes it
        // a signal and leaves the rest of the report; GIN mode is left and nothing of the
        // report runs as a command.
        REQUIRE(term.expect_gin());
        term.type("\x03");
        REQUIRE(term.expect("READY"));
        CHECK_FALSE(term.terminal().gin());
        igds.send("LIST SURFACE\r");
        REQUIRE(term.expect("NOCUR 100"));
        CHECK(igds.output().find("INCORRECT") == std::string::npos);
      } else {
        igds.send("\x03");
        REQUIRE(term.expect("READY"));
      }
    }

    // The session as it was: the surface and its image.
    igds.send("LIST SURFACE\r");
    CHECK(term.expect("NOCUR 100"));
    igds.send("END CMS\r");
    CHECK(igds.wait(60) == 0);
    CHECK(!fs::exists(disk.path("BINSAVE.IGDSLOCK")));
  }
}

TEST_CASE(
    "a command file stopped by Ctrl-C: igds ends 130, the session saved, the lock given back") {
  const ReturningDisk disk;
  TempDir files;
  const fs::path commands = files.path() / "long.igds";
  write_file(commands, "ERASE\nEXPORT DUCT BIG\nCHANGE GRID\n1 1\n");
  // At the lowest priority, so that on a busy machine the signal still comes while the file is
  // being written, not after it.
  LiveIgds igds("/usr/bin/nice",
                {"-n", "19", igds_binary().string(), "--term", "none", "--disk",
                 disk.disk.path().string(), commands.string()},
                false);
  Threads during;
  REQUIRE(appears(disk.path("BIG.DUCTPIC.IGDSTEMP"), igds.pid(), during));
  ::kill(igds.pid(), SIGINT);
  int status = 0;
  REQUIRE(::waitpid(igds.pid(), &status, 0) == igds.pid());
  CHECK(WIFEXITED(status));  // not ended by the signal: it ended itself
  CHECK(WEXITSTATUS(status) == 128 + SIGINT);
  CHECK(!fs::exists(disk.path("BINSAVE.IGDSLOCK")));
  CHECK(during.receiving == 0);
  CHECK(!fs::exists(disk.path("BIG.DUCTPIC")));
  CHECK(!fs::exists(disk.path("BIG.DUCTPIC.IGDSTEMP")));
  // The commands before it are saved, the ones after it never ran.
  const auto next = run_commands(disk.disk, "LIST SURFACE\nEND CMS\n");
  CHECK(next.status == 0);
  CHECK(next.out.find("NOCUR 100") != std::string::npos);
  CHECK(next.out.find("INTCU 9") != std::string::npos);
  CHECK(next.out.find("DAMAGED") == std::string::npos);
}

}  // namespace igds::test
