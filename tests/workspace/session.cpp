// The session on the disk: BINSAVE.IGDSCONT saved after every change, loaded at start; never
// half-loaded; only what changed is rewritten; one igds per disk.
#include "workspace/disk/session.h"

#include <doctest/doctest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <thread>

#include <fmt/format.h>

#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/forge.h"
#include "tests/workspace/small_disk.h"
#include "workspace/disk/files.h"
#include "workspace/disk/frame.h"
#include "workspace/disk/session_file.h"
#include "workspace/error.h"
#include "workspace/journal.h"
#include "workspace/kernels/data_error.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

std::set<std::string> files_of_type(const fs::path& dir, std::string_view type) {
  std::set<std::string> names;
  for (const auto& n : files_in(dir))
    if (n.ends_with(type)) names.insert(n);
  return names;
}

// Inode numbers of the session's variable files: a file rewritten would get a new one.
std::map<std::string, ino_t> variable_files(const fs::path& dir) {
  std::map<std::string, ino_t> files;
  for (const auto& n : files_of_type(dir, ".IGDSVARS")) {
    struct stat st;
    REQUIRE(::stat((dir / n).c_str(), &st) == 0);
    files[n] = st.st_ino;
  }
  return files;
}

// Bytes this process has handed to write(2) so far (Linux /proc/self/io).
// Bytes written to files by the disk layer so far (what the write limit counts).
std::size_t bytes_written_so_far() {
  return disk::bytes_written_for_testing();
}

Workspace load_fresh(const Disk& disk, std::vector<std::string>* notices = nullptr) {
  Session session(disk);
  Workspace ws = session.load();
  if (notices) *notices = session.notices();
  return ws;
}

// `ws` saved as the session of a disk that has none, then loaded afresh.
Workspace saved_and_loaded(const Disk& disk, Workspace& ws,
                           std::vector<std::string>* notices = nullptr) {
  {
    Session session(disk);
    session.load();
    session.save(ws);
  }
  return load_fresh(disk, notices);
}

std::string report_of(auto&& f) {
  try {
    f();
  } catch (const Report& r) {
    return r.what();
  }
  return "(no report)";
}

struct Scratch {
  test::TempDir dir;
  Disk disk{dir.path()};
  fs::path session() const { return disk.path("BINSAVE", "IGDSCONT"); }
};

}  // namespace

TEST_CASE("the very first session starts empty and quietly") {
  Scratch s;
  std::vector<std::string> notices;
  CHECK(load_fresh(s.disk, &notices) == Workspace{});
  CHECK(notices.empty());
  // A clean end leaves nothing behind when nothing was saved.
  CHECK(fs::is_empty(s.dir.path()));
}

TEST_CASE("a saved session is loaded bit for bit, every variable") {
  Scratch s;
  Workspace ws = test::make_workspace(4, 5, 3, 2);
  std::vector<std::string> notices;
  Workspace back = saved_and_loaded(s.disk, ws, &notices);
  test::check_same_workspace(back, ws);
  CHECK(notices.empty());
  // The disk holds the session and the files of its large variables; no lock, no temporary.
  for (const auto& n : files_in(s.dir.path()))
    CHECK((n == "BINSAVE.IGDSCONT" || n.ends_with(".IGDSVARS")));

  SUBCASE("and the empty session after it too") {
    {
      Session session(s.disk);
      session.load();
      Workspace empty;
      session.save(empty);
    }
    test::check_same_workspace(load_fresh(s.disk), Workspace{});
    CHECK(files_in(s.dir.path()) == std::set<std::string>{"BINSAVE.IGDSCONT"});
  }
}

TEST_CASE("a surface made again at start keeps the tangents it was made with") {
  Scratch s;
  Workspace ws = test::make_interpolated(6, 5, 2, 1);
  const Workspace back = saved_and_loaded(s.disk, ws);
  test::check_same_surface(back, ws);
  test::check_kept_splines(back);
}

TEST_CASE("END APL's defined functions are kept with the session") {
  Scratch s;
  Workspace ws = test::make_workspace(3, 3, 1, 1);
  ws.functions = {{"Z←TOP A", "Z←⌈/,A[;;3]"}, {"HELLO", "'⍝ ¯1'"}};
  {
    Session session(s.disk);
    session.load();
    session.save(ws);
    // A function changed alone is a change: the session is written again.
    ws.functions.pop_back();
    session.save(ws);
  }
  test::check_same_workspace(load_fresh(s.disk), ws);
  // Counts that the file cannot hold are FORMAT, never a huge allocation.
  disk::SessionTable t;
  t.functions = {{"F"}};
  std::string bytes = disk::encode_session(t);
  CHECK(disk::decode_session(bytes).functions == t.functions);
  std::string crafted = bytes;
  crafted[crafted.size() - 10] = '\xFF';  // the count of functions, now 4278190081
  CHECK_THROWS_AS(disk::decode_session(crafted), disk::Damage);
  CHECK_THROWS_AS(disk::decode_session(bytes.substr(0, bytes.size() - 1)), disk::Damage);
}

TEST_CASE("END APL's own variables are kept with the session") {
  Scratch s;
  Workspace ws = test::make_workspace(3, 3, 1, 1);
  ws.apl_variables = {{"V", {3}, false, {1, 2, 3}, {}}, {"W", {2}, true, {}, U"⍴A"}};
  {
    Session session(s.disk);
    session.load();
    session.save(ws);
    // A variable changed alone is a change: the session is written again.
    ws.apl_variables.pop_back();
    session.save(ws);
  }
  CHECK(load_fresh(s.disk).apl_variables == ws.apl_variables);
}

