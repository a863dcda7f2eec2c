// SAVE/RESTORE (IGDSDATA), STORE FILE/DISPLAY FILE (IGDSIMAG): exact round trips, and every
// kind of bad file or refusing disk gets a clear report and loses nothing.
#include <doctest/doctest.h>

#include <filesystem>
#include <set>

#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/small_disk.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/format.h"
#include "workspace/error.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

std::string report_of(auto&& f) {
  try {
    f();
  } catch (const Report& r) {
    return r.what();
  }
  return "(no report)";
}

// Sets the version of a framed file and makes its checksum right again.
std::string with_version(std::string file, std::uint32_t version) {
  for (int i = 0; i < 4; ++i) file[8 + i] = static_cast<char>(version >> (8 * i));
  std::size_t end = file.size() - 8;
  std::uint64_t sum = disk::checksum(std::string_view(file).substr(0, end));
  for (int i = 0; i < 8; ++i) file[end + i] = static_cast<char>(sum >> (8 * i));
  return file;
}

struct Scratch {
  test::TempDir dir;
  Disk disk{dir.path()};
};

}  // namespace

TEST_CASE("SAVE then RESTORE gives every surface variable back bit for bit") {
  Scratch s;
  Workspace saved = test::make_workspace(4, 5, 3, 2);
  save_surface(s.disk, "HULL", saved);
  CHECK(files_in(s.dir.path()) == std::set<std::string>{"HULL.IGDSDATA"});

  Workspace ws = test::make_workspace(2, 3, 0, 0);
  ws.image = std::make_shared<const Image>(test::make_image(0, Projection::orthogonal, 2, 2, 99));
  ws.status = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  Workspace before = ws;
  restore_surface(s.disk, "HULL", ws);
  test::check_same_surface(ws, saved);
  // Images and STATUS are not part of a surface.
  CHECK(test::same_bits(ws.image, before.image));
  CHECK(test::same_bits(ws.temp1, before.temp1));
  CHECK(ws.status == before.status);
}

TEST_CASE("SAVE replaces a file of the same name") {
  Scratch s;
  save_surface(s.disk, "HULL", test::make_workspace(4, 5, 3, 2));
  Workspace second = test::make_workspace(2, 2, 0, 1);
  save_surface(s.disk, "HULL", second);
  Workspace ws;
  restore_surface(s.disk, "HULL", ws);
  test::check_same_surface(ws, second);
  CHECK(files_in(s.dir.path()) == std::set<std::string>{"HULL.IGDSDATA"});
}

TEST_CASE("a surface without interpolation yet round-trips too") {
  Scratch s;
  Workspace w = test::make_workspace(3, 2, 1, 1, false);
  w.patches = Array{};
  w.intpn = Array{};
  save_surface(s.disk, "RAW", w);
  Workspace ws;
  restore_surface(s.disk, "RAW", ws);
  test::check_same_surface(ws, w);
}

TEST_CASE("RESTORE of a file that is not there: FILE NOT FOUND, nothing changed") {
  Scratch s;
  Workspace ws = test::make_workspace(2, 2, 1, 1);
  Workspace before = ws;
  CHECK_THROWS_WITH_AS(restore_surface(s.disk, "NONE", ws), reports::file_not_found, Report);
  CHECK_THROWS_WITH_AS(load_image(s.disk, "NONE"), reports::file_not_found, Report);
  test::check_same_workspace(ws, before);
}

