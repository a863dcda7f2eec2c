// END APL's speed: on workspace-sized arrays, INTPN of a 2000 × 2000 surface (12 M doubles) held
// by the host, statements run through AplSession::execute, against NumPy doing the same on this
// machine; and a loop of scalar statements in a defined function against the same loop in
// CPython (ratio = the other's time / igds's time; 1 or more is the goal).
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "interp/apl/apl_session.h"
#include "interp/apl_env.h"
#include "tests/bench/bench.h"
#include "tests/bench/inputs.h"
#include "workspace/kernels/surface.h"

namespace igds::bench {

namespace {

// A host that owns INTPN, as igds's workspace will.
struct BenchHost : apl::Host {
  apl::Value intpn;
  std::vector<std::string> printed;
  void print(std::string_view line) override { printed.emplace_back(line); }
  std::optional<std::string> read_line(std::string_view) override { return std::nullopt; }
  bool owns(std::string_view name) const override { return name == "INTPN"; }
  std::optional<apl::Value> get(std::string_view) override { return intpn; }
  void set(std::string_view, const apl::Value& v) override { intpn = v; }
};

apl::Value grid(std::size_t rows, std::size_t cols, std::size_t planes) {
  apl::Value v = apl::Value::uninitialised_numbers({rows, cols, planes});
  auto x = v.mutable_numbers();
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(0.001 * static_cast<double>(i));
  return v;
}

// NumPy's best times for the same four operations, or empty when python3 or NumPy is missing.
// P[:, :, 0] is a view in NumPy: .copy() makes the array that INTPN[;;1] makes.
std::vector<double> numpy_times() {
  const char* script =
      "import time, numpy as np\n"
      "P = np.sin(0.001 * np.arange(2000 * 2000 * 3)).reshape(2000, 2000, 3)\n"
      "A = np.sin(0.001 * np.arange(250000)).reshape(500, 500)\n"
      "B = np.cos(0.001 * np.arange(250000)).reshape(500, 500)\n"
      "def best(f, n):\n"
      "    t = 1e300\n"
      "    for _ in range(n):\n"
      "        t0 = time.perf_counter(); f(); t = min(t, time.perf_counter() - t0)\n"
      "    return t\n"
      "X = None\n"
      "def times2():\n"
      "    global X\n"
      "    X = P * 2\n"
      "print(best(times2, 5), best(lambda: P.ravel().sum(), 5),\n"
      "      best(lambda: P[:, :, 0].copy(), 5), best(lambda: A @ B, 3))\n";
  for (const char* python : {"python3", "/usr/bin/python3"}) {
    std::string command = fmt::format("{} -c '{}' 2>/dev/null", python, script);
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) continue;
    std::vector<double> t(4, 0);
    int read = std::fscanf(pipe, "%lf %lf %lf %lf", &t[0], &t[1], &t[2], &t[3]);
    int status = pclose(pipe);
    if (read == 4 && status == 0) return t;
  }
  return {};
}

// CPython's best time for one pass of the loop SUM runs (Z←Z+I, I←I+1, →(I<N)/L), in seconds,
// or a negative number when there is no python3.
double cpython_loop_seconds(int n) {
  const std::string script = fmt::format(
      "import time\n"
      "def f(n):\n"
      "    z = 0; i = 0\n"
      "    while True:\n"
      "        z = z + i\n"
      "        i = i + 1\n"
      "        if not (i < n): break\n"
      "    return z\n"
      "t = 1e300\n"
      "for _ in range(5):\n"
      "    t0 = time.perf_counter(); f({}); t = min(t, time.perf_counter() - t0)\n"
      "print(t / {})\n",
      n, n);
  for (const char* python : {"python3", "/usr/bin/python3"}) {
    std::string command = fmt::format("{} -c '{}' 2>/dev/null", python, script);
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) continue;
    double t = -1;
    int read = std::fscanf(pipe, "%lf", &t);
    int status = pclose(pipe);
    if (read == 1 && status == 0) return t;
  }
  return -1;
}

}  // namespace