TEST_CASE("a save rewrites only what changed") {
  Scratch s;
  Workspace ws = test::make_workspace(10, 10, 10, 10);  // INTPN 100 x 100 x 3, three images
  ws.intpn.ravel[17] = 0.0;
  std::optional<Session> open(std::in_place, s.disk);
  Session& session = *open;
  session.load();
  session.save(ws);
  auto before = variable_files(s.dir.path());
  CHECK(before.size() == 6);  // INPPN, INPTG, PATCHES, INTPN, IMAGE, TEMP1; TEMP2 is small

  SUBCASE("STATUS only: the small session file alone") {
    ws.status[0] = 1;
    std::size_t w0 = bytes_written_so_far();
    session.save(ws);
    std::size_t written = bytes_written_so_far() - w0;
    CHECK(written < 4096);
    CHECK(variable_files(s.dir.path()) == before);
    CHECK(fs::file_size(s.session()) < 4096);
  }
  SUBCASE("nothing: nothing written at all") {
    std::size_t w0 = bytes_written_so_far();
    session.save(ws);
    CHECK(bytes_written_so_far() - w0 == 0);
  }
  SUBCASE("an edited INTPN: its file and no other") {
    test::own_surface(ws);      // as the APL environment says it
    ws.intpn.ravel[17] = -0.0;  // was 0.0: only the bits tell
    REQUIRE(ws.intpn.ravel[17] == 0.0);
    session.save(ws);
    auto after = variable_files(s.dir.path());
    CHECK(after.size() == 6);
    std::size_t same = 0;
    for (const auto& [name, inode] : after) same += before.count(name) && before[name] == inode;
    CHECK(same == 4);  // INPPN and INPTG (a new record of the same pieces) and the images
  }
  SUBCASE("an image removed") {
    ws.temp1.reset();
    session.save(ws);
    CHECK(variable_files(s.dir.path()).size() == 5);
  }
  open.reset();  // a second look at the disk needs the lock
  std::vector<std::string> notices;
  test::check_same_workspace(load_fresh(s.disk, &notices), ws);
  CHECK_MESSAGE(notices.empty(), fmt::format("{}", fmt::join(notices, "\n")));
}

TEST_CASE("an interpolated surface is saved as its inputs, its images as recipes") {
  Scratch s;
  // 500 x 500 input points (6 MB of INPPN in three pieces), 1997 x 1997 interpolated points.
  Workspace ws = test::make_interpolated(500, 500, 3, 3);
  std::optional<Session> open(std::in_place, s.disk);
  open->load();
  std::size_t w0 = bytes_written_so_far();
  open->save(ws);
  const std::size_t inputs = (ws.inppn.size() + ws.inptg.size()) * sizeof(double);
  // The inputs and a little more: no INTPN (96 MB), no PATCHES (96 MB), no image (64 MB).
  CHECK(bytes_written_so_far() - w0 < inputs + 64 * 1024);

  SUBCASE("a DISPLAY: the recipe alone") {
    ws.image =
        std::make_shared<const Image>(image_of(ws, {1, Projection::conic, {9000, -7000, 600}}));
    w0 = bytes_written_so_far();
    open->save(ws);
    CHECK(bytes_written_so_far() - w0 < 4096);
  }
  SUBCASE("STORE SECOND of the current image: nothing but the session file") {
    ws.temp2 = ws.image;
    w0 = bytes_written_so_far();
    open->save(ws);
    CHECK(bytes_written_so_far() - w0 < 4096);
  }
  SUBCASE("CHANGE POINTS of one point: that piece of INPPN alone") {
    const auto before = variable_files(s.dir.path());
    ws.inppn.ravel[3 * 1000 + 2] += 5;  // point 1001
    Edits points = Edits::none();
    points.part(3 * 1000, 3 * 1001);
    Surface again = interpolate({ws.nocur, ws.nostr, ws.intcu, ws.intst, &ws.inppn, &ws.inptg});
    ws.patches = std::move(again.patches);
    ws.intpn = std::move(again.intpn);
    ws.changes.edited(points, Edits::none());
    w0 = bytes_written_so_far();
    open->save(ws);
    const std::size_t written = bytes_written_so_far() - w0;
    CHECK(written < disk::piece_bytes + 64 * 1024);
    CHECK(written > 1024);
    // The images drawn from the surface before keep it on the disk: its other pieces are shared.
    const auto after = variable_files(s.dir.path());
    CHECK(after.size() == before.size() + 1);
  }
  SUBCASE("CHANGE GRID: the new grid of the same inputs writes no piece at all") {
    ws.intcu = ws.intst = 2;
    Surface again = interpolate({ws.nocur, ws.nostr, ws.intcu, ws.intst, &ws.inppn, &ws.inptg});
    ws.patches = std::move(again.patches);
    ws.intpn = std::move(again.intpn);
    ws.changes.edited(Edits::none(), Edits::none());
    w0 = bytes_written_so_far();
    open->save(ws);
    CHECK(bytes_written_so_far() - w0 < 4096);
  }
  open.reset();
  std::vector<std::string> notices;
  const Workspace back = load_fresh(s.disk, &notices);
  CHECK(notices.empty());
  test::check_same_workspace(back, ws);
  // The images come back as images of their surfaces: the next DISPLAY FIRST of one of them
  // after a CHANGE still writes no image.
  CHECK(back.image->drawn_from != 0);
  CHECK(back.temp2->drawn_from != 0);
}

TEST_CASE("an image read from a file is kept as the session's own copy of that file") {
  Scratch s;
  Workspace ws = test::make_interpolated(40, 40, 10, 10);
  store_image(s.disk, "PIC", *ws.image);
  std::optional<Session> open(std::in_place, s.disk);
  open->load();
  open->save(ws);
  ws.image = std::make_shared<const Image>(load_image(s.disk, "PIC"));
  ws.temp1 = ws.image;
  open->save(ws);
  const auto copies = files_of_type(s.dir.path(), ".IGDSVIMG");
  REQUIRE(copies.size() == 1);
  // Its own file, never a second name of the user's (which a copy over it in place changes).
  struct stat user, kept;
  REQUIRE(::stat(s.disk.path("PIC", "IGDSIMAG").c_str(), &user) == 0);
  REQUIRE(::stat((s.dir.path() / *copies.begin()).c_str(), &kept) == 0);
  CHECK(user.st_ino != kept.st_ino);
  CHECK(user.st_nlink == 1);
  SUBCASE("the user's file copied over in place, as cp does") {
    store_image(s.disk, "OTHER", *ws.temp2);
    const std::string other = test::read_file(s.disk.path("OTHER", "IGDSIMAG"));
    std::ofstream(s.disk.path("PIC", "IGDSIMAG"), std::ios::binary | std::ios::trunc)
        .write(other.data(), static_cast<long>(other.size()));
  }
  SUBCASE("the user's file removed") {
    fs::remove(s.disk.path("PIC", "IGDSIMAG"));
  }
  open.reset();
  std::vector<std::string> notices;
  const Workspace back = load_fresh(s.disk, &notices);
  CHECK(notices.empty());
  test::check_same_workspace(back, ws);
  CHECK(back.image == back.temp1);  // one image, as before
  // The box of its points, found as the copy was checked, as DISPLAY FILE found it.
  REQUIRE(ws.image->extent);
  CHECK(back.image->extent == ws.image->extent);
}

