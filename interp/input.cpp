#include "interp/input.h"

#include <fcntl.h>
#include <poll.h>
#include <readline/history.h>
#include <readline/readline.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "interp/apl/keyboard.h"
#include "interp/words.h"
#include "workspace/disk/files.h"
#include "workspace/kernels/interrupt.h"

namespace igds {

// ---- Interrupts -------------------------------------------------------------------------------

Interrupts::Interrupts() {
  // Blocked already by main; here too for a conversation made without it (the tests).
  block_interrupts();
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  fd_ = signalfd(-1, &interrupt, SFD_CLOEXEC | SFD_NONBLOCK);
}

Interrupts::~Interrupts() {
  if (fd_ >= 0) close(fd_);
}

bool Interrupts::take() {
  bool any = false;
  signalfd_siginfo info;
  while (fd_ >= 0 && ::read(fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info))
    any = true;
  return any;
}

Event::Kind wait_for(int fd, Interrupts* interrupts, int timeout) {
  for (;;) {
    pollfd fds[2] = {{fd, POLLIN, 0}, {interrupts ? interrupts->fd() : -1, POLLIN, 0}};
    const int n = poll(fds, interrupts ? 2 : 1, timeout);
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) return Event::Kind::timeout;
    if (interrupts && (fds[1].revents & POLLIN) && interrupts->take())
      return Event::Kind::interrupt;
    // Readable, at its end, or in error: the read says which.
    return Event::Kind::key;
  }
}

// ---- FdSource ---------------------------------------------------------------------------------

FdSource::FdSource(int fd, bool command_file, Interrupts* interrupts)
    : fd_(fd), command_file_(command_file), interrupts_(interrupts) {}

FdSource::~FdSource() {
  if (fd_ > 2) close(fd_);
}

Event FdSource::line(std::string_view) {
  for (;;) {
    // Searched once: a long line arriving in pieces costs its length, not its square.
    const auto end = buffer_.find('\n', scanned_);
    if (end != std::string::npos || (eof_ && start_ < buffer_.size())) {
      const std::size_t stop = end == std::string::npos ? buffer_.size() : end;
      std::string text = buffer_.substr(start_, stop - start_);
      start_ = std::min(stop + 1, buffer_.size());
      scanned_ = start_;
      if (!text.empty() && text.back() == '\r') text.pop_back();
      if (is_comment_line(text)) continue;
      return {Event::Kind::line, std::move(text)};
    }
    if (eof_) return {Event::Kind::end, {}};
    scanned_ = buffer_.size();
    if (start_ > 0 && start_ * 2 >= buffer_.size()) {
      buffer_.erase(0, start_);
      scanned_ -= start_;
      start_ = 0;
    }
    if (wait_for(fd_, interrupts_, -1) == Event::Kind::interrupt) {
      buffer_.clear();
      start_ = scanned_ = 0;
      return {Event::Kind::interrupt, {}};
    }
    char chunk[65536];
    ssize_t n = ::read(fd_, chunk, sizeof chunk);
    if (n > 0)
      buffer_.append(chunk, static_cast<std::size_t>(n));
    else if (n == 0 || (errno != EINTR && errno != EAGAIN))
      eof_ = true;
  }
}

bool FdSource::line_ready() const {
  if (eof_) return true;
  // A whole line that is not a comment (line() passes over those).
  for (std::size_t at = start_;;) {
    const auto end = buffer_.find('\n', at);
    if (end == std::string::npos) return false;
    if (!is_comment_line(std::string_view(buffer_).substr(at, end - at))) return true;
    at = end + 1;
  }
}

Event FdSource::key(std::optional<std::chrono::milliseconds>) {
  return line("");
}

// ---- KeySource --------------------------------------------------------------------------------

KeySource::KeySource(int fd, Interrupts& interrupts) : fd_(fd), interrupts_(interrupts) {
  termios t;
  if (tcgetattr(fd_, &t) == 0) {
    saved_ = t;
    // Keys one at a time, not echoed (igds echoes them on its screen); Ctrl-C still a signal,
    // but the tty drops no output with it: what the terminal had not yet read would be missing
    // from a screen igds keeps account of. igds drops the keys typed ahead itself.
    t.c_lflag &= static_cast<tcflag_t>(~(ICANON | ECHO | ECHONL));
    t.c_lflag |= NOFLSH;
    t.c_cc[VMIN] = 1;
    t.c_cc[VTIME] = 0;
    tcsetattr(fd_, TCSANOW, &t);
  }
}

