#include "interp/interpreter.h"

#include <fmt/format.h>

#include <array>
#include <new>
#include <utility>

#include "commands/entries.h"
#include "commands/picture.h"
#include "commands/reports.h"
#include "interp/apl_env.h"
#include "interp/words.h"
#include "workspace/apl.h"
#include "workspace/error.h"
#include "workspace/kernels/data_error.h"

namespace igds {

namespace {

constexpr std::string_view apl_short_help =
    "Type a variable's name, ⍴NAME for its shape, )VARS, START to go back to IGDS or )OFF to "
    "leave.";
constexpr std::string_view apl_long_help =
    R"(The APL environment shows the IGDS workspace variables (manual section 7):
  NOCUR NOSTR INTCU INTST   the grid: input curves and stringers, interpolated ones
  INPPN    input points, (NOCUR x NOSTR) x 3      INPTG   border tangents and point numbers
  PATCHES  the Coons matrices of every patch      INTPN   the interpolated grid
  IMAGE DESIM               the current image and its description
  TEMP1 DEST1 TEMP2 DEST2   the copies of STORE FIRST and SECOND
  STATUS   STATUS[1] is 1 for HELP LONG, 0 for SHORT
Type a name to display it, ⍴NAME (or RHO NAME) for its shape, )VARS for the names
that have a value, START to go back to IGDS (READY), )OFF to leave igds.
A name without a value gives VALUE ERROR, anything else SYNTAX ERROR.
Example:
      ⍴INTPN
9 9 3)";

}  // namespace

Interpreter::Interpreter(Options options, Disk disk, Session& session, Workspace ws,
                         Terminal& terminal)
    : options_(std::move(options)),
      disk_(std::move(disk)),
      session_(session),
      ws_(std::move(ws)),
      terminal_(terminal) {}

Interpreter::Outcome Interpreter::converse() {
  input_ended_ = false;
  const int errors_before = errors_;
  auto strict_stop = [&] {
    return options_.strict && terminal_.command_file() && errors_ > errors_before;
  };
  for (;;) {
    const Event e = terminal_.read_line("", ready_due_ ? "READY" : "");
    ready_due_ = false;
    if (e.kind == Event::Kind::interrupt) {
      ready_due_ = true;
      continue;
    }
    if (e.kind != Event::Kind::line) return Outcome::input_ended;
    auto words = split_words(e.text);
    if (words.empty()) continue;
    execute(words);
    save();
    ready_due_ = true;
    if (terminal_.output_failed()) return Outcome::ended;
    if (strict_stop()) return Outcome::strict_stop;
    if (ending_ == Ending::cms) return Outcome::ended;
    if (ending_ == Ending::apl) {
      ending_ = Ending::none;
      Outcome outcome = apl_environment();
      save();
      if (strict_stop()) return Outcome::strict_stop;
      if (outcome != Outcome::input_ended) return outcome;
    }
    if (input_ended_) return Outcome::input_ended;
  }
}

void Interpreter::execute(const std::vector<std::string>& words) {
  current_ = nullptr;
  asking_ = nullptr;
  pending_.clear();
  running_ = true;
  struct Finish {
    bool& running;
    ~Finish() { running = false; }
  } finish{running_};
  try {
    // PATCHES and INTPN of a session just loaded are made while the first line is typed.
    session_.complete(ws_);
    run_command(words);
  } catch (const StrictStop&) {
    // The report is printed; converse() stops.
  } catch (const Error& r) {
    running_ = false;
    report(r.what());
  } catch (const DataError& e) {
    running_ = false;
    report(worded(e).what());
  } catch (const Abandon&) {
    // Ctrl-C: nothing of the command was kept; READY follows.
  } catch (const EndOfInput&) {
    running_ = false;
    input_ended_ = true;
    report(fmt::format("END OF INPUT: {} ABANDONED", current_ ? current_->name : "COMMAND"));
  } catch (const std::bad_alloc&) {
    running_ = false;
    report("NOT ENOUGH MEMORY: THE COMMAND IS IGNORED");
  } catch (const std::exception& e) {
    running_ = false;
    report(upper(fmt::format("{}: THE COMMAND IS IGNORED", e.what())));
  }
  current_ = nullptr;
  asking_ = nullptr;
  pending_.clear();
}

void Interpreter::run_command(const std::vector<std::string>& words) {
  const Command* command = find_command(words[0]);
  if (!command) throw Report(reports::incorrect_command);
  current_ = command;
  pending_.assign(words.begin() + 1, words.end());
  on_line_ = true;
  const Choice* option = nullptr;
  if (!command->options.empty()) {
    if (!pending_.empty()) {
      option = choose(command->options, pending_.front());
      pending_.erase(pending_.begin());
      if (!option) throw Report(command->bad_option);
    } else if (!command->option_prompt.text.empty()) {
      std::vector<std::string> reply;
      while (reply.empty()) reply = ask(command->option_prompt);
      option = choose(command->options, reply.front());
      if (!option) throw Report(command->bad_option);
      reply.erase(reply.begin());
      unread(std::move(reply));
    }
  }
  command->run(*this, option);
}