TEST_CASE("a damaged copy of an image file costs that image alone, kept aside with a notice") {
  Scratch s;
  Workspace ws = test::make_interpolated(40, 40, 10, 10);
  store_image(s.disk, "PIC", *ws.temp2);
  {
    Session session(s.disk);
    session.load();
    ws.temp1 = std::make_shared<const Image>(load_image(s.disk, "PIC"));
    session.save(ws);
  }
  const auto copies = files_of_type(s.dir.path(), ".IGDSVIMG");
  REQUIRE(copies.size() == 1);
  const fs::path copy = s.dir.path() / *copies.begin();
  std::string bytes = test::read_file(copy);
  std::string reason = "CHECKSUM";
  // The points' rank, after DESIM (two i32, three f64) in the payload: 99 does not read.
  const std::size_t rank_at = disk::frame_header_bytes + 32;
  auto payload = [](const std::string& file) {
    return file.substr(disk::frame_header_bytes,
                       file.size() - disk::frame_header_bytes - disk::frame_trailer_bytes);
  };
  SUBCASE("a byte of its points changed") {
    bytes[bytes.size() / 2] ^= 1;
  }
  SUBCASE("a payload that does not read, its checksum not made again: the checksum is said") {
    bytes[rank_at] = 99;
  }
  SUBCASE("another good image file in its place") {
    store_image(s.disk, "OTHER", test::make_image(1, Projection::conic, 2, 3, 5));
    bytes = test::read_file(s.disk.path("OTHER", "IGDSIMAG"));
    reason = "NOT THE ONE SAVED";
  }
  SUBCASE("a payload that does not read, framed anew: not the one saved, before it is read") {
    std::string p = payload(bytes);
    p[rank_at - disk::frame_header_bytes] = 99;
    bytes = disk::frame("IGDSIMAG", p);
    reason = "NOT THE ONE SAVED";
  }
  test::rewrite_file(copy, bytes);
  std::vector<std::string> notices;
  Workspace back = load_fresh(s.disk, &notices);
  const std::string name = copies.begin()->substr(0, 8);
  REQUIRE(notices.size() == 1);
  CHECK(notices[0] == fmt::format("TEMP1 IN BINSAVE.IGDSCONT DAMAGED ({}.IGDSVIMG: {}): "
                                  "KEPT AS {}.IGDSBAD; TEMP1 STARTS EMPTY",
                                  name, reason, name));
  // The rest of the workspace is there: surface, the other images.
  test::check_same_surface(back, ws);
  CHECK(test::same_bits(back.image, ws.image));
  CHECK(!back.temp1);
  CHECK(test::same_bits(back.temp2, ws.temp2));
  CHECK(fs::exists(s.dir.path() / (name + ".IGDSBAD")));
  CHECK(!fs::exists(copy));
}

TEST_CASE("a damaged session is never half-loaded: kept aside, empty start, notice") {
  Scratch s;
  Workspace big = test::make_workspace(5, 5, 4, 4);  // INTPN, PATCHES, IMAGE in files
  Workspace small = test::make_workspace(2, 2, 0, 0, false);
  auto save = [&](Workspace ws) {
    Session session(s.disk);
    session.load();
    session.save(ws);
  };
  auto expect_empty_start = [&](const std::string& reason, const std::string& kept) {
    std::vector<std::string> notices;
    Workspace ws = load_fresh(s.disk, &notices);
    CHECK(ws == Workspace{});
    REQUIRE(notices.size() == 1);
    CHECK(notices[0] == fmt::format("SESSION FILE BINSAVE.IGDSCONT {}: KEPT AS {}; THE WORKSPACE "
                                    "STARTS EMPTY",
                                    reason, kept));
    CHECK(!fs::exists(s.session()));
    CHECK(files_of_type(s.dir.path(), ".IGDSVARS").empty());
  };

  SUBCASE("truncated at every length, with the bad file kept each time") {
    save(small);
    const std::string good = test::read_file(s.session());
    CHECK(files_of_type(s.dir.path(), ".IGDSVARS").empty());  // all in the session file
    for (std::size_t n = 0; n < good.size(); ++n) {
      CAPTURE(n);
      test::rewrite_file(s.session(), good.substr(0, n));
      std::vector<std::string> notices;
      CHECK(load_fresh(s.disk, &notices) == Workspace{});
      REQUIRE(notices.size() == 1);
      CHECK(notices[0].starts_with(n == 0 ? "SESSION FILE BINSAVE.IGDSCONT DAMAGED (EMPTY FILE)"
                                          : "SESSION FILE BINSAVE.IGDSCONT DAMAGED (TRUNCATED)"));
      CHECK(!fs::exists(s.session()));
      if (n >= 2) fs::remove(s.disk.path("BINSAVE2", "IGDSBAD"));
    }
    // None overwritten: the first bad file, the second under the next free name.
    CHECK(test::read_file(s.disk.path("BINSAVE", "IGDSBAD")) == "");
    CHECK(test::read_file(s.disk.path("BINSAVE1", "IGDSBAD")) == good.substr(0, 1));
    CHECK(files_of_type(s.dir.path(), ".IGDSBAD").size() == 2);
  }
  SUBCASE("every byte changed") {
    save(small);
    const std::string good = test::read_file(s.session());
    for (std::size_t i = 0; i < good.size(); ++i) {
      std::string b = good;
      b[i] = static_cast<char>(b[i] ^ 0x20);
      test::rewrite_file(s.session(), b);
      std::vector<std::string> notices;
      CHECK(load_fresh(s.disk, &notices) == Workspace{});
      CHECK(notices.size() == 1);
      for (const auto& bad : files_of_type(s.dir.path(), ".IGDSBAD"))
        fs::remove(s.dir.path() / bad);
    }
  }
  SUBCASE("the reasons") {
    save(small);
    std::string good = test::read_file(s.session());
    std::string b = good;
    b[good.size() - 12] ^= 1;
    test::rewrite_file(s.session(), b);
    expect_empty_start("DAMAGED (CHECKSUM)", "BINSAVE.IGDSBAD");
    CHECK(test::read_file(s.disk.path("BINSAVE", "IGDSBAD")) == b);

    test::rewrite_file(s.session(), "READY\n");
    expect_empty_start("DAMAGED (NOT AN IGDSCONT FILE)", "BINSAVE1.IGDSBAD");
    b = good;
    b[8] = 7;  // version 7
    test::rewrite_file(s.session(), b);
    expect_empty_start("DAMAGED (FORMAT VERSION 7 OF A NEWER IGDS)", "BINSAVE2.IGDSBAD");
    fs::create_directory(s.session());
    expect_empty_start("CANNOT BE READ (IS A DIRECTORY)", "BINSAVE3.IGDSBAD");
    CHECK(fs::is_directory(s.disk.path("BINSAVE3", "IGDSBAD")));
  }
  SUBCASE("a variable file missing or damaged: the files go aside together") {
    save(big);
    auto vars = files_of_type(s.dir.path(), ".IGDSVARS");
    REQUIRE(vars.size() == 3);
    std::string first = *vars.begin();
    SUBCASE("missing") {
      fs::remove(s.dir.path() / first);
      expect_empty_start(fmt::format("DAMAGED ({} MISSING)", first), "BINSAVE.IGDSBAD");
      CHECK(files_of_type(s.dir.path(), ".IGDSBAD").size() == 3);
    }
    SUBCASE("damaged") {
      std::string b = test::read_file(s.dir.path() / first);
      b[100] ^= 8;
      test::rewrite_file(s.dir.path() / first, b);
      expect_empty_start(fmt::format("DAMAGED ({}: CHECKSUM)", first), "BINSAVE.IGDSBAD");
      CHECK(files_of_type(s.dir.path(), ".IGDSBAD").size() == 4);
      CHECK(test::read_file(s.dir.path() / (first.substr(0, 8) + ".IGDSBAD")) == b);
    }
    SUBCASE("empty, truncated, or a folder in its place") {
      std::string b = test::read_file(s.dir.path() / first);
      SUBCASE("empty") {
        test::rewrite_file(s.dir.path() / first, "");
        expect_empty_start(fmt::format("DAMAGED ({}: EMPTY FILE)", first), "BINSAVE.IGDSBAD");
      }
      SUBCASE("truncated") {
        test::rewrite_file(s.dir.path() / first, b.substr(0, b.size() / 2));
        expect_empty_start(fmt::format("DAMAGED ({}: TRUNCATED)", first), "BINSAVE.IGDSBAD");
      }
      SUBCASE("a folder") {
        fs::remove(s.dir.path() / first);
        fs::create_directory(s.dir.path() / first);
        expect_empty_start(fmt::format("DAMAGED ({}: IS A DIRECTORY)", first), "BINSAVE.IGDSBAD");
      }
      SUBCASE("a FIFO, which must not hang the start") {
        fs::remove(s.dir.path() / first);
        REQUIRE(::mkfifo((s.dir.path() / first).c_str(), 0600) == 0);
        expect_empty_start(fmt::format("DAMAGED ({}: NOT A REGULAR FILE)", first),
                           "BINSAVE.IGDSBAD");
      }
    }
    SUBCASE("another good one in its place") {
      std::string other = *std::next(vars.begin());
      fs::copy_file(s.dir.path() / other, s.dir.path() / first,
                    fs::copy_options::overwrite_existing);
      expect_empty_start(fmt::format("DAMAGED ({}: NOT THE ONE SAVED)", first), "BINSAVE.IGDSBAD");
    }
  }
  // Whatever happened, the next session saves and loads normally.
  save(big);
  test::check_same_workspace(load_fresh(s.disk), big);
}