KeySource::~KeySource() {
  if (saved_) tcsetattr(fd_, TCSANOW, &*saved_);
}

Event KeySource::line(std::string_view) {
  std::string text;
  for (;;) {
    Event e = key(std::nullopt);
    if (e.kind != Event::Kind::key) return e;
    if (e.text == "\r" || e.text == "\n") return {Event::Kind::line, text};
    text += e.text;
  }
}

bool KeySource::read_more(std::optional<std::chrono::milliseconds> timeout, Event::Kind& kind) {
  const int ms = timeout ? static_cast<int>(timeout->count()) : -1;
  for (;;) {
    kind = wait_for(fd_, &interrupts_, ms);
    if (kind == Event::Kind::interrupt) {
      pending_.clear();
      tcflush(fd_, TCIFLUSH);
      return false;
    }
    if (kind == Event::Kind::timeout) return false;
    char chunk[256];
    const ssize_t n = ::read(fd_, chunk, sizeof chunk);
    if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) {
      kind = Event::Kind::end;
      return false;
    }
    if (n > 0) {
      pending_.append(chunk, static_cast<std::size_t>(n));
      return true;
    }
  }
}

bool KeySource::interrupted() {
  if (!interrupts_.take()) return false;
  pending_.clear();
  tcflush(fd_, TCIFLUSH);
  return true;
}

Event KeySource::key(std::optional<std::chrono::milliseconds> timeout) {
  // Keys read already do not hide a Ctrl-C typed after them.
  if (!pending_.empty() && interrupted()) return {Event::Kind::interrupt, {}};
  for (;;) {
    // One character: a UTF-8 lead byte and its continuation bytes (a lead byte followed by a
    // byte that continues nothing is a key of its own).
    if (!pending_.empty()) {
      const auto lead = static_cast<unsigned char>(pending_[0]);
      std::size_t length = lead < 0xC0 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
      for (std::size_t k = 1; k < length && k < pending_.size(); ++k)
        if ((static_cast<unsigned char>(pending_[k]) & 0xC0) != 0x80) length = k;
      if (pending_.size() >= length) {
        std::string c = pending_.substr(0, length);
        pending_.erase(0, length);
        return {Event::Kind::key, std::move(c)};
      }
    }
    Event::Kind kind;
    if (!read_more(timeout, kind)) return {kind, {}};
  }
}

Event KeySource::bytes(std::optional<std::chrono::milliseconds> timeout) {
  if (!pending_.empty() && interrupted()) return {Event::Kind::interrupt, {}};
  Event::Kind kind;
  if (pending_.empty() && !read_more(timeout, kind)) return {kind, {}};
  return {Event::Kind::key, std::exchange(pending_, {})};
}

// ---- ReadlineSource ---------------------------------------------------------------------------

namespace {

// The one way Readline's C callbacks reach the source in use.
ReadlineSource* active = nullptr;

int take_key(FILE*) {
  return active ? active->next_key() : EOF;
}

int keys_waiting() {
  return active && active->key_waiting() ? 1 : 0;
}

void on_line(char* line) {
  if (active) active->line_done(line);
}

char* completion(const char* text, int state) {
  return active ? active->next_completion(text, state) : nullptr;
}

char** complete(const char* text, int start, int) {
  rl_attempted_completion_over = 1;  // never file names
  return active ? active->complete(text, start) : nullptr;
}

bool starts_with_ignoring_case(std::string_view word, std::string_view typed) {
  return typed.size() <= word.size() && upper(word.substr(0, typed.size())) == upper(typed);
}

}  // namespace