IGDS_BENCH("apl") {
  BenchHost host;
  host.intpn = grid(2000, 2000, 3);
  apl::AplSession session(host);
  session.assign("A", grid(500, 500, 1).reshaped({500, 500}));
  apl::Value b = grid(500, 500, 1);
  for (auto& x : b.mutable_numbers()) x = std::cos(std::asin(x));
  session.assign("B", b.reshaped({500, 500}));

  auto run = [&](const char* line) {
    session.execute(line);
    if (!host.printed.empty()) {
      fmt::print(stderr, "bench_apl: {} printed {}\n", line, host.printed.front());
      host.printed.clear();
    }
  };
  const double times2 = best_seconds(5, [&] { run("X←INTPN×2"); });
  const double sum = best_seconds(5, [&] { run("S←+/,INTPN"); });
  const double plane = best_seconds(5, [&] { run("Y←INTPN[;;1]"); });
  const double product = best_seconds(3, [&] { run("C←A+.×B"); });
  // A, the matrix, is done with: the small statement is the A←1+2.
  constexpr int small_runs = 20000;
  auto small_statements = [&] {
    for (int i = 0; i < small_runs; ++i) run("A←1+2");
  };
  const double small = best_seconds(3, small_statements) / small_runs;

  fmt::print("apl_intpn_times_2_s {:.6f}\n", times2);
  fmt::print("apl_sum_ravel_intpn_s {:.6f}\n", sum);
  fmt::print("apl_intpn_plane_1_s {:.6f}\n", plane);
  fmt::print("apl_inner_product_500_s {:.6f}\n", product);
  fmt::print("apl_small_statement_us {:.3f}\n", small * 1e6);
  // A loop of three scalar statements an iteration, as an APL\360 user writes one.
  for (const char* line : {"∇Z←SUM N;I", "Z←I←0", "L:Z←Z+I", "I←I+1", "→(I<N)/L", "∇"})
    session.execute(line);
  constexpr int passes = 1000000;
  const double loop = best_seconds(5, [&] { run("S←SUM 1000000"); }) / passes;
  fmt::print("apl_loop_iteration_ns {:.1f}\n", loop * 1e9);
  const double cpython = cpython_loop_seconds(passes);
  if (cpython > 0) {
    fmt::print("apl_cpython_loop_iteration_ns {:.1f}\n", cpython * 1e9);
    fmt::print("apl_cpython_ratio_loop {:.2f}\n", cpython / loop);
  } else {
    fmt::print("apl_cpython_ratio_loop unavailable (no python3)\n");
  }
  const std::vector<double> numpy = numpy_times();
  if (numpy.empty()) {
    fmt::print("apl_numpy_ratios unavailable (no python3 with NumPy)\n");
    return;
  }
  fmt::print("apl_numpy_ratio_times_2 {:.2f}\n", numpy[0] / times2);
  fmt::print("apl_numpy_ratio_sum_ravel {:.2f}\n", numpy[1] / sum);
  fmt::print("apl_numpy_ratio_plane_1 {:.2f}\n", numpy[2] / plane);
  fmt::print("apl_numpy_ratio_inner_product {:.2f}\n", numpy[3] / product);
}

// The same statements in END APL itself (interp/apl_env.h) on the 4 M-point surface of a 500 x
// 500 input grid with INTCU = INTST = 3: INTPN read from the workspace, assignments checked.
IGDS_BENCH("apl_workspace") {
  Input in = wavy(500, 500);
  Workspace ws;
  ws.nocur = ws.nostr = 500;
  ws.intcu = ws.intst = 3;
  ws.inppn = std::move(in.inppn);
  ws.inptg = std::move(in.inptg);
  Surface surface = interpolate({500, 500, 3, 3, &ws.inppn, &ws.inptg});
  ws.patches = std::move(surface.patches);
  ws.intpn = std::move(surface.intpn);
  std::size_t printed = 0;
  AplEnvironment::Hooks hooks;
  hooks.report = [&](std::string_view) { ++printed; };
  // X and Y (96 and 32 MB) are more than the session keeps of END APL's variables: said once.
  hooks.say = [&](std::string_view line) {
    printed += line.find("IS NOT KEPT WITH THE SESSION") == std::string_view::npos;
  };
  hooks.read = [](std::string_view) { return std::nullopt; };
  hooks.command = [](const std::vector<std::string>&) { return true; };
  AplEnvironment apl(ws, hooks);
  auto run = [&](const char* line) { apl.execute(line); };
  const double first = best_seconds(1, [&] { run("X←INTPN×2"); });  // INTPN made an APL value
  const double times2 = best_seconds(5, [&] { run("X←INTPN×2"); });
  const double sum = best_seconds(5, [&] { run("S←+/,INTPN"); });
  const double plane = best_seconds(5, [&] { run("Y←INTPN[;;1]"); });
  const double assign = best_seconds(3, [&] { run("INPPN[1;3]←INPPN[1;3]"); });
  const double start = best_seconds(3, [&] {
    run("INPPN[1;3]←INPPN[1;3]");
    apl.start();
  });
  constexpr int small_runs = 20000;
  const double small = best_seconds(3,
                                    [&] {
                                      for (int i = 0; i < small_runs; ++i) run("A←1+2");
                                    }) /
                       small_runs;
  fmt::print("apl_workspace_points {}\n", ws.intpn.size() / 3);
  fmt::print("apl_workspace_first_read_intpn_s {:.6f}\n", first);
  fmt::print("apl_workspace_intpn_times_2_s {:.6f}\n", times2);
  fmt::print("apl_workspace_sum_ravel_intpn_s {:.6f}\n", sum);
  fmt::print("apl_workspace_intpn_plane_1_s {:.6f}\n", plane);
  fmt::print("apl_workspace_assign_one_point_s {:.6f}\n", assign);
  fmt::print("apl_workspace_assign_and_start_s {:.6f}\n", start);
  fmt::print("apl_workspace_small_statement_us {:.3f}\n", small * 1e6);
  if (printed != 0) fmt::print(stderr, "bench_apl: {} lines printed\n", printed);
}

}  // namespace igds::bench
