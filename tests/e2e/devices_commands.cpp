// PLOT, EXPORT and ERASE (commands/plot.cpp, export.cpp, erase.cpp) driven through a Context.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "commands/command.h"
#include "devices/hpgl_plot.h"
#include "devices/tek_stream.h"
#include "tests/devices/support.h"
#include "tests/support/fake_context.h"
#include "tests/support/process.h"
#include "workspace/disk/files.h"
#include "workspace/error.h"

namespace igds {
extern const Command plot_command;
extern const Command export_command;
extern const Command erase_command;
}  // namespace igds

namespace igds::test::devices {

using igds::test::FakeContext;

namespace {

using DeviceContext = FakeContext;

// The report a command throws, or "" when it succeeds.
template <class F>
std::string report_of(F f) {
  try {
    f();
  } catch (const Error& r) {
    return r.what();
  }
  return "";
}

// Clears the write limit of the disk functions even when a check fails.
struct WriteLimit {
  explicit WriteLimit(std::size_t bytes) { disk::set_write_limit_for_testing(bytes); }
  ~WriteLimit() { disk::set_write_limit_for_testing(std::nullopt); }
};

// Files of this process may not grow past `bytes` (SIGXFSZ ignored: the write fails with EFBIG).
struct FileSizeLimit {
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &old);
    previous = signal(SIGXFSZ, SIG_IGN);
    rlimit r = old;
    r.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &r);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &old);
    signal(SIGXFSZ, previous);
  }
  rlimit old{};
  sighandler_t previous{};
};

}  // namespace

TEST_CASE("PLOT: IMAGE NOT FOUND first, nothing recorded") {
  TempDir dir;
  DeviceContext ctx(dir.path());
  CHECK(report_of([&] { ctx.run(plot_command, "SELECTRIC"); }) == reports::image_not_found);
  CHECK(ctx.ws.status[1] == 0);
  CHECK(std::filesystem::is_empty(dir.path()));
}

TEST_CASE("PLOT: new PLOTnnnn.HPGL files on the disk, the keyboard in STATUS[2]") {
  TempDir dir;
  DeviceContext ctx(dir.path());
  ctx.ws.image = std::make_shared<const Image>(surface_image(5, 4));
  ctx.run(plot_command, "SELECTRIC");
  CHECK(ctx.ws.status[1] == 1);
  Plot expected = plot_hpgl(*ctx.ws.image, {});
  CHECK(read_file(dir.path() / "PLOT0001.HPGL") == expected.hpgl);
  REQUIRE(ctx.said.size() == 1);
  CHECK(ctx.said[0] == plot_summary("PLOT0001.HPGL", expected.stats));
  CHECK(ctx.said[0] == fmt::format("PLOT0001.HPGL: {} VECTORS, {} PEN LIFTS, PEN-UP TRAVEL {:.0f} "
                                   "MM, {} BYTES",
                                   expected.stats.vectors, expected.stats.pen_lifts,
                                   expected.stats.pen_up_mm, expected.hpgl.size()));
  ctx.opts.plot.paper = Paper::a3;
  ctx.run(plot_command, "EBCDIC");
  CHECK(ctx.ws.status[1] == 2);
  CHECK(read_file(dir.path() / "PLOT0002.HPGL") == plot_hpgl(*ctx.ws.image, {Paper::a3}).hpgl);
  // A freed number is used again: the next free one, counting from 1.
  std::filesystem::remove(dir.path() / "PLOT0001.HPGL");
  ctx.run(plot_command, "SELECTRIC");
  CHECK(std::filesystem::exists(dir.path() / "PLOT0001.HPGL"));
  CHECK(ctx.said.back().rfind("PLOT0001.HPGL: ", 0) == 0);
}