ReadlineSource::ReadlineSource(std::filesystem::path history, Candidates candidates,
                               Interrupts& interrupts, int fd)
    : history_(std::move(history)),
      candidates_(std::move(candidates)),
      interrupts_(interrupts),
      fd_(fd) {
  active = this;
  rl_readline_name = "igds";
  // The APL characters (¯ ⍴ ⍝) are UTF-8: edit them as characters, never as Meta keys, even
  // when the environment names no UTF-8 locale.
  if (!std::setlocale(LC_CTYPE, "") || MB_CUR_MAX == 1) std::setlocale(LC_CTYPE, "C.UTF-8");
  rl_variable_bind("input-meta", "on");
  rl_variable_bind("output-meta", "on");
  rl_variable_bind("convert-meta", "off");
  rl_catch_signals = 0;  // Ctrl-C is an event of the wait (Interrupts)
  rl_getc_function = take_key;
  rl_input_available_hook = keys_waiting;
  rl_attempted_completion_function = igds::complete;
  rl_basic_word_break_characters = const_cast<char*>(" \t,");
  // APL without an APL keyboard: ` then a key types its glyph (interp/apl/keyboard.h).
  for (const auto& k : apl::prefix_keys()) {
    const char sequence[3] = {apl::prefix_key, k.key, 0};
    const std::string glyph(k.glyph);
    rl_macro_bind(sequence, glyph.c_str(), rl_get_keymap());
  }
  const char twice[3] = {apl::prefix_key, apl::prefix_key, 0};
  rl_bind_keyseq(twice, rl_insert);  // `` is ` itself
  using_history();
  stifle_history(static_cast<int>(history_lines));
  load_history();
}

ReadlineSource::~ReadlineSource() {
  keep_history();
  rl_getc_function = rl_getc;
  rl_input_available_hook = nullptr;
  rl_attempted_completion_function = nullptr;
  active = nullptr;
}

void ReadlineSource::read_keys() {
  // What the terminal holds, without waiting (nothing, when Ctrl-C has just flushed it).
  const int flags = fcntl(fd_, F_GETFL);
  fcntl(fd_, F_SETFL, flags | O_NONBLOCK);
  char chunk[256];
  const ssize_t n = ::read(fd_, chunk, sizeof chunk);
  fcntl(fd_, F_SETFL, flags);
  if (n > 0) keys_.append(chunk, static_cast<std::size_t>(n));
  if (n == 0) keys_ += '\x04';  // the terminal is gone: as Ctrl-D
}

int ReadlineSource::next_key() {
  while (keys_.empty()) {
    // Waiting for the rest of a key: Ctrl-C meanwhile ends the wait.
    if (wait_for(fd_, &interrupts_, -1) == Event::Kind::interrupt) {
      interrupted_ = true;
      return EOF;
    }
    read_keys();
  }
  const auto key = static_cast<unsigned char>(keys_.front());
  keys_.erase(0, 1);
  return key;
}

bool ReadlineSource::key_waiting() {
  if (!keys_.empty()) return true;
  pollfd in{fd_, POLLIN, 0};
  return poll(&in, 1, 0) > 0;
}

void ReadlineSource::line_done(char* line) {
  done_ = true;
  if (line) {
    read_ = line;
    std::free(line);
  } else {
    read_.reset();
  }
  // As Readline's own example does: no prompt again until igds asks for one.
  rl_callback_handler_remove();
}

char** ReadlineSource::complete(const char* text, int start) {
  completions_.clear();
  if (candidates_) completions_ = candidates_(split_words(std::string_view(rl_line_buffer, start)));
  return rl_completion_matches(text, completion);
}

char* ReadlineSource::next_completion(const char* text, int state) {
  if (state == 0) next_completion_ = 0;
  while (next_completion_ < completions_.size()) {
    const std::string& word = completions_[next_completion_++];
    if (starts_with_ignoring_case(word, text)) return strdup(word.c_str());
  }
  return nullptr;
}

// The history is igds's own file: never followed through a link, never waited for (a FIFO put
// at its name), never written when it is not a plain file with one name; Readline's own
// read_history and write_history would do all three. When it cannot be kept, the lines typed
// are kept for this session only.
namespace {

// A plain file of one name at `path`, opened with `flags` without following a link or waiting;
// -1 for anything else.
int own_file(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
  if (fd < 0) return -1;
  struct stat st;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_nlink != 1) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// A history larger than this is not the one igds keeps (1000 lines of what a person types).
constexpr std::size_t max_history_bytes = 4u << 20;

}  // namespace

