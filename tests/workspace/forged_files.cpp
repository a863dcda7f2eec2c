// Sessions, journals and files forged with valid frames and checksums (tests/workspace/forge.h):
// each gives a report or a notice and the old state, never a crash, and costs no more memory
// than the file it is read from.
#include <doctest/doctest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/forge.h"
#include "workspace/disk/files.h"
#include "workspace/disk/journal_file.h"
#include "workspace/disk/session.h"
#include "workspace/error.h"
#include "workspace/images.h"
#include "workspace/journal.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

struct Scratch {
  test::TempDir dir;
  Disk disk{dir.path()};
};

Workspace load_fresh(const Disk& disk, std::vector<std::string>* notices = nullptr) {
  Session session(disk);
  Workspace ws = session.load();
  if (notices) *notices = session.notices();
  return ws;
}

void save(const Disk& disk, Workspace& ws, const Journal* journal = nullptr) {
  Session session(disk);
  session.load();
  session.save(ws, journal);
}

// A start on `disk`, whose session is refused for `why`: the workspace starts empty, the one
// notice says so, and the damaged session, kept aside, is removed for the next case.
void refused_at_start(const Disk& disk, const std::string& why) {
  std::vector<std::string> notices;
  CHECK(load_fresh(disk, &notices) == Workspace{});
  CHECK(notices == std::vector<std::string>{"SESSION FILE BINSAVE.IGDSCONT DAMAGED (" + why +
                                            "): KEPT AS BINSAVE.IGDSBAD; THE WORKSPACE STARTS "
                                            "EMPTY"});
  fs::remove(disk.path("BINSAVE", "IGDSBAD"));
}

}  // namespace

TEST_CASE("a session naming one variable file twice with two sizes is refused, not overrun") {
  Scratch s;
  Workspace ws = test::make_interpolated(30, 30, 0, 0);  // INPPN 21600 bytes: one file
  ws.image = ws.temp1 = ws.temp2 = nullptr;
  save(s.disk, ws);
  disk::SessionTable t = test::forge::session_table(s.disk);
  disk::Record& r = *t.record(t.current);
  REQUIRE(r.inppn.ravel.pieces.size() == 1);
  REQUIRE(r.inppn.ravel.pieces[0].in_file);
  // The same file again, said to be 24 bytes long: one point more than the file holds.
  disk::Piece again = r.inppn.ravel.pieces[0];
  again.size = 24;
  again.file.length = 24 + disk::frame_header_bytes + disk::frame_trailer_bytes;
  r.inppn.ravel.pieces.push_back(again);
  r.nocur = 1;
  r.nostr = 901;
  r.inppn.shape = {901, 3};
  r.inptg.shape = {1804, 4};
  r.inptg.ravel.pieces = {test::forge::file_piece(
      test::forge::variable_file(s.disk, 0x100, std::string(1804 * 4 * sizeof(double), '\0')))};
  test::forge::write_session(s.disk, t);

  std::vector<std::string> notices;
  CHECK(load_fresh(s.disk, &notices) == Workspace{});
  REQUIRE(notices.size() == 1);
  CHECK(notices[0] == fmt::format("SESSION FILE BINSAVE.IGDSCONT DAMAGED ({}.IGDSVARS: NOT THE "
                                  "ONE SAVED): KEPT AS BINSAVE.IGDSBAD; THE WORKSPACE STARTS EMPTY",
                                  disk::variable_file_name(again.file.number)));
}

namespace {

// Runs `f` in a child process and returns the most memory it held (its peak resident set, in
// MB), the parent's included as the child starts with it.
long peak_megabytes_of(const std::function<void()>& f) {
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    try {
      f();
    } catch (...) {
      ::_exit(2);
    }
    ::_exit(0);
  }
  int status = 0;
  rusage usage{};
  REQUIRE(::wait4(pid, &status, 0, &usage) == pid);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  return usage.ru_maxrss / 1024;
}

long own_peak_megabytes() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024;
}

}  // namespace

TEST_CASE("a journal's counts are checked against what it can hold before anything is made") {
  Scratch s;
  Workspace ws = test::make_interpolated(3, 3, 0, 0);
  save(s.disk, ws);
  disk::SessionTable t = test::forge::session_table(s.disk);
  // One step, and a table of 15 million images: what the bytes left could hold at one byte each,
  // but not what one step can name.
  disk::Writer w;
  w.u32(1);  // version
  w.u32(1);  // steps
  w.u32(0);  // position
  const std::uint32_t images = 15u << 20;
  w.u32(images);
  w.bytes(std::string(images, '\x01'));
  t.journal = w.str();
  test::forge::write_session(s.disk, t);

  const long before = own_peak_megabytes();
  const long peak = peak_megabytes_of([&] {
    std::vector<std::string> notices;
    Workspace back = load_fresh(s.disk, &notices);
    if (notices.size() != 1 ||
        notices[0] != "UNDO JOURNAL IN BINSAVE.IGDSCONT DAMAGED (FORMAT): NOTHING TO UNDO" ||
        back.nocur != 3)
      ::_exit(3);
  });
  // The session file is 15 MB: its reading may hold it and a copy, not 64 bytes an image.
  CHECK(peak < before + 100);
}