TEST_CASE("every damaged IGDSDATA is refused whole, with the reason, and the surface kept") {
  Scratch s;
  Workspace small = test::make_workspace(2, 2, 0, 0, false);
  save_surface(s.disk, "GOOD", small);
  const std::string good = test::read_file(s.disk.path("GOOD", "IGDSDATA"));
  const fs::path bad = s.disk.path("BAD", "IGDSDATA");
  Workspace ws = test::make_workspace(3, 3, 1, 1);
  const Workspace before = ws;
  auto refused = [&](const std::string& bytes) {
    test::rewrite_file(bad, bytes);
    return report_of([&] { restore_surface(s.disk, "BAD", ws); });
  };
  const std::string kept = "; CURRENT SURFACE KEPT";

  SUBCASE("truncated at every length") {
    CHECK(refused("") == "FILE DAMAGED: BAD.IGDSDATA (EMPTY FILE)" + kept);
    for (std::size_t n = 1; n < good.size(); ++n) {
      CAPTURE(n);
      std::string r = refused(good.substr(0, n));
      CHECK((r == "FILE DAMAGED: BAD.IGDSDATA (TRUNCATED)" + kept ||
             (n >= 24 && r == "FILE DAMAGED: BAD.IGDSDATA (LENGTH)" + kept)));
    }
  }
  SUBCASE("every single byte changed") {
    for (std::size_t i = 0; i < good.size(); ++i) {
      for (unsigned char x : {0x01, 0x80, 0xFF}) {
        std::string b = good;
        b[i] = static_cast<char>(b[i] ^ x);
        CAPTURE(i);
        CHECK(refused(b).starts_with("FILE DAMAGED: BAD.IGDSDATA ("));
      }
    }
  }
  SUBCASE("the reasons") {
    CHECK(refused("PK\x03\x04 a zip file") ==
          "FILE DAMAGED: BAD.IGDSDATA (NOT AN IGDSDATA FILE)" + kept);
    std::string b = good;
    b[good.size() - 20] ^= 0x10;  // a value: only the checksum can tell
    CHECK(refused(b) == "FILE DAMAGED: BAD.IGDSDATA (CHECKSUM)" + kept);
    CHECK(refused(with_version(good, 2)) ==
          "FILE DAMAGED: BAD.IGDSDATA (FORMAT VERSION 2 OF A NEWER IGDS)" + kept);
    CHECK(refused(good + "x") == "FILE DAMAGED: BAD.IGDSDATA (LENGTH)" + kept);
    // A well-made file whose shapes do not agree with NOCUR and NOSTR.
    Workspace odd = small;
    odd.nocur = 3;
    disk::Writer w;
    disk::write_surface(w, odd);
    CHECK(refused(disk::frame("IGDSDATA", w.str())) ==
          "FILE DAMAGED: BAD.IGDSDATA (SHAPES)" + kept);
    // An image file under the name of a surface file.
    store_image(s.disk, "PIC", test::make_image(0, Projection::conic, 2, 2, 1));
    CHECK(refused(test::read_file(s.disk.path("PIC", "IGDSIMAG"))) ==
          "FILE DAMAGED: BAD.IGDSDATA (NOT AN IGDSDATA FILE)" + kept);
  }
  SUBCASE("a folder where the file should be") {
    fs::create_directory(bad);
    CHECK(report_of([&] { restore_surface(s.disk, "BAD", ws); }) ==
          "CANNOT READ BAD.IGDSDATA (IS A DIRECTORY)" + kept);
  }
  test::check_same_workspace(ws, before);
}

TEST_CASE("STORE FILE then DISPLAY FILE gives the image back bit for bit") {
  Scratch s;
  for (int what : {0, 1}) {
    Image image = test::make_image(what, Projection::assonometric, 7, 9, 42 + what);
    store_image(s.disk, "PIC", image);
    Image back = load_image(s.disk, "PIC");
    CHECK(
        test::same_bits(std::make_shared<const Image>(back), std::make_shared<const Image>(image)));
  }
  Image empty;
  store_image(s.disk, "EMPTY", empty);
  CHECK(load_image(s.disk, "EMPTY") == empty);
  CHECK(files_in(s.dir.path()) == std::set<std::string>{"PIC.IGDSIMAG", "EMPTY.IGDSIMAG"});
}

TEST_CASE("a damaged IGDSIMAG is refused with the current image kept") {
  Scratch s;
  store_image(s.disk, "PIC", test::make_image(1, Projection::conic, 2, 3, 5));
  std::string good = test::read_file(s.disk.path("PIC", "IGDSIMAG"));
  for (std::size_t n = 0; n < good.size(); n += 7) {
    test::rewrite_file(s.disk.path("PIC", "IGDSIMAG"), good.substr(0, n));
    CHECK(
        report_of([&] { load_image(s.disk, "PIC"); }).starts_with("FILE DAMAGED: PIC.IGDSIMAG ("));
  }
  std::string b = good;
  b[40] ^= 4;
  test::rewrite_file(s.disk.path("PIC", "IGDSIMAG"), b);
  CHECK(report_of([&] { load_image(s.disk, "PIC"); }) ==
        "FILE DAMAGED: PIC.IGDSIMAG (CHECKSUM); CURRENT IMAGE KEPT");
  // A projection code the manual does not have.
  disk::Writer w;
  w.i32(1);
  w.i32(9);
  for (int i = 0; i < 3; ++i) w.f64(0);
  w.array(Array{});
  w.array(Array{});
  test::rewrite_file(s.disk.path("PIC", "IGDSIMAG"), disk::frame("IGDSIMAG", w.str()));
  CHECK(report_of([&] { load_image(s.disk, "PIC"); }) ==
        "FILE DAMAGED: PIC.IGDSIMAG (FORMAT); CURRENT IMAGE KEPT");
}