void ReadlineSource::load_history() {
  const int fd = own_file(history_, O_RDONLY);
  if (fd < 0) return;
  std::string text;
  struct stat st;
  if (::fstat(fd, &st) == 0 && static_cast<std::uint64_t>(st.st_size) <= max_history_bytes) {
    text.resize(static_cast<std::size_t>(st.st_size));
    std::size_t got = 0;
    while (got < text.size()) {
      const ssize_t n = ::read(fd, text.data() + got, text.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    text.resize(got);
  }
  ::close(fd);
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    if (end > at) {
      add_history(text.substr(at, end - at).c_str());
      ++history_file_lines_;
    }
    at = end + 1;
  }
}

void ReadlineSource::keep_line(const std::string& line) {
  // Appended, so that a session that dies keeps it; the file is cut back to the last lines
  // when it has grown to twice as many.
  if (history_file_lines_ >= 2 * history_lines) return keep_history();
  const int fd = own_file(history_, O_WRONLY | O_APPEND | O_CREAT);
  if (fd < 0) return;
  const std::string text = line + '\n';
  std::size_t sent = 0;
  while (sent < text.size()) {
    const ssize_t n = ::write(fd, text.data() + sent, text.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    sent += static_cast<std::size_t>(n);
  }
  ::close(fd);
  ++history_file_lines_;
}

void ReadlineSource::keep_history() {
  // Written whole through the disk's own writing (a temporary created beside it, renamed over
  // it): only where there is nothing yet or igds's own plain file.
  struct stat st;
  if (::lstat(history_.c_str(), &st) == 0) {
    const int fd = own_file(history_, O_RDONLY);
    if (fd < 0) return;
    ::close(fd);
  } else if (errno != ENOENT) {
    return;
  }
  std::string text;
  std::size_t lines = 0;
  if (HIST_ENTRY** entries = history_list()) {
    for (; entries[lines]; ++lines) {
      text += entries[lines]->line;
      text += '\n';
    }
  }
  try {
    disk::write_file(history_, text);
    history_file_lines_ = lines;
  } catch (const disk::IoError&) {
    // A disk that refuses it: the history is kept for this session only.
  }
}

Event ReadlineSource::abandon() {
  // Ctrl-C: the line being typed is dropped, the terminal is as before.
  keys_.clear();
  interrupted_ = false;
  rl_free_line_state();
  rl_callback_sigcleanup();
  rl_cleanup_after_signal();
  rl_callback_handler_remove();
  std::fputs("\n", stdout);
  return {Event::Kind::interrupt, {}};
}

Event ReadlineSource::line(std::string_view prompt) {
  interrupts_.take();  // Ctrl-C typed while a command computed is not acted on
  const std::string shown(prompt);
  for (;;) {
    std::fflush(stdout);
    done_ = false;
    read_.reset();
    rl_callback_handler_install(shown.c_str(), on_line);
    while (!done_) {
      while (keys_.empty() && !interrupted_) {
        if (wait_for(fd_, &interrupts_, -1) == Event::Kind::interrupt) {
          interrupted_ = true;
          break;
        }
        read_keys();  // nothing there after all when Ctrl-C flushed it: wait again
      }
      if (interrupted_) return abandon();
      rl_callback_read_char();
    }
    // Ctrl-C while Readline waited for the rest of a key: its EOF is no end of input.
    if (interrupted_) return abandon();
    if (!read_) {
      std::fputs("\n", stdout);
      return {Event::Kind::end, {}};
    }
    if (!read_->empty()) {
      add_history(read_->c_str());
      // Kept at once, so that a session that dies keeps its history too.
      keep_line(*read_);
    }
    if (is_comment_line(*read_)) continue;
    return {Event::Kind::line, std::move(*read_)};
  }
}

Event ReadlineSource::key(std::optional<std::chrono::milliseconds> timeout) {
  if (keys_.empty()) {
    const int ms = timeout ? static_cast<int>(timeout->count()) : -1;
    const Event::Kind k = wait_for(fd_, &interrupts_, ms);
    if (k != Event::Kind::key) return {k, {}};
    read_keys();
  }
  if (keys_.empty()) return {Event::Kind::timeout, {}};
  std::string c(1, keys_.front());
  keys_.erase(0, 1);
  return {c == "\x04" ? Event::Kind::end : Event::Kind::key, c};
}

}  // namespace igds
