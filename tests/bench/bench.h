// A tiny benchmark registry: each benchmark prints `key value` lines on standard output.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace igds::bench {

struct Benchmark {
  std::string_view name;
  std::function<void()> run;
};

std::vector<Benchmark>& registry();

// How the commands are typed (igds_bench's options): `pause` seconds before each timed command,
// as a person pauses; `busy`: every core kept busy by other processes meanwhile, as by a parallel
// compile; `only`: the cases whose name (e.g. 500x500_4m) holds it.
struct Settings {
  double pause = 0;
  bool busy = false;
  std::string only;
};
Settings& settings();

struct Register {
  Register(std::string_view name, std::function<void()> run) {
    registry().push_back({name, std::move(run)});
  }
};

// Seconds taken by the best of `repeats` runs of `f`.
template <class F>
double best_seconds(int repeats, F&& f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (s < best) best = s;
  }
  return best;
}

}  // namespace igds::bench

#define IGDS_BENCH_CAT2(a, b) a##b
#define IGDS_BENCH_CAT(a, b) IGDS_BENCH_CAT2(a, b)
#define IGDS_BENCH(name)                                                     \
  static void IGDS_BENCH_CAT(bench_fn_, __LINE__)();                         \
  static const ::igds::bench::Register IGDS_BENCH_CAT(bench_reg_, __LINE__){ \
      name, IGDS_BENCH_CAT(bench_fn_, __LINE__)};                            \
  static void IGDS_BENCH_CAT(bench_fn_, __LINE__)()