TEST_CASE("a disk that refuses the session: report, and the last saved session stays") {
  Scratch s;
  Workspace first = test::make_workspace(3, 3, 4, 4);
  Workspace second = test::make_workspace(6, 6, 6, 6);
  second.status[5] = 3;
  std::size_t total = 0;  // what saving `second` writes over `first`
  {
    Scratch dry;
    Session session(dry.disk);
    session.save(first);
    std::size_t w0 = bytes_written_so_far();
    session.save(second);
    total = bytes_written_so_far() - w0;
  }
  REQUIRE(total > 50000);
  {
    Session session(s.disk);
    session.load();
    session.save(first);
    const auto files = files_in(s.dir.path());
    for (std::size_t limit :
         {std::size_t(0), std::size_t(1), total / 4, total / 2, total - 200, total - 1}) {
      CAPTURE(limit);
      disk::set_write_limit_for_testing(limit);
      std::string r = report_of([&] { session.save(second); });
      disk::set_write_limit_for_testing(std::nullopt);
      CHECK(r ==
            "CANNOT SAVE THE SESSION IN BINSAVE.IGDSCONT (NO SPACE LEFT ON DEVICE); THE LAST "
            "SAVED SESSION IS KEPT");
      CHECK(files_in(s.dir.path()) == files);
    }
    // A STATUS-only change after the failures is still saved completely.
    second.status[6] = 4;
    session.save(second);
  }
  test::check_same_workspace(load_fresh(s.disk), second);
}

TEST_CASE("a really full disk (tmpfs; needs the right to mount)") {
  test::TempDir dir;
  test::SmallDisk small(dir.path() / "disk", 200);
  IGDS_SKIP_UNLESS(small.mounted(), "cannot mount a tmpfs here (root can)");
  Disk disk(small.path());
  Workspace first = test::make_workspace(3, 3, 4, 4);
  Workspace big = test::make_workspace(10, 10, 10, 10);  // about 500 KB in all
  {
    Session session(disk);
    session.load();
    session.save(first);
    CHECK(report_of([&] { session.save(big); }) ==
          "CANNOT SAVE THE SESSION IN BINSAVE.IGDSCONT (NO SPACE LEFT ON DEVICE); THE LAST "
          "SAVED SESSION IS KEPT");
  }
  test::check_same_workspace(load_fresh(disk), first);
  for (const auto& n : files_in(small.path()))
    CHECK((n == "BINSAVE.IGDSCONT" || n.ends_with(".IGDSVARS")));
}

TEST_CASE("what a crash leaves behind is cleared at start, and nothing else") {
  Scratch s;
  Workspace ws = test::make_workspace(3, 3, 4, 4);
  {
    Session session(s.disk);
    session.load();
    session.save(ws);
  }
  auto kept = files_in(s.dir.path());
  test::rewrite_file(s.dir.path() / "BINSAVE.IGDSCONT.IGDSTEMP", "half");
  test::rewrite_file(s.dir.path() / "B0000FFF.IGDSVARS", "written before a crash");
  test::rewrite_file(s.dir.path() / "HULL.IGDSDATA", "a user's file");
  test::rewrite_file(s.dir.path() / "notes.txt", "not ours");
  test::check_same_workspace(load_fresh(s.disk), ws);
  kept.insert("HULL.IGDSDATA");
  kept.insert("notes.txt");
  CHECK(files_in(s.dir.path()) == kept);
}

