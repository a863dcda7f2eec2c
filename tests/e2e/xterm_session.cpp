// igds in a real xterm Tek window under Xvfb: an example is typed key by key with xdotool
// (abbreviated commands, HELP at a prompt, point entries), and screenshots of the Tek window must
// show the picture that igds's own 4013 stream for the same lines describes: dark pixels on its
// vectors, light ones in the empty areas between them.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <fmt/core.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <thread>

#include "commands/menu.h"
#include "devices/menu_layout.h"
#include "tests/e2e/e2e_support.h"
#include "tests/e2e/examples_support.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"

namespace igds::test {

namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// A program running beside the test; killed (with its process group) when it goes out of scope.
class Background {
 public:
  // `log`: where its standard error goes (default: nowhere).
  Background(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
             const std::filesystem::path& log = "/dev/null") {
    pid_ = fork();
    if (pid_ == 0) {
      setpgid(0, 0);
      for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
      // Not freopen: that would flush a copy of the test's own buffered output.
      int null = open("/dev/null", O_RDWR);
      int err = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(null, 0);
      dup2(null, 1);
      dup2(err >= 0 ? err : null, 2);
      std::vector<char*> args;
      for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      execvp(args[0], args.data());
      _exit(127);
    }
  }
  // SIGTERM first, so that Xvfb removes its lock file and socket and xterm hangs up on igds;
  // SIGKILL for whatever is still there after two seconds.
  ~Background() {
    if (!running()) return;
    kill(-pid_, SIGTERM);
    auto deadline = Clock::now() + 2s;
    while (running() && Clock::now() < deadline) std::this_thread::sleep_for(20ms);
    if (running()) {
      kill(-pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
      reaped_ = true;
    }
  }
  Background(const Background&) = delete;
  Background& operator=(const Background&) = delete;

  bool running() {
    if (reaped_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      reaped_ = true;
      status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      return false;
    }
    return true;
  }
  int status() const { return status_; }
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
  int status_ = -1;
};

RunOptions in_env(const std::map<std::string, std::string>& env, double timeout_seconds = 20) {
  RunOptions options;
  options.env = env;
  options.timeout_seconds = timeout_seconds;
  return options;
}

// Polls `ready` every 100 ms until it holds or `limit` has passed.
template <class F>
bool wait_for(F ready, std::chrono::milliseconds limit) {
  auto deadline = Clock::now() + limit;
  while (Clock::now() < deadline) {
    if (ready()) return true;
    std::this_thread::sleep_for(100ms);
  }
  return ready();
}

// An Xvfb server on the first free display number from 90 on. -noreset: by default the server
// resets when its last client leaves, and a client connecting meanwhile is refused.
struct Xserver {
  std::optional<Background> process;
  std::string display;

  Xserver() {
    for (int n = 90; n < 190; ++n) {
      auto socket = fmt::format("/tmp/.X11-unix/X{}", n);
      if (std::filesystem::exists(fmt::format("/tmp/.X{}-lock", n)) ||
          std::filesystem::exists(socket))
        continue;
      process.emplace(std::vector<std::string>{"Xvfb", fmt::format(":{}", n), "-screen", "0",
                                               "1280x1024x24", "-nolisten", "tcp", "-noreset"},
                      std::map<std::string, std::string>{});
      // Ours when the lock file names our Xvfb: another server may have taken the number.
      auto lock = fmt::format("/tmp/.X{}-lock", n);
      auto ours = [&] {
        return std::filesystem::exists(socket) && std::filesystem::exists(lock) &&
               std::atoi(read_file(lock).c_str()) == process->pid();
      };
      // Ready when it answers a client, not merely when its socket exists.
      auto answers = [&] {
        RunOptions o;
        o.env = {{"DISPLAY", fmt::format(":{}", n)}};
        o.timeout_seconds = 5;
        return run({"xdotool", "getdisplaygeometry"}, o).status == 0;
      };
      if (wait_for([&] { return (ours() && answers()) || !process->running(); }, 10s) &&
          process->running()) {
        display = fmt::format(":{}", n);
        return;
      }
      process.reset();  // someone else took that number meanwhile: the next one
    }
  }
};

// A screenshot of a window, as 8-bit grey pixels.
struct Shot {
  int width = 0, height = 0;
  std::string grey;  // width * height bytes, row by row from the top
  bool dark(int x, int y) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return false;
    return static_cast<unsigned char>(grey[static_cast<std::size_t>(y) * width + x]) < 128;
  }
  bool dark_near(int x, int y, int r) const {
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx)
        if (dark(x + dx, y + dy)) return true;
    return false;
  }
};

