// The sources of input (interp/terminal.h, EventSource): command files and pipes, the keyboard
// through GNU Readline, and the keyboard key by key (tek mode); and Ctrl-C, read as an event
// rather than caught by a handler.
#pragma once

#include <termios.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "interp/terminal.h"

namespace igds {

// Ctrl-C while igds waits for input: SIGINT, blocked in every thread of igds
// (workspace/kernels/interrupt.h), is read from a signalfd, so that it arrives as an event of the
// wait, never lost between a check and the wait.
class Interrupts {
 public:
  Interrupts();
  ~Interrupts();
  Interrupts(const Interrupts&) = delete;
  Interrupts& operator=(const Interrupts&) = delete;
  int fd() const { return fd_; }
  // True when Ctrl-C came since the last call; forgets it.
  bool take();

 private:
  int fd_ = -1;
};

// Waits until `fd` can be read or, when `interrupts` is given, Ctrl-C comes, at most `timeout`
// milliseconds (-1: no limit). Returns the kind of event: key (readable), interrupt or timeout.
Event::Kind wait_for(int fd, Interrupts* interrupts, int timeout);

// Lines from a file descriptor: a command file, a pipe, or a terminal read line by line.
class FdSource final : public EventSource {
 public:
  // `command_file`: a command file or a pipe (see EventSource). The descriptor is closed at the
  // end unless it is one of the standard ones.
  FdSource(int fd, bool command_file, Interrupts* interrupts = nullptr);
  ~FdSource() override;
  Event line(std::string_view prompt) override;
  Event key(std::optional<std::chrono::milliseconds> timeout) override;
  bool command_file() const override { return command_file_; }
  bool line_ready() const override;

 private:
  int fd_;
  bool command_file_;
  Interrupts* interrupts_;
  std::string buffer_;
  std::size_t start_ = 0;    // the first byte of the next line
  std::size_t scanned_ = 0;  // bytes already searched for its end
  bool eof_ = false;
};

// The keyboard key by key, with the terminal's own echo off: tek mode, where igds echoes what is
// typed on the screen it manages. Restores the terminal's settings when it goes.
class KeySource final : public EventSource {
 public:
  KeySource(int fd, Interrupts& interrupts);
  ~KeySource() override;
  Event line(std::string_view prompt) override;
  Event key(std::optional<std::chrono::milliseconds> timeout) override;
  Event bytes(std::optional<std::chrono::milliseconds> timeout) override;
  void unread(std::string bytes) override { pending_.insert(0, bytes); }
  bool gives_keys() const override { return true; }
  bool command_file() const override { return false; }

 private:
  int fd_;
  Interrupts& interrupts_;
  // The next bytes from the terminal, waiting at most `timeout`: false at a timeout, an
  // interrupt (`kind` says which) or the end.
  bool read_more(std::optional<std::chrono::milliseconds> timeout, Event::Kind& kind);
  // Ctrl-C came: what was typed ahead is dropped, here and in the tty, as the tty's own flush
  // would (it is off, NOFLSH). False when none came.
  bool interrupted();

  std::optional<termios> saved_;
  std::string pending_;  // bytes read but not yet given
};

// GNU Readline on the terminal: editing, a history kept on the disk, and completion of the word
// being typed from the words before it (`candidates`). Readline's callbacks reach this object
// through one pointer, set while it exists.
class ReadlineSource final : public EventSource {
 public:
  using Candidates = std::function<std::vector<std::string>(const std::vector<std::string>&)>;
  ReadlineSource(std::filesystem::path history, Candidates candidates, Interrupts& interrupts,
                 int fd = 0);
  ~ReadlineSource() override;
  ReadlineSource(const ReadlineSource&) = delete;
  ReadlineSource& operator=(const ReadlineSource&) = delete;
  Event line(std::string_view prompt) override;
  Event key(std::optional<std::chrono::milliseconds> timeout) override;
  bool echoes() const override { return true; }
  bool command_file() const override { return false; }

  // For Readline's callbacks.
  int next_key();
  bool key_waiting();
  void line_done(char* line);
  char** complete(const char* text, int start);
  char* next_completion(const char* text, int state);

 private:
  void read_keys();
  Event abandon();
  // HISTORY.IGDSHIST: read at start, each line appended as it is typed, written whole at the
  // end (only ever igds's own plain file: see input.cpp).
  void load_history();
  void keep_line(const std::string& line);
  void keep_history();

  static constexpr std::size_t history_lines = 1000;
  std::filesystem::path history_;
  std::size_t history_file_lines_ = 0;  // lines in the file as far as this source knows
  Candidates candidates_;
  Interrupts& interrupts_;
  int fd_;
  std::string keys_;  // keys read from the terminal that Readline has not taken yet
  bool interrupted_ = false;
  bool done_ = false;
  std::optional<std::string> read_;
  std::vector<std::string> completions_;
  std::size_t next_completion_ = 0;
};

}  // namespace igds
