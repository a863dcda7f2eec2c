// igds_bench [NAME ...]: runs the benchmarks (all, or those whose name starts with NAME).
#include <cstdio>
#include <string_view>

#include "tests/bench/bench.h"

namespace igds::bench {
std::vector<Benchmark>& registry() {
  static std::vector<Benchmark> all;
  return all;
}
}  // namespace igds::bench

int main(int argc, char** argv) {
  for (const auto& b : igds::bench::registry()) {
    bool wanted = argc < 2;
    for (int i = 1; i < argc; ++i)
      if (b.name.starts_with(argv[i])) wanted = true;
    if (!wanted) continue;
    b.run();
    std::fflush(stdout);
  }
  return 0;
}