std::optional<Shot> screenshot(const std::string& display, const std::string& window,
                               const std::filesystem::path& png) {
  std::map<std::string, std::string> env{{"DISPLAY", display}};
  auto taken = run({"import", "-window", window, png.string()}, in_env(env));
  if (taken.status != 0) return std::nullopt;
  auto size = run({"identify", "-format", "%w %h", png.string()}, in_env({}));
  auto raw = run({"convert", png.string(), "-depth", "8", "gray:-"}, in_env({}));
  Shot shot;
  if (std::sscanf(size.out.c_str(), "%d %d", &shot.width, &shot.height) != 2) return std::nullopt;
  shot.grey = raw.out;
  if (shot.grey.size() != static_cast<std::size_t>(shot.width) * shot.height) return std::nullopt;
  return shot;
}

// Where xterm's Tek window puts a 4013 point (xterm Tekproc.c: one scale for both axes, the
// 4096 x 3072 screen plus 34 units of top and 23 of bottom padding, a border of 2 pixels).
struct TekWindowMap {
  double scale;
  int border = 2;
  TekWindowMap(int width, int height)
      : scale(std::min((width - 4) / 4096.0, (height - 4) / (3072.0 + 34 + 23))) {}
  int px(double x) const { return border + static_cast<int>(4 * x * scale); }
  int py(double y) const { return border + static_cast<int>((3072 + 34 - 4 * y) * scale); }
};

struct Probes {
  std::vector<TekPoint> on;     // middles of vectors: must be dark
  std::vector<TekPoint> empty;  // far from every vector and every line of text: must be light
};

Probes probes_of(const TekPage& page) {
  Probes p;
  std::vector<const TekSegment*> long_ones;
  for (const auto& s : page.segments)
    if (std::hypot(s.b.x - s.a.x, s.b.y - s.a.y) >= 6 && std::max(s.a.y, s.b.y) <= 760)
      long_ones.push_back(&s);
  std::size_t step = std::max<std::size_t>(1, long_ones.size() / 150);
  for (std::size_t i = 0; i < long_ones.size(); i += step)
    p.on.push_back(
        {(long_ones[i]->a.x + long_ones[i]->b.x) / 2, (long_ones[i]->a.y + long_ones[i]->b.y) / 2});
  for (double y = 24; y <= 744; y += 12) {
    bool near_text = false;
    for (const auto& t : page.texts) near_text = near_text || std::abs(t.at.y + 8 - y) < 34;
    if (near_text) continue;
    for (double x = 24; x <= 1000; x += 12) {
      bool near = false;
      for (const auto& s : page.segments) {
        if (distance({x, y}, s) < 8) {
          near = true;
          break;
        }
      }
      if (!near) p.empty.push_back({x, y});
    }
  }
  return p;
}

struct Verdict {
  std::size_t on_missing = 0, empty_dark = 0;
  bool good() const { return on_missing == 0 && empty_dark == 0; }
};

Verdict judge(const Shot& shot, const Probes& probes) {
  TekWindowMap map(shot.width, shot.height);
  Verdict v;
  for (const auto& p : probes.on)
    if (!shot.dark_near(map.px(p.x), map.py(p.y), 2)) ++v.on_missing;
  for (const auto& p : probes.empty)
    if (shot.dark_near(map.px(p.x), map.py(p.y), 1)) ++v.empty_dark;
  return v;
}

