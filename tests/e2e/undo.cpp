// UNDO and REDO on the real igds (issue 14): across a restart, after igds was killed -9 in the
// middle of a command, and the journal's size after 200 CHANGE POINTS on a 100 x 100 surface.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <random>
#include <thread>

#include <fmt/format.h>

#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/live_igds.h"
#include "workspace/disk/frame.h"
#include "workspace/disk/session.h"
#include "workspace/disk/session_file.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

// Each command changes the workspace, so that UNDO goes back exactly one of them.
const std::vector<std::pair<std::string, std::string>> commands = {
    {"BUILD\n3 3\n1 0 0 0 1 0 1 2 0 2\n4 0 1 0 1 1 1 2 1 1\n7 0 2 0 1 2 0 2 2 0\n\n1 1 0 0 1\n\n"
     "1 1\n",
     "BUILD"},
    {"CHANGE POINTS\n5 1 1 3\n\nN\nN\n", "CHANGE POINTS"},
    {"DISPLAY SURFACE ORTHOGONAL XY\n", "DISPLAY SURFACE"},
    {"CHANGE GRID 3 3\n", "CHANGE GRID"},
    {"STORE FIRST\n", "STORE FIRST"},
    {"HELP SHORT\n", "HELP SHORT"},
    {"CHANGE POINTS\n5 1 1 -2\n\nN\nN\n", "CHANGE POINTS"},
    {"DISPLAY INPUT ISOMETRIC 1 30\n", "DISPLAY INPUT"},
    {"CHANGE GRID 1 1\n", "CHANGE GRID"},
    {"HELP LONG\n", "HELP LONG"},
};

std::string command_file(std::size_t n) {
  std::string text;
  for (std::size_t i = 0; i < n; ++i) text += commands[i].first;
  return text;
}

Workspace session_on(const fs::path& dir) {
  Disk disk(dir);
  Session session(disk);
  return session.load();
}

std::size_t count_ready(const std::string& out) {
  std::size_t n = 0;
  for (std::size_t at = out.find("READY\n"); at != std::string::npos;
       at = out.find("READY\n", at + 1))
    n += at == 0 || out[at - 1] == '\n';
  return n;
}

test::RunResult run_file(const fs::path& disk, const fs::path& file, std::string_view text) {
  test::write_file(file, text);
  auto r = test::run_igds({"--disk", disk.string(), "--term", "none", file.string()});
  REQUIRE_MESSAGE(r.status == 0, (r.out + r.err));
  return r;
}

bool has(const std::string& out, std::string_view text) {
  return out.find(text) != std::string::npos;
}

// The state after each number of commands, from clean runs of the prefixes.
std::vector<Workspace> states_of(const fs::path& work) {
  std::vector<Workspace> states;
  for (std::size_t n = 0; n <= commands.size(); ++n) {
    const fs::path disk = work / fmt::format("prefix{}", n);
    fs::create_directories(disk);
    run_file(disk, work / "prefix.igds", command_file(n));
    states.push_back(session_on(disk));
  }
  return states;
}

}  // namespace

TEST_CASE("UNDO and REDO across a restart: the journal is in the session on the disk") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir work;
  const auto states = states_of(work.path());
  const fs::path disk = work.path() / "disk", file = work.path() / "f.igds";
  fs::create_directory(disk);
  run_file(disk, file, command_file(5));

  auto r = run_file(disk, file, "UNDO\nUNDO\n");
  CHECK(has(r.out, "UNDO\nUNDONE: STORE FIRST\nREADY\nUNDO\nUNDONE: CHANGE GRID\nREADY\n"));
  CHECK(test::same_workspace(session_on(disk), states[3]));
  r = run_file(disk, file, "REDO\n");
  CHECK(has(r.out, "REDO\nREDONE: CHANGE GRID\n"));
  CHECK(test::same_workspace(session_on(disk), states[4]));
  // The image of DISPLAY SURFACE, drawn again from its state's surface, bit for bit.
  r = run_file(disk, file, "UNDO\nUNDO\nUNDO\nUNDO\nUNDO\n");
  CHECK(has(r.out,
            "UNDONE: DISPLAY SURFACE\nREADY\nUNDO\nUNDONE: CHANGE POINTS\nREADY\nUNDO\n"
            "UNDONE: BUILD\nREADY\nUNDO\nNOTHING TO UNDO\nREADY\n"));
  CHECK(test::same_workspace(session_on(disk), states[0]));
  r = run_file(disk, file, "REDO\nREDO\nREDO\n");
  // The image the last REDO puts back is shown (here the none terminal's line of it).
  CHECK(has(r.out, "REDONE: BUILD\nREADY\nREDO\nREDONE: CHANGE POINTS\nREADY\nREDO\n"));
  if (!has(r.out, "\nIMAGE: SURFACE, ")) FAIL(r.out);
  CHECK(has(r.out, "\nREDONE: DISPLAY SURFACE\nREADY\n"));
  CHECK(test::same_workspace(session_on(disk), states[3]));
  // A change after UNDO: what REDO had is gone, here and after the next start.
  run_file(disk, file, "UNDO\nHELP SHORT\n");
  r = run_file(disk, file, "REDO\nUNDO\n");
  CHECK(has(r.out, "REDO\nNOTHING TO REDO\nREADY\nUNDO\nUNDONE: HELP SHORT\n"));
  CHECK(test::same_workspace(session_on(disk), states[2]));
}

