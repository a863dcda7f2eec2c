// SAVE/RESTORE (IGDSDATA), STORE FILE/DISPLAY FILE (IGDSIMAG): exact round trips, and every
// kind of bad file or refusing disk gets a clear report and loses nothing.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <stdexcept>
#include <thread>

#include "tests/kernels/helpers.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/small_disk.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/files.h"
#include "workspace/disk/frame.h"
#include "workspace/error.h"
#include "workspace/images.h"
#include "workspace/kernels/interrupt.h"
#include "workspace/kernels/parallel.h"
#include "workspace/text_out.h"

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
  // Images and STATUS are not part of a surface, but for STATUS[3] and STATUS[4] (its twists and
  // AUTO mark, zero in this one).
  CHECK(test::same_bits(ws.image, before.image));
  CHECK(test::same_bits(ws.temp1, before.temp1));
  auto status = before.status;
  status[Workspace::status_twists] = status[Workspace::status_auto] = 0;
  CHECK(ws.status == status);
}

TEST_CASE("RESTORE of an interpolated surface keeps the tangents it was made with") {
  Scratch s;
  const Workspace saved = test::make_interpolated(6, 5, 2, 1);
  save_surface(s.disk, "HULL", saved);
  Workspace ws;
  restore_surface(s.disk, "HULL", ws);
  test::check_same_surface(ws, saved);
  test::check_kept_splines(ws);
}

TEST_CASE("SAVE stores PATCHES and INTPN only when they are not the interpolation of the inputs") {
  Scratch s;
  Workspace made = test::make_interpolated(30, 30, 4, 4);
  REQUIRE(made.changes.derived);
  save_surface(s.disk, "MADE", made);
  const std::size_t arrays =
      (test::given_patches(made).size() + made.intpn.size()) * sizeof(double);
  const std::string file = test::read_file(s.disk.path("MADE", "IGDSDATA"));
  CHECK(file.size() < arrays / 10);
  Workspace ws = test::make_workspace(2, 3, 0, 0);
  restore_surface(s.disk, "MADE", ws);
  test::check_same_surface(ws, made);
  CHECK(ws.changes.derived);
  // Arrays of their own (as END APL assigns them) are stored, and come back as they were.
  Workspace own = made;
  test::own_surface(own);
  own.intpn.ravel[7] += 1;
  save_surface(s.disk, "OWN", own);
  CHECK(test::read_file(s.disk.path("OWN", "IGDSDATA")).size() > arrays);
  restore_surface(s.disk, "OWN", ws);
  test::check_same_surface(ws, own);
  CHECK(!ws.changes.derived);
  // The mark between INPTG and what follows is 0 or 1.
  disk::Writer w;
  w.i32(made.nocur), w.i32(made.nostr), w.i32(made.intcu), w.i32(made.intst);
  w.array(made.inppn), w.array(made.inptg), w.i32(2), w.i32(0), w.i32(0);
  test::rewrite_file(s.disk.path("BAD", "IGDSDATA"), disk::frame("IGDSDATA", w.str(), 2));
  CHECK(report_of([&] { restore_surface(s.disk, "BAD", ws); }) ==
        "FILE DAMAGED: BAD.IGDSDATA (FORMAT); CURRENT SURFACE KEPT");
  test::check_same_surface(ws, own);
}

TEST_CASE("a version 1 IGDSDATA, PATCHES and INTPN always in it, is read as before") {
  Scratch s;
  const Workspace made = test::make_interpolated(6, 5, 2, 3);
  auto version_1 = [&](const Workspace& from, bool modes) {
    const Array patches = test::given_patches(from);  // igds 1.0 kept them
    disk::Writer w;
    w.i32(from.nocur), w.i32(from.nostr), w.i32(from.intcu), w.i32(from.intst);
    w.array(from.inppn), w.array(from.inptg), w.array(patches), w.array(from.intpn);
    if (modes) w.i32(0), w.i32(1);
    test::rewrite_file(s.disk.path("OLD", "IGDSDATA"), disk::frame("IGDSDATA", w.str(), 1));
    Workspace ws;
    restore_surface(s.disk, "OLD", ws);
    return ws;
  };
  Workspace ws = version_1(made, true);
  test::check_same_surface(ws, made);
  CHECK(ws.changes.derived);
  CHECK(ws.auto_tangents());
  ws = version_1(made, false);  // written before the twists and AUTO mark
  test::check_same_surface(ws, made);
  CHECK(!ws.auto_tangents());
  // Arrays that are not the interpolation are kept.
  Workspace own = made;
  keep_patches(own);
  own.patches.ravel[3] = 0.5;
  ws = version_1(own, false);
  CHECK(ws.patches == own.patches);
  CHECK(!ws.changes.derived);
}

