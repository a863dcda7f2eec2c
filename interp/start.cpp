#include "interp/start.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "interp/command_line.h"
#include "interp/input.h"
#include "interp/interpreter.h"
#include "interp/version.h"
#include "interp/ws2250.h"
#include "workspace/disk/session.h"
#include "workspace/error.h"
#include "workspace/kernels/processor.h"

namespace igds {

namespace {

void close_all(const std::vector<int>& fds) {
  for (int fd : fds) {
    if (fd >= 0) close(fd);
  }
}

// The standard output, written whole (a short write is retried; an error is remembered so that
// igds can end with it, instead of losing the dialogue silently).
class StdOutput final : public Output {
 public:
  void write(std::string_view bytes) override {
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size())
      failed_ = true;
  }
  void flush() override {
    if (std::fflush(stdout) != 0) failed_ = true;
  }
  bool failed() const override { return failed_ || std::ferror(stdout); }

 private:
  bool failed_ = false;
};

}  // namespace

int igds_main(int argc, char** argv) {
  // A reader that goes away (`igds | head -1`) is a failed write, not a death that leaves the
  // lock behind: the conversation ends and the session is saved.
  std::signal(SIGPIPE, SIG_IGN);
  // Output that is no terminal (a pipe, a file) goes out in writes of up to 64 KB: at each READY,
  // before igds waits for input, or when the buffer is full (Terminal::read_line). A BUILD of
  // 250,000 points echoed line by line in 4 KB writes woke its reader some 1,500 times.
  // (glibc takes the size only with a buffer given.)
  static char out_buffer[std::size_t(1) << 16];
  if (isatty(STDOUT_FILENO) != 1) std::setvbuf(stdout, out_buffer, _IOFBF, sizeof out_buffer);
  CommandLine line;
  try {
    line = parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const UsageError& e) {
    fmt::print(stderr, "igds: {}\n{}", e.what(), usage_text());
    return 2;
  }
  if (line.help) {
    fmt::print("{}", usage_text());
    return 0;
  }
  if (line.version) {
    fmt::print("igds {}\nbuilt with {}, {}\nkernels: {}\n", IGDS_VERSION, IGDS_COMPILER,
               IGDS_BUILD_TYPE, kernel_code_in_use());
    return 0;
  }
  // The 2250 workspace needs the cross-hair of a Tek terminal in GIN mode (xterm's Tek window).
  const char* term_env = std::getenv("TERM");
  const std::string term_name = term_env ? term_env : "";
  const bool in_tek_window = term_name.starts_with("tek");
  if (line.device_2250) {
    const bool tty = isatty(STDIN_FILENO) == 1 && isatty(STDOUT_FILENO) == 1;
    const bool xterm = std::getenv("XTERM_VERSION") || term_name.starts_with("xterm");
    if (!tty || !(xterm || in_tek_window)) {
      fmt::print(stderr,
                 "igds 2250: the light-pen workspace needs xterm's Tektronix window, whose "
                 "cross-hair (GIN mode) is the light pen, and {}.\n"
                 "Run it in an xterm: xterm -t -e igds 2250 (or type igds 2250 in an xterm "
                 "window).\nigds 4013 (the default) works on any terminal.\n",
                 !tty ? "its input or output is not a terminal"
                      : fmt::format("this terminal is TERM={}",
                                    term_name.empty() ? "(unset)" : term_name));
      return 1;
    }
  }

  Options options = line.options;
  const char* disk_env = std::getenv("IGDS_DISK");
  options.disk = line.disk ? *line.disk : (disk_env && *disk_env ? disk_env : ".");
  options.term = line.term ? *line.term
                           : choose_term(isatty(STDOUT_FILENO) == 1, std::getenv("TERM"),
                                         std::getenv("XTERM_VERSION"));
  // The 2250's screen is the Tek window, dialogue included (from the VT window igds switches).
  if (line.device_2250) options.term = TermMode::tek;
  const bool switch_window = line.device_2250 && !in_tek_window;

  // Every command file is opened before anything starts: a missing one stops igds at once.
  std::vector<int> files;
  for (const auto& name : line.files) {
    int fd = open(name.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat info {};
    if (fd >= 0 && (fstat(fd, &info) != 0 || S_ISDIR(info.st_mode))) {
      close(fd);
      fd = -1;
      errno = EISDIR;
    }
    if (fd < 0) {
      fmt::print(stderr, "igds: cannot read the command file {}: {}\n", name, std::strerror(errno));
      close_all(files);
      return 1;
    }
    files.push_back(fd);
  }

  StdOutput out;
  // Ctrl-C, read as an event in every mode (workspace/kernels/interrupt.h).
  Interrupts interrupts;
  try {
    Disk disk(options.disk);
    Session session(disk);
    Workspace ws = session.load();
    Terminal terminal(options.term, options.tek, out);
    // Texts are laid out at the terminal's width (80 columns when the output is no terminal).
    if (winsize size{}; ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col >= 20)
      terminal.set_columns(size.ws_col);
    Interpreter interpreter(options, disk, session, std::move(ws), terminal);
    if (switch_window) out.write("\x1b[?38h");
    terminal.begin();
    for (const auto& notice : session.notices()) interpreter.say(notice);

    auto outcome = Interpreter::Outcome::input_ended;
    for (std::size_t i = 0; i < files.size(); ++i) {
      FdSource input(std::exchange(files[i], -1), true, &interrupts);
      terminal.use_input(&input);
      outcome = interpreter.converse();
      terminal.use_input(nullptr);
      if (outcome != Interpreter::Outcome::input_ended) break;
    }
    close_all(files);
    if (outcome == Interpreter::Outcome::input_ended && line.device_2250) {
      KeySource keys(STDIN_FILENO, interrupts);
      terminal.use_input(&keys);
      outcome = Workspace2250(interpreter, terminal).run();
      terminal.use_input(nullptr);
    } else if (outcome == Interpreter::Outcome::input_ended &&
               (files.empty() || line.then_interactive)) {
      const bool keyboard = isatty(STDIN_FILENO) == 1;
      std::unique_ptr<EventSource> input;
      if (keyboard && options.term == TermMode::tek) {
        // The 4013 had no line editing; igds reads keys and echoes them on its screen.
        input = std::make_unique<KeySource>(STDIN_FILENO, interrupts);
      } else if (keyboard) {
        input = std::make_unique<ReadlineSource>(
            disk.path("HISTORY", "IGDSHIST"),
            [&interpreter](const std::vector<std::string>& before) {
              return interpreter.completions(before);
            },
            interrupts);
      } else {
        // A pipe is a command file.
        input = std::make_unique<FdSource>(STDIN_FILENO, true, &interrupts);
      }
      terminal.use_input(input.get());
      outcome = interpreter.converse();
      terminal.use_input(nullptr);
    }
    interpreter.save();
    // Alpha mode, and back to the VT window the 2250 session started in.
    if (switch_window) out.write("\x1f\x1b\x03");
    out.flush();
    if (outcome == Interpreter::Outcome::strict_stop) return 3;
    // As a shell reports a program that Ctrl-C stopped: 128 + SIGINT.
    if (outcome == Interpreter::Outcome::interrupted) return 128 + SIGINT;
    // The designer must learn from the status what the screen may not have shown.
    return interpreter.saved() && !out.failed() ? 0 : 1;
  } catch (const Error& r) {
    out.flush();
    fmt::print(stderr, "{}\n", r.what());
    return 1;
  }
}

}  // namespace igds