TEST_CASE("a disk that refuses a write: clear report, old file kept, no temporary left") {
  Scratch s;
  Workspace first = test::make_workspace(2, 2, 1, 1);
  save_surface(s.disk, "HULL", first);
  const std::string old = test::read_file(s.disk.path("HULL", "IGDSDATA"));
  Workspace second = test::make_workspace(3, 3, 2, 2);

  SUBCASE("a folder is where the temporary must go") {
    fs::create_directory(disk::temporary_for(s.disk.path("HULL", "IGDSDATA")));
    CHECK(report_of([&] { save_surface(s.disk, "HULL", second); }) ==
          "CANNOT WRITE HULL.IGDSDATA (IS A DIRECTORY); NO FILE CHANGED");
    fs::remove(disk::temporary_for(s.disk.path("HULL", "IGDSDATA")));
  }
  SUBCASE("a symbolic link is where the temporary must go") {
    test::TempDir elsewhere;
    fs::create_symlink(elsewhere.path() / "target",
                       disk::temporary_for(s.disk.path("HULL", "IGDSDATA")));
    CHECK(report_of([&] { save_surface(s.disk, "HULL", second); }) ==
          "CANNOT WRITE HULL.IGDSDATA (A SYMBOLIC LINK IS IN THE WAY); NO FILE CHANGED");
    CHECK(fs::is_empty(elsewhere.path()));
    fs::remove(disk::temporary_for(s.disk.path("HULL", "IGDSDATA")));
  }
  SUBCASE("a folder is where the file must go") {
    fs::create_directory(s.disk.path("PIC", "IGDSIMAG"));
    CHECK(report_of([&] { store_image(s.disk, "PIC", *second.image); }) ==
          "CANNOT WRITE PIC.IGDSIMAG (IS A DIRECTORY); NO FILE CHANGED");
    CHECK(fs::is_directory(s.disk.path("PIC", "IGDSIMAG")));
    fs::remove(s.disk.path("PIC", "IGDSIMAG"));
  }
  SUBCASE("the disk fills up (simulated) at every stage of the write") {
    for (std::size_t limit : {0, 1, 100, 1000}) {
      disk::set_write_limit_for_testing(limit);
      std::string r = report_of([&] { save_surface(s.disk, "HULL", second); });
      disk::set_write_limit_for_testing(std::nullopt);
      CHECK(r == "CANNOT WRITE HULL.IGDSDATA (NO SPACE LEFT ON DEVICE); NO FILE CHANGED");
    }
  }
  CHECK(test::read_file(s.disk.path("HULL", "IGDSDATA")) == old);
  CHECK(files_in(s.dir.path()) == std::set<std::string>{"HULL.IGDSDATA"});
}

TEST_CASE("a really full disk and a read-only disk (tmpfs; needs the right to mount)") {
  test::TempDir dir;
  test::SmallDisk small(dir.path() / "disk", 64);
  IGDS_SKIP_UNLESS(small.mounted(), "cannot mount a tmpfs here (root can)");
  Disk disk(small.path());
  Workspace fits = test::make_workspace(2, 2, 1, 1, false);
  save_surface(disk, "HULL", fits);
  std::string old = test::read_file(disk.path("HULL", "IGDSDATA"));
  Workspace big = test::make_workspace(10, 10, 10, 10, false);  // INTPN alone: 240 KB
  CHECK(report_of([&] { save_surface(disk, "HULL", big); }) ==
        "CANNOT WRITE HULL.IGDSDATA (NO SPACE LEFT ON DEVICE); NO FILE CHANGED");
  CHECK(test::read_file(disk.path("HULL", "IGDSDATA")) == old);
  CHECK(files_in(small.path()) == std::set<std::string>{"HULL.IGDSDATA"});

  REQUIRE(small.make_read_only());
  CHECK(report_of([&] { save_surface(disk, "HULL", fits); }) ==
        "CANNOT WRITE HULL.IGDSDATA (READ-ONLY FILE SYSTEM); NO FILE CHANGED");
  CHECK(report_of([&] { write_char(disk, "HULL", fits); }) ==
        "CANNOT WRITE HULL.IGDSCHAR (READ-ONLY FILE SYSTEM); NO FILE CHANGED");
  Workspace ws;
  restore_surface(disk, "HULL", ws);
  test::check_same_surface(ws, fits);
}