TEST_CASE("a large SAVE, written a piece at a time, gives the same surface back") {
  Scratch s;
  Workspace saved = test::make_workspace(30, 30, 25, 25, false);  // INTPN alone: 13.7 MB
  save_surface(s.disk, "HULL", saved);
  Workspace ws;
  restore_surface(s.disk, "HULL", ws);
  test::check_same_surface(ws, saved);
  // Under a write limit (a full disk's writes, a few bytes short at a time) the same file.
  disk::set_write_limit_for_testing(std::size_t{1} << 30);
  save_surface(s.disk, "AGAIN", saved);
  disk::set_write_limit_for_testing(std::nullopt);
  CHECK(test::read_file(s.disk.path("AGAIN", "IGDSDATA")) ==
        test::read_file(s.disk.path("HULL", "IGDSDATA")));
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
    CHECK(refused(with_version(good, 3)) ==
          "FILE DAMAGED: BAD.IGDSDATA (FORMAT VERSION 3 OF A NEWER IGDS)" + kept);
    CHECK(refused(good + "x") == "FILE DAMAGED: BAD.IGDSDATA (LENGTH)" + kept);
    // A well-made file whose shapes do not agree with NOCUR and NOSTR.
    Workspace odd = small;
    odd.nocur = 3;
    save_surface(s.disk, "ODD", odd);
    CHECK(refused(test::read_file(s.disk.path("ODD", "IGDSDATA"))) ==
          "FILE DAMAGED: BAD.IGDSDATA (SHAPES: INPPN IS 4 BY 3, NOT 6 BY 3)" + kept);
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
    // The box of the points, found as they were checked.
    CHECK(back.extent == test::box_of_points(image.points.data(), image.points.size() / 2));
  }
  // A box whose four sides are four points' own: x is not taken for y.
  Image wide = test::make_image(1, Projection::orthogonal, 2, 3, 5);
  wide.points.ravel = {0, -1, 4, 2, -3, 7, 1, 1, 2, 0, 5, -2};
  store_image(s.disk, "WIDE", wide);
  CHECK(load_image(s.disk, "WIDE").extent == std::array<double, 4>{-3, -2, 5, 7});
  Image empty;
  store_image(s.disk, "EMPTY", empty);
  CHECK(load_image(s.disk, "EMPTY") == empty);
  CHECK_FALSE(load_image(s.disk, "EMPTY").extent);
  CHECK(files_in(s.dir.path()) ==
        std::set<std::string>{"PIC.IGDSIMAG", "WIDE.IGDSIMAG", "EMPTY.IGDSIMAG"});
}

TEST_CASE("a hidden-line image kept by STORE FILE comes back with its depths, and says so") {
  Scratch s;
  const Workspace ws = test::make_interpolated(5, 6, 2, 2);
  const Image image = image_of(ws, {1, Projection::conic, {90, -70, 60}, true});
  REQUIRE(image.nearness.shape == std::vector<std::size_t>{ws.intpn.shape[0], ws.intpn.shape[1]});
  store_image(s.disk, "PIC", image);
  const Image back = load_image(s.disk, "PIC");
  CHECK(back.desim.hidden);
  CHECK(back == image);
  // A forged file: the flag on an input image, or depths that do not fit its points.
  auto forged = [&](int what, const Array& points, const Array& depths) {
    disk::Writer w;
    w.i32(what | 0x100);
    w.i32(2);
    for (double p : {110.0, 130.0, 120.0}) w.f64(p);
    w.array(points);
    w.array(Array{});
    w.array(depths);
    test::rewrite_file(s.disk.path("PIC", "IGDSIMAG"), disk::frame("IGDSIMAG", w.str()));
    return report_of([&] { load_image(s.disk, "PIC"); });
  };
  CHECK(forged(0, Array({2, 2, 2}), Array({2, 2})) ==
        "FILE DAMAGED: PIC.IGDSIMAG (FORMAT: IMAGE IS NOT A SURFACE: ITS HIDDEN LINES CANNOT BE "
        "REMOVED); CURRENT IMAGE KEPT");
  CHECK(forged(1, Array({2, 2, 2}), Array({2, 3})) ==
        "FILE DAMAGED: PIC.IGDSIMAG (FORMAT: THE DEPTHS OF IMAGE ARE 2 BY 3, NOT ONE FOR EACH "
        "POINT); CURRENT IMAGE KEPT");
  Array nan({2, 2});
  nan.ravel[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK(forged(1, Array({2, 2, 2}), nan) ==
        "FILE DAMAGED: PIC.IGDSIMAG (FORMAT: A DEPTH OF IMAGE IS NOT A FINITE NUMBER); CURRENT "
        "IMAGE KEPT");
  CHECK(forged(1, Array({2, 2, 2}), Array({2, 2})) == "(no report)");
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
        "FILE DAMAGED: PIC.IGDSIMAG (FORMAT: DESIM[2] IS NOT A PROJECTION (1 TO 4)); CURRENT "
        "IMAGE KEPT");
}

