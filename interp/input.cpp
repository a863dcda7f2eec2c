#include "interp/input.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <readline/history.h>
#include <readline/readline.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "commands/context.h"
#include "devices/terminal.h"
#include "interp/words.h"

namespace igds {

volatile std::sig_atomic_t interrupted = 0;

namespace {

extern "C" void on_interrupt(int) {
  interrupted = 1;
}

}  // namespace

void catch_interrupts() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: the wait for a line must end
  sigaction(SIGINT, &action, nullptr);
  // A parent may have started igds with SIGINT blocked; Ctrl-C must reach it all the same.
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  pthread_sigmask(SIG_UNBLOCK, &interrupt, nullptr);
}

namespace {

// tek mode: the dialogue's place on the Tek screen (a 4013 is also a 7-bit terminal).
std::optional<TekDialogue> tek_dialogue;

// What a 7-bit terminal can show of the APL characters igds writes or echoes.
std::string transliterated(std::string_view text) {
  static constexpr std::pair<std::string_view, std::string_view> apl[] = {
      {"\xC2\xAF", "-"},         // ¯ high minus: the same number
      {"\xE2\x8D\xB4", "RHO "},  // ⍴
      {"\xE2\x8D\x9D", "NB."},   // ⍝ lamp: a comment
  };
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x80) {
      out += text[i++];
      continue;
    }
    bool known = false;
    for (const auto& [utf8, ascii] : apl) {
      if (text.substr(i).starts_with(utf8)) {
        out += ascii;
        i += utf8.size();
        known = true;
        break;
      }
    }
    if (known) continue;
    // Any other character: one '?' for all its bytes.
    out += '?';
    ++i;
    while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
  }
  return out;
}

// Waits until `fd` can be read. False when Ctrl-C came before or during the wait: SIGINT is
// blocked outside ppoll, so that one arriving between the check and the wait is not lost.
bool wait_for_input(int fd) {
  sigset_t block, old;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  pthread_sigmask(SIG_BLOCK, &block, &old);
  bool ready = false;
  while (!interrupted) {
    pollfd in{fd, POLLIN, 0};
    int n = ppoll(&in, 1, nullptr, &old);
    if (n > 0 || (n < 0 && errno != EINTR)) {
      ready = true;
      break;
    }
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return ready && !interrupted;
}

}  // namespace

void set_tek_dialogue(std::optional<TekOptions> tek) {
  if (tek)
    tek_dialogue.emplace(*tek);
  else
    tek_dialogue.reset();
}

TekDialogue* tek_dialogue_in_use() {
  return tek_dialogue ? &*tek_dialogue : nullptr;
}

void write_out(std::string_view text) {
  if (tek_dialogue) {
    const std::string shown = tek_dialogue->text(transliterated(text));
    std::fwrite(shown.data(), 1, shown.size(), stdout);
    return;
  }
  std::fwrite(text.data(), 1, text.size(), stdout);
}

void write_raw(std::string_view bytes) {
  std::fwrite(bytes.data(), 1, bytes.size(), stdout);
}

// ---- FdInput ---------------------------------------------------------------------------------

FdInput::FdInput(int fd, bool echo, bool command_file)
    : fd_(fd), echo_(echo), command_file_(command_file) {}

FdInput::~FdInput() {
  if (fd_ > 2) close(fd_);
}