std::string joined(const std::vector<std::string>& lines, std::size_t from, std::size_t to) {
  std::string text;
  for (std::size_t i = from; i < to; ++i) text += lines[i] + "\n";
  return text;
}

// The first window of `xterm` (whose name contains `name`, if given), once it exists ("" after
// 15 s).
std::string window_of(const Background& xterm, const std::map<std::string, std::string>& env,
                      const std::string& name) {
  std::string window;
  wait_for(
      [&] {
        std::vector<std::string> search{"xdotool", "search", "--pid", std::to_string(xterm.pid())};
        if (!name.empty()) search.insert(search.end(), {"--name", name});
        auto found = run(search, in_env(env));
        window = found.out.substr(0, found.out.find('\n'));
        return !window.empty();
      },
      15s);
  return window;
}

// igds has started when READY is in the window (dark pixels in its top left corner).
bool ready_shown(const std::string& display, const std::string& window,
                 const std::filesystem::path& png) {
  return wait_for(
      [&] {
        auto shot = screenshot(display, window, png);
        if (!shot) return false;
        for (int y = 0; y < 40; ++y)
          for (int x = 0; x < 200; ++x)
            if (shot->dark(x, y)) return true;
        return false;
      },
      15s);
}

// Types `lines` key by key into the focused window, each ended by Return. The APL minus ¯ is
// typed as -, which igds reads the same: xdotool types a character that is not on the keyboard
// map by mapping it to a spare key for a moment, and xterm sometimes reads that key after the
// mapping is gone, losing the sign. Other such characters (⍴) are typed alone and slowly.
void type_lines(const std::map<std::string, std::string>& env,
                const std::vector<std::string>& lines) {
  auto type = [&](const std::string& keys, const char* delay) {
    auto typed = run({"xdotool", "type", "--delay", delay, "--", keys}, in_env(env));
    REQUIRE(typed.status == 0);
  };
  constexpr std::string_view high_minus = "\u00AF";
  for (const auto& line : lines) {
    std::string plain;
    for (std::size_t i = 0; i < line.size();) {
      auto c = static_cast<unsigned char>(line[i]);
      if (line.compare(i, high_minus.size(), high_minus) == 0) {
        plain += '-';
        i += high_minus.size();
        continue;
      }
      if (c < 0x80) {
        plain += line[i++];
        continue;
      }
      std::size_t len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
      if (!plain.empty()) type(plain, "8");
      plain.clear();
      type(line.substr(i, len), "60");
      std::this_thread::sleep_for(60ms);
      i += len;
    }
    type(plain + "\n", "8");
  }
}

// Screenshots of the Tek window until it shows what `probes` say (30 s at most). A failing
// screenshot is kept next to the test binary as `failure_png` for whoever looks into it.
void check_picture(const std::string& display, const std::string& window, const Probes& probes,
                   const TempDir& scratch, const std::string& failure_png) {
  Verdict verdict;
  bool seen = wait_for(
      [&] {
        auto shot = screenshot(display, window, scratch.path() / "display.png");
        if (!shot) return false;
        verdict = judge(*shot, probes);
        return verdict.good();
      },
      30s);
  if (!seen && std::filesystem::exists(scratch.path() / "display.png"))
    std::filesystem::copy_file(scratch.path() / "display.png", failure_png,
                               std::filesystem::copy_options::overwrite_existing);
  CHECK_MESSAGE(seen, fmt::format("{} of {} vector probes light, {} of {} empty probes dark "
                                  "(screenshot: {})",
                                  verdict.on_missing, probes.on.size(), verdict.empty_dark,
                                  probes.empty.size(), failure_png));
}

