// Every command that touches the disk, on a disk that fails under igds's feet (issue: one error
// base; docs/disk.md): read-only, full, or removed while igds runs. Each command gives
// its report, igds goes on to READY, and the session on the disk stays the last saved one.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>

#include <fmt/format.h>

#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/live_igds.h"
#include "tests/workspace/small_disk.h"
#include "workspace/disk/session.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

const char* const build_3x3 =
    "BUILD\n3 3\n1 0 0 0 1 0 1 2 0 2\n4 0 1 0 1 1 1 2 1 1\n7 0 2 0 1 2 0 2 2 0\n\n1 1 0 0 1\n\n"
    "1 1\n";

// Every command that reads or writes the disk, each changing the surface first so that the
// automatic save has something to write.
const char* const disk_commands[] = {
    "CHANGE GRID 4 4\n", "SAVE HULL\n",
    "RESTORE OLD\n",     "DISPLAY SURFACE ORTHOGONAL XY\n",
    "STORE FILE PIC\n",  "DISPLAY FILE OLDPIC\n",
    "PLOT SELECTRIC\n",  "EXPORT SVG PIC\n",
    "EXPORT HPGL PIC\n", "EXPORT TEK PIC\n",
    "WRITE HULL\n",      "CHANGE GRID 5 5\n",
    "END CMS\n",
};

Workspace session_on(const fs::path& dir) {
  Disk disk(dir);
  Session session(disk);
  return session.load();
}

// The session of a disk that a live igds holds: read from a copy without the lock.
Workspace session_of_live(const fs::path& dir) {
  test::TempDir copy;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != "BINSAVE.IGDSLOCK")
      fs::copy_file(e.path(), copy.path() / e.path().filename());
  return session_on(copy.path());
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

enum class Fault { read_only, full, removed };

// Runs the commands on a disk that `fault` breaks after the surface is built and saved; returns
// igds's output after the fault.
std::string run_with(Fault fault, const fs::path& disk) {
  // Root writes through permission bits: igds runs as nobody on a folder of its own.
  const int as_user = fault == Fault::read_only && ::geteuid() == 0 ? 65534 : -1;
  fs::path binary = test::igds_binary();
  if (as_user >= 0) {
    // A copy of the binary beside the disk: the build folder may be closed to others (/root).
    fs::permissions(disk.parent_path(), fs::perms::owner_all | fs::perms::others_exec);
    REQUIRE(::chown(disk.c_str(), 65534, 65534) == 0);
    const fs::path copy = disk.parent_path() / "igds";
    fs::copy_file(binary, copy);
    fs::permissions(copy, fs::perms::owner_all | fs::perms::others_read | fs::perms::others_exec);
    binary = copy;
  }
  std::string after;
  {
    test::LiveIgds igds(binary, {"--disk", disk.string(), "--term", "none"}, true, as_user);
    igds.send(build_3x3);
    igds.send("SAVE OLD\nDISPLAY SURFACE ISOMETRIC 3 30\nSTORE FILE OLDPIC\n");
    REQUIRE(igds.wait_for("STORE FILE OLDPIC\nREADY\n", 60));
    Workspace before = session_of_live(disk);
    const std::size_t seen = igds.output().size();
    switch (fault) {
      case Fault::read_only:
        fs::permissions(disk, fs::perms::owner_read | fs::perms::owner_exec);
        break;
      case Fault::full: {
        // Fill what is left, byte by byte at the end, so that no write of igds fits.
        std::FILE* f = std::fopen((disk / "FILLER").c_str(), "wb");
        REQUIRE(f);
        std::vector<char> block(4096, 'x');
        while (std::fwrite(block.data(), 1, block.size(), f) == block.size()) {
        }
        while (std::fwrite("x", 1, 1, f) == 1 && std::fflush(f) == 0) {
        }
        std::fclose(f);
        break;
      }
      case Fault::removed:
        fs::remove_all(disk);
        break;
    }
    for (const char* command : disk_commands) igds.send(command);
    const int status = igds.finish();
    after = igds.output().substr(seen);
    CAPTURE(after);
    // No command ended the program: each has its READY, and END ends normally; the last
    // change could not be saved, so END says so with a failing status.
    CHECK(count(after, "READY\n") == std::size(disk_commands) - 1);
    CHECK(after.ends_with("END CMS\n"));
    CHECK(status == 1);
    CHECK(after.find("CANNOT") != std::string::npos);
    if (fault != Fault::removed) {
      if (fault == Fault::full) fs::remove(disk / "FILLER");
      if (fault == Fault::read_only) fs::permissions(disk, fs::perms::owner_all);
      test::check_same_workspace(session_on(disk), before);
      for (const auto& e : fs::directory_iterator(disk))
        CHECK(!e.path().filename().string().ends_with(".IGDSTEMP"));
    }
  }
  return after;
}

}  // namespace

