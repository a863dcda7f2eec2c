// PLOT SELECTRIC | EBCDIC (manual 4.5): the current image on the HP-GL pen plotter.
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <functional>

#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/picture.h"
#include "commands/plot.h"
#include "devices/hpgl_plot.h"
#include "workspace/disk/files.h"
#include "workspace/error.h"

namespace igds {

namespace {

// The escape sequences that wake and put to sleep a plotter wired on the terminal line.
constexpr std::string_view plotter_on = "\x1b.(", plotter_off = "\x1b.)";

// A new PLOTnnnn.HPGL on the disk, the first number not used yet (never replacing a file that
// appears meanwhile), the plot made by make(out) while it is written; its name.
std::string to_new_file(const Disk& disk, const std::function<void(TextOut& out)>& make) {
  for (int n = 1; n <= 9999; ++n) {
    std::string name = fmt::format("PLOT{:04}", n);
    if (disk.exists(name, "HPGL")) continue;
    if (write_new_user_file(disk, name, "HPGL", make, "NOTHING PLOTTED")) return name + ".HPGL";
  }
  throw Report("NO FREE PLOT FILE NAME (PLOT0001 TO PLOT9999 ALL USED); NOTHING PLOTTED");
}

// Appended to a file, plot after plot, or written to a device such as /dev/ttyUSB0. Nothing
// may hold the conversation: the path is opened without waiting (a FIFO without a reader, a
// serial line without its carrier), and a device that takes no bytes for `patience` does not
// answer. A link is followed only to a device (how /dev/serial/by-id names them), never to a file.
void to_path(const std::string& path, std::string_view hpgl, std::chrono::milliseconds patience) {
  constexpr int flags = O_WRONLY | O_APPEND | O_NOCTTY | O_CLOEXEC | O_NONBLOCK;
  auto refused = [&](int error) {
    if (error == ENXIO)  // a FIFO without a reader, a device that is not there
      return Report(fmt::format("PLOTTER {} DOES NOT ANSWER; NOTHING PLOTTED", path));
    return Report(fmt::format("CANNOT OPEN PLOTTER {} ({}); NOTHING PLOTTED", path,
                              disk::system_reason(error)));
  };
  int fd = ::open(path.c_str(), flags | O_CREAT | O_NOFOLLOW, 0666);
  if (fd < 0 && errno == ELOOP) {
    struct stat target;
    if (::stat(path.c_str(), &target) != 0) throw refused(errno);
    if (!S_ISCHR(target.st_mode) && !S_ISFIFO(target.st_mode))
      throw Report(
          fmt::format("CANNOT OPEN PLOTTER {} (A SYMBOLIC LINK TO A FILE); NOTHING PLOTTED", path));
    fd = ::open(path.c_str(), flags);
  }
  if (fd < 0) throw refused(errno);
  std::size_t sent = 0;
  int error = 0;
  bool answered = true;
  while (sent < hpgl.size()) {
    ssize_t n = ::write(fd, hpgl.data() + sent, hpgl.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) {
      // Full: wait for the plotter to take more, as long as it takes some within `patience`.
      pollfd out{fd, POLLOUT, 0};
      const int ready = ::poll(&out, 1, static_cast<int>(patience.count()));
      if (ready < 0 && errno == EINTR) continue;
      if (ready == 0) {
        answered = false;
        break;
      }
      if (out.revents & (POLLERR | POLLHUP)) {
        error = EPIPE;
        break;
      }
      continue;
    }
    if (n <= 0) {
      error = n < 0 ? errno : EIO;
      break;
    }
    sent += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0 && error == 0 && answered && errno != EINTR) error = errno;
  const std::string_view kept = sent == 0 ? "NOTHING PLOTTED" : "THE PLOT IS INCOMPLETE";
  if (!answered) throw Report(fmt::format("PLOTTER {} DOES NOT ANSWER; {}", path, kept));
  if (error != 0)
    throw Report(
        fmt::format("CANNOT WRITE TO PLOTTER {} ({}); {}", path, disk::system_reason(error), kept));
}

enum Option { selectric = 1, ebcdic = 2 };  // STATUS[2]

constexpr Choice options[] = {
    {"SELECTRIC", selectric, {}, "a terminal with a SELECTRIC keyboard (= on the left)"},
    {"EBCDIC", ebcdic, {}, "a terminal with an EBCDIC keyboard (= on the right)"},
};

void run_plot(Context& ctx, const Choice* option) {
  Workspace& ws = ctx.workspace();
  if (!ws.image) throw Report(reports::image_not_found);
  expect_no_more_words(ctx);
  plot_picture(ctx, picture_of(ws.image));
  // STATUS[2]: the keyboard of the last PLOT, 1 SELECTRIC, 2 EBCDIC.
  ws.status[1] = option->code;
}

}  // namespace

void plot_picture(Context& ctx, const Picture& picture) {
  const PlotOptions& options = ctx.options().plot;
  const std::string& plotter = ctx.options().plotter;
  std::string where;
  PlotStats stats;
  if (plotter.empty()) {
    // Written while it is made: a plot may be tens of megabytes.
    where =
        to_new_file(ctx.disk(), [&](TextOut& out) { stats = plot_hpgl(picture, options, out); });
  } else {
    const Plot plot = plot_hpgl(picture, options);
    stats = plot.stats;
    if (plotter == "tty") {
      ctx.send_to_terminal(std::string(plotter_on) + plot.hpgl + std::string(plotter_off));
      where = "PLOTTER";
    } else {
      to_path(plotter, plot.hpgl, ctx.options().plotter_patience);
      where = plotter;
    }
  }
  ctx.say(plot_summary(where, stats));
  if (stats.clipped) ctx.say(plot_clipped_notice);
  if (stats.texts_cut) ctx.say(plot_texts_cut_notice);
}

extern const Command plot_command{
    .name = "PLOT",
    .options = options,
    .follows = {},
    .option_prompt = {"SELECTRIC OR EBCDIC?",
                      "The keyboard of your terminal: SELECTRIC or EBCDIC (kept for the record; "
                      "the plot is the same).",
                      options},
    .bad_option = reports::incorrect_command,  // the manual's 4.5
    .summary = "draws the current image on the HP plotter",
    .long_help =
        "PLOT draws the current image (the one last displayed) on a pen plotter that speaks HP-GL "
        "(HP 7475A and its kin), with its description beside it, as large as the paper allows, "
        "aspect kept, centred on a landscape sheet.\n"
        "\n"
        "  PLOT SELECTRIC  the option named the keyboard of the 1975 terminal\n"
        "  PLOT EBCDIC     (the = sign on the left or on the right); it is recorded in STATUS but "
        "no longer changes the output.\n"
        "\n"
        "Where the plot goes is chosen when igds starts:\n"
        "  (default)               a new file PLOTnnnn.HPGL on the disk\n"
        "  --plotter tty           the plotter wired on the terminal line\n"
        "  --plotter PATH          a file (each plot appended) or a device (/dev/ttyUSB0)\n"
        "  --paper A4|A3|LETTER|B  the paper in the plotter (A4 unless told)\n"
        "\n"
        "After each plot igds says how many vectors were drawn, how often the pen was lifted, how "
        "far it travelled lifted, and how many bytes were sent. The pen order is chosen to keep "
        "that travel short. With no current image PLOT says IMAGE NOT FOUND.\n"
        "\n"
        "Example (P S is PLOT SELECTRIC):\n"
        "  DISPLAY SURFACE ASSONOMETRIC 110 130 120\n"
        "  P S",
    .questions = {},
    .run = run_plot,
};

}  // namespace igds