bool x_tools_present() {
  if (!have_program("Xvfb") && skip_now("Xvfb is not installed")) return false;
  for (const char* tool : {"xterm", "xdotool", "import", "convert", "identify"}) {
    CAPTURE(tool);
    REQUIRE(have_program(tool));
  }
  return true;
}

std::vector<std::string> example_lines(const std::string& name) {
  for (auto& e : examples())
    if (e.name == name) return command_lines(read_file(e.file));
  FAIL("no example named " << name);
  return {};
}

}  // namespace

TEST_CASE("an example typed key by key into igds in an xterm Tek window draws its picture") {
  if (!x_tools_present()) return;
  auto lines = example_lines("abbreviations");
  // The screen is looked at right after DISPLAY FILE DOME, before HELP LONG fills it with text.
  auto checkpoint = std::find(lines.begin(), lines.end(), "D FIL DOME");
  REQUIRE(checkpoint != lines.end());
  ++checkpoint;
  std::vector<std::string> before(lines.begin(), checkpoint), after(checkpoint, lines.end());

  // What the screen must show: igds's own 4013 stream for the same lines, its last page.
  TempDir reference;
  write_file(reference.path() / "typed.igds", joined(before, 0, before.size()));
  auto stream = run_igds({"--disk", reference.path().string(), "--term", "tek",
                          (reference.path() / "typed.igds").string()});
  REQUIRE(stream.status == 0);
  auto drawing = decode_tek(stream.out);
  REQUIRE(drawing.errors.empty());
  auto probes = probes_of(drawing.pages.back());
  REQUIRE(probes.on.size() >= 20);
  REQUIRE(probes.empty.size() >= 30);

  Xserver x;
  REQUIRE_MESSAGE(!x.display.empty(), "no free display for Xvfb");
  std::map<std::string, std::string> env{{"DISPLAY", x.display}};
  TempDir disk, scratch;
  // As the README says: xterm -t, igds finds out by itself that it runs in the Tek window.
  Background xterm({"xterm", "-t", "-xrm", "XTerm*tekGeometry: 1030x800+0+0", "-e",
                    igds_binary().string(), "--disk", disk.path().string()},
                   env, scratch.path() / "xterm.log");
  auto window = window_of(xterm, env, "tektronix");
  REQUIRE_MESSAGE(!window.empty(), "no Tek window; xterm "
                                       << std::string(xterm.running() ? "runs" : "ended") << ": "
                                       << read_file(scratch.path() / "xterm.log"));
  REQUIRE(ready_shown(x.display, window, scratch.path() / "start.png"));
  REQUIRE(run({"xdotool", "windowfocus", "--sync", window}, in_env(env)).status == 0);

  type_lines(env, before);
  check_picture(x.display, window, probes, scratch, "xterm_session_failure.png");

  // The rest of the session, down to END CMS, which ends igds and so the xterm.
  type_lines(env, after);
  CHECK(wait_for([&] { return !xterm.running(); }, 20s));
  for (const char* file : {"DOME.IGDSIMAG", "DOME.IGDSDATA", "DOME.IGDSCHAR", "BINSAVE.IGDSCONT"}) {
    CAPTURE(file);
    CHECK(std::filesystem::exists(disk.path() / file));
  }
}