std::optional<std::string> FdInput::next_line() {
  for (;;) {
    auto end = buffer_.find('\n', start_);
    if (end != std::string::npos || (eof_ && start_ < buffer_.size())) {
      if (end == std::string::npos) end = buffer_.size();
      std::string line = buffer_.substr(start_, end - start_);
      start_ = std::min(end + 1, buffer_.size());
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
    if (eof_) return std::nullopt;
    buffer_.erase(0, start_);
    start_ = 0;
    // Whoever drives igds through a pipe sees the prompt before igds waits.
    std::fflush(stdout);
    if (!wait_for_input(fd_)) {
      interrupted = 0;
      buffer_.clear();
      write_out("\n");
      throw Abandon{};
    }
    char chunk[65536];
    ssize_t n = ::read(fd_, chunk, sizeof chunk);
    if (n > 0)
      buffer_.append(chunk, static_cast<std::size_t>(n));
    else if (n == 0 || errno != EINTR)
      eof_ = true;
  }
}

std::optional<std::string> FdInput::read(std::string_view prompt) {
  interrupted = 0;
  for (;;) {
    if (!echo_) write_out(prompt);
    auto line = next_line();
    if (!line) return std::nullopt;
    if (is_comment_line(*line)) continue;
    if (echo_) {
      // The transcript shows the line after its prompt, as on the screen.
      std::string shown = std::string(prompt) + *line;
      shown.erase(shown.find_last_not_of(" \t") + 1);
      shown += '\n';
      write_out(shown);
    }
    return line;
  }
}

// ---- ReadlineInput ---------------------------------------------------------------------------

namespace {

bool line_done = false;
std::optional<std::string> line_read;

// The keys read from the terminal that readline has not taken yet. igds reads the terminal
// itself: Ctrl-C flushes the terminal's input queue, and readline's own read, waiting for keys
// that are gone, would never see the interrupt.
std::string keys;
int key_fd = 0;

// Reads what the terminal holds, without waiting (nothing, when Ctrl-C has just flushed it).
void read_keys() {
  const int flags = fcntl(key_fd, F_GETFL);
  fcntl(key_fd, F_SETFL, flags | O_NONBLOCK);
  char chunk[256];
  ssize_t n = ::read(key_fd, chunk, sizeof chunk);
  fcntl(key_fd, F_SETFL, flags);
  if (n > 0) keys.append(chunk, static_cast<std::size_t>(n));
  if (n == 0) keys += '\x04';  // the terminal is gone: as Ctrl-D
}

// readline's getc: the next key, waiting for one only when a multi-byte key is incomplete. EOF
// when Ctrl-C comes meanwhile: read() sees `interrupted` when readline returns.
int take_key(FILE*) {
  while (keys.empty()) {
    if (!wait_for_input(key_fd)) return EOF;
    read_keys();
  }
  const auto key = static_cast<unsigned char>(keys.front());
  keys.erase(0, 1);
  return key;
}

// Ctrl-C: the line being typed is dropped, the terminal is as before, the command abandoned.
[[noreturn]] void abandon_line() {
  keys.clear();
  interrupted = 0;
  rl_free_line_state();
  rl_callback_sigcleanup();
  rl_cleanup_after_signal();
  rl_callback_handler_remove();
  write_out("\n");
  throw Abandon{};
}

// Whether a key is waiting (for readline's escape-sequence timeout).
int keys_waiting() {
  if (!keys.empty()) return 1;
  pollfd in{key_fd, POLLIN, 0};
  return poll(&in, 1, 0) > 0 ? 1 : 0;
}
ReadlineInput::Candidates* completion_source = nullptr;
std::vector<std::string> completion_words;
std::size_t completion_next = 0;

void on_line(char* line) {
  line_done = true;
  if (line) {
    line_read = line;
    std::free(line);
  } else {
    line_read.reset();
  }
  // As readline's own example does: no prompt again until igds asks for one.
  rl_callback_handler_remove();
}

bool starts_with_ignoring_case(std::string_view word, std::string_view typed) {
  return typed.size() <= word.size() && upper(word.substr(0, typed.size())) == upper(typed);
}

char* next_completion(const char* text, int state) {
  if (state == 0) completion_next = 0;
  while (completion_next < completion_words.size()) {
    const std::string& word = completion_words[completion_next++];
    if (starts_with_ignoring_case(word, text)) return strdup(word.c_str());
  }
  return nullptr;
}

char** complete(const char* text, int start, int) {
  rl_attempted_completion_over = 1;  // never file names
  completion_words.clear();
  if (completion_source && *completion_source)
    completion_words = (*completion_source)(split_words(std::string_view(rl_line_buffer, start)));
  return rl_completion_matches(text, next_completion);
}

}  // namespace

ReadlineInput::ReadlineInput(std::filesystem::path history, Candidates candidates)
    : history_(std::move(history)) {
  static Candidates source;
  source = std::move(candidates);
  completion_source = &source;
  rl_readline_name = "igds";
  // The APL characters (¯ ⍴ ⍝) are UTF-8: edit them as characters, never as Meta keys, even
  // when the environment names no UTF-8 locale.
  if (!std::setlocale(LC_CTYPE, "") || MB_CUR_MAX == 1) std::setlocale(LC_CTYPE, "C.UTF-8");
  rl_variable_bind("input-meta", "on");
  rl_variable_bind("output-meta", "on");
  rl_variable_bind("convert-meta", "off");
  rl_catch_signals = 0;  // igds handles Ctrl-C itself (catch_interrupts)
  key_fd = fileno(rl_instream ? rl_instream : stdin);
  rl_getc_function = take_key;
  rl_input_available_hook = keys_waiting;
  rl_attempted_completion_function = complete;
  rl_basic_word_break_characters = const_cast<char*>(" \t,");
  using_history();
  stifle_history(1000);
  read_history(history_.c_str());
}

ReadlineInput::~ReadlineInput() {
  write_history(history_.c_str());
}

std::optional<std::string> ReadlineInput::read(std::string_view prompt) {
  interrupted = 0;
  const std::string shown(prompt);
  for (;;) {
    std::fflush(stdout);
    line_done = false;
    line_read.reset();
    rl_callback_handler_install(shown.c_str(), on_line);
    while (!line_done) {
      while (keys.empty() && !interrupted) {
        if (!wait_for_input(key_fd)) break;
        read_keys();  // nothing there after all when Ctrl-C flushed it: wait again
      }
      if (interrupted) abandon_line();
      rl_callback_read_char();
    }
    // Ctrl-C while readline waited for the rest of a key: its EOF is no end of input.
    if (interrupted) abandon_line();
    if (!line_read) {
      write_out("\n");
      return std::nullopt;
    }
    if (!line_read->empty()) {
      add_history(line_read->c_str());
      // Kept at once, so that a session that dies keeps its history too.
      write_history(history_.c_str());
    }
    if (is_comment_line(*line_read)) continue;
    return line_read;
  }
}

}  // namespace igds