std::vector<std::string> Interpreter::ask(const Prompt& prompt) {
  if (!pending_.empty()) return std::exchange(pending_, {});
  const std::string shown = prompt.text.empty() ? "" : std::string(prompt.text) + " ";
  asking_ = &prompt;
  for (;;) {
    const Event e = terminal_.read_line(shown);
    if (e.kind == Event::Kind::interrupt) throw Abandon{};
    if (e.kind != Event::Kind::line) throw EndOfInput{};
    auto words = split_words(e.text);
    if (answer_help(words, prompt)) continue;
    on_line_ = false;
    return words;
  }
}

bool Interpreter::answer_help(const std::vector<std::string>& words, const Prompt& prompt) {
  const HelpRequest help = help_request(words);
  if (!help.asked) return false;
  // HELP SHORT and HELP LONG change the setting (STATUS[1]); HELP alone keeps it.
  if (help.length >= 0) ws_.status[0] = help.length;
  if (ws_.status[0] == 0)
    terminal_.document(prompt.short_help);
  else
    terminal_.document(current_ ? current_->long_help : prompt.short_help);
  return true;
}

void Interpreter::unread(std::vector<std::string> words) {
  words.insert(words.end(), pending_.begin(), pending_.end());
  pending_ = std::move(words);
}

void Interpreter::say(std::string_view line) {
  terminal_.say(line);
}

void Interpreter::document(std::string_view text) {
  terminal_.document(text);
}

void Interpreter::report(std::string_view text) {
  say(text);
  ++errors_;
  if (running_ && options_.strict && terminal_.command_file()) throw StrictStop{};
}

void Interpreter::show(const ImageRef& image) {
  // The picture is made only for a terminal that draws it.
  auto picture = terminal_.mode() == TermMode::none
                     ? nullptr
                     : std::make_shared<const Picture>(picture_of(image));
  terminal_.show(std::move(picture), describe_line(image->desim));
}

void Interpreter::erase() {
  terminal_.erase();
}

void Interpreter::send_to_terminal(std::string_view bytes) {
  terminal_.raw(bytes);
}

void Interpreter::end_session(bool apl) {
  ending_ = apl ? Ending::apl : Ending::cms;
}

void Interpreter::save() {
  try {
    session_.save(ws_);
    if (!save_failure_.empty()) say("THE SESSION IS SAVED AGAIN");
    save_failure_.clear();
  } catch (const Error& r) {
    // Said once per streak of failures: the same words after every command hide the dialogue.
    if (r.what() != save_failure_) report(r.what());
    save_failure_ = r.what();
  }
}

Interpreter::Outcome Interpreter::apl_environment() {
  in_apl_ = true;
  struct Leave {
    bool& flag;
    ~Leave() { flag = false; }
  } leave{in_apl_};
  for (;;) {
    const Event e = terminal_.read_line(apl_prompt);
    if (e.kind == Event::Kind::interrupt) continue;
    if (e.kind != Event::Kind::line) return Outcome::ended;  // the end of the input is )OFF
    auto words = split_words(e.text);
    if (words.empty()) continue;
    if (const HelpRequest help = help_request(words); help.asked) {
      if (help.length >= 0) ws_.status[0] = help.length;
      terminal_.document(ws_.status[0] == 1 ? apl_long_help : apl_short_help);
      continue;
    }
    std::string joined;
    for (const auto& w : words) joined += (joined.empty() ? "" : " ") + w;
    AplReply reply = apl_line(ws_, joined);
    bool error = false;
    for (const auto& out : reply.lines) {
      error = out == "VALUE ERROR" || out == "SYNTAX ERROR";
      if (error)
        report(out);
      else
        say(out);
    }
    if (error && options_.strict && terminal_.command_file()) return Outcome::strict_stop;
    if (reply.next == AplNext::start) return Outcome::input_ended;
    if (reply.next == AplNext::off) return Outcome::ended;
  }
}

std::vector<std::string> Interpreter::completions(const std::vector<std::string>& before) const {
  std::vector<std::string> out;
  auto add = [&out](std::span<const Choice> choices) {
    for (const Choice& c : choices) out.emplace_back(c.word);
  };
  if (in_apl_) {
    out = {")VARS", ")OFF", "START", std::string(help_word())};
    for (auto& name : defined_variables(ws_)) out.push_back(name);
    return out;
  }
  if (current_ != nullptr) {
    // At a question: its answers, and HELP with its lengths.
    if (!before.empty()) {
      if (help_request(before).asked) add(help_lengths());
      return out;
    }
    if (asking_) add(asking_->answers);
    out.emplace_back(help_word());
    return out;
  }
  if (before.empty()) {
    for (const Command* c : command_table()) out.emplace_back(c->name);
    return out;
  }
  const Command* command = find_command(before[0]);
  if (!command) return out;
  if (before.size() == 1) {
    add(command->options);
    return out;
  }
  // After the option: the words that answer the command's questions.
  for (const Prompt* q : command->questions) add(q->answers);
  return out;
}

}  // namespace igds