TEST_CASE("from an xterm's VT window, DISPLAY draws in its Tek window and the dialogue goes on") {
  if (!x_tools_present()) return;
  auto lines = example_lines("fig6-multipatch");
  auto display = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.rfind("DISPLAY INPUT", 0) == 0;
  });
  REQUIRE(display != lines.end());
  std::vector<std::string> typed(lines.begin(), display + 1);

  // What the Tek window must show: EXPORT TEK writes that one image as a 4013 stream.
  TempDir reference;
  write_file(reference.path() / "typed.igds",
             joined(typed, 0, typed.size()) + "EXPORT TEK SHOWN\nEND CMS\n");
  auto ran = run_igds({"--disk", reference.path().string(), "--term", "none",
                       (reference.path() / "typed.igds").string()});
  REQUIRE(ran.status == 0);
  auto drawing = decode_tek(read_file(reference.path() / "SHOWN.TEK"));
  REQUIRE(drawing.errors.empty());
  auto probes = probes_of(drawing.pages.back());
  REQUIRE(probes.on.size() >= 20);
  REQUIRE(probes.empty.size() >= 30);

  Xserver x;
  REQUIRE_MESSAGE(!x.display.empty(), "no free display for Xvfb");
  std::map<std::string, std::string> env{{"DISPLAY", x.display}};
  TempDir disk, scratch;
  // No --term: igds sees XTERM_VERSION and a TERM of xterm's own, and chooses xterm.
  Background xterm({"xterm", "-geometry", "80x24+0+0", "-xrm", "XTerm*tekGeometry: 1030x800+0+0",
                    "-e", igds_binary().string(), "--disk", disk.path().string()},
                   env, scratch.path() / "xterm.log");
  auto vt = window_of(xterm, env, "");
  REQUIRE_MESSAGE(!vt.empty(), "no VT window; xterm "
                                   << std::string(xterm.running() ? "runs" : "ended") << ": "
                                   << read_file(scratch.path() / "xterm.log"));
  REQUIRE(ready_shown(x.display, vt, scratch.path() / "start.png"));
  REQUIRE(run({"xdotool", "windowfocus", "--sync", vt}, in_env(env)).status == 0);

  type_lines(env, typed);
  // The Tek window opens at the first DISPLAY (ESC [ ? 38 h) and keeps the picture.
  std::string tek;
  REQUIRE(wait_for(
      [&] {
        auto found = run({"xdotool", "search", "--name", "tektronix"}, in_env(env));
        tek = found.out.substr(0, found.out.find('\n'));
        return !tek.empty();
      },
      20s));
  check_picture(x.display, tek, probes, scratch, "xterm_vt_failure.png");

  // Back in the VT window (ESC ETX): the dialogue goes on there, and END CMS ends igds.
  REQUIRE(run({"xdotool", "windowfocus", "--sync", vt}, in_env(env)).status == 0);
  type_lines(env, {"SAVE WAVE", "END CMS"});
  CHECK(wait_for([&] { return !xterm.running(); }, 20s));
  CHECK(std::filesystem::exists(disk.path() / "WAVE.IGDSDATA"));
}

// The pointer is xterm's cross-hair (GIN mode): a cursor with its hot spot in its middle (the
// arrow's is at its tip), read with XFIXES (tests/support/xcursor.cpp).
bool cross_hair(const std::map<std::string, std::string>& env) {
#ifdef IGDS_XCURSOR
  auto shape = run({IGDS_XCURSOR}, in_env(env, 5));
  int w = 0, h = 0, x = 0, y = 0;
  return shape.status == 0 && std::sscanf(shape.out.c_str(), "%d %d %d %d", &w, &h, &x, &y) == 4 &&
         w == h && x == w / 2 && y == h / 2;
#else
  (void)env;
  return false;
#endif
}