TEST_CASE("DISPLAY COMBS in an IGDSIMAG: kept exactly; forged combs refused") {
  Scratch s;
  Image combs = test::make_image(3, Projection::orthogonal, 2, 3, 5);
  combs.combs = Array({2, 3, 4});
  for (std::size_t k = 0; k < combs.combs.size(); ++k) combs.combs.ravel[k] = 0.25 * double(k);
  combs.comb_scale = 20;
  store_image(s.disk, "PIC", combs);
  const Image back = load_image(s.disk, "PIC");
  CHECK(back == combs);
  CHECK(back.combs == combs.combs);
  CHECK(back.comb_scale == 20);
  auto forged = [&](auto&& change, const std::string& reason) {
    CAPTURE(reason);
    Image bad = combs;
    change(bad);
    disk::Writer w;
    w.image(bad);
    test::rewrite_file(s.disk.path("PIC", "IGDSIMAG"), disk::frame("IGDSIMAG", w.str()));
    CHECK(report_of([&] { load_image(s.disk, "PIC"); }) ==
          "FILE DAMAGED: PIC.IGDSIMAG (FORMAT: " + reason + "); CURRENT IMAGE KEPT");
  };
  forged(
      [](Image& i) {
        i.combs = Array({3, 2, 4});
      },
      "THE COMBS OF IMAGE ARE 3 BY 2 BY 4, NOT 2 BY 3 BY 4");
  forged([](Image& i) { i.combs.ravel[5] = std::nan(""); },
         "COMB 3 OF IMAGE IS NOT A FINITE NUMBER");
  forged([](Image& i) { i.comb_scale = -1; },
         "THE COMB SCALE OF IMAGE IS NOT A FINITE NUMBER, 0 OR MORE");
  forged([](Image& i) { i.desim.what = 7; }, "DESIM[1] IS NOT 0, 1, 2 OR 3");
  // A point that is not finite, found in the pass that finds the points' box.
  forged([](Image& i) { i.points.ravel[7] = HUGE_VAL; },
         "PLANE 2 ROW 1 OF IMAGE IS NOT A FINITE NUMBER");
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
  SUBCASE("a folder where the file must go keeps the old file's temporary name free") {
    fs::create_directory(s.disk.path("NEW", "IGDSDATA"));
    CHECK(report_of([&] { save_surface(s.disk, "NEW", second); }) ==
          "CANNOT WRITE NEW.IGDSDATA (IS A DIRECTORY); NO FILE CHANGED");
    fs::remove(s.disk.path("NEW", "IGDSDATA"));
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

TEST_CASE("a link put where a temporary goes is removed, never written through") {
  Scratch s;
  test::TempDir elsewhere;
  const fs::path outside = elsewhere.path() / "precious";
  test::rewrite_file(outside, "not igds's");
  const fs::path tmp = disk::temporary_for(s.disk.path("HULL", "IGDSDATA"));
  Workspace w = test::make_workspace(3, 3, 1, 1);

  SUBCASE("a hard link") {
    fs::create_hard_link(outside, tmp);
  }
  SUBCASE("a symbolic link") {
    fs::create_symlink(outside, tmp);
  }
  SUBCASE("a symbolic link to nothing yet") {
    fs::remove(outside);
    fs::create_symlink(outside, tmp);
  }
  save_surface(s.disk, "HULL", w);
  Workspace back;
  restore_surface(s.disk, "HULL", back);
  test::check_same_surface(back, w);
  if (fs::exists(outside)) CHECK(test::read_file(outside) == "not igds's");
  CHECK(files_in(s.dir.path()) == std::set<std::string>{"HULL.IGDSDATA"});
  CHECK(files_in(elsewhere.path()).size() <= 1);
}

TEST_CASE("the checksum of bytes given in runs is the checksum of the whole") {
  std::string bytes;
  for (int i = 0; i < 1000; ++i) bytes += static_cast<char>(i * 37 + i / 7);
  for (std::size_t cut1 : {0u, 1u, 7u, 31u, 32u, 33u, 100u})
    for (std::size_t cut2 : {0u, 5u, 64u, 500u}) {
      disk::Checksum sum;
      std::string_view v(bytes);
      const std::size_t a = std::min(cut1, v.size()), b = std::min(a + cut2, v.size());
      sum.add(v.substr(0, a));
      sum.add(v.substr(a, b - a));
      sum.add(v.substr(b));
      CHECK(sum.value() == disk::checksum(bytes));
    }
  // And a frame built of borrowed runs is the frame of the joined payload.
  disk::Writer w;
  w.u32(7);
  Array a({10, 3});
  for (std::size_t i = 0; i < a.size(); ++i) a.ravel[i] = 0.5 * double(i);
  w.array(a);
  w.bytes(std::string(5000, 'x'));
  const std::string joined = w.str();
  CHECK(disk::frame("IGDSDATA", w).str() == disk::frame("IGDSDATA", joined));
}

TEST_CASE("a framed file read in one pass: the payload read and its checksum said before it") {
  // A payload of a number, an array of many runs of the one-pass copy, a small array, a number.
  disk::Writer w;
  w.u32(7);
  Array big({70001, 3});
  for (std::size_t i = 0; i < big.size(); ++i) big.ravel[i] = 0.25 * double(i) - 3;
  const Array small({2, 2});  // borrowed by the writer, as big is
  w.array(big);
  w.array(small);
  w.u64(42);
  const std::string good = disk::frame("IGDSDATA", w).str();
  struct Read {
    std::uint32_t version, first;
    Array big, small;
    std::uint64_t last;
  };
  auto read_all = [](disk::Reader& r, std::uint32_t version) {
    Read out{version, r.u32(), r.array(), r.array(), 0};
    out.last = r.u64();
    r.finish();
    return out;
  };
  auto read_first = [](disk::Reader& r, std::uint32_t) { return r.u32(); };
  auto reason = [&](const std::string& file, auto read) {
    try {
      disk::read_framed("IGDSDATA", file, read);
      return std::string("(read)");
    } catch (const disk::Damage& d) {
      return d.reason();
    }
  };
  const Read back = disk::read_framed("IGDSDATA", good, read_all);
  CHECK(back.version == 1);
  CHECK(back.first == 7);
  CHECK(back.big == big);
  CHECK(back.small == small);
  CHECK(back.last == 42);
  CHECK(disk::read_framed("IGDSDATA", good, read_first) == 7u);
  // The array's rank, right after the first number.
  const std::size_t rank_at = disk::frame_header_bytes + 4;
  for (std::size_t at : {std::size_t{0}, std::size_t{8}, rank_at, rank_at + 40,
                         rank_at + 40 + 3 * 65536 + 5, good.size() / 2, good.size() - 9}) {
    CAPTURE(at);
    std::string b = good;
    b[at] ^= 0x10;
    // The magic word, the version and the length have their own reports.
    const std::string expected = at == 0   ? "NOT AN IGDSDATA FILE"
                                 : at == 8 ? "FORMAT VERSION 17 OF A NEWER IGDS"
                                           : "CHECKSUM";
    CHECK(reason(b, read_all) == expected);
    // Bytes the reading never looks at are summed all the same.
    CHECK(reason(b, read_first) == expected);
  }
  // A rank that does not read: the checksum first, then, framed anew, the payload's own report.
  std::string b = good;
  b[rank_at] = 99;
  CHECK(reason(b, read_all) == "CHECKSUM");
  const std::string framed_anew = disk::frame(
      "IGDSDATA",
      std::string_view(b).substr(disk::frame_header_bytes,
                                 b.size() - disk::frame_header_bytes - disk::frame_trailer_bytes));
  CHECK(reason(framed_anew, read_all) == "FORMAT");
  // What else the reading throws comes through when the checksum holds, and not otherwise.
  auto refuse = [](disk::Reader&, std::uint32_t) -> int { throw std::runtime_error("no"); };
  CHECK_THROWS_AS(disk::read_framed("IGDSDATA", good, refuse), std::runtime_error);
  b = good;
  b[good.size() / 2] ^= 1;
  CHECK(reason(b, refuse) == "CHECKSUM");
}

TEST_CASE("a file larger than any legal one is refused before it is read") {
  Scratch s;
  const fs::path big = s.disk.path("BIG", "IGDSDATA");
  { std::ofstream out(big); }
  fs::resize_file(big, max_surface_file_bytes() + 1);  // sparse: no room taken
  Workspace ws = test::make_workspace(2, 2, 0, 0);
  CHECK(report_of([&] { restore_surface(s.disk, "BIG", ws); }) ==
        "CANNOT READ BIG.IGDSDATA (FILE TOO LARGE); CURRENT SURFACE KEPT");
  const fs::path pic = s.disk.path("BIG", "IGDSIMAG");
  { std::ofstream out(pic); }
  fs::resize_file(pic, std::uintmax_t(40) << 30);
  CHECK(report_of([&] { load_image(s.disk, "BIG"); }) ==
        "CANNOT READ BIG.IGDSIMAG (FILE TOO LARGE); CURRENT IMAGE KEPT");
}

TEST_CASE("RESTORE applies the 4,000,000-point limit to what the file says") {
  Scratch s;
  // A small file whose INTCU and INTST ask for 10^8 points, with PATCHES and INTPN empty.
  Workspace w = test::make_workspace(2, 2, 0, 0, false);
  w.intcu = w.intst = 9998;
  w.patches = Array{};
  w.intpn = Array{};
  save_surface(s.disk, "HUGE", w);
  Workspace ws = test::make_workspace(2, 2, 0, 0);
  const Workspace before = ws;
  CHECK(report_of([&] { restore_surface(s.disk, "HUGE", ws); }) ==
        "FILE DAMAGED: HUGE.IGDSDATA (SHAPES: 100000000 INTERPOLATED POINTS, MORE THAN 4000000); "
        "CURRENT SURFACE KEPT");
  test::check_same_workspace(ws, before);
  // One point more than the limit: a line of two points with 3999999 stringers between.
  Workspace line;
  line.nocur = 1;
  line.nostr = 2;
  line.intst = 3999999;
  line.inppn = Array({2, 3});
  line.inppn.ravel = {0, 0, 0, 1, 0, 0};
  line.inptg = Array({6, 4});
  save_surface(s.disk, "OVER", line);
  CHECK(report_of([&] { restore_surface(s.disk, "OVER", ws); }) ==
        "FILE DAMAGED: OVER.IGDSDATA (SHAPES: 4000001 INTERPOLATED POINTS, MORE THAN 4000000); "
        "CURRENT SURFACE KEPT");
  line.intst = 3999998;  // exactly the limit
  save_surface(s.disk, "LIMIT", line);
  restore_surface(s.disk, "LIMIT", ws);
  CHECK(ws.intst == 3999998);
}

namespace igds {

// A text of several pieces with a hole filled later, as EXPORT IGES writes its directory.
void holed_text(TextOut& out) {
  // A text made aside in pieces of a megabyte (as put_in_order's are), put whole: a file takes
  // its runs from where they are, after the bytes in its buffer.
  PiecesOut aside;
  aside.put('x', 1500000);
  aside.put('y', 1500000);
  out.put("head\n");
  const std::uint64_t hole = out.offset();
  out.skip(10);
  aside.put_into(out);
  for (int k = 0; k < 3000000; ++k) {
    char* w = out.room(4);
    w[0] = char('a' + k % 26), w[1] = 'b', w[2] = 'c';
    out.commit(w + 3);
  }
  aside.put_into(out);
  const std::uint64_t end = out.offset();
  out.seek(hole);
  out.put("0123456789");
  out.seek(end);
  out.put('\n');
}

TEST_CASE("a made text: pieces, a hole written later, the same in a string and in a file") {
  StringOut text;
  holed_text(text);
  const std::string expected = text.take_text();
  REQUIRE(expected.size() == 5 + 10 + 3000000 + 9000000 + 3000000 + 1);
  CHECK(expected.substr(0, 15) == "head\n0123456789");
  CHECK(expected.substr(15, 3000000) == std::string(1500000, 'x') + std::string(1500000, 'y'));
  CHECK(expected.substr(3000015, 6) == "abcbbc");
  CHECK(expected.substr(12000015, 3000000) == expected.substr(15, 3000000));
  Scratch s;
  CHECK(write_user_file(s.disk, "TEXT", "IGS", holed_text) == expected.size());
  std::ifstream in(s.disk.path("TEXT", "IGS"), std::ios::binary);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(written == expected);
  // A writer that fails part way, or a disk that fills, leaves the file as it was.
  CHECK_THROWS_AS(write_user_file(s.disk, "TEXT", "IGS",
                                  [](TextOut& out) {
                                    holed_text(out);
                                    throw std::runtime_error("writer failed");
                                  }),
                  std::runtime_error);
  // The disk fills in the runs of a text made aside, then in the buffer's bytes.
  for (const std::size_t limit : {std::size_t{1} << 20, std::size_t{5} << 20}) {
    disk::set_write_limit_for_testing(limit);
    CHECK_THROWS_AS(write_user_file(s.disk, "TEXT", "IGS", holed_text), Report);
  }
  disk::set_write_limit_for_testing(std::nullopt);
  std::ifstream again(s.disk.path("TEXT", "IGS"), std::ios::binary);
  CHECK(std::string((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>()) ==
        expected);
  CHECK(disk::folder_entries(s.dir.path()).size() == 1);
}

TEST_CASE("a disk that fills during a large write: the report, and no file left") {
  test::TempDir dir;
  test::SmallDisk small(dir.path() / "disk", 6 * 1024);  // room for one piece and a half
  IGDS_SKIP_UNLESS(small.mounted(), "cannot mount a tmpfs here (root can)");
  Disk disk(small.path());
  std::string report;
  try {
    write_user_file(disk, "TEXT", "IGS", holed_text);
  } catch (const Report& r) {
    report = r.what();
  }
  CHECK(report == "CANNOT WRITE TEXT.IGS (NO SPACE LEFT ON DEVICE); NO FILE CHANGED");
  CHECK(disk::folder_entries(small.path()).empty());
}

}  // namespace igds

namespace igds {

TEST_CASE("put_each: the items' text in order, made on the cores or on one, string or file") {
  // Lines of 1 to 60 characters, several blocks of them, each naming its number.
  auto make = [](char* w, std::size_t i) {
    const std::string line = std::to_string(i) + std::string(i % 50, char('a' + i % 26)) + '\n';
    return std::copy(line.begin(), line.end(), w);
  };
  const std::size_t count = 400000;
  std::string expected;
  for (std::size_t i = 0; i < count; ++i) {
    char line[64];
    expected.append(line, make(line, i));
  }
  REQUIRE(count * 64 > (std::size_t{16} << 20));  // more than one block of 8 MB
  StringOut text;
  text.put("head\n");
  put_each(text, count / 3, 64, make);
  put_each(text, count - count / 3, 64,
           [&](char* w, std::size_t i) { return make(w, i + count / 3); });
  put_each(text, 0, 64, make);
  CHECK(text.take_text() == "head\n" + expected);
  Scratch s;
  const auto size = write_user_file(s.disk, "LINES", "IGS",
                                    [&](TextOut& out) { put_each(out, count, 64, make); });
  CHECK(size == expected.size());
  CHECK(test::read_file(s.disk.path("LINES", "IGS")) == expected);
}

TEST_CASE("put_each: a Ctrl-C waiting stops a text of many texts between them, not one of one") {
  block_interrupts();
  while (take_interrupt()) {
  }
  auto make = [](char* w, std::size_t) { return std::fill_n(w, 64, 'x'); };
  REQUIRE(::kill(::getpid(), SIGINT) == 0);
  // Less than 4 MB of room: made whole, the Ctrl-C left for the conversation.
  StringOut one;
  CHECK_NOTHROW(put_each(one, 1000, 64, make));
  CHECK(one.take_text().size() == 64000);
  CHECK(interrupt_pending());
  // 24 MB of text on the cores, in texts of 1 MB: the first put, then stopped, however many the
  // other threads made meanwhile.
  REQUIRE(put_each_text_bytes == std::size_t{1} << 20);
  StringOut many;
  CHECK_THROWS_AS(put_each(many, 3 * 131072, 64, make), Interrupted);
  CHECK(many.size() == put_each_text_bytes);
  CHECK(take_interrupt());
}

// The threads of this process now.
std::size_t threads_now() {
  return static_cast<std::size_t>(
      std::distance(fs::directory_iterator("/proc/self/task"), fs::directory_iterator()));
}

TEST_CASE(
    "put_in_order: texts of any length in order and a text that fails stops it with its threads "
    "joined") {
  // Texts of 0 to about 3 MB, each of its number's letter.
  auto length = [](std::size_t k) { return k % 7 == 3 ? 0 : (k * 7919) % (3 << 20); };
  auto make = [&](std::size_t k, TextOut& to) { to.put(char('a' + k % 26), length(k)); };
  const std::size_t texts = 40;
  std::string expected;
  for (std::size_t k = 0; k < texts; ++k) expected.append(length(k), char('a' + k % 26));
  const std::size_t before = threads_now();
  StringOut text;
  put_in_order(text, texts, make);
  CHECK(text.take_text() == expected);
  Scratch s;
  CHECK(write_user_file(s.disk, "TEXTS", "IGS",
                        [&](TextOut& out) { put_in_order(out, texts, make); }) == expected.size());
  CHECK(test::read_file(s.disk.path("TEXTS", "IGS")) == expected);
  // Text 17 throws before it writes: the texts before it are put, and the error comes here.
  StringOut cut;
  CHECK_THROWS_AS(put_in_order(cut, texts,
                               [&](std::size_t k, TextOut& to) {
                                 if (k == 17) throw std::runtime_error("text 17");
                                 make(k, to);
                               }),
                  std::runtime_error);
  std::size_t first17 = 0;
  for (std::size_t k = 0; k < 17; ++k) first17 += length(k);
  CHECK(cut.take_text() == expected.substr(0, first17));
  // A text that fails on another thread: its error comes here too (tried until one does).
  if (cores() > 1) {
    const auto here = std::this_thread::get_id();
    bool failed_elsewhere = false;
    for (int attempt = 0; attempt < 1000 && !failed_elsewhere; ++attempt) {
      std::atomic<bool> thrown{false};
      StringOut some;
      try {
        put_in_order(some, texts, [&](std::size_t k, TextOut& to) {
          if (std::this_thread::get_id() != here) {
            thrown = true;
            throw std::runtime_error("elsewhere");
          }
          make(k, to);
        });
        CHECK_FALSE(thrown.load());
      } catch (const std::runtime_error&) {
        failed_elsewhere = true;
      }
    }
    CHECK(failed_elsewhere);
  }
  CHECK(threads_now() == before);
}

TEST_CASE("put_each: an item longer than it said is a fault, seen before another byte is put") {
  StringOut text;
  CHECK_THROWS_AS(put_each(text, 10, 4,
                           [](char* w, std::size_t i) {
                             const std::size_t n = i == 7 ? 5 : 4;
                             std::fill_n(w, n, 'x');
                             return w + n;
                           }),
                  std::logic_error);
}

}  // namespace igds

namespace igds {

TEST_CASE("a new file made while it is written never replaces one of that name") {
  Scratch s;
  auto text = [](std::string_view words) { return [words](TextOut& out) { out.put(words); }; };
  CHECK(write_new_user_file(s.disk, "PLOT0001", "HPGL", text("IN;PU;SP0;")) == 10u);
  // Already there: nothing written, the file as it was, no temporary left.
  CHECK(write_new_user_file(s.disk, "PLOT0001", "HPGL", text("IN;")) == std::nullopt);
  std::ifstream in(s.disk.path("PLOT0001", "HPGL"), std::ios::binary);
  CHECK(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()) ==
        "IN;PU;SP0;");
  CHECK(disk::folder_entries(s.dir.path()).size() == 1);
}

}  // namespace igds
