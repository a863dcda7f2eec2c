// The fuzz targets' corpora replayed by the ordinary test suite: every file of
// tests/fuzz/corpus/<target>, the seeds and every input a fuzz run found to crash (kept there as
// regress_*), fed to the same entry as libFuzzer's (tests/fuzz/fuzz.h). A target aborts on what
// must never happen and an escaped exception fails the test.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/fuzz/records.h"
#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/session.h"
#include "workspace/images.h"
#include "workspace/journal.h"

namespace igds::fuzz {
int apl(const std::uint8_t*, std::size_t);
int cad(const std::uint8_t*, std::size_t);
int duct(const std::uint8_t*, std::size_t);
int files(const std::uint8_t*, std::size_t);
int gin(const std::uint8_t*, std::size_t);
int marks(const std::uint8_t*, std::size_t);
int records(const std::uint8_t*, std::size_t);
int session(const std::uint8_t*, std::size_t);
int words(const std::uint8_t*, std::size_t);
}  // namespace igds::fuzz

namespace igds::fuzz {

namespace {

namespace fs = std::filesystem;

// Every file of the target's corpus, in the order of their names; how many.
std::size_t replay(const std::string& target, int (*run)(const std::uint8_t*, std::size_t)) {
  const fs::path dir = test::source_dir() / "tests" / "fuzz" / "corpus" / target;
  REQUIRE(fs::is_directory(dir));
  std::vector<fs::path> inputs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) inputs.push_back(e.path());
  std::sort(inputs.begin(), inputs.end());
  for (const fs::path& input : inputs) {
    CAPTURE(input.string());
    const std::string bytes = test::read_file(input);
    run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  return inputs.size();
}

}  // namespace

TEST_CASE("fuzz corpus: apl") {
  CHECK(replay("apl", apl) > 0);
}
TEST_CASE("fuzz corpus: cad") {
  CHECK(replay("cad", cad) > 0);
}
TEST_CASE("fuzz corpus: duct") {
  CHECK(replay("duct", duct) > 0);
}
TEST_CASE("fuzz corpus: files") {
  CHECK(replay("files", files) > 0);
}
TEST_CASE("fuzz corpus: gin") {
  CHECK(replay("gin", gin) > 0);
}
TEST_CASE("fuzz corpus: marks") {
  CHECK(replay("marks", marks) > 0);
}
TEST_CASE("fuzz corpus: records") {
  CHECK(replay("records", records) > 0);
}
TEST_CASE("fuzz corpus: session") {
  CHECK(replay("session", session) > 0);
}
TEST_CASE("fuzz corpus: words") {
  CHECK(replay("words", words) > 0);
}

TEST_CASE("fuzz_records reads a disk igds saved as igds does, journal and images included") {
  // A session with a journal of CHANGEs and DISPLAYs, images by recipe, by their points and as
  // the copy of an image file: packed as fuzz_records' input, read back and written again, the
  // target goes through it to the ends of its journal without a complaint.
  test::TempDir dir;
  Disk disk(dir.path());
  Workspace ws = test::make_interpolated(12, 12, 2, 2);
  store_image(disk, "PIC", *ws.temp2);
  {
    Session session(disk);
    Workspace loaded = session.load();
    Journal journal(loaded);
    journal.record(ws, "BUILD");
    session.save(ws, &journal);
    for (std::size_t k = 0; k < 3; ++k) {
      ws.inppn.ravel[3 * (10 + k) + 2] += 1.5;
      Edits points = Edits::none();
      points.part(3 * (10 + k), 3 * (10 + k) + 3);
      ws.changes.edited(points, Edits::none());
      Surface s = interpolate(surface_input(ws));
      ws.patches = std::move(s.patches);
      ws.intpn = std::move(s.intpn);
      journal.record(ws, "CHANGE POINTS");
      session.save(ws, &journal);
      ws.image = std::make_shared<const Image>(
          image_of(ws, {static_cast<int>(k % 2), Projection::isometric, {3, 30, 0}}));
      journal.record(ws, "DISPLAY SURFACE");
      session.save(ws, &journal);
    }
    ws.temp1 = std::make_shared<const Image>(load_image(disk, "PIC"));
    journal.record(ws, "DISPLAY FILE");
    session.save(ws, &journal);
  }
  const RecordsInput in = pack_records(dir.path());
  CHECK(in.files.size() >= 2);
  const std::string bytes = records_bytes(in);
  CHECK(records_bytes(read_records(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                   bytes.size())) == bytes);
  records(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

TEST_CASE("fuzz_records' changes of a session with END APL's variables: reports, never a crash") {
  test::TempDir dir;
  Disk disk(dir.path());
  Workspace ws = test::make_interpolated(3, 3, 1, 1);
  ws.functions = {{"Z←F X", "Z←X"}};
  ws.apl_variables = {{"A", {2}, false, {1, 2}, {}}, {"T", {1}, true, {}, U"X"}};
  {
    Session session(disk);
    session.load();
    session.save(ws);
  }
  const RecordsInput in = pack_records(dir.path());
  std::size_t forged = 0;
  for (unsigned seed = 1; seed <= 300; ++seed) {
    RecordsInput mutated = in;
    const auto session = std::find_if(mutated.files.begin(), mutated.files.end(),
                                      [](const RecordsFile& f) { return f.kind == 0; });
    REQUIRE(session != mutated.files.end());
    disk::SessionTable t = disk::decode_session(session->payload);
    REQUIRE(t.apl_variables == ws.apl_variables);
    std::minstd_rand rng(seed);
    for (int k = 0; k < 3; ++k) mutate_table(t, rng);
    forged += t.apl_variables != ws.apl_variables;
    session->payload = disk::encode_session(t);
    const std::string bytes = records_bytes(mutated);
    records(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  CHECK(forged > 10);  // the variables were among what changed
}

}  // namespace igds::fuzz
