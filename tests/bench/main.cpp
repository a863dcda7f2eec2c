// igds_bench [NAME ...] [--pause SECONDS] [--busy] [--only CASE]: runs the benchmarks (all, or
// those whose name starts with NAME); the options are bench.h's Settings.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "tests/bench/bench.h"

namespace igds::bench {
std::vector<Benchmark>& registry() {
  static std::vector<Benchmark> all;
  return all;
}
Settings& settings() {
  static Settings s;
  return s;
}
}  // namespace igds::bench

int main(int argc, char** argv) {
  std::vector<std::string_view> names;
  auto& settings = igds::bench::settings();
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--pause" && i + 1 < argc) {
      settings.pause = std::atof(argv[++i]);
    } else if (arg == "--busy") {
      settings.busy = true;
    } else if (arg == "--only" && i + 1 < argc) {
      settings.only = argv[++i];
    } else if (arg.starts_with("--")) {
      std::fprintf(stderr, "igds_bench: unknown option %s\n", argv[i]);
      return 2;
    } else {
      names.push_back(arg);
    }
  }
  for (const auto& b : igds::bench::registry()) {
    bool wanted = names.empty();
    for (std::string_view name : names)
      if (b.name.starts_with(name)) wanted = true;
    if (!wanted) continue;
    b.run();
    std::fflush(stdout);
  }
  return 0;
}