TEST_CASE("one session per disk") {
  Scratch s;
  auto in_use_by = [&](pid_t pid) {
    return fmt::format("DISK {} IN USE BY IGDS PROCESS {}", s.dir.path().string(), pid);
  };
  SUBCASE("two in one process") {
    Session first(s.disk);
    CHECK_THROWS_WITH_AS(Session{s.disk}, in_use_by(::getpid()).c_str(), Report);
    CHECK(first.notices().empty());
  }
  SUBCASE("after a clean end the next one starts quietly") {
    { Session first(s.disk); }
    Session second(s.disk);
    CHECK(second.notices().empty());
  }
  SUBCASE("another process holds it, then is killed -9: taken over with a notice") {
    int ready[2];
    REQUIRE(::pipe(ready) == 0);
    pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      try {
        Session session(s.disk);
        Workspace ws = test::make_workspace(2, 2, 1, 1);
        session.save(ws);
        char c = 'y';
        if (::write(ready[1], &c, 1) != 1) ::_exit(2);
        for (;;) ::pause();
      } catch (...) {
        ::_exit(1);
      }
    }
    ::close(ready[1]);
    char c = 0;
    REQUIRE(::read(ready[0], &c, 1) == 1);
    ::close(ready[0]);
    auto files = files_in(s.dir.path());
    CHECK_THROWS_WITH_AS(Session{s.disk}, in_use_by(child).c_str(), Report);
    CHECK(files_in(s.dir.path()) == files);  // the refused one touched nothing
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    Session taken(s.disk);
    REQUIRE(taken.notices().size() == 1);
    CHECK(taken.notices()[0] ==
          fmt::format("DISK LOCK LEFT BY IGDS PROCESS {}, WHICH HAS ENDED, TAKEN OVER", child));
    test::check_same_workspace(taken.load(), test::make_workspace(2, 2, 1, 1));
  }
  SUBCASE("a disk where no lock can be made") {
    fs::create_directory(s.disk.path("BINSAVE", "IGDSLOCK"));
    CHECK_THROWS_WITH_AS(
        Session{s.disk},
        fmt::format("DISK {} CANNOT BE LOCKED (IS A DIRECTORY)", s.dir.path().string()).c_str(),
        Report);
  }
}

TEST_CASE("a session whose checksum holds but whose variables disagree is refused") {
  Scratch s;
  Workspace small = test::make_workspace(2, 2, 0, 0, false);
  {
    Session session(s.disk);
    session.save(small);
  }
  // The checksum has no key: anyone can make a session file that passes it.
  const std::string good = test::read_file(s.session());
  const auto table = disk::decode_session(disk::unframe("IGDSCONT", good).payload);
  auto crafted = [&](auto&& change, const std::string& reason) {
    CAPTURE(reason);
    disk::SessionTable t = table;
    change(t);
    test::rewrite_file(s.session(), disk::frame("IGDSCONT", disk::encode_session(t), 2));
    std::vector<std::string> notices;
    CHECK(load_fresh(s.disk, &notices) == Workspace{});
    REQUIRE(notices.size() == 1);
    CHECK(notices[0] == fmt::format("SESSION FILE BINSAVE.IGDSCONT DAMAGED ({}): KEPT AS "
                                    "BINSAVE.IGDSBAD; THE WORKSPACE STARTS EMPTY",
                                    reason));
    fs::remove(s.disk.path("BINSAVE", "IGDSBAD"));
  };
  crafted([](disk::SessionTable& t) { t.records[0].nocur = t.records[0].nostr = 40; },
          "SHAPES: INPPN DOES NOT MATCH NOCUR AND NOSTR");
  crafted([](disk::SessionTable& t) { t.records[0].nocur = 1000000; },
          "SHAPES: 2000000 INPUT POINTS, MORE THAN 1000000");
  crafted([](disk::SessionTable& t) { t.records[0].nocur = 100000000; },
          "SHAPES: 200000000 INPUT POINTS, MORE THAN 1000000");
  crafted([](disk::SessionTable& t) { t.records[0].intcu = t.records[0].intst = 9998; },
          "SHAPES: 100000000 INTERPOLATED POINTS, MORE THAN 4000000");
  crafted(
      [](disk::SessionTable& t) {
        t.records[0].inptg.shape = {4, 8};
      },
      "SHAPES: INPTG DOES NOT MATCH NOCUR AND NOSTR");
  crafted([](disk::SessionTable& t) { t.status[1] = 7; }, "STATUS: STATUS[2] IS NOT 0, 1 OR 2");
  crafted([](disk::SessionTable& t) { t.status[2] = 2; }, "STATUS: STATUS[3] IS NOT 0 OR 1");
  crafted([](disk::SessionTable& t) { t.status[3] = -1; }, "STATUS: STATUS[4] IS NOT 0 OR 1");
  crafted(
      [](disk::SessionTable& t) {
        t.derived = false;
        t.intpn.shape = {2, 2};
      },
      "FORMAT");
  // An image that does not read costs that image alone (its slot starts empty, said), and a
  // claim of a huge one costs nothing before it is refused.
  auto image_crafted = [&](auto&& change, const std::string& notice) {
    CAPTURE(notice);
    disk::SessionTable t = table;
    change(t);
    test::rewrite_file(s.session(), disk::frame("IGDSCONT", disk::encode_session(t), 2));
    std::vector<std::string> notices;
    Workspace back = load_fresh(s.disk, &notices);
    test::check_same_surface(back, small);
    CHECK(!back.image);
    CHECK(!back.temp1);
    CHECK(notices == std::vector<std::string>{notice});
    // The session without it is written at the next save, the notice not said again.
    {
      Session session(s.disk);
      Workspace ws = session.load();
      session.save(ws);
    }
    notices.clear();
    load_fresh(s.disk, &notices);
    CHECK(notices.empty());
  };
  image_crafted(
      [](disk::SessionTable& t) {
        t.images[0].kind = disk::ImageEntry::recipe;
        t.images[0].record = t.current;
        t.images[0].desim.projection = static_cast<Projection>(9);
      },
      "IMAGE IN BINSAVE.IGDSCONT DAMAGED (IMAGE: DESIM[2] IS NOT A PROJECTION (1 TO 4)): IMAGE "
      "STARTS EMPTY");
  image_crafted(
      [](disk::SessionTable& t) {
        t.images[0].kind = disk::ImageEntry::recipe;
        t.images[0].record = t.current;
        t.images[0].desim.what = 4;
      },
      "IMAGE IN BINSAVE.IGDSCONT DAMAGED (IMAGE: DESIM[1] IS NOT 0, 1, 2 OR 3): IMAGE STARTS "
      "EMPTY");
  image_crafted(
      [](disk::SessionTable& t) {
        t.images[1].kind = disk::ImageEntry::stored;
        t.images[1].data.pieces = {
            disk::Piece{true, {}, {1, (std::uint64_t(1) << 40) + 32, 0}, std::uint64_t(1) << 40}};
      },
      "TEMP1 IN BINSAVE.IGDSCONT DAMAGED (IMAGE: TOO LARGE): TEMP1 STARTS EMPTY");
}