TEST_CASE("igds 2250 in an xterm Tek window: menu items clicked with the mouse, entries typed") {
  if (!x_tools_present()) return;
#ifndef IGDS_XCURSOR
  if (skip_now("no Xlib with XFIXES to see xterm's cross-hair (libxfixes-dev)")) return;
#endif
  Xserver x;
  REQUIRE_MESSAGE(!x.display.empty(), "no free display for Xvfb");
  std::map<std::string, std::string> env{{"DISPLAY", x.display}};
  TempDir disk, scratch;
  // As igds-tek starts it: the 4013's screen, GIN reports ended by CR.
  Background xterm({"xterm", "-t", "-xrm", "XTerm*tekGeometry: 1030x800+0+0", "-xrm",
                    "XTerm*ginTerminator: CRonly", "-e", igds_binary().string(), "2250", "--disk",
                    disk.path().string()},
                   env, scratch.path() / "xterm.log");
  auto window = window_of(xterm, env, "tektronix");
  REQUIRE_MESSAGE(!window.empty(), "no Tek window: " << read_file(scratch.path() / "xterm.log"));
  REQUIRE(ready_shown(x.display, window, scratch.path() / "start.png"));
  REQUIRE(run({"xdotool", "windowfocus", "--sync", window}, in_env(env)).status == 0);

  const auto items = menu_items(false, menu_screen::label_columns);
  const MenuLayout layout = menu_layout(items.size());
  const auto shot = screenshot(x.display, window, scratch.path() / "menu.png");
  REQUIRE(shot);
  const TekWindowMap map(shot->width, shot->height);
  // Every box of the menu is on the screen: its top and bottom edges are dark.
  for (const Box& b : layout.items) {
    const double mx = (b.x0 + b.x1) / 2;
    CHECK(shot->dark_near(map.px(mx), map.py(b.y1), 1));
    CHECK(shot->dark_near(map.px(mx), map.py(b.y0), 1));
  }
  auto index = [&](const std::string& label) {
    for (std::size_t k = 0; k < items.size(); ++k)
      if (items[k].label == label) return k;
    FAIL("no item " << label);
    return std::size_t{0};
  };
  // A click on an item: the mouse to its middle (`dx` aside), once the cross-hair is up there,
  // then until xterm has left GIN mode with the report (or igds has asked for the next pick).
  auto point_at = [&](std::size_t k, int dx) {
    const Box& b = layout.items[k];
    REQUIRE(run({"xdotool", "mousemove", "--window", window,
                 std::to_string(map.px((b.x0 + b.x1) / 2 + dx)),
                 std::to_string(map.py((b.y0 + b.y1) / 2))},
                in_env(env))
                .status == 0);
  };
  auto click = [&](const std::string& label, int dx = 0) {
    point_at(index(label), dx);
    REQUIRE_MESSAGE(wait_for([&] { return cross_hair(env); }, 20s), "no cross-hair for " << label);
    REQUIRE(run({"xdotool", "click", "1"}, in_env(env)).status == 0);
    wait_for([&] { return !cross_hair(env); }, 1s);
  };
  click("HELP");  // RETURN, in the help environment
  click("BUILD");
  // Typed at once, while igds may still be drawing the question: read in step all the same.
  type_lines(env, {"2 2", "1 0 0 0  0 10 0  10 0 0  10 10 5", "", "", "3 3"});
  // A command typed at the menu, then HELP typed at a question of a picked command.
  REQUIRE(wait_for([&] { return cross_hair(env); }, 20s));
  type_lines(env, {"LIST SURFACE"});
  click("D SURFACE", 20);
  type_lines(env, {"HELP SHORT", "O XY"});
  // The picture in its square: dark pixels where the grid is drawn.
  const Box& square = layout.picture;
  REQUIRE(wait_for(
      [&] {
        auto s = screenshot(x.display, window, scratch.path() / "surface.png");
        if (!s) return false;
        int dark = 0;
        for (double y = square.y0 + 20; y < square.y1 - 20; y += 4)
          for (double x = square.x0 + 20; x < square.x1 - 20; x += 4)
            dark += s->dark(map.px(x), map.py(y)) ? 1 : 0;
        return dark > 50;
      },
      20s));
  // A double click on UNDO undoes once (the second click is dropped, or finds GIN mode off and
  // rings the bell): BUILD is still there to undo after END CMS.
  point_at(index("UNDO"), 0);
  REQUIRE(wait_for([&] { return cross_hair(env); }, 20s));
  REQUIRE(run({"xdotool", "click", "--repeat", "2", "--delay", "80", "1"}, in_env(env)).status ==
          0);
  wait_for([&] { return !cross_hair(env); }, 1s);
  click("END CMS");
  CHECK(wait_for([&] { return !xterm.running(); }, 20s));
  auto after = run_igds({"--disk", disk.path().string(), "--term", "none"}, [] {
    RunOptions o;
    o.input = "UNDO\nEND CMS\n";
    o.timeout_seconds = 30;
    return o;
  }());
  CHECK(after.out.find("UNDONE: BUILD") != std::string::npos);
}

