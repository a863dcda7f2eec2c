// The IGDS conversation (manual sections 4 and 6, spec igds.md section 2): READY, a command
// looked up by prefix in the table, its option, its questions, HELP at every prompt, error
// reports, the session saved after every command, and the END APL environment. It knows no
// particular command: everything comes from command_table().
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "commands/command.h"
#include "commands/context.h"
#include "interp/input.h"
#include "workspace/disk/session.h"

namespace igds {

class Interpreter final : public Context {
 public:
  Interpreter(Options options, Disk disk, Session& session, Workspace ws);

  // How a conversation on one input ended.
  enum class Outcome {
    input_ended,  // the input has no more lines: go on with the next one, or end
    ended,        // END CMS or )OFF: igds ends
    strict_stop,  // --strict and an error report in a command file
  };
  // Runs READY / command until the input ends, END, or a --strict stop. The session is saved
  // after every command.
  Outcome converse(LineInput& input);

  // The words that may complete the next word of a line that has `before` so far (commands,
  // options, projections, HELP and its options, answers, APL names), for Readline.
  std::vector<std::string> completions(const std::vector<std::string>& before) const;

  // Saves the session (a Report is printed): done after every command and at the end.
  void save();
  // Error reports printed so far (INCORRECT ENTRY included).
  int error_count() const { return errors_; }

  // Context
  Workspace& workspace() override { return ws_; }
  const Options& options() const override { return options_; }
  const Disk& disk() const override { return disk_; }
  std::vector<std::string> ask(const Prompt& prompt) override;
  void unread(std::vector<std::string> words) override;
  bool has_pending() const override { return !pending_.empty(); }
  void say(std::string_view line) override;
  void report(std::string_view text) override;
  void show(const ImageRef& image) override;
  void erase() override;
  void send_to_terminal(std::string_view bytes) override;
  void end_session(bool apl) override;

 private:
  enum class Ending { none, cms, apl };
  // Runs one command line (words not empty); reports what goes wrong.
  void execute(const std::vector<std::string>& words);
  void run_command(const std::vector<std::string>& words);
  // HELP, HELP SHORT or HELP LONG typed at a prompt: answered, true.
  bool answer_help(const std::vector<std::string>& words, const Prompt& prompt);
  void say_lines(std::string_view text);
  Outcome apl_environment();

  Options options_;
  Disk disk_;
  Session& session_;
  Workspace ws_;
  LineInput* input_ = nullptr;
  const Command* current_ = nullptr;  // the command being run (nullptr at READY)
  bool in_apl_ = false;
  bool running_ = false;              // a command is running: a --strict stop abandons it
  std::vector<std::string> pending_;  // unread words of the command line
  Ending ending_ = Ending::none;
  bool input_ended_ = false;  // the input ended inside a command
  bool told_how_to_see_ = false;
  bool ready_due_ = true;  // READY is printed before the next command line is read
  int errors_ = 0;
};

// A one-line description of an image (what, projection, parameters), as the none terminal
// mode prints it.
std::string describe_image(const Description& desim);

}  // namespace igds