TEST_CASE("igds killed -9 in the middle of a command: after the restart UNDO goes back one") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir work;
  const auto states = states_of(work.path());
  const fs::path disk = work.path() / "disk", all = work.path() / "all.igds";
  const fs::path undo = work.path() / "undo.igds";
  test::write_file(all, command_file(commands.size()));
  test::write_file(undo, "UNDO\n");

  // Killed while a command waits for its next answer: the command never happened.
  {
    fs::create_directory(disk);
    test::LiveIgds igds(test::igds_binary(), {"--disk", disk.string(), "--term", "none"}, true);
    igds.send(command_file(3) + "CHANGE POINTS\n5 1 1 9\n");
    REQUIRE(igds.wait_for("POINTS? 5 1 1 9\n", 60));
    igds.kill();
  }
  CHECK(test::same_workspace(session_on(disk), states[3]));
  auto r = run_file(disk, undo, "UNDO\n");
  CHECK(has(r.out, "UNDONE: DISPLAY SURFACE"));
  CHECK(test::same_workspace(session_on(disk), states[2]));

  // Killed at moments spread over the commands by progress (as tests/e2e/disk_crash.cpp): the
  // session is the state after some command, and UNDO then gives the one before it.
  const int total = 3 * static_cast<int>(commands.size() + 1);
  std::mt19937 random(20261123);
  std::uniform_real_distribution<double> inside(0, 0.02);
  for (int kill = 0; kill < total; ++kill) {
    const std::size_t target = std::size_t(kill) % (commands.size() + 1);
    fs::remove_all(disk);
    fs::create_directory(disk);
    std::size_t finished = 0;
    {
      test::LiveIgds igds(test::igds_binary(),
                          {"--disk", disk.string(), "--term", "none", all.string()}, false);
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
      while (count_ready(igds.output()) < target && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      std::this_thread::sleep_for(std::chrono::duration<double>(inside(random)));
      igds.kill();
      const std::size_t ready = count_ready(igds.output());
      finished = ready > 0 ? ready - 1 : 0;
    }
    std::optional<std::size_t> which;
    {
      const Workspace ws = session_on(disk);
      for (std::size_t j = finished; j < states.size() && !which; ++j)
        if (test::same_workspace(ws, states[j])) which = j;
    }
    CAPTURE(kill);
    CAPTURE(finished);
    REQUIRE_MESSAGE(which.has_value(), "the session is none of the states after a command");
    r = run_file(disk, undo, "UNDO\n");
    CHECK_MESSAGE(!has(r.out, "DAMAGED"), r.out);
    if (*which == 0) {
      CHECK(has(r.out, "NOTHING TO UNDO"));
      CHECK(test::same_workspace(session_on(disk), states[0]));
    } else {
      CHECK(has(r.out, "UNDONE: " + commands[*which - 1].second + "\n"));
      CHECK(test::same_workspace(session_on(disk), states[*which - 1]));
    }
  }
}

TEST_CASE("the journal after 200 CHANGE POINTS of one point on a 100 x 100 surface") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir work;
  const fs::path disk = work.path() / "disk", file = work.path() / "f.igds";
  fs::create_directory(disk);
  std::string text = "BUILD\n100 100\n";
  Array inppn({10000, 3});
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) {
      const int k = i * 100 + j;
      // Numbers that a line carries exactly (the session keeps the doubles typed).
      const double p[3] = {j * 1.0, i * 1.5, double((i * j) % 17) - 8};
      text += fmt::format("{} {} {} {}\n", k + 1, p[0], p[1], p[2]);
      for (int c = 0; c < 3; ++c) inppn.ravel[std::size_t(3 * k + c)] = p[c];
    }
  }
  text += "\n\n0 0\n";
  std::vector<Array> after{inppn};
  for (int c = 0; c < 200; ++c) {
    const int k = (c * 37) % 10000;
    text += fmt::format("CHANGE POINTS\n{} 1 2 {}\n\nN\nN\n", k + 1, c);
    Array next = after.back();
    next.ravel[std::size_t(3 * k)] = 1;
    next.ravel[std::size_t(3 * k + 1)] = 2;
    next.ravel[std::size_t(3 * k + 2)] = c;
    after.push_back(std::move(next));
  }
  auto r = run_file(disk, file, text);
  CHECK(count_ready(r.out) == 202);

  const std::string session = test::read_file(disk / "BINSAVE.IGDSCONT");
  const auto table = disk::decode_session(disk::unframe("IGDSCONT", session).payload);
  // 200 steps of one point each, not 200 copies of INPPN's 240 KB.
  CHECK(table.journal.size() < 200 * 400);
  CHECK(session.size() < 100000);
  MESSAGE(
      fmt::format("journal after 200 CHANGE POINTS on 100 x 100: {} bytes; session file {} "
                  "bytes",
                  table.journal.size(), session.size()));

  // The last 20 taken back, after a restart.
  std::string undo;
  for (int k = 0; k < 20; ++k) undo += "UNDO\n";
  r = run_file(disk, file, undo);
  std::size_t undone = 0;
  for (auto at = r.out.find("UNDONE: CHANGE POINTS\n"); at != std::string::npos;
       at = r.out.find("UNDONE: CHANGE POINTS\n", at + 1))
    ++undone;
  CHECK(undone == 20);
  CHECK(test::same_bits(session_on(disk).inppn, after[180]));
}