TEST_CASE("PLOT: on the terminal line, wrapped in ESC.( ... ESC.)") {
  TempDir dir;
  DeviceContext ctx(dir.path());
  ctx.ws.image = std::make_shared<const Image>(input_image(3, 4));
  ctx.opts.plotter = "tty";
  ctx.run(plot_command, "EBCDIC");
  CHECK(ctx.terminal == "\x1B.(" + plot_hpgl(*ctx.ws.image, {}).hpgl + "\x1B.)");
  CHECK(std::filesystem::is_empty(dir.path()));
  CHECK(ctx.said.at(0).rfind("PLOTTER: ", 0) == 0);
}

TEST_CASE("PLOT: a path is appended to, plot after plot") {
  TempDir dir, elsewhere;
  DeviceContext ctx(dir.path());
  ctx.ws.image = std::make_shared<const Image>(surface_image(3, 3));
  ctx.opts.plotter = (elsewhere.path() / "plotter.hpgl").string();
  ctx.run(plot_command, "SELECTRIC");
  ctx.run(plot_command, "SELECTRIC");
  std::string one = plot_hpgl(*ctx.ws.image, {}).hpgl;
  CHECK(read_file(ctx.opts.plotter) == one + one);
  CHECK(ctx.said.at(1).rfind(ctx.opts.plotter + ": ", 0) == 0);
}

TEST_CASE("PLOT: a plotter that cannot be written, a full disk, words left: nothing changes") {
  TempDir dir;
  DeviceContext ctx(dir.path());
  ctx.ws.image = std::make_shared<const Image>(surface_image(3, 3));
  ctx.opts.plotter = (dir.path() / "no" / "such" / "folder").string();
  std::string r = report_of([&] { ctx.run(plot_command, "EBCDIC"); });
  CHECK(r == fmt::format("CANNOT OPEN PLOTTER {} (NO SUCH FILE OR DIRECTORY); NOTHING PLOTTED",
                         ctx.opts.plotter));
  CHECK(ctx.ws.status[1] == 0);
  // A device that takes nothing: /dev/full fails every write.
  if (std::filesystem::exists("/dev/full")) {
    ctx.opts.plotter = "/dev/full";
    CHECK(report_of([&] { ctx.run(plot_command, "EBCDIC"); }) ==
          "CANNOT WRITE TO PLOTTER /dev/full (NO SPACE LEFT ON DEVICE); NOTHING PLOTTED");
    CHECK(ctx.ws.status[1] == 0);
  }
  {
    // A file that may grow by 100 bytes only: the plot breaks off part way.
    auto path = dir.path() / "short.hpgl";
    ctx.opts.plotter = path.string();
    FileSizeLimit limit(100);
    CHECK(report_of([&] { ctx.run(plot_command, "EBCDIC"); }) ==
          fmt::format("CANNOT WRITE TO PLOTTER {} (FILE TOO LARGE); THE PLOT IS INCOMPLETE",
                      path.string()));
  }
  CHECK(ctx.ws.status[1] == 0);
  std::filesystem::remove(dir.path() / "short.hpgl");
  ctx.opts.plotter = "";
  {
    WriteLimit full(10);
    CHECK(report_of([&] { ctx.run(plot_command, "EBCDIC"); }) ==
          "CANNOT WRITE PLOT0001.HPGL (NO SPACE LEFT ON DEVICE); NOTHING PLOTTED");
  }
  CHECK(ctx.ws.status[1] == 0);
  CHECK(std::filesystem::is_empty(dir.path()));
  CHECK(report_of([&] { ctx.run(plot_command, "SELECTRIC", {"NOW"}); }) ==
        reports::incorrect_command);
  CHECK(ctx.ws.status[1] == 0);
  CHECK(ctx.said.empty());
}

