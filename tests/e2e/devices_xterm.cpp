// A 4013 stream in a real xterm Tek window under Xvfb: `xterm -t` runs `cat FILE`, a screenshot
// of the Tek window is taken, and its pixels are probed where vectors must be and where they
// must not. Another program's stream is not needed: the vectors are those igds meant to draw.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <optional>
#include <thread>

#include "devices/layout.h"
#include "devices/tek4013.h"
#include "devices/tek_stream.h"
#include "tests/devices/support.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"

namespace igds::test::devices {

namespace {

using namespace std::chrono_literals;

// A program started by the test in its own process group; killed with the group at the end.
class Started {
 public:
  // `fd3`: a descriptor the program gets as its descriptor 3 (-1: none).
  Started(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
          int fd3 = -1) {
    pid_ = fork();
    if (pid_ == 0) {
      setpgid(0, 0);
      for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
      int null = open("/dev/null", O_RDWR);
      dup2(null, 0), dup2(null, 1), dup2(null, 2);
      if (fd3 >= 0) dup2(fd3, 3);
      std::vector<char*> args;
      for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      execvp(args[0], args.data());
      _exit(127);
    }
  }
  ~Started() {
    if (pid_ <= 0) return;
    kill(-pid_, SIGKILL);
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  Started(const Started&) = delete;
  Started& operator=(const Started&) = delete;

 private:
  pid_t pid_ = -1;
};

// Xvfb on a display number it chooses itself (-displayfd): no clash with other tests.
struct Xvfb {
  std::optional<Started> process;
  std::string display;
  Xvfb() {
    int p[2];
    if (pipe(p) != 0) return;
    process.emplace(std::vector<std::string>{"Xvfb", "-displayfd", "3", "-screen", "0",
                                             "1280x1024x24", "-nolisten", "tcp",
                                             // Without it the server resets when its last
                                             // client leaves, and the next xterm can miss it.
                                             "-noreset"},
                    std::map<std::string, std::string>{}, p[1]);
    close(p[1]);
    std::string number;
    auto deadline = std::chrono::steady_clock::now() + 15s;
    while (std::chrono::steady_clock::now() < deadline) {
      pollfd fd{p[0], POLLIN, 0};
      if (poll(&fd, 1, 200) <= 0) continue;
      char c;
      if (read(p[0], &c, 1) != 1 || c == '\n') break;
      number += c;
    }
    close(p[0]);
    if (!number.empty()) display = ":" + number;
  }
};

template <class F>
bool wait_for(F ready, std::chrono::milliseconds limit) {
  auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (ready()) return true;
    std::this_thread::sleep_for(200ms);
  }
  return ready();
}

struct Shot {
  int width = 0, height = 0;
  std::string grey;
  int at(int x, int y) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return 255;
    return static_cast<unsigned char>(grey[static_cast<std::size_t>(y * width + x)]);
  }
  // A dark pixel within `r` pixels of (x, y).
  bool dark_near(double x, double y, int r) const {
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx)
        if (at(static_cast<int>(std::lround(x)) + dx, static_cast<int>(std::lround(y)) + dy) < 128)
          return true;
    return false;
  }
};

// The Tek window of `display`, as grey pixels (xterm draws black on white there).
std::optional<Shot> screenshot(const std::string& display, const std::filesystem::path& dir) {
  RunOptions options;
  options.env = {{"DISPLAY", display}};
  options.timeout_seconds = 20;
  RunResult id = run({"xdotool", "search", "--name", "tektronix"}, options);
  if (id.status != 0 || id.out.empty()) return std::nullopt;
  std::string window = id.out.substr(0, id.out.find('\n'));
  auto png = (dir / "shot.png").string();
  if (run({"import", "-window", window, png}, options).status != 0) return std::nullopt;
  RunResult size = run({"identify", "-format", "%w %h", png}, options);
  RunResult grey = run({"convert", png, "-colorspace", "gray", "-depth", "8", "gray:-"}, options);
  Shot s;
  if (std::sscanf(size.out.c_str(), "%d %d", &s.width, &s.height) != 2) return std::nullopt;
  s.grey = grey.out;
  if (s.grey.size() != static_cast<std::size_t>(s.width * s.height)) return std::nullopt;
  return s;
}

// The calibration frame drawn around the screen: 4013 points to window pixels.
constexpr int frame_lo = 4, frame_x1 = 1019, frame_y1 = 763;

std::string frame(int bits) {
  int u = bits == 12 ? 4 : 1;
  TekEncoder t(bits);
  for (DevicePoint p : {DevicePoint{frame_lo, frame_lo}, DevicePoint{frame_x1, frame_lo},
                        DevicePoint{frame_x1, frame_y1}, DevicePoint{frame_lo, frame_y1},
                        DevicePoint{frame_lo, frame_lo}})
    t.draw({u * p.x, u * p.y});
  return t.take();
}

struct Mapping {
  double x0 = 0, sx = 0, y0 = 0, sy = 0;
  double px(double x) const { return x0 + sx * (x - frame_lo); }
  double py(double y) const { return y0 - sy * (y - frame_lo); }
};

