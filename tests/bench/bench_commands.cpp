// Every command at the speed of its data: a real igds session (the binary, --term none, its
// session on a scratch disk of the system's temporary folder, fsync included) on surfaces of about
// 1 M and 4 M points from a 100 x 100 and a 500 x 500 input grid. For each command (run three
// times, the median; the display after the exchange files once): the
// milliseconds from sending its lines to the next READY (the autosave included) and the bytes
// igds wrote to files meanwhile; at the end the session's peak resident memory. Also the start-up
// with that session saved (to READY: PATCHES and INTPN are made again before it), a PLOT typed
// as the first command after a start, and the variables' own size for comparison.
//
// With --pause S each timed command is typed S seconds after the READY before it, as a person
// types (the memory a command freed may have gone back to the system by then); with --busy every
// core is kept busy by as many processes spinning meanwhile, as by a parallel compile (bench.h).
//
// Keys: commands_<grid>_<points>_<command>_ms, ..._<command>_written_bytes,
// ..._<command>_peak_rss_mb (the session's peak once the command is done), ..._peak_rss_mb,
// ..._variables_mb, e.g. commands_500x500_4m_change_points_ms; commands_paused_...,
// commands_busy_... and commands_paused_busy_... with the options.
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tests/bench/bench.h"
#include "workspace/disk/disk.h"
#include "workspace/kernels/surface.h"

