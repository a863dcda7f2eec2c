// The IGDS conversation (manual sections 4 and 6, docs/interp.md): READY, a command
// looked up by prefix in the table, its option, its questions, HELP at every question, error
// reports, the session saved after every command, and the END APL environment. It knows no
// particular command: everything comes from the commands' declarations (commands/command.h).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "commands/command.h"
#include "commands/context.h"
#include "interp/apl_env.h"
#include "interp/terminal.h"
#include "workspace/disk/session.h"

namespace igds {

class Interpreter final : public Context {
 public:
  Interpreter(Options options, Disk disk, Session& session, Workspace ws, Terminal& terminal);

  // How a conversation on one input ended.
  enum class Outcome {
    input_ended,  // the input has no more lines: go on with the next one, or end
    ended,        // END CMS or )OFF: igds ends
    strict_stop,  // --strict and an error report in a command file
    interrupted,  // Ctrl-C while a command file or a pipe was read: igds ends
  };
  // Runs READY / command on the terminal's input until it ends, END, or a --strict stop. The
  // session is saved after every command.
  Outcome converse();

  // The other way of choosing a command (the 2250's light pen): `command` with `option` already
  // chosen (nullptr: asked as when it is not typed), run exactly as the typed line would be:
  // the same questions, HELP, reports, the session saved after it, END APL's environment.
  // Returns how the conversation ends when it does (END CMS, an output that failed).
  std::optional<Outcome> run_chosen(const Command& command, const Choice* option);
  // A command line typed where the 2250's menu waits for a pick: run as typed after READY.
  std::optional<Outcome> run_line(std::string_view line);

  // The words that may complete the next word of a line that has `before` so far: at READY the
  // commands, their options and what the options take; at a question its answers and HELP.
  std::vector<std::string> completions(const std::vector<std::string>& before) const;

  // Saves the session, with the undo journal (the command just run is a step of it when it
  // changed the workspace): done after every command and at the end. A failure is reported once
  // for as long as saves keep failing for the same reason, and once more when they work again.
  void save();
  // True when the last save worked: the disk holds the session as it is now.
  bool saved() const { return save_failure_.empty(); }
  // Error reports printed so far (INCORRECT ENTRY included).
  int error_count() const { return errors_; }

  // Context
  Workspace& workspace() override { return ws_; }
  const Options& options() const override { return options_; }
  const Disk& disk() const override { return disk_; }
  Journal& journal() override { return journal_; }
  std::span<const std::string_view> ask_words(const Prompt& prompt) override;
  void unread(std::vector<std::string> words) override;
  bool has_pending() const override { return !pending_.empty(); }
  bool pending_from_command_line() const override { return !pending_.empty() && on_line_; }
  void say(std::string_view line) override;
  void document(std::string_view text) override;
  void report(std::string_view text) override;
  void show(const ImageRef& image) override;
  std::optional<PickedAddress> pick(const Prompt& prompt) override;
  void erase() override;
  void send_to_terminal(std::string_view bytes) override;
  void end_session(bool apl) override;

 private:
  enum class Ending { none, cms, apl };
  // Runs one command line (words not empty); reports what goes wrong.
  void execute(const std::vector<std::string>& words);
  // Runs `run` as a command: what goes wrong is reported, READY follows.
  void perform(const std::function<void()>& run);
  void run_command(const std::vector<std::string>& words);
  // The command with its option; the option is asked when it is null and the command has some.
  void run_with(const Command& command, const Choice* option);
  // After a command: the session saved, END and END APL, --strict; an outcome when the
  // conversation ends there.
  std::optional<Outcome> after_command(int errors_before);
  // HELP, HELP SHORT or HELP LONG typed at a question: answered, true.
  bool answer_help(std::span<const std::string_view> words, const Prompt& prompt);
  Outcome apl_environment();

  Options options_;
  Disk disk_;
  Session& session_;
  Workspace ws_;
  Terminal& terminal_;
  Journal journal_;        // UNDO and REDO: a step recorded before each save that has changes
  std::string step_name_;  // the last command run and its option, e.g. "CHANGE POINTS"
  const Command* current_ = nullptr;  // the command being run (nullptr at READY)
  const Prompt* asking_ = nullptr;    // the question being asked (for completion)
  bool in_apl_ = false;
  // END APL's session: its own variables and functions last until igds ends.
  std::unique_ptr<AplEnvironment> apl_;
  bool running_ = false;              // a command is running: a --strict stop abandons it
  std::vector<std::string> pending_;  // unread words
  Reply reply_;
  bool on_line_ = false;  // the unread words are the command line's
  Ending ending_ = Ending::none;
  bool input_ended_ = false;  // the input ended inside a command
  bool interrupted_ = false;  // the last command was abandoned by Ctrl-C
  bool ready_due_ = true;     // READY is printed before the next command line is read
  int errors_ = 0;
  std::string save_failure_;  // the report of the failing saves; empty when the last one worked
};

}  // namespace igds