// The outermost long dark rows and columns are the frame.
std::optional<Mapping> find_frame(const Shot& s) {
  std::vector<int> rows, cols;
  for (int y = 0; y < s.height; ++y) {
    int n = 0;
    for (int x = 0; x < s.width; ++x) n += s.at(x, y) < 128;
    if (n > s.width * 8 / 10) rows.push_back(y);
  }
  for (int x = 0; x < s.width; ++x) {
    int n = 0;
    for (int y = 0; y < s.height; ++y) n += s.at(x, y) < 128;
    if (n > s.height * 9 / 10) cols.push_back(x);
  }
  if (rows.size() < 2 || cols.size() < 2) return std::nullopt;
  Mapping m;
  m.x0 = cols.front();
  m.sx = double(cols.back() - cols.front()) / (frame_x1 - frame_lo);
  m.y0 = rows.back();
  m.sy = double(rows.back() - rows.front()) / (frame_y1 - frame_lo);
  return m;
}

bool tek_window_shown(const std::string& display) {
  RunOptions options;
  options.env = {{"DISPLAY", display}};
  options.timeout_seconds = 20;
  return !run({"xdotool", "search", "--name", "tektronix"}, options).out.empty();
}

// Runs `xterm -t -e cat FILE` on `stream` and returns the settled screenshot of its Tek window.
std::optional<Shot> show_in_xterm(const Xvfb& x, const std::string& stream, const TempDir& dir) {
  // The window of the previous xterm must be gone, or it could be the one photographed.
  wait_for([&] { return !tek_window_shown(x.display); }, 20s);
  write_file(dir.path() / "stream.tek", stream);
  Started xterm({"xterm", "-hold", "-t", "-xrm", "XTerm*tekGeometry: 1030x800+0+0", "-e", "cat",
                 (dir.path() / "stream.tek").string()},
                {{"DISPLAY", x.display}});
  std::optional<Shot> shot, last;
  // Settled: the frame is there and two screenshots in a row agree. A slow machine gets time.
  wait_for(
      [&] {
        auto now = screenshot(x.display, dir.path());
        if (!now) return false;
        last = std::move(shot);
        shot = std::move(now);
        return last && shot->grey == last->grey && find_frame(*shot);
      },
      60s);
  return shot;
}

}  // namespace

TEST_CASE("xterm Tek window: the vectors are where they must be, nothing where they must not") {
  IGDS_SKIP_UNLESS(have_program("Xvfb"), "Xvfb is not installed");
  for (const char* program : {"xterm", "xdotool", "import", "convert", "identify"})
    REQUIRE_MESSAGE(have_program(program), program << " is needed");
  Xvfb x;
  REQUIRE(!x.display.empty());
  TempDir dir;
  struct Case {
    Image image;
    int bits;
  };
  for (const auto& [im, bits] :
       {Case{flat_grid(8), 10}, Case{input_image(4, 5), 10}, Case{flat_grid(8), 12}}) {
    const std::string what =
        std::to_string(bits) + "-bit addresses, " + (im.desim.what ? "surface" : "input");
    INFO(what);
    // Drawn in 4013 points whatever the address size, to probe the window in one scale.
    const int unit = bits == 12 ? 4 : 1;
    Recorder drawn;
    draw_tek_display(picture_of(im), drawn, unit);
    Recorder r;
    for (const auto& p : drawn.drawn()) {
      DevicePath q;
      for (auto d : p) q.push_back({d.x / unit, d.y / unit});
      r.paths.push_back(q);
    }
    std::string stream =
        erase_bytes(TermMode::tek, {bits}) + frame(bits) + display_bytes(im, TermMode::tek, {bits});
    auto shot = show_in_xterm(x, stream, dir);
    REQUIRE(shot);
    auto m = find_frame(*shot);
    REQUIRE(m);
    // xterm's Tek window: about one pixel per 4013 point in a 1030 x 800 window.
    CHECK(m->sx == doctest::Approx(1).epsilon(0.05));
    CHECK(m->sy == doctest::Approx(1).epsilon(0.05));
    // On every vector: its middle and its quarter points are dark.
    int probes = 0, missed = 0;
    for (const auto& path : r.drawn())
      for (std::size_t i = 0; i + 1 < path.size(); ++i)
        for (double t : {0.25, 0.5, 0.75}) {
          double tx = path[i].x + t * (path[i + 1].x - path[i].x);
          double ty = path[i].y + t * (path[i + 1].y - path[i].y);
          ++probes;
          if (!shot->dark_near(m->px(tx), m->py(ty), 1)) ++missed;
        }
    CHECK(probes > 20);
    CHECK(missed == 0);
    // The description is written right of the image.
    bool text = false;
    for (double y = 700; y <= 745 && !text; y += 2)
      for (double tx = 780; tx <= 860 && !text; tx += 2)
        text = shot->dark_near(m->px(tx), m->py(y), 0);
    CHECK(text);
    if (im.desim.what == 1) {
      // Between the grid lines (the middle of every cell) the screen stays clear.
      int n = static_cast<int>(im.points.shape[0]);
      auto corner = [&](int c, int k) {
        return r.drawn()[static_cast<std::size_t>(c)][static_cast<std::size_t>(k)];
      };
      for (int c = 0; c + 1 < n; ++c)
        for (int k = 0; k + 1 < n; ++k) {
          double cx = (corner(c, k).x + corner(c + 1, k + 1).x) / 2.0;
          double cy = (corner(c, k).y + corner(c + 1, k + 1).y) / 2.0;
          CHECK(!shot->dark_near(m->px(cx), m->py(cy), 6));
        }
    }
    // Right of the description and below the image's square nothing is drawn.
    CHECK(!shot->dark_near(m->px(960), m->py(300), 8));
  }
}

}  // namespace igds::test::devices