TEST_CASE("images kept by recipe are made when first looked at, not at start") {
  Scratch s;
  Workspace ws = test::make_interpolated(6, 6, 2, 2);
  ws.image =
      std::make_shared<const Image>(image_of(ws, {1, Projection::assonometric, {110, 130, 120}}));
  ws.temp1 = std::make_shared<const Image>(image_of(ws, {1, Projection::isometric, {3, 30, 0}}));
  {
    Session session(s.disk);
    session.load();
    session.save(ws);
  }
  Session session(s.disk);
  Workspace back = session.load();
  CHECK(back.has_surface());  // PATCHES and INTPN made again by the load
  CHECK(back.intpn == ws.intpn);
  CHECK(!back.image.made());
  CHECK(!back.temp1.made());
  CHECK(*back.image == *ws.image);
  CHECK(back.image.made());
  CHECK(!back.temp1.made());
  CHECK(*back.temp1 == *ws.temp1);
  session.save(back);
}

TEST_CASE("a hidden-line image is kept by its recipe, and made again the same") {
  Scratch s;
  Workspace ws = test::make_interpolated(6, 6, 2, 2);
  ws.image = std::make_shared<const Image>(
      image_of(ws, {1, Projection::assonometric, {110, 130, 120}, true}));
  {
    Session session(s.disk);
    session.load();
    session.save(ws);
  }
  auto table =
      disk::decode_session(disk::unframe("IGDSCONT", test::read_file(s.session())).payload);
  REQUIRE(table.images[0].kind == disk::ImageEntry::recipe);
  CHECK(table.images[0].desim.hidden);
  {
    Session session(s.disk);
    Workspace back = session.load();
    CHECK(!back.image.made());
    CHECK(back.image->desim.hidden);
    CHECK(*back.image == *ws.image);
  }
  // A forged recipe: an input image said to be drawn without its hidden lines.
  table.images[0].desim = {0, Projection::assonometric, {110, 130, 120}, true};
  test::rewrite_file(s.session(), disk::frame("IGDSCONT", disk::encode_session(table), 2));
  std::vector<std::string> notices;
  const Workspace back = load_fresh(s.disk, &notices);
  CHECK(!back.image);
  CHECK(notices == std::vector<std::string>{
                       "IMAGE IN BINSAVE.IGDSCONT DAMAGED (IMAGE: IMAGE IS NOT A SURFACE: ITS "
                       "HIDDEN LINES CANNOT BE REMOVED): IMAGE STARTS EMPTY"});
}

TEST_CASE("DISPLAY COMBS is kept by its recipe and made again the same, combs and scale") {
  Scratch s;
  Workspace ws = test::make_interpolated(6, 6, 2, 2);
  ws.image =
      std::make_shared<const Image>(image_of(ws, {3, Projection::assonometric, {110, 130, 120}}));
  REQUIRE(ws.image->combs.shape == std::vector<std::size_t>{16, 16, 4});
  REQUIRE(ws.image->comb_scale > 0);
  // A copy whose recipe is not the current surface's is kept by its points, combs included.
  Image stored = *ws.image;
  stored.drawn_from = 0;
  ws.temp1 = std::make_shared<const Image>(stored);
  {
    Session session(s.disk);
    session.load();
    session.save(ws);
  }
  Session session(s.disk);
  Workspace back = session.load();
  CHECK(!back.image.made());
  CHECK(*back.image == *ws.image);
  CHECK(back.image->combs == ws.image->combs);
  CHECK(back.image->comb_scale == ws.image->comb_scale);
  CHECK(*back.temp1 == *ws.temp1);
}

TEST_CASE("an image kept by a recipe that cannot be made: nothing said at start, a look says why") {
  Scratch s;
  {
    Session session(s.disk);
    session.load();
    Workspace ws = test::make_interpolated(6, 6, 2, 2);
    ws.image =
        std::make_shared<const Image>(image_of(ws, {1, Projection::assonometric, {110, 130, 120}}));
    session.save(ws);
  }
  auto table =
      disk::decode_session(disk::unframe("IGDSCONT", test::read_file(s.session())).payload);
  REQUIRE(table.images[0].kind == disk::ImageEntry::recipe);
  // A conic view from inside the surface's box (the surface spans 0..50, 0..35.5, -1..1), which
  // DISPLAY refuses and a crafted file can say.
  table.images[0].desim = {1, Projection::conic, {25, 17, 0}};
  test::rewrite_file(s.session(), disk::frame("IGDSCONT", disk::encode_session(table), 2));
  Session session(s.disk);
  Workspace back = session.load();
  CHECK(session.notices().empty());
  CHECK_THROWS_AS(static_cast<void>(*back.image), DataError);
  CHECK(!back.image.made());
  // Every look says it again.
  CHECK_THROWS_AS(static_cast<void>(*back.image), DataError);
}

TEST_CASE("an image refused at start costs that image, not the surface") {
  Scratch s;
  Workspace ws = test::make_interpolated(6, 6, 2, 2);
  {
    Session session(s.disk);
    session.load();
    session.save(ws);
  }
  auto table =
      disk::decode_session(disk::unframe("IGDSCONT", test::read_file(s.session())).payload);
  REQUIRE(table.derived);
  table.images[0].kind = disk::ImageEntry::recipe;
  table.images[0].record = table.current;
  table.images[0].desim.projection = static_cast<Projection>(9);
  test::rewrite_file(s.session(), disk::frame("IGDSCONT", disk::encode_session(table), 2));
  Session session(s.disk);
  Workspace loaded = session.load();
  REQUIRE(session.notices().size() == 1);
  CHECK(session.notices()[0].starts_with("IMAGE IN BINSAVE.IGDSCONT DAMAGED (IMAGE: "));
  test::check_same_surface(loaded, ws);
  CHECK(!loaded.image);
  CHECK(test::same_bits(loaded.temp2, ws.temp2));
}