TEST_CASE("igds in an xterm Tek window: HELP and Ctrl-C at a cross-hair question, then a zoom") {
  if (!x_tools_present()) return;
#ifndef IGDS_XCURSOR
  if (skip_now("no Xlib with XFIXES to see xterm's cross-hair (libxfixes-dev)")) return;
#endif
  TempDir disk, scratch;
  REQUIRE(run_commands(disk, std::string(saddle_build) + "DISPLAY INPUT ORTHOGONAL XY\n").status ==
          0);
  Xserver x;
  REQUIRE_MESSAGE(!x.display.empty(), "no free display for Xvfb");
  std::map<std::string, std::string> env{{"DISPLAY", x.display}};
  // xterm logs what igds writes: what the dialogue said.
  const auto said = scratch.path() / "said.log";
  Background xterm({"xterm", "-t", "-xrm", "XTerm*tekGeometry: 1030x800+0+0", "-xrm",
                    "XTerm*ginTerminator: CRonly", "-l", "-lf", said.string(), "-e",
                    igds_binary().string(), "--disk", disk.path().string()},
                   env, scratch.path() / "xterm.log");
  auto window = window_of(xterm, env, "tektronix");
  REQUIRE_MESSAGE(!window.empty(), "no Tek window: " << read_file(scratch.path() / "xterm.log"));
  REQUIRE(ready_shown(x.display, window, scratch.path() / "start.png"));
  REQUIRE(run({"xdotool", "windowfocus", "--sync", window}, in_env(env)).status == 0);
  const auto shot = screenshot(x.display, window, scratch.path() / "start.png");
  REQUIRE(shot);
  const TekWindowMap map(shot->width, shot->height);
  auto key = [&](const char* name) {
    REQUIRE(run({"xdotool", "key", name}, in_env(env)).status == 0);
  };
  auto click_at = [&](int x4013, int y4013) {
    REQUIRE(run({"xdotool", "mousemove", "--window", window, std::to_string(map.px(x4013)),
                 std::to_string(map.py(y4013))},
                in_env(env))
                .status == 0);
    REQUIRE_MESSAGE(wait_for([&] { return cross_hair(env); }, 20s), "no cross-hair");
    REQUIRE(run({"xdotool", "click", "1"}, in_env(env)).status == 0);
    wait_for([&] { return !cross_hair(env); }, 1s);
  };
  // HELP typed at the cross-hair is a line: the help, and the question again.
  type_lines(env, {"ZOOM PICK"});
  REQUIRE(wait_for([&] { return cross_hair(env); }, 20s));
  type_lines(env, {"HELP"});
  REQUIRE(wait_for([&] { return cross_hair(env); }, 20s));
  CHECK(xterm.running());
  // Ctrl-C abandons the question: no cross-hair, READY.
  key("ctrl+c");
  CHECK(wait_for([&] { return !cross_hair(env); }, 20s));
  // The next cross-hair question is read in step: two corners clicked zoom.
  type_lines(env, {"ZOOM PICK"});
  click_at(100, 450);
  click_at(400, 150);
  type_lines(env, {"LIST IMAGES", "", "END CMS"});
  CHECK(wait_for([&] { return !xterm.running(); }, 20s));
  const std::string log = read_file(said);
  CHECK(log.find("ZOOM shows a part") != std::string::npos);  // HELP at FIRST CORNER?
  CHECK(log.find("ZOOMED TO") != std::string::npos);
  CHECK(log.find("END OF INPUT") == std::string::npos);
  CHECK(log.find("INCORRECT") == std::string::npos);
}

}  // namespace igds::test
