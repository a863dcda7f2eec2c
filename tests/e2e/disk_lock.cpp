// One igds per disk (docs/disk.md), with the real binary: a second one is told which
// process holds the disk and stops without touching anything; a lock left by a killed igds is
// taken over with a notice.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "tests/support/process.h"
#include "tests/workspace/live_igds.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir))
    files[e.path().filename().string()] = test::read_file(e.path());
  return files;
}

}  // namespace

TEST_CASE("a second igds on a disk in use stops and touches nothing") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir dir, other;
  const std::string disk = dir.path().string();
  test::write_file(other.path() / "build.igds",
                   "BUILD\n2 2\n1 0 0 0 0 1 0 1 0 0 1 1 1\n\n\n2 2\nSAVE HULL\n");
  // The first one builds a surface and stays, waiting for more commands.
  test::LiveIgds first(test::igds_binary(), {"--disk", disk, "--term", "none"}, true);
  {
    test::LiveIgds setup(
        test::igds_binary(),
        {"--disk", other.path().string(), "--term", "none", (other.path() / "build.igds").string()},
        false);
    REQUIRE(setup.finish() == 0);
  }
  REQUIRE(first.wait_for("READY\n", 10));
  const auto before = contents(dir.path());
  CHECK(before.count("BINSAVE.IGDSLOCK") == 1);

  auto second =
      test::run_igds({"--disk", disk, "--term", "none", (other.path() / "build.igds").string()});
  CHECK(second.status == 1);
  CHECK(second.err == fmt::format("DISK {} IN USE BY IGDS PROCESS {}\n", disk, first.pid()));
  CHECK(second.out.find("READY") == std::string::npos);
  CHECK(contents(dir.path()) == before);

  // Once the first one has ended, the disk is free, with nothing to report.
  CHECK(first.finish() == 0);
  CHECK(!fs::exists(dir.path() / "BINSAVE.IGDSLOCK"));
  auto third =
      test::run_igds({"--disk", disk, "--term", "none", (other.path() / "build.igds").string()});
  CHECK(third.status == 0);
  CHECK(third.out.starts_with("READY\n"));
  CHECK(fs::exists(dir.path() / "HULL.IGDSDATA"));
}

TEST_CASE("the lock of an igds killed -9 is taken over, with a notice") {
  REQUIRE(fs::exists(test::igds_binary()));
  test::TempDir dir;
  const std::string disk = dir.path().string();
  test::LiveIgds first(test::igds_binary(), {"--disk", disk, "--term", "none"}, true);
  REQUIRE(first.wait_for("READY\n", 10));
  pid_t pid = first.pid();
  first.kill();
  CHECK(fs::exists(dir.path() / "BINSAVE.IGDSLOCK"));

  test::RunOptions input;
  input.input = "HELP SHORT\n";
  auto next = test::run_igds({"--disk", disk, "--term", "none"}, input);
  CHECK(next.status == 0);
  CHECK(next.out.starts_with(
      fmt::format("DISK LOCK LEFT BY IGDS PROCESS {}, WHICH HAS ENDED, TAKEN OVER\n", pid)));
  CHECK(!fs::exists(dir.path() / "BINSAVE.IGDSLOCK"));
}
