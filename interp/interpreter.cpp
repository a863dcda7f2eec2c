#include "interp/interpreter.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <new>
#include <utility>

#include "commands/entries.h"
#include "commands/picture.h"
#include "commands/plot.h"
#include "commands/reports.h"
#include "interp/apl/keyboard.h"
#include "interp/apl_env.h"
#include "interp/words.h"
#include "workspace/error.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/limits.h"

namespace igds {

extern const Command save_command, restore_command;

Interpreter::Interpreter(Options options, Disk disk, Session& session, Workspace ws,
                         Terminal& terminal)
    : options_(std::move(options)),
      disk_(std::move(disk)),
      session_(session),
      ws_(std::move(ws)),
      terminal_(terminal),
      journal_(session.take_journal(ws_)) {}

Interpreter::Outcome Interpreter::converse() {
  input_ended_ = false;
  // --strict stops at the first error of this input.
  const int errors_before = errors_;
  for (;;) {
    const Event e = terminal_.read_line("", ready_due_ ? "READY" : "");
    ready_due_ = false;
    if (e.kind == Event::Kind::interrupt) {
      // A person: READY again. A command file or a pipe: igds stops, as any program.
      if (terminal_.command_file()) return Outcome::interrupted;
      ready_due_ = true;
      continue;
    }
    if (e.kind != Event::Kind::line) return Outcome::input_ended;
    auto words = split_words(e.text);
    if (words.empty()) continue;
    execute(words);
    if (auto outcome = after_command(errors_before)) return *outcome;
  }
}

std::optional<Interpreter::Outcome> Interpreter::run_chosen(const Command& command,
                                                            const Choice* option) {
  input_ended_ = false;
  const int errors_before = errors_;
  perform([&] {
    current_ = &command;
    on_line_ = true;
    run_with(command, option);
  });
  return after_command(errors_before);
}

std::optional<Interpreter::Outcome> Interpreter::run_line(std::string_view line) {
  input_ended_ = false;
  const int errors_before = errors_;
  const auto words = split_words(line);
  if (words.empty()) return std::nullopt;
  execute(words);
  return after_command(errors_before);
}

std::optional<Interpreter::Outcome> Interpreter::after_command(int errors_before) {
  auto strict_stop = [&] {
    return options_.strict && terminal_.command_file() && errors_ > errors_before;
  };
  save();
  ready_due_ = true;
  if (terminal_.output_failed()) return Outcome::ended;
  if (interrupted_ && terminal_.command_file()) return Outcome::interrupted;
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
  return std::nullopt;
}

void Interpreter::execute(const std::vector<std::string>& words) {
  perform([&] { run_command(words); });
}

void Interpreter::perform(const std::function<void()>& run) {
  current_ = nullptr;
  asking_ = nullptr;
  pending_.clear();
  running_ = true;
  interrupted_ = false;
  struct Finish {
    bool& running;
    ~Finish() { running = false; }
  } finish{running_};
  try {
    run();
  } catch (const StrictStop&) {
    // The report is printed; converse() stops.
  } catch (const Error& r) {
    running_ = false;
    report(r.what());
  } catch (const DataError& e) {
    running_ = false;
    report(worded(e).what());
  } catch (const Interrupted&) {
    // Ctrl-C: nothing of the command was kept; READY follows. Read here when the command's own
    // work saw it waiting (a question's wait has read it already).
    running_ = false;
    interrupted_ = true;
    if (take_interrupt())
      say(fmt::format("INTERRUPTED: {} ABANDONED", current_ ? current_->name : "COMMAND"));
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
  if (!command->options.empty() && !pending_.empty()) {
    option = choose(command->options, pending_.front());
    pending_.erase(pending_.begin());
    if (!option) throw Report(command->bad_option);
  }
  run_with(*command, option);
}

void Interpreter::run_with(const Command& command, const Choice* option) {
  // A word that is no option, typed at the question, gets the report and the question again
  // (docs/interp.md, "Wrong answers").
  while (!option && !command.options.empty() && !command.option_prompt.text.empty()) {
    std::vector<std::string> reply;
    while (reply.empty()) reply = ask(command.option_prompt);
    option = choose(command.options, reply.front());
    if (!option) {
      report(command.bad_option);
      continue;
    }
    reply.erase(reply.begin());
    unread(std::move(reply));
  }
  // A command run from END APL (COMDIS ...) is part of the END APL step.
  if (!in_apl_)
    step_name_ =
        option ? fmt::format("{} {}", command.name, option->word) : std::string(command.name);
  command.run(*this, option);
}

std::span<const std::string_view> Interpreter::ask_words(const Prompt& prompt) {
  if (!pending_.empty()) return reply_.of(std::exchange(pending_, {}));
  const std::string shown = prompt.text.empty() ? "" : std::string(prompt.text) + " ";
  asking_ = &prompt;
  for (;;) {
    Event e = terminal_.read_line(shown);
    if (e.kind == Event::Kind::interrupt) throw Interrupted{};
    if (e.kind != Event::Kind::line) throw EndOfInput{};
    const auto words = reply_.of(
        std::move(e.text),
        [](std::string_view line, std::vector<std::string_view>& w) { split_words(line, w); });
    if (answer_help(words, prompt)) continue;
    on_line_ = false;
    return words;
  }
}

bool Interpreter::answer_help(std::span<const std::string_view> words, const Prompt& prompt) {
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
  // What END APL prints itself (a result, an error with its caret) is set out by APL.
  if (in_apl_ && !current_)
    terminal_.print(line);
  else
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
  terminal_.show(std::move(picture), image_line(*image));
}

std::optional<PickedAddress> Interpreter::pick(const Prompt& prompt) {
  asking_ = &prompt;
  for (;;) {
    const Event e = terminal_.pick(prompt.text.empty() ? "" : std::string(prompt.text) + " ");
    if (e.kind == Event::Kind::interrupt) throw Interrupted{};
    if (e.kind == Event::Kind::pick) return PickedAddress{{e.x, e.y}, e.layout};
    if (e.kind == Event::Kind::end) throw EndOfInput{};
    if (e.kind != Event::Kind::line) continue;
    std::vector<std::string_view> words;
    split_words(e.text, words);
    if (!answer_help(words, prompt)) return std::nullopt;
  }
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
  // Said once per streak of failures: the same words after every command hide the dialogue.
  auto failed = [this](const std::string& line) {
    if (line != save_failure_) report(line);
    save_failure_ = line;
  };
  auto kept = [](std::string_view reason) {
    return fmt::format("CANNOT SAVE THE SESSION ({}); THE LAST SAVED SESSION IS KEPT", reason);
  };
  // Whatever a layer below throws, the conversation goes on and the session on the disk stays.
  try {
    // Here a command that changed the workspace becomes a step of the journal, before the
    // session forgets which parts of the inputs it changed (Workspace::changes).
    journal_.record(ws_, step_name_);
    for (const UnsavedImage& u : session_.save(ws_, &journal_)) {
      const Report r = worded(u.error);
      say(fmt::format("{} CANNOT BE DRAWN AGAIN ({}): NOT KEPT IN THE SESSION", info(u.slot).name,
                      r.reason().empty() ? r.line() : r.reason()));
    }
    if (!save_failure_.empty()) say("THE SESSION IS SAVED AGAIN");
    save_failure_.clear();
  } catch (const Error& r) {
    failed(r.what());
  } catch (const DataError& e) {
    const Report r = worded(e);
    failed(kept(r.reason().empty() ? r.line() : r.reason()));
  } catch (const std::bad_alloc&) {
    failed(kept("NOT ENOUGH MEMORY"));
  } catch (const std::exception& e) {
    failed(kept(upper(e.what())));
  }
}

Interpreter::Outcome Interpreter::apl_environment() {
  in_apl_ = true;
  struct Leave {
    bool& flag;
    ~Leave() { flag = false; }
  } leave{in_apl_};
  // The lines are APL's: a `*` line is a statement, ⍞ takes any line (interp/words.h).
  ReadingFor apl_lines(true);
  if (!apl_) {
    AplEnvironment::Hooks hooks;
    hooks.say = [this](std::string_view line) { say(line); };
    hooks.report = [this](std::string_view line) { report(line); };
    hooks.document = [this](std::string_view text) { document(text); };
    hooks.read = [this](std::string_view prompt) -> std::optional<std::string> {
      const Event e = terminal_.read_line(prompt);
      if (e.kind != Event::Kind::line) return std::nullopt;
      return e.text;
    };
    // A command run from APL (COMDIS ..., )SAVE, )LOAD): true when it reported nothing.
    hooks.command = [this](const std::vector<std::string>& words) {
      const int before = errors_;
      execute(words);
      return errors_ == before;
    };
    hooks.save_session = [this] {
      save();
      return save_failure_;
    };
    hooks.load_session = [this]() -> std::optional<Workspace> {
      const std::size_t notices = session_.notices().size();
      Workspace loaded = session_.load();
      if (session_.notices().size() != notices) {
        for (std::size_t i = notices; i < session_.notices().size(); ++i)
          report(session_.notices()[i]);
        return std::nullopt;
      }
      return loaded;
    };
    hooks.show = [this](const ImageRef& image) { show(image); };
    hooks.draw = [this](const Picture& picture, std::string_view line) {
      terminal_.show(
          terminal_.mode() == TermMode::none ? nullptr : std::make_shared<const Picture>(picture),
          line);
    };
    hooks.plot = [this](const Picture& picture) {
      try {
        plot_picture(*this, picture);
      } catch (const Error& r) {
        throw apl::Error(apl::ErrorKind::domain, r.what());
      }
    };
    hooks.disk = &disk_;
    apl_ = std::make_unique<AplEnvironment>(ws_, std::move(hooks));
  }
  apl_->forget();
  step_name_ = "END APL";
  // Leaving APL, by START or by )OFF: the workspace made whole again, or why it cannot be.
  auto leave_apl = [this]() {
    auto problem = apl_->start();
    if (problem) report(fmt::format("CANNOT START: {}", *problem));
    return !problem;
  };
  for (;;) {
    const Event e = terminal_.read_line(apl_->prompt());
    if (e.kind == Event::Kind::interrupt) continue;
    if (e.kind != Event::Kind::line) {
      leave_apl();
      return Outcome::ended;  // the end of the input is )OFF
    }
    const int before = errors_;
    auto next = apl::AplSession::Next::stay;
    // Whatever escapes the APL session, the conversation goes on (as perform() does).
    try {
      next = apl_->execute(e.text);
    } catch (const std::bad_alloc&) {
      report("WS FULL");
    } catch (const std::exception& x) {
      report(upper(x.what()));
    }
    // The user's functions and variables are saved as they change, as a command's work is (a
    // killed igds keeps them); not while an IGDS variable APL assigned waits for START.
    if (apl_->settled()) save();
    if (options_.strict && terminal_.command_file() && errors_ > before)
      return Outcome::strict_stop;
    if (next == apl::AplSession::Next::start && leave_apl()) return Outcome::input_ended;
    if (next == apl::AplSession::Next::off) {
      leave_apl();
      return Outcome::ended;
    }
  }
}

std::vector<std::string> Interpreter::completions(const std::vector<std::string>& before) const {
  std::vector<std::string> out;
  auto add = [&out](std::span<const Choice> choices) {
    for (const Choice& c : choices) out.emplace_back(c.word);
  };
  if (in_apl_) {
    out = apl_->names();
    out.emplace_back("START");
    out.emplace_back(help_word());
    return out;
  }
  if (current_ != nullptr) {
    // At a question: its answers, and HELP with its lengths.
    if (!before.empty()) {
      const std::vector<std::string_view> words(before.begin(), before.end());
      if (help_request(words).asked) add(help_lengths());
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
