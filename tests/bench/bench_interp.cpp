// The interpreter's speed: start-up with a large saved session, and a large BUILD read from a
// command file. Each runs the real igds binary.
#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "interp/words.h"
#include "tests/bench/bench.h"
#include "workspace/numbers/typed.h"

namespace igds::bench {

namespace {

namespace fs = std::filesystem;

// A scratch disk, removed at the end.
struct ScratchDisk {
  fs::path dir;
  ScratchDisk() {
    dir = fs::temp_directory_path() / fmt::format("igds-bench-{}", getpid());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~ScratchDisk() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// Runs igds --term none --disk DISK FILE with its output thrown away; the seconds it took.
double run_igds(const fs::path& disk, const fs::path& file) {
  std::vector<std::string> args{IGDS_BINARY, "--term",      "none",
                                "--disk",    disk.string(), file.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  int status = 0;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0)
    waitpid(pid, &status, 0);
  auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  posix_spawn_file_actions_destroy(&actions);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    fmt::print(stderr, "bench_interp: igds failed on {}\n", file.string());
  return seconds;
}

// BUILD of an n x n grid of a gently curved sheet: one point per line, tangents at the border.
void write_build(const fs::path& file, int n, int density) {
  std::ofstream out(file);
  out << "BUILD\n" << n << ' ' << n << '\n';
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      double x = 10.0 * i, y = 10.0 * j, z = 20 * std::sin(i * 0.05) * std::cos(j * 0.04);
      out << i * n + j + 1 << ' ' << x << ' ' << y << ' ' << z << '\n';
    }
  }
  out << "\n1 0 1 0 1\n1 1 0 0 0\n" << n * n << " 0 1 0 1\n\n";
  out << density << ' ' << density << "\nEND CMS\n";
}

// A typed line of 500 points (as in a BUILD of a 500 x 500 grid) split into words and read as
// numbers, in memory: megabytes of typed text a second.
void read_points() {
  std::string line = "1";
  for (int j = 0; j < 500; ++j)
    line += fmt::format(" {} {} {:.6f}", 10.0 * j, 12.0 * 7, 20 * std::sin(0.05 * j));
  double sum = 0;
  const int lines = 500;
  std::vector<std::string_view> words;
  const double best = best_seconds(7, [&] {
    for (int r = 0; r < lines; ++r) {
      split_words(line, words);
      for (const auto w : words) sum += parse_typed_number(w).value_or(0);
    }
  });
  fmt::print("read_points_mb_s {:.0f}\n", double(line.size()) * lines / best / 1e6);
  if (sum == 0) fmt::print(stderr, "bench_interp: the line read as zeros\n");
}

}  // namespace

IGDS_BENCH("interp") {
  read_points();
  ScratchDisk disk;
  const fs::path build100 = disk.dir / "build100.igds", end = disk.dir / "end.igds";
  write_build(build100, 100, 1);
  std::ofstream(end) << "END CMS\n";
  run_igds(disk.dir, build100);
  std::vector<double> ms;
  for (int r = 0; r < 21; ++r) ms.push_back(1000 * run_igds(disk.dir, end));
  std::sort(ms.begin(), ms.end());
  fmt::print("startup_100x100_ms_median {:.2f}\n", ms[ms.size() / 2]);

  ScratchDisk other;
  const fs::path build200 = other.dir / "build200.igds";
  write_build(build200, 200, 1);
  double best = best_seconds(3, [&] { run_igds(other.dir, build200); });
  fmt::print("build_200x200_s {:.3f}\n", best);
}

}  // namespace igds::bench