TEST_CASE(
    "a record of the current surface whose modes STATUS contradicts: STATUS's are the surface's") {
  // A forged record of the current surface that says MARKS twists where STATUS says ZERO: its
  // image (the same surface's generation) is drawn with the workspace's modes, so that UNDO, REDO
  // and the saves between them keep the image the workspace shows.
  Scratch s;
  Workspace ws = test::make_interpolated(5, 6, 2, 3);
  ws.changes.inppn.saved();
  ws.changes.inptg.saved();
  Journal journal(ws);
  // CHANGE POINTS, then DISPLAY SURFACE of the new surface: the image is its recipe.
  ws.inppn.ravel[3 * 7 + 2] = 4;
  Edits point = Edits::none();
  point.part(3 * 7, 3 * 8);
  ws.changes.edited(point, Edits::none());
  Surface zero = interpolate(surface_input(ws));
  ws.patches = std::move(zero.patches);
  ws.intpn = std::move(zero.intpn);
  REQUIRE(journal.record(ws, "CHANGE POINTS"));
  const Description desim{1, Projection::assonometric, {110, 130, 120}};
  ws.image = std::make_shared<const Image>(image_of(ws, desim));
  REQUIRE(journal.record(ws, "DISPLAY SURFACE"));
  // The same points with Marks's twists draw another image.
  Workspace marks = ws;
  marks.status[Workspace::status_twists] = 1;
  marks.intpn = interpolate(surface_input(marks)).intpn;
  REQUIRE(image_of(marks, desim) != *ws.image);
  {
    Session session(s.disk);
    session.load();
    session.save(ws, &journal);
  }
  disk::SessionTable table = test::forge::session_table(s.disk);
  REQUIRE(table.images[0].kind == disk::ImageEntry::recipe);
  REQUIRE(table.images[0].record == table.current);
  REQUIRE(table.status[Workspace::status_twists] == 0);
  table.record(table.current)->twists = 1;
  test::forge::write_session(s.disk, table);

  Workspace back;
  {
    Session session(s.disk);
    back = session.load();
    CHECK(session.notices().empty());
    test::check_same_workspace(back, ws);
    CHECK(back.image->drawn_from == back.changes.surface);
    Journal again = session.take_journal(back);
    REQUIRE(again.undo_count() == 2);
    while (again.undo(back)) session.save(back, &again);
    while (again.redo(back)) session.save(back, &again);
  }
  test::check_same_workspace(back, ws);
  test::check_same_workspace(load_fresh(s.disk), ws);
}

TEST_CASE("the session never saves a workspace that the next start would refuse") {
  Scratch s;
  Workspace odd = test::make_workspace(2, 2, 1, 1);
  odd.nocur = 7;  // shapes that do not agree with NOCUR
  Session session(s.disk);
  CHECK(report_of([&] { session.save(odd); }) ==
        "CANNOT SAVE THE SESSION (INPPN IS 4 BY 3, NOT 14 BY 3); THE LAST SAVED SESSION IS KEPT");
  CHECK(!fs::exists(s.session()));
  // A surface new to the session is checked as it is saved (one it holds was checked then).
  Workspace ws = test::make_workspace(2, 2, 1, 1);
  session.save(ws);
  const std::string saved = test::read_file(s.session());
  ws.inppn.ravel[4] = std::numeric_limits<double>::infinity();
  ws.changes.replaced();
  CHECK(report_of([&] { session.save(ws); }) ==
        "CANNOT SAVE THE SESSION (POINT 2 OF INPPN IS NOT A FINITE NUMBER); THE LAST SAVED SESSION "
        "IS KEPT");
  CHECK(test::read_file(s.session()) == saved);
}

TEST_CASE("variable files without a session are kept aside, never deleted") {
  Scratch s;
  {
    Session session(s.disk);
    Workspace ws = test::make_workspace(5, 5, 4, 4);
    session.save(ws);
  }
  const auto vars = files_of_type(s.dir.path(), ".IGDSVARS");
  REQUIRE(vars.size() == 3);
  fs::rename(s.session(), s.dir.path() / "moved.away");
  std::vector<std::string> notices;
  CHECK(load_fresh(s.disk, &notices) == Workspace{});
  REQUIRE(notices.size() == 1);
  CHECK(notices[0] == fmt::format("3 VARIABLE FILES WITHOUT A SESSION FILE: KEPT AS {}.IGDSBAD ...",
                                  vars.begin()->substr(0, 8)));
  CHECK(files_of_type(s.dir.path(), ".IGDSVARS").empty());
  CHECK(files_of_type(s.dir.path(), ".IGDSBAD").size() == 3);
  // Temporaries of a first save killed before its session file: removed, with nothing to say.
  Scratch first;
  test::write_file(first.dir.path() / "B0000001.IGDSVARS.IGDSTEMP", "half");
  test::write_file(first.dir.path() / "BINSAVE.IGDSCONT.IGDSTEMP", "half");
  notices.clear();
  CHECK(load_fresh(first.disk, &notices) == Workspace{});
  CHECK(notices.empty());
  CHECK(files_of_type(first.dir.path(), ".IGDSTEMP").empty());
}

TEST_CASE(
    "variable files removed while igds runs are written again before the session names them") {
  Scratch s;
  Workspace ws = test::make_workspace(5, 5, 4, 4);
  Session session(s.disk);
  session.save(ws);
  for (const auto& name : files_of_type(s.dir.path(), ".IGDSVARS")) fs::remove(s.dir.path() / name);
  ws.status[0] = 1;  // a small change: the save notices the files are gone
  session.save(ws);
  CHECK(files_of_type(s.dir.path(), ".IGDSVARS").size() == 3);
}

TEST_CASE("a session of the first format (version 1) still opens") {
  Scratch s;
  // Written as igds 1.0 wrote it: NOCUR NOSTR INTCU INTST, STATUS, the next file number, then
  // INPPN INPTG PATCHES INTPN IMAGE TEMP1 TEMP2, each inline or in a file of its own.
  Workspace ws = test::make_interpolated(6, 5, 2, 2);
  ws.temp2.reset();
  keep_patches(ws);  // igds 1.0 kept them
  disk::Writer w;
  for (int v : {ws.nocur, ws.nostr, ws.intcu, ws.intst}) w.i32(v);
  for (int v : ws.status) w.i32(v);
  w.u32(9);
  w.u32(7);
  std::uint32_t number = 1;
  auto slot = [&](const disk::Writer& variable) {
    const std::string bytes = variable.str();
    if (bytes.size() <= 1024) {
      w.u8(1);
      w.u64(bytes.size());
      w.bytes(bytes);
      return;
    }
    const std::string file = disk::frame("IGDSVARS", bytes);
    test::write_file(s.dir.path() / fmt::format("B{:07X}.IGDSVARS", number), file);
    w.u8(2);
    w.u32(number++);
    w.u64(file.size());
    w.u64(disk::trailing_checksum(file));
  };
  for (const Array* a : {&ws.inppn, &ws.inptg, &ws.patches, &ws.intpn}) {
    disk::Writer v;
    v.array(*a);
    slot(v);
  }
  for (const ImageRef& im : {ws.image, ws.temp1}) {
    disk::Writer v;
    v.image(*im);
    slot(v);
  }
  w.u8(0);
  test::write_file(s.session(), disk::frame("IGDSCONT", w.str(), 1));
  const auto old_files = files_of_type(s.dir.path(), ".IGDSVARS");
  REQUIRE(!old_files.empty());
  {
    Session session(s.disk);
    Workspace back = session.load();
    CHECK(session.notices().empty());
    test::check_same_workspace(back, ws);
    CHECK(back.changes.derived);  // its PATCHES and INTPN are igds's own: not saved again
    back.status[0] = 0;
    session.save(back);
    for (const auto& f : old_files) CHECK(!fs::exists(s.dir.path() / f));
  }
  Workspace again = load_fresh(s.disk);
  ws.status[0] = 0;
  test::check_same_workspace(again, ws);
}