TEST_CASE("PLOT: a plotter that does not answer holds nothing: a FIFO without a reader, or full") {
  TempDir dir, elsewhere;
  DeviceContext ctx(dir.path());
  ctx.ws.image = std::make_shared<const Image>(surface_image(200, 200));
  const auto fifo = elsewhere.path() / "plotter";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  ctx.opts.plotter = fifo.string();
  // No reader: the open does not wait for one.
  CHECK(report_of([&] { ctx.run(plot_command, "EBCDIC"); }) ==
        fmt::format("PLOTTER {} DOES NOT ANSWER; NOTHING PLOTTED", fifo.string()));
  CHECK(ctx.ws.status[1] == 0);
  // A reader that takes nothing: the plot (far more than a pipe holds) waits as long as the
  // plotter's patience, then breaks off.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  REQUIRE(reader >= 0);
  ctx.opts.plotter_patience = std::chrono::milliseconds(50);
  CHECK(report_of([&] { ctx.run(plot_command, "EBCDIC"); }) ==
        fmt::format("PLOTTER {} DOES NOT ANSWER; THE PLOT IS INCOMPLETE", fifo.string()));
  ::close(reader);
  CHECK(ctx.ws.status[1] == 0);
  CHECK(ctx.said.empty());
}

TEST_CASE("PLOT: a link is followed to a device, never to a file") {
  TempDir dir, elsewhere;
  DeviceContext ctx(dir.path());
  ctx.ws.image = std::make_shared<const Image>(surface_image(3, 3));
  const auto file = elsewhere.path() / "someone's.txt", link = elsewhere.path() / "plotter";
  write_file(file, "kept\n");
  std::filesystem::create_symlink(file, link);
  ctx.opts.plotter = link.string();
  CHECK(report_of([&] { ctx.run(plot_command, "EBCDIC"); }) ==
        fmt::format("CANNOT OPEN PLOTTER {} (A SYMBOLIC LINK TO A FILE); NOTHING PLOTTED",
                    link.string()));
  CHECK(read_file(file) == "kept\n");
  // A dangling link makes nothing where it points.
  const auto dangling = elsewhere.path() / "dangling";
  std::filesystem::create_symlink(elsewhere.path() / "made", dangling);
  ctx.opts.plotter = dangling.string();
  CHECK(report_of([&] { ctx.run(plot_command, "EBCDIC"); }).starts_with("CANNOT OPEN PLOTTER"));
  CHECK(!std::filesystem::exists(elsewhere.path() / "made"));
  // A link to a device (as /dev/serial/by-id names serial lines) is the device.
  const auto device = elsewhere.path() / "device";
  std::filesystem::create_symlink("/dev/null", device);
  ctx.opts.plotter = device.string();
  CHECK(report_of([&] { ctx.run(plot_command, "EBCDIC"); }).empty());
  CHECK(ctx.ws.status[1] == 2);
}

TEST_CASE("PLOT: every PLOTnnnn number taken") {
  TempDir dir;
  for (int n = 1; n <= 9999; ++n)
    std::ofstream(dir.path() / fmt::format("PLOT{:04}.HPGL", n)).put('x');
  DeviceContext ctx(dir.path());
  ctx.ws.image = std::make_shared<const Image>(surface_image(3, 3));
  CHECK(report_of([&] { ctx.run(plot_command, "SELECTRIC"); }) ==
        "NO FREE PLOT FILE NAME (PLOT0001 TO PLOT9999 ALL USED); NOTHING PLOTTED");
  CHECK(ctx.ws.status[1] == 0);
  CHECK(read_file(dir.path() / "PLOT0001.HPGL") == "x");
}