TEST_CASE("a disk made read-only under igds: every command reports, nothing is lost") {
  test::TempDir scratch;
  fs::create_directory(scratch.path() / "disk");
  std::string out = run_with(Fault::read_only, scratch.path() / "disk");
  CHECK(has(out, "SAVE HULL\nCANNOT WRITE HULL.IGDSDATA (PERMISSION DENIED); NO FILE CHANGED\n"));
  // What only reads still works: the old surface and picture come back.
  CHECK(has(out, "RESTORE OLD\nNOCUR 3 NOSTR 3 INTCU 1 INTST 1\n"));
  CHECK(has(out, "DISPLAY FILE OLDPIC\nIMAGE: "));
  CHECK(has(out, "STORE FILE PIC\nCANNOT WRITE PIC.IGDSIMAG (PERMISSION DENIED); NO FILE CHANGED"));
  CHECK(
      has(out, "PLOT SELECTRIC\nCANNOT WRITE PLOT0001.HPGL (PERMISSION DENIED); NOTHING PLOTTED"));
  CHECK(has(out, "EXPORT TEK PIC\nCANNOT WRITE PIC.TEK (PERMISSION DENIED); NO FILE CHANGED"));
  CHECK(has(out, "WRITE HULL\nCANNOT WRITE HULL.IGDSCHAR (PERMISSION DENIED); NO FILE CHANGED"));
  // The failing automatic save is said once, not after every command.
  CHECK(count(out, "THE LAST SAVED SESSION IS KEPT") == 1);
}

TEST_CASE("a full disk under igds: every command reports, nothing is lost") {
  test::TempDir scratch;
  test::SmallDisk small(scratch.path() / "disk", 512);
  IGDS_SKIP_UNLESS(small.mounted(), "cannot mount a tmpfs here (root can)");
  std::string out = run_with(Fault::full, small.path());
  CHECK(has(out,
            "SAVE HULL\nCANNOT WRITE HULL.IGDSDATA (NO SPACE LEFT ON DEVICE); NO FILE "
            "CHANGED\n"));
  CHECK(has(out, "RESTORE OLD\nNOCUR 3 NOSTR 3 INTCU 1 INTST 1\n"));
  CHECK(has(out, "DISPLAY FILE OLDPIC\nIMAGE: "));
  CHECK(has(out,
            "EXPORT SVG PIC\nCANNOT WRITE PIC.SVG (NO SPACE LEFT ON DEVICE); NO FILE "
            "CHANGED\n"));
  CHECK(count(out, "THE LAST SAVED SESSION IS KEPT") == 1);
}

TEST_CASE("the disk removed under igds: every command reports, igds goes on") {
  test::TempDir scratch;
  fs::create_directory(scratch.path() / "disk");
  std::string out = run_with(Fault::removed, scratch.path() / "disk");
  CHECK(has(out,
            "SAVE HULL\nCANNOT WRITE HULL.IGDSDATA (NO SUCH FILE OR DIRECTORY); NO FILE "
            "CHANGED\n"));
  CHECK(has(out, "RESTORE OLD\nFILE NOT FOUND\n"));
  CHECK(count(out, "THE LAST SAVED SESSION IS KEPT") == 1);
}

TEST_CASE("a disk that fills and has room again: the failure said once, then the save said") {
  test::TempDir scratch;
  test::SmallDisk small(scratch.path() / "disk", 512);
  IGDS_SKIP_UNLESS(small.mounted(), "cannot mount a tmpfs here (root can)");
  const fs::path disk = small.path();
  test::LiveIgds igds(test::igds_binary(), {"--disk", disk.string(), "--term", "none"}, true);
  igds.send(build_3x3);
  REQUIRE(igds.wait_for("INTERPOLATED CURVES AND STRINGERS? 1 1\nREADY\n", 60));
  {
    std::FILE* f = std::fopen((disk / "FILLER").c_str(), "wb");
    REQUIRE(f);
    std::vector<char> block(4096, 'x');
    while (std::fwrite(block.data(), 1, block.size(), f) == block.size()) {
    }
    while (std::fwrite("x", 1, 1, f) == 1 && std::fflush(f) == 0) {
    }
    std::fclose(f);
  }
  igds.send("CHANGE GRID 4 4\nCHANGE GRID 3 3\n");
  REQUIRE(igds.wait_for("CHANGE GRID 3 3\nREADY\n", 60));
  fs::remove(disk / "FILLER");
  igds.send("CHANGE GRID 5 5\nEND CMS\n");
  CHECK(igds.finish() == 0);
  const std::string out = igds.output();
  CAPTURE(out);
  CHECK(count(out, "THE LAST SAVED SESSION IS KEPT") == 1);
  CHECK(has(out, "CHANGE GRID 5 5\nTHE SESSION IS SAVED AGAIN\nREADY\n"));
  CHECK(session_on(disk).intcu == 5);
}