// Labelled slow: its memory is measured in the build as igds ships; AddressSanitizer keeps freed
// blocks aside, which would count here.
TEST_CASE("a journal naming many states costs their changes and one copy of the inputs" *
          doctest::test_suite("slow")) {
  // Two hundred DISPLAYs, each after a CHANGE of one point of a 400 x 400 surface: the journal
  // keeps each image as its recipe, a state of its own. Read back, the states are made again
  // from the steps when an image is made, not copied at start (200 copies of INPPN, 770 MB).
  Scratch s;
  Workspace ws = test::make_interpolated(400, 400, 0, 0);
  ws.image = ws.temp1 = ws.temp2 = nullptr;
  ws.changes.inppn.saved();
  ws.changes.inptg.saved();
  Journal journal(ws);
  const Description view{0, Projection::isometric, {3, 30, 0}};
  for (std::size_t k = 0; k < 200; ++k) {
    ws.inppn.ravel[3 * k + 2] += 1;
    Edits points = Edits::none();
    points.part(3 * k, 3 * k + 3);
    ws.changes.edited(points, Edits::none());
    // Drawn from this state, never made here: its recipe is all the journal keeps.
    ws.image = image_by_recipe([] { return Workspace{}; }, ws.changes.surface, view);
    REQUIRE(journal.record(ws, "DISPLAY INPUT"));
    ws.changes.inppn.saved();
  }
  {
    Session session(s.disk);
    session.load();
    session.save(ws, &journal);
  }
  const long before = own_peak_megabytes();
  const long peak = peak_megabytes_of([&] {
    Session session(s.disk);
    Workspace back = session.load();
    Journal j = session.take_journal(back);
    if (!session.notices().empty() || j.undo_count() != 200) ::_exit(3);
    // An image of an older state is that state's, its inputs made again from the steps.
    for (int k = 0; k < 10; ++k) j.undo(back);
    if (!(*back.image == input_image(back, {view.projection, view.parameters}))) ::_exit(4);
  });
  CHECK(peak < before + 150);
}

TEST_CASE("RESTORE of a surface that overflows, or holds numbers that are not finite, is refused") {
  Scratch s;
  Workspace current = test::make_interpolated(3, 3, 1, 1);
  const Workspace before = current;
  auto restored = [&](const Workspace& in) {
    save_surface(s.disk, "F", in);  // igds's own writer: frame and checksum hold
    try {
      restore_surface(s.disk, "F", current);
    } catch (const Report& r) {
      test::check_same_surface(current, before);
      return std::string(r.what());
    }
    return std::string("RESTORED");
  };
  // Finite inputs whose interpolation is not: a tangent of 1E308.
  Workspace huge = test::make_interpolated(3, 3, 1, 1);
  huge.inptg.ravel[0] = 1e308;
  CHECK(restored(huge) ==
        "FILE DAMAGED: F.IGDSDATA (ITS SURFACE OVERFLOWS: PATCH 1 IS NOT A FINITE "
        "NUMBER); CURRENT SURFACE KEPT");
  // PATCHES and INTPN of the file, kept as they are when they are not the interpolation's (as
  // END APL assigns them).
  Workspace odd = test::make_interpolated(3, 3, 1, 1);
  test::own_surface(odd);
  odd.patches.ravel[48 + 5] = std::numeric_limits<double>::quiet_NaN();
  CHECK(restored(odd) ==
        "FILE DAMAGED: F.IGDSDATA (PATCH 2 OF PATCHES IS NOT A FINITE NUMBER); CURRENT SURFACE "
        "KEPT");
  odd = test::make_interpolated(3, 3, 1, 1);
  test::own_surface(odd);
  odd.intpn.ravel[3 * (5 * 2 + 3) + 1] = -std::numeric_limits<double>::infinity();
  CHECK(restored(odd) ==
        "FILE DAMAGED: F.IGDSDATA (ROW 3 COLUMN 4 OF INTPN IS NOT A FINITE NUMBER); CURRENT "
        "SURFACE KEPT");
  CHECK(restored(test::make_interpolated(3, 3, 1, 1)) == "RESTORED");
}

TEST_CASE("a session whose inputs overflow, or whose kept arrays are not finite, is refused") {
  Scratch s;
  Workspace ws = test::make_interpolated(3, 3, 1, 1);
  ws.image = ws.temp1 = ws.temp2 = nullptr;
  ws.inptg.ravel[0] = 1e308;  // saved as the designer's inputs, the surface never made
  ws.changes.replaced(true);
  save(s.disk, ws);
  refused_at_start(s.disk, "PATCH 1 IS NOT A FINITE NUMBER");

  // PATCHES kept by the session (as END APL or FIT leaves them), one of them made a NaN.
  Workspace kept = test::make_interpolated(3, 3, 1, 1);
  kept.image = kept.temp1 = kept.temp2 = nullptr;
  test::own_surface(kept);
  save(s.disk, kept);
  disk::SessionTable t = test::forge::session_table(s.disk);
  REQUIRE(!t.derived);
  Array patches = kept.patches;
  patches.ravel[7] = std::numeric_limits<double>::quiet_NaN();
  const std::string_view bytes(reinterpret_cast<const char*>(patches.data()),
                               patches.size() * sizeof(double));
  t.patches.ravel.pieces = {
      test::forge::file_piece(test::forge::variable_file(s.disk, 0x200, bytes))};
  test::forge::write_session(s.disk, t);
  refused_at_start(s.disk, "PATCH 1 OF PATCHES IS NOT A FINITE NUMBER");

  // A session that says it keeps its arrays, without PATCHES: an interpolated surface keeps none,
  // but this one is not the interpolation.
  save(s.disk, kept);
  t = test::forge::session_table(s.disk);
  REQUIRE(!t.derived);
  t.patches = disk::StoredArray{};
  test::forge::write_session(s.disk, t);
  refused_at_start(s.disk, "SHAPES: PATCHES IS EMPTY, NOT 2 BY 2 BY 3 BY 4 BY 4");
}
