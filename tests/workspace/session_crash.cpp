// Session::save under SIGKILL at random moments, in a child process: the session on disk is
// always the last one whose save() had returned, or the one being saved, never anything else.
// (tests/e2e/disk_crash.cpp does the same to the real igds binary.)
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/disk/session.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

// The k-th state: every few saves a different variable changes (a file of its own or inline).
Workspace state(int k) {
  Workspace ws = test::make_workspace(5, 5, 4, 4);
  ws.status[9] = k;
  ws.intpn.ravel[0] = k / 2;
  if (k % 3 == 0) ws.patches.ravel[5] = -k;
  if (k % 5 == 0) {
    Image image = *ws.image;
    image.points.ravel[3] = k;
    ws.image = std::make_shared<const Image>(image);
  }
  if (k % 7 == 0) ws.temp1.reset();
  if (k % 4 == 0) ws.inppn.ravel[2] = k;
  return ws;
}

}  // namespace

TEST_CASE("Session::save killed -9 at random moments: old or new, never torn") {
  test::TempDir dir;
  Disk disk(dir.path());
  std::mt19937 random(1975);
  std::uniform_int_distribution<int> micros(0, 60000);
  // A fixed number of kills: the time the test takes varies with the machine, not what it checks.
  const int kills = 150;
  int advanced = 0, next_start = 0;
  for (int kill = 0; kill < kills; ++kill) {
    int done[2];
    REQUIRE(::pipe(done) == 0);
    const int first = next_start;
    pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      ::close(done[0]);
      try {
        Session session(disk);
        session.load();
        for (int k = first;; ++k) {
          Workspace ws = state(k);
          session.save(ws);
          // Like READY: said only once save() has returned.
          if (::write(done[1], &k, sizeof k) != sizeof k) ::_exit(2);
        }
      } catch (...) {
        ::_exit(1);
      }
    }
    ::close(done[1]);
    int last = first - 1, k = 0;
    // Every other kill waits for a save to have returned first, so that kills land in the
    // middle of a session's life on a slow or loaded machine too, not only at its start.
    if (kill % 2 == 1 && ::read(done[0], &k, sizeof k) == sizeof k) last = k;
    std::this_thread::sleep_for(std::chrono::microseconds(micros(random)));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    REQUIRE(WIFSIGNALED(status));
    while (::read(done[0], &k, sizeof k) == sizeof k) last = k;
    ::close(done[0]);

    Session session(disk);
    Workspace ws = session.load();
    for (const auto& notice : session.notices())
      CHECK_MESSAGE(notice.find("DAMAGED") == std::string::npos, notice);
    bool as_last = last >= 0 && test::same_workspace(ws, state(last));
    bool as_next = test::same_workspace(ws, state(last + 1));
    bool as_empty = last < 0 && ws == Workspace{};
    CAPTURE(last);
    CHECK((as_last || as_next || as_empty));
    advanced += last >= first;
    next_start = (as_next ? last + 1 : last) + 1;
    // Garbage of the killed save is gone after load: only what the session names is left.
    for (const auto& e : fs::directory_iterator(dir.path())) {
      std::string name = e.path().filename().string();
      CAPTURE(name);
      // A kill inside the very first save leaves variable files and no session: they are kept
      // aside, never deleted (a session file moved away looks the same).
      CHECK((name == "BINSAVE.IGDSCONT" || name == "BINSAVE.IGDSLOCK" ||
             name.ends_with(".IGDSVARS") || name.ends_with(".IGDSBAD")));
    }
    std::size_t vars = 0;
    for (const auto& e : fs::directory_iterator(dir.path()))
      vars += e.path().filename().string().ends_with(".IGDSVARS");
    CHECK(vars <= 4);  // INTPN, PATCHES, IMAGE, TEMP1 at most
  }
  MESSAGE(kills << " kills; " << advanced << " of them after at least one save had returned");
  CHECK(advanced >= kills / 2);
}