namespace igds::bench {

namespace {

namespace fs = std::filesystem;

// A scratch disk, removed at the end.
struct Scratch {
  fs::path dir;
  Scratch() {
    std::string t = (fs::temp_directory_path() / "igds-bench-XXXXXX").string();
    dir = ::mkdtemp(t.data());
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// A number from /proc/PID/FILE: the value after `key`.
std::size_t proc_value(pid_t pid, const char* file, const std::string& key) {
  std::ifstream in(fmt::format("/proc/{}/{}", pid, file));
  std::string word;
  while (in >> word) {
    if (word == key) {
      std::size_t v = 0;
      in >> v;
      return v;
    }
  }
  return 0;
}

// igds running on pipes; each command's lines are sent at once, then the output is read up to
// the READY that follows.
class Igds {
 public:
  explicit Igds(const fs::path& disk) {
    int in[2], out[2];
    if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_adddup2(&actions, out[1], 2);
    std::vector<std::string> args{IGDS_BINARY, "--term", "none", "--disk", disk.string()};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const auto t0 = std::chrono::steady_clock::now();
    if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    ::close(in[0]);
    ::close(out[1]);
    to_ = in[1];
    from_ = out[0];
    wait_ready();
    startup_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  ~Igds() {
    if (to_ >= 0) ::close(to_);
    if (from_ >= 0) ::close(from_);
    if (pid_ > 0) {
      int status = 0;
      ::waitpid(pid_, &status, 0);
    }
  }
  Igds(const Igds&) = delete;
  Igds& operator=(const Igds&) = delete;

  double startup_seconds() const { return startup_; }

  struct Timing {
    double seconds = 0;
    std::size_t written = 0;  // bytes written to files (not the output read here)
  };

  // Sends `lines` and waits for READY (or for the end, after END).
  Timing command(const std::string& lines) {
    const std::size_t wrote_before = proc_value(pid_, "io", "wchar:");
    const std::size_t output_before = output_bytes_;
    const auto t0 = std::chrono::steady_clock::now();
    // igds echoes long answers (a BUILD's lines of points): its output is read while the lines
    // are written, or both would wait for the other.
    for (std::size_t done = 0; done < lines.size();) {
      pollfd p[2] = {{to_, POLLOUT, 0}, {from_, POLLIN, 0}};
      if (::poll(p, 2, 300000) <= 0) break;
      if (p[1].revents & (POLLIN | POLLHUP)) read_some();
      if (!(p[0].revents & POLLOUT)) continue;
      ssize_t n =
          ::write(to_, lines.data() + done, std::min<std::size_t>(lines.size() - done, 4096));
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    const bool ended = !wait_ready();
    Timing t;
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!ended) {
      const std::size_t wrote = proc_value(pid_, "io", "wchar:") - wrote_before;
      t.written = wrote - std::min(wrote, output_bytes_ - output_before);
    }
    return t;
  }

  std::size_t peak_rss_kb() const { return proc_value(pid_, "status", "VmHWM:"); }
  const std::string& output() const { return output_; }

 private:
  // True at READY, false at the end of the output.
  bool wait_ready() {
    for (;;) {
      auto at = output_.find("READY\n", scanned_);
      if (at != std::string::npos) {
        scanned_ = at + 6;
        return true;
      }
      scanned_ = output_.size() > 5 ? output_.size() - 5 : 0;
      // A command that waits for an answer the steps did not give would hang the benchmark.
      pollfd p{from_, POLLIN, 0};
      if (::poll(&p, 1, 300000) != 1) {
        fmt::print(stderr, "bench commands: no READY within 300 s; output ends:\n{}\n",
                   output_.substr(output_.size() > 2000 ? output_.size() - 2000 : 0));
        ::kill(pid_, SIGKILL);
        return false;
      }
      if (!read_some()) return false;
    }
  }

  // Reads what igds wrote; false at the end of its output.
  bool read_some() {
    char buffer[65536];
    ssize_t n = ::read(from_, buffer, sizeof buffer);
    if (n <= 0) return false;
    output_.append(buffer, static_cast<std::size_t>(n));
    output_bytes_ += static_cast<std::size_t>(n);
    if (output_.size() > (1u << 20)) {  // keep the tail only
      output_.erase(0, output_.size() - 4096);
      scanned_ = 0;
    }
    return true;
  }

  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
  std::string output_;
  std::size_t scanned_ = 0, output_bytes_ = 0;
  double startup_ = 0;
};

// A wavy n x n input grid with border tangents, saved as NAME.IGDSDATA with INTCU = INTST = 0
// (RESTORE then CHANGE GRID make it big inside the session).
void save_grid(const Disk& disk, const std::string& name, int n) {
  Workspace ws;
  ws.nocur = ws.nostr = n;
  ws.inppn = Array({std::size_t(n) * std::size_t(n), 3});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double* p = ws.inppn.data() + 3 * (std::size_t(i) * n + j);
      p[0] = 10.0 * j, p[1] = 12.0 * i, p[2] = 20 * std::sin(0.05 * j) * std::cos(0.04 * i);
    }
  ws.inptg = Array({std::size_t(4 * n), 4});
  for (int r = 0; r < 4 * n; ++r) ws.inptg.ravel[4 * r + (r < 2 * n ? 0 : 1)] = 1;
  Surface s = interpolate({n, n, 0, 0, &ws.inppn, &ws.inptg});
  ws.patches = std::move(s.patches);
  ws.intpn = std::move(s.intpn);
  save_surface(disk, name, ws);
}

struct Step {
  const char* key;
  std::string lines;
  int runs = 3;  // the median of these: one run moves by a fifth with the machine's other work
  std::string before = {};  // commands typed before each run, a line each, not timed
};

// BUILD of the grid save_grid saves, typed as a designer would: a line of points for each curve,
// the tangents by AUTO, then the interpolated curves and stringers.
std::string build_lines(int n, int density) {
  std::string lines = fmt::format("BUILD\n{} {}\n", n, n);
  for (int i = 0; i < n; ++i) {
    lines += fmt::format("{}", i * n + 1);
    for (int j = 0; j < n; ++j)
      lines += fmt::format(" {} {} {:.6f}", 10.0 * j, 12.0 * i,
                           20 * std::sin(0.05 * j) * std::cos(0.04 * i));
    lines += '\n';
  }
  return lines + fmt::format("\nAUTO\n\n{} {}\n", density, density);
}

// Every core kept busy by a process of its own spinning, from construction to destruction.
class Load {
 public:
  explicit Load(unsigned processes) {
    for (unsigned k = 0; k < processes; ++k) {
      const pid_t pid = ::fork();
      if (pid == 0) {
        volatile unsigned long spin = 0;
        for (;;) spin = spin + 1;
      }
      if (pid > 0) pids_.push_back(pid);
    }
  }
  ~Load() {
    for (pid_t pid : pids_) ::kill(pid, SIGKILL);
    for (pid_t pid : pids_) ::waitpid(pid, nullptr, 0);
  }
  Load(const Load&) = delete;
  Load& operator=(const Load&) = delete;

 private:
  std::vector<pid_t> pids_;
};

// The pause before a timed command (--pause).
void pause_as_a_person() {
  if (settings().pause > 0) ::usleep(static_cast<useconds_t>(settings().pause * 1e6));
}

void run_case(const Disk& disk, const std::string& grid, int n, int density,
              const std::string& size) {
  const std::string mode =
      std::string(settings().pause > 0 ? "_paused" : "") + (settings().busy ? "_busy" : "");
  const std::string prefix = fmt::format("commands{}_{}x{}_{}", mode, n, n, size);
  const int side = n + density * (n - 1);
  const double points = double(side) * side;
  fmt::print("{}_points {:.0f}\n", prefix, points);
  // The variables: INPPN, INPTG, PATCHES (made when a command reads them), INTPN and three images
  // of the surface.
  const double variables =
      8.0 * (3.0 * n * n + 16.0 * n + 48.0 * (n - 1) * (n - 1) + 3 * points + 3 * 2 * points);
  fmt::print("{}_variables_mb {:.1f}\n", prefix, variables / 1e6);

  const int mid = (n / 2) * n + n / 2;  // a point inside
  const std::string surface = "DISPLAY SURFACE ISOMETRIC 3 30\n";
  const std::vector<Step> steps{
      {"build", build_lines(n, density)},
      {"restore", fmt::format("RESTORE {}\n", grid)},
      {"change_grid", fmt::format("CHANGE GRID {} {}\n", density, density)},
      {"change_points",
       fmt::format("CHANGE POINTS\n{} {} {} 5\n\nN\nN\n", mid + 1, 10.0 * (n / 2), 12.0 * (n / 2))},
      {"change_tangents", "CHANGE TANGENTS\n1 1 0.2 0 1\n\nN\n"},
      {"change_twists", "CHANGE TWISTS MARKS\n"},
      {"display_surface", "DISPLAY SURFACE ASSONOMETRIC 110 130 120\n"},
      {"display_surface_conic",
       fmt::format("DISPLAY SURFACE CONIC {} {} {}\n", 30.0 * n, -20.0 * n, 15.0 * n)},
      // The first combs of the surface (a surface image before each run), then combs in another
      // view of a surface whose combs were drawn (their scale known, images.h).
      {"display_combs", "DISPLAY COMBS ASSONOMETRIC 110 130 120\n", 3, surface},
      {"display_combs_conic",
       fmt::format("DISPLAY COMBS CONIC {} {} {}\n", 30.0 * n, -20.0 * n, 15.0 * n), 3, surface},
      {"display_combs_again", "DISPLAY COMBS ISOMETRIC 3 30\n", 3,
       "DISPLAY COMBS ASSONOMETRIC 110 130 120\n"},
      {"display_combs_conic_again",
       fmt::format("DISPLAY COMBS CONIC {} {} {}\n", 30.0 * n, -20.0 * n, 15.0 * n), 3,
       "DISPLAY COMBS ASSONOMETRIC 110 130 120\n"},
      {"display_input", "DISPLAY INPUT ISOMETRIC 3 30\n"},
      {"store_first", "STORE FIRST\n", 3, surface},
      {"display_first", "DISPLAY FIRST\n"},
      {"store_second", "STORE SECOND\n", 3, surface},
      {"display_second", "DISPLAY SECOND\n"},
      {"zoom", "ZOOM 2\n"},
      {"zoom_whole", "ZOOM\n"},
      {"list_surface", "LIST SURFACE\n"},
      {"undo", "UNDO\n", 3, surface},
      {"redo", "REDO\n", 3, surface + "UNDO\n"},
      {"erase", "ERASE\n"},
      {"help_short", "HELP SHORT\n"},
      {"store_file", "STORE FILE IMG\n"},
      {"display_file", "DISPLAY FILE IMG\n"},
      {"save", "SAVE COPY\n"},
      {"write", "WRITE CARDS\n"},
      {"plot", "PLOT SELECTRIC\n"},
      {"export_hpgl", "EXPORT HPGL DRAWING\n"},
      {"export_tek", "EXPORT TEK DRAWING\n"},
      {"export_svg", "EXPORT SVG DRAWING\n"},
      {"export_duct", "EXPORT DUCT DRAWING\n"},
      {"export_iges", "EXPORT IGES DRAWING\n"},
      {"export_step", "EXPORT STEP DRAWING\n"},
      // Once: the first image made after the plots and files, where the memory they left may
      // not hold it (the heap grows).
      {"display_after_plots", "DISPLAY SURFACE ASSONOMETRIC 110 130 120\n", 1},
  };
  std::size_t peak = 0;
  {
    Igds igds(disk.dir());
    // The work a start leaves behind READY (the saved surface made again) done first, not
    // counted in BUILD's time: it is the start-up's, measured below as the first answer.
    igds.command("HELP SHORT\n");
    for (const auto& step : steps) {
      // Each step three times, after its commands `before`, the median; a BUILD after the
      // first replaces the surface it made.
      std::vector<Igds::Timing> runs;
      for (int r = 0; r < step.runs; ++r) {
        for (std::size_t at = 0, end; at < step.before.size(); at = end + 1) {
          end = step.before.find('\n', at);
          igds.command(step.before.substr(at, end + 1 - at));
        }
        pause_as_a_person();
        runs.push_back(igds.command(step.lines));
      }
      // The image it replaced back (not timed): the start-ups below measure the session they
      // always measured, whose image was read from a file.
      if (std::string_view(step.key) == "display_after_plots") igds.command("UNDO\n");
      std::sort(runs.begin(), runs.end(),
                [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
      const auto& median = runs[runs.size() / 2];
      fmt::print("{}_{}_ms {:.1f}\n{}_{}_written_bytes {}\n", prefix, step.key,
                 1000 * median.seconds, prefix, step.key, median.written);
      // The session's peak so far: which command sets it.
      fmt::print("{}_{}_peak_rss_mb {:.1f}\n", prefix, step.key, igds.peak_rss_kb() / 1024.0);
      std::fflush(stdout);
    }
    peak = igds.peak_rss_kb();
    pause_as_a_person();
    auto t = igds.command("END CMS\n");
    fmt::print("{}_end_ms {:.1f}\n", prefix, 1000 * t.seconds);
  }
  fmt::print("{}_peak_rss_mb {:.1f}\n", prefix, peak / 1024.0);
  // To READY, and to the answer of a first command typed at once.
  std::vector<double> starts, answers;
  for (int r = 0; r < 3; ++r) {
    Igds igds(disk.dir());
    starts.push_back(igds.startup_seconds());
    answers.push_back(igds.startup_seconds() + igds.command("HELP SHORT\n").seconds);
    igds.command("END CMS\n");
  }
  std::sort(starts.begin(), starts.end());
  std::sort(answers.begin(), answers.end());
  fmt::print("{}_startup_ms {:.1f}\n", prefix, 1000 * starts[1]);
  fmt::print("{}_startup_first_answer_ms {:.1f}\n", prefix, 1000 * answers[1]);
  // A PLOT typed half a second after READY (or after the pause), as the first command of the
  // session: its image (kept by recipe) is made then, the plot's memory is new to igds.
  std::vector<double> plots;
  for (int r = 0; r < 3; ++r) {
    Igds igds(disk.dir());
    if (settings().pause > 0)
      pause_as_a_person();
    else
      ::usleep(500000);
    plots.push_back(igds.command("PLOT SELECTRIC\n").seconds);
    igds.command("END CMS\n");
  }
  std::sort(plots.begin(), plots.end());
  fmt::print("{}_first_plot_after_start_ms {:.1f}\n", prefix, 1000 * plots[1]);
  for (const auto& entry : fs::directory_iterator(disk.dir())) {
    const auto name = entry.path().filename().string();
    if (!name.ends_with(".IGDSDATA")) fs::remove_all(entry.path());
  }
}

}  // namespace

IGDS_BENCH("commands") {
  ::signal(SIGPIPE, SIG_IGN);
  Scratch scratch;
  Disk disk(scratch.dir);
  // About 1 M and 4 M points: (n + d(n-1))^2.
  struct Case {
    int n, density;
    const char* size;
  };
  const Case cases[] = {{100, 9, "1m"}, {100, 19, "4m"}, {500, 1, "1m"}, {500, 3, "4m"}};
  std::optional<Load> load;
  if (settings().busy) load.emplace(std::thread::hardware_concurrency());
  for (const Case& c : cases) {
    const std::string name = fmt::format("{}x{}_{}", c.n, c.n, c.size);
    if (name.find(settings().only) == std::string::npos) continue;
    const std::string grid = fmt::format("G{}", c.n);
    if (!fs::exists(disk.path(grid, "IGDSDATA"))) save_grid(disk, grid, c.n);
    run_case(disk, grid, c.n, c.density, c.size);
  }
}

}  // namespace igds::bench