TEST_CASE("a read-only disk cannot hold a session: said at once (tmpfs; needs mount)") {
  test::TempDir dir;
  test::SmallDisk small(dir.path() / "disk", 64);
  IGDS_SKIP_UNLESS(small.mounted() && small.make_read_only(),
                   "cannot mount a read-only tmpfs here");
  Disk disk(small.path());
  CHECK_THROWS_WITH_AS(
      Session{disk},
      fmt::format("DISK {} CANNOT BE LOCKED (READ-ONLY FILE SYSTEM)", small.path().string())
          .c_str(),
      Report);
}

TEST_CASE("lock files that say nothing useful") {
  Scratch s;
  const fs::path lock = s.disk.path("BINSAVE", "IGDSLOCK");
  SUBCASE("left with something that is not a process number") {
    test::write_file(lock, "garbage\n");
    Session session(s.disk);
    REQUIRE(session.notices().size() == 1);
    CHECK(session.notices()[0] == "DISK LOCK LEFT BY AN IGDS THAT HAS ENDED, TAKEN OVER");
  }
  SUBCASE("held, but without a process number in it") {
    test::write_file(lock, "");
    int fd = ::open(lock.c_str(), O_RDWR);
    REQUIRE(fd >= 0);
    REQUIRE(::flock(fd, LOCK_EX) == 0);
    CHECK_THROWS_WITH_AS(
        Session{s.disk},
        fmt::format("DISK {} IN USE BY ANOTHER IGDS PROCESS", s.dir.path().string()).c_str(),
        Report);
    ::close(fd);
  }
}

TEST_CASE("a bad session that cannot even be put aside stays where it is (needs mount)") {
  Scratch s;
  // A mount point cannot be renamed: the session "file" is a folder with a tmpfs on it.
  test::SmallDisk in_the_way(s.session(), 16);
  IGDS_SKIP_UNLESS(in_the_way.mounted(), "cannot mount a tmpfs here (root can)");
  test::write_file(s.dir.path() / "B0000001.IGDSVARS", "a variable of the bad session");
  std::vector<std::string> notices;
  CHECK(load_fresh(s.disk, &notices) == Workspace{});
  REQUIRE(notices.size() == 1);
  CHECK(notices[0] ==
        "SESSION FILE BINSAVE.IGDSCONT CANNOT BE READ (IS A DIRECTORY): NOT KEPT ASIDE (DEVICE OR "
        "RESOURCE BUSY); THE WORKSPACE STARTS EMPTY");
  CHECK(fs::exists(s.dir.path() / "B0000001.IGDSVARS"));
}

TEST_CASE("the lock is never anything but a plain file of igds's own") {
  Scratch s;
  const fs::path lock = s.disk.path("BINSAVE", "IGDSLOCK");
  const std::string where = s.dir.path().string();
  SUBCASE("a hard link to a file elsewhere: refused, the file untouched") {
    test::TempDir elsewhere;
    test::write_file(elsewhere.path() / "precious", "12345\n");
    fs::create_hard_link(elsewhere.path() / "precious", lock);
    CHECK_THROWS_WITH_AS(
        Session{s.disk},
        fmt::format("DISK {} CANNOT BE LOCKED (BINSAVE.IGDSLOCK HAS ANOTHER NAME TOO)", where)
            .c_str(),
        Report);
    CHECK(test::read_file(elsewhere.path() / "precious") == "12345\n");
  }
  SUBCASE("a FIFO: refused at once, and left where it is") {
    REQUIRE(::mkfifo(lock.c_str(), 0600) == 0);
    CHECK_THROWS_WITH_AS(
        Session{s.disk},
        fmt::format("DISK {} CANNOT BE LOCKED (BINSAVE.IGDSLOCK IS NOT A PLAIN FILE)", where)
            .c_str(),
        Report);
    CHECK(fs::is_fifo(lock));
  }
  SUBCASE("a symbolic link") {
    fs::create_symlink(s.dir.path() / "elsewhere", lock);
    CHECK_THROWS_WITH_AS(
        Session{s.disk},
        fmt::format("DISK {} CANNOT BE LOCKED (BINSAVE.IGDSLOCK IS A SYMBOLIC LINK)", where)
            .c_str(),
        Report);
    CHECK(!fs::exists(s.dir.path() / "elsewhere"));
  }
}

TEST_CASE("a full disk still opens: said at start, saved as soon as there is room") {
  Scratch s;
  Workspace first = test::make_workspace(3, 3, 1, 1);
  {
    Session session(s.disk);
    session.save(first);
  }
  disk::set_write_limit_for_testing(0);
  {
    Session session(s.disk);
    Workspace ws = session.load();
    REQUIRE(session.notices().size() == 1);
    CHECK(session.notices()[0] ==
          fmt::format("DISK {} IS FULL: THE SESSION IS SAVED AGAIN WHEN THERE IS ROOM",
                      s.dir.path().string()));
    test::check_same_workspace(ws, first);
    ws.status[0] = 1;
    CHECK(report_of([&] { session.save(ws); }) ==
          "CANNOT SAVE THE SESSION IN BINSAVE.IGDSCONT (NO SPACE LEFT ON DEVICE); THE LAST SAVED "
          "SESSION IS KEPT");
    disk::set_write_limit_for_testing(std::nullopt);
    session.save(ws);
    first = ws;
  }
  disk::set_write_limit_for_testing(std::nullopt);
  test::check_same_workspace(load_fresh(s.disk), first);
}