TEST_CASE("EXPORT: SVG, TEK and HPGL files of the current image") {
  TempDir dir;
  DeviceContext ctx(dir.path());
  ctx.ws.image = std::make_shared<const Image>(input_image(3, 4));
  ctx.opts.tek.bits = 12;
  ctx.opts.plot.paper = Paper::letter;
  Workspace before = ctx.ws;
  ctx.run(export_command, "SVG", {"hull"});
  ctx.run(export_command, "TEK", {"Hull"});
  ctx.type({"", "hull"});  // an empty reply asks again
  ctx.run(export_command, "HPGL");
  CHECK(ctx.prompts == std::vector<std::string>{"FILE NAME?", "FILE NAME?"});
  CHECK(read_file(dir.path() / "HULL.SVG") == svg_of(*ctx.ws.image));
  CHECK(read_file(dir.path() / "HULL.TEK") == tek_stream(*ctx.ws.image, {12}));
  CHECK(read_file(dir.path() / "HULL.HPGL") == plot_hpgl(*ctx.ws.image, {Paper::letter}).hpgl);
  CHECK(ctx.said.at(0) == fmt::format("HULL.SVG: {} BYTES", svg_of(*ctx.ws.image).size()));
  CHECK(ctx.ws == before);
  // Replaced whole by the next export of the same name; no temporary left behind.
  ctx.ws.image = std::make_shared<const Image>(surface_image(2, 2));
  ctx.run(export_command, "SVG", {"HULL"});
  CHECK(read_file(dir.path() / "HULL.SVG") == svg_of(*ctx.ws.image));
  std::size_t files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir.path())) ++files, (void)e;
  CHECK(files == 3);
}

TEST_CASE("EXPORT: IMAGE NOT FOUND, INCORRECT PARAMETER, a full disk keeps the old file") {
  TempDir dir;
  DeviceContext ctx(dir.path());
  CHECK(report_of([&] { ctx.run(export_command, "SVG", {"A"}); }) == reports::image_not_found);
  CHECK(ctx.prompts.empty());
  ctx.ws.image = std::make_shared<const Image>(surface_image(3, 3));
  for (std::vector<std::string> words :
       std::vector<std::vector<std::string>>{{"../X"}, {"TOOLONGNAME"}, {"A.B"}, {"A", "B"}})
    CHECK(report_of([&] { ctx.run(export_command, "TEK", words); }) ==
          "INCORRECT PARAMETER: A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - _");
  CHECK(std::filesystem::is_empty(dir.path()));
  ctx.run(export_command, "HPGL", {"KEEP"});
  std::string old = read_file(dir.path() / "KEEP.HPGL");
  ctx.ws.image = std::make_shared<const Image>(input_image(4, 4));
  {
    WriteLimit full(10);
    CHECK(report_of([&] { ctx.run(export_command, "HPGL", {"KEEP"}); }) ==
          "CANNOT WRITE KEEP.HPGL (NO SPACE LEFT ON DEVICE); NO FILE CHANGED");
  }
  CHECK(read_file(dir.path() / "KEEP.HPGL") == old);
}

TEST_CASE("ERASE: the Context's erase, nothing else on the line") {
  TempDir dir;
  DeviceContext ctx(dir.path());
  ctx.run(erase_command, "");
  CHECK(ctx.erases == 1);
  CHECK(report_of([&] { ctx.run(erase_command, "", {"ALL"}); }) == reports::incorrect_command);
  CHECK(ctx.erases == 1);
}

TEST_CASE("PLOT, EXPORT, ERASE: help texts and options as the table needs them") {
  auto words = [](std::span<const Choice> choices) {
    std::vector<std::string_view> out;
    for (const Choice& c : choices) out.push_back(c.word);
    return out;
  };
  CHECK(words(plot_command.options) == std::vector<std::string_view>{"SELECTRIC", "EBCDIC"});
  CHECK(words(export_command.options) ==
        std::vector<std::string_view>{"SVG", "TEK", "HPGL", "DUCT", "IGES", "STEP"});
  CHECK(erase_command.options.empty());
  CHECK(plot_command.long_help.find("no longer changes the output") != std::string_view::npos);
  for (const Command* c : {&plot_command, &export_command, &erase_command}) {
    CHECK(!c->summary.empty());
    CHECK(c->long_help.find("Example") != std::string_view::npos);
  }
}

}  // namespace igds::test::devices
