// Crash safety of the session (docs/disk.md): igds killed with SIGKILL at random
// moments of a command file always leaves, on restart, the state after one of its commands,
// never before a command that had printed READY, and never a damaged session.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <random>
#include <set>
#include <thread>

#include <fmt/format.h>

#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/live_igds.h"
#include "tests/workspace/small_disk.h"
#include "workspace/disk/session.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

// Commands that change every kind of variable: the surface (small arrays in the session file,
// large ones in files of their own), the images and STATUS; some change nothing.
const std::vector<std::string> commands = {
    "BUILD\n3 3\n1 0 0 0 1 0 1 2 0 2\n4 0 1 0 1 1 1 2 1 1\n7 0 2 0 1 2 0 2 2 0\n\n1 1 0 0 1\n\n"
    "1 1\n",
    "DISPLAY SURFACE ORTHOGONAL XY\n",
    "STORE FIRST\n",
    "CHANGE GRID 6 6\n",
    "HELP SHORT\n",
    "DISPLAY INPUT ISOMETRIC 1 30\n",
    "STORE SECOND\n",
    "CHANGE GRID 2 3\n",
    "HELP LONG\n",
    "SAVE HULL\n",
    "DISPLAY SURFACE CONIC 10 10 10\n",
    "STORE FILE PIC\n",
    "CHANGE GRID 9 9\n",
    "HELP SHORT\n",
    "DISPLAY FIRST\n",
    "CHANGE GRID 1 1\n",
    "RESTORE HULL\n",
    "WRITE HULL\n",
    "STORE SECOND\n",
    "CHANGE GRID 7 5\n",
    "HELP LONG\n",
    "DISPLAY SURFACE ORTHOGONAL YZ\n",
};

std::string command_file(std::size_t n) {
  std::string text;
  for (std::size_t i = 0; i < n; ++i) text += commands[i];
  return text;
}

Workspace session_on(const fs::path& dir, std::vector<std::string>* notices = nullptr) {
  Disk disk(dir);
  Session session(disk);
  Workspace ws = session.load();
  if (notices) *notices = session.notices();
  return ws;
}

// Lines that are READY alone (HELP LONG shows "  READY" in its example session).
std::size_t count_ready(const std::string& out) {
  std::size_t n = 0;
  for (std::size_t at = out.find("READY\n"); at != std::string::npos;
       at = out.find("READY\n", at + 1))
    n += at == 0 || out[at - 1] == '\n';
  return n;
}

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("igds killed -9 at random moments: restart gives a state after a finished command" *
          doctest::test_suite("slow")) {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir scratch;
  // A kill -9 leaves the page cache as it is, so a tmpfs behaves as any disk here, and without
  // the waits of fsync the kills come faster; a plain folder when no tmpfs can be mounted.
  test::SmallDisk tmpfs(scratch.path() / "tmpfs", 256 * 1024);
  const fs::path work = tmpfs.mounted() ? tmpfs.path() : scratch.path();
  const fs::path files = work / "files";
  fs::create_directory(files);

  // The state after each number of commands, from clean runs of the prefixes.
  std::vector<Workspace> states;
  for (std::size_t n = 0; n <= commands.size(); ++n) {
    fs::path disk = work / fmt::format("prefix{}", n);
    fs::create_directory(disk);
    fs::path file = files / fmt::format("prefix{}.igds", n);
    test::write_file(file, command_file(n));
    auto r = test::run_igds({"--disk", disk.string(), "--term", "none", file.string()});
    REQUIRE_MESSAGE(r.status == 0, (r.out + r.err));
    REQUIRE(count_ready(r.out) == n + 1);
    CHECK(r.out.find("NOT FOUND") == std::string::npos);
    states.push_back(session_on(disk));
    // A clean run leaves the session and the files the commands wrote, nothing else.
    for (const auto& name : files_in(disk)) {
      CAPTURE(name);
      CHECK((name == "BINSAVE.IGDSCONT" || name.ends_with(".IGDSVARS") || name == "HULL.IGDSDATA" ||
             name == "HULL.IGDSCHAR" || name == "PIC.IGDSIMAG" || name == "HISTORY.IGDSHIST"));
    }
  }
  REQUIRE(states.size() == commands.size() + 1);
  CHECK(!test::same_workspace(states[3], states[4]));  // CHANGE GRID changed something

  const fs::path all = files / "all.igds";
  test::write_file(all, command_file(commands.size()));
  const fs::path empty = files / "empty.igds";
  test::write_file(empty, "");
  const fs::path disk = work / "crash";
  // How long a whole run takes when started the way the killed ones are.
  std::vector<double> runs;
  for (int i = 0; i < 3; ++i) {
    fs::remove_all(disk);
    fs::create_directory(disk);
    auto t0 = std::chrono::steady_clock::now();
    test::LiveIgds igds(test::igds_binary(),
                        {"--disk", disk.string(), "--term", "none", all.string()}, false);
    REQUIRE(igds.finish() == 0);
    runs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(runs.begin(), runs.end());
  // A fixed number of kills at moments spread evenly over a run (one in each of `total` equal
  // slices, at a random place inside it): the time the test takes varies, what it checks not.
  // A fixed number of kills, spread over the commands by progress, not by time: kill k waits
  // until command k % (commands + 1) has started (its READY seen), then a random part of one
  // command's time. What the test checks does not depend on the machine's speed.
  const int total = 200;
  const double per_command = runs[1] / double(commands.size() + 1);
  std::mt19937 random(20261121);
  std::uniform_real_distribution<double> inside(0, 1);
  const auto start = std::chrono::steady_clock::now();
  int taken_over = 0;
  std::set<std::size_t> states_seen;
  for (int kills = 0; kills < total; ++kills) {
    const std::size_t target = std::size_t(kills) % (commands.size() + 1);
    fs::remove_all(disk);
    fs::create_directory(disk);
    std::size_t finished = 0;
    {
      test::LiveIgds igds(test::igds_binary(),
                          {"--disk", disk.string(), "--term", "none", all.string()}, false);
      // Only a hang reaches this bound.
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
      while (count_ready(igds.output()) < target && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      std::this_thread::sleep_for(std::chrono::duration<double>(per_command * inside(random)));
      igds.kill();
      std::size_t ready = count_ready(igds.output());
      finished = ready > 0 ? ready - 1 : 0;
    }
    // Restart the real igds on what was left, then look at the session it leaves.
    auto r = test::run_igds({"--disk", disk.string(), "--term", "none", empty.string()});
    REQUIRE_MESSAGE(r.status == 0, (r.out + r.err));
    CHECK_MESSAGE(r.out.find("DAMAGED") == std::string::npos, r.out);
    if (r.out.find("TAKEN OVER") != std::string::npos) ++taken_over;
    Workspace ws = session_on(disk);
    std::optional<std::size_t> which;
    for (std::size_t j = finished; j < states.size() && !which; ++j)
      if (test::same_workspace(ws, states[j])) which = j;
    CAPTURE(finished);
    CHECK_MESSAGE(which.has_value(), "the session is none of the states after READY was seen");
    if (which) states_seen.insert(*which);
    for (const auto& name : files_in(disk)) {
      CAPTURE(name);
      CHECK(!name.ends_with(".IGDSTEMP"));
      CHECK(name != "BINSAVE.IGDSLOCK");
    }
  }
  MESSAGE(
      fmt::format("{} kills in {:.0f} s; {} locks taken over; {} different states seen", total,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                  taken_over, states_seen.size()));
  CHECK(taken_over > 0);
  CHECK(states_seen.size() > commands.size() / 2);  // the kills fell all over the file
}
