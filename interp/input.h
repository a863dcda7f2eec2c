// Where the lines of the conversation come from: a command file or a pipe (read as if typed,
// each line echoed after its prompt so that the output reads like the session), a terminal in
// tek mode (plain lines, as on the 4013), or a terminal with GNU Readline (editing, history on
// the disk, completion).
#pragma once

#include <csignal>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "devices/terminal.h"

namespace igds {

// Set by SIGINT while igds waits for a line on a terminal.
extern volatile std::sig_atomic_t interrupted;
// Ctrl-C interrupts the wait for a line (no SA_RESTART) instead of killing igds.
void catch_interrupts();

// Writes text to standard output (the dialogue, prompts and image bytes share it).
void write_out(std::string_view text);

class LineInput {
 public:
  virtual ~LineInput() = default;
  // The next line that is not a comment line, `prompt` shown before it; nullopt at the end of
  // the input. Throws Abandon on Ctrl-C.
  virtual std::optional<std::string> read(std::string_view prompt) = 0;
  // The same after a line of its own (READY): written first, or by Readline as the first line of
  // its prompt, so that a key typed as soon as READY shows already finds Readline waiting.
  virtual std::optional<std::string> read_after(std::string_view line) {
    write_out(line);
    write_out("\n");
    return read("");
  }
  // A command file (or a pipe): --strict applies, and the end of the input is not a person
  // leaving.
  virtual bool is_command_file() const = 0;
};

// Lines from a file descriptor. `echo`: write the prompt and the line after reading it (command
// files); otherwise the prompt is written first and the terminal echoes.
class FdInput final : public LineInput {
 public:
  FdInput(int fd, bool echo, bool command_file);
  ~FdInput() override;
  std::optional<std::string> read(std::string_view prompt) override;
  bool is_command_file() const override { return command_file_; }

 private:
  std::optional<std::string> next_line();
  int fd_;
  bool echo_, command_file_;
  std::string buffer_;
  std::size_t start_ = 0;
  bool eof_ = false;
};

// GNU Readline on the terminal. `history` is a file on the disk; `candidates` gives the words
// that may complete the word being typed, from the words before it on the line.
class ReadlineInput final : public LineInput {
 public:
  using Candidates = std::function<std::vector<std::string>(const std::vector<std::string>&)>;
  ReadlineInput(std::filesystem::path history, Candidates candidates);
  ~ReadlineInput() override;
  std::optional<std::string> read(std::string_view prompt) override;
  std::optional<std::string> read_after(std::string_view line) override {
    return read(std::string(line) + "\n");
  }
  bool is_command_file() const override { return false; }

 private:
  std::filesystem::path history_;
};

// tek mode (with the Tek options) or not: in tek mode the dialogue is on the Tek screen, written
// in 7-bit ASCII (APL characters as ASCII: ¯ as -, ⍴ as RHO, ⍝ as NB., any other as ?) with
// its lines kept on the screen (devices/terminal.h, TekDialogue).
void set_tek_dialogue(std::optional<TekOptions> tek);
// The dialogue on the Tek screen in tek mode, else nullptr.
TekDialogue* tek_dialogue_in_use();
// Bytes for the terminal as they are (graph data, escapes), not dialogue text.
void write_raw(std::string_view bytes);

}  // namespace igds
