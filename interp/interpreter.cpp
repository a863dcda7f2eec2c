#include "interp/interpreter.h"

#include <fmt/format.h>

#include <array>
#include <new>
#include <utility>

#include "commands/entries.h"
#include "commands/picture.h"
#include "commands/reports.h"
#include "devices/terminal.h"
#include "interp/apl_env.h"
#include "interp/words.h"
#include "workspace/apl.h"
#include "workspace/error.h"
#include "workspace/kernels/data_error.h"

namespace igds {

namespace {

constexpr std::array<std::string_view, 1> help_words{"HELP"};
constexpr std::array<std::string_view, 2> help_lengths{"SHORT", "LONG"};  // STATUS[1] 0 and 1
constexpr std::array<std::string_view, 2> yes_no{"YES", "NO"};
constexpr std::array<std::string_view, 3> planes{"XY", "YZ", "XZ"};

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

std::span<const std::string_view> command_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> all;
    for (const Command* command : command_table()) all.push_back(command->name);
    return all;
  }();
  return names;
}

}  // namespace

std::string describe_image(const Description& d) {
  const auto& p = d.parameters;
  auto number = [](double v) { return format_apl_number(v); };
  std::string projection;
  switch (d.projection) {
    case Projection::conic:
      projection =
          fmt::format("CONIC, VIEW POINT {} {} {}", number(p[0]), number(p[1]), number(p[2]));
      break;
    case Projection::assonometric:
      projection = fmt::format("ASSONOMETRIC {} {} {}", number(p[0]), number(p[1]), number(p[2]));
      break;
    case Projection::isometric:
      projection = fmt::format("ISOMETRIC, AXIS {} ANGLE {}", number(p[0]), number(p[1]));
      break;
    case Projection::orthogonal: {
      static constexpr std::string_view names[] = {"XY", "XZ", "YZ"};  // DESIM[3] 1 2 3
      int plane = static_cast<int>(p[0]);
      projection =
          fmt::format("ORTHOGONAL {}", plane >= 1 && plane <= 3 ? names[plane - 1] : number(p[0]));
      break;
    }
  }
  return fmt::format("IMAGE: {}, {}", d.what == 0 ? "INPUT" : "SURFACE", projection);
}

Interpreter::Interpreter(Options options, Disk disk, Session& session, Workspace ws)
    : options_(std::move(options)), disk_(std::move(disk)), session_(session), ws_(std::move(ws)) {}

Interpreter::Outcome Interpreter::converse(LineInput& input) {
  input_ = &input;
  input_ended_ = false;
  const int errors_before = errors_;
  auto strict_stop = [&] {
    return options_.strict && input.is_command_file() && errors_ > errors_before;
  };
  for (;;) {
    std::optional<std::string> line;
    try {
      line = ready_due_ ? input.read_after("READY") : input.read("");
      ready_due_ = false;
    } catch (const Abandon&) {
      ready_due_ = true;
      continue;
    }
    if (!line) return Outcome::input_ended;
    auto words = split_words(*line);
    if (words.empty()) continue;
    execute(words);
    save();
    ready_due_ = true;
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
  pending_.clear();
  running_ = true;
  struct Finish {
    bool& running;
    ~Finish() { running = false; }
  } finish{running_};
  try {
    run_command(words);
  } catch (const StrictStop&) {
    // The report is printed; converse() stops.
  } catch (const Report& r) {
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
  pending_.clear();
}

void Interpreter::run_command(const std::vector<std::string>& words) {
  const int index = lookup_prefix(command_names(), words[0]);
  if (index < 0) throw Report(reports::incorrect_command);
  const Command& command = *command_table()[static_cast<std::size_t>(index)];
  current_ = &command;
  pending_.assign(words.begin() + 1, words.end());
  int option = -1;
  if (!command.options.empty()) {
    if (!pending_.empty()) {
      option = lookup_prefix(command.options, pending_.front());
      pending_.erase(pending_.begin());
      if (option < 0) throw Report(reports::incorrect_choice);
    } else if (!command.option_prompt.text.empty()) {
      std::vector<std::string> reply;
      while (reply.empty()) reply = ask(command.option_prompt);
      option = lookup_prefix(command.options, reply.front());
      if (option < 0) throw Report(reports::incorrect_choice);
      reply.erase(reply.begin());
      unread(std::move(reply));
    }
  }
  command.run(*this, option);
}

std::vector<std::string> Interpreter::ask(const Prompt& prompt) {
  if (!pending_.empty()) return std::exchange(pending_, {});
  const std::string shown = prompt.text.empty() ? "" : std::string(prompt.text) + " ";
  for (;;) {
    auto line = input_->read(shown);
    if (!line) throw EndOfInput{};
    auto words = split_words(*line);
    if (answer_help(words, prompt)) continue;
    return words;
  }
}

bool Interpreter::answer_help(const std::vector<std::string>& words, const Prompt& prompt) {
  if (words.empty() || words.size() > 2 || lookup_prefix(help_words, words[0]) != 0) return false;
  int length = ws_.status[0] == 1 ? 1 : 0;
  if (words.size() == 2) {
    length = lookup_prefix(help_lengths, words[1]);
    if (length < 0) return false;
    ws_.status[0] = length;  // HELP SHORT and HELP LONG change the setting (STATUS[1])
  }
  if (length == 0)
    say_lines(prompt.short_help);
  else
    say_lines(current_ ? current_->long_help : prompt.short_help);
  return true;
}

void Interpreter::unread(std::vector<std::string> words) {
  words.insert(words.end(), pending_.begin(), pending_.end());
  pending_ = std::move(words);
}

void Interpreter::say(std::string_view line) {
  write_out(line);
  write_out("\n");
}

void Interpreter::say_lines(std::string_view text) {
  while (!text.empty()) {
    auto end = text.find('\n');
    say(text.substr(0, end));
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
  }
}

void Interpreter::report(std::string_view text) {
  say(text);
  ++errors_;
  if (running_ && options_.strict && input_ && input_->is_command_file()) throw StrictStop{};
}

void Interpreter::show(const ImageRef& image) {
  if (options_.term != TermMode::none) {
    const Picture picture = picture_of(image);
    write_raw(display_bytes(picture, options_.term, options_.tek));
    if (TekDialogue* dialogue = tek_dialogue_in_use()) dialogue->displayed(picture);
    return;
  }
  if (!told_how_to_see_) {
    told_how_to_see_ = true;
    say("IMAGES ARE NOT DRAWN ON THIS TERMINAL. TO SEE THEM RUN IGDS IN AN XTERM");
    say("(xterm -t -e igds), OR WRITE THEM TO FILES WITH EXPORT SVG, TEK OR HPGL.");
  }
  say(describe_image(image->desim));
}

void Interpreter::erase() {
  write_raw(erase_bytes(options_.term, options_.tek));
  if (TekDialogue* dialogue = tek_dialogue_in_use()) write_raw(dialogue->home());
}

void Interpreter::send_to_terminal(std::string_view bytes) {
  write_raw(bytes);
}

void Interpreter::end_session(bool apl) {
  ending_ = apl ? Ending::apl : Ending::cms;
}

void Interpreter::save() {
  try {
    session_.save(ws_);
  } catch (const Report& r) {
    report(r.what());
  }
}

Interpreter::Outcome Interpreter::apl_environment() {
  in_apl_ = true;
  struct Leave {
    bool& flag;
    ~Leave() { flag = false; }
  } leave{in_apl_};
  for (;;) {
    std::optional<std::string> line;
    try {
      line = input_->read(apl_prompt);
    } catch (const Abandon&) {
      continue;
    }
    if (!line) return Outcome::ended;  // the end of the input is )OFF
    auto words = split_words(*line);
    if (words.empty()) continue;
    if (lookup_prefix(help_words, words[0]) == 0 && words.size() <= 2) {
      int length = ws_.status[0] == 1 ? 1 : 0;
      if (words.size() == 2) length = lookup_prefix(help_lengths, words[1]);
      if (length >= 0) {
        ws_.status[0] = length;
        say_lines(length == 1 ? apl_long_help : apl_short_help);
        continue;
      }
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
    if (error && options_.strict && input_->is_command_file()) return Outcome::strict_stop;
    if (reply.next == AplNext::start) return Outcome::input_ended;
    if (reply.next == AplNext::off) return Outcome::ended;
  }
}

std::vector<std::string> Interpreter::completions(const std::vector<std::string>& before) const {
  std::vector<std::string> out;
  auto add = [&out](auto&& words) {
    for (std::string_view w : words) out.emplace_back(w);
  };
  if (in_apl_) {
    out = {")VARS", ")OFF", "START", "HELP"};
    add(defined_variables(ws_));
    return out;
  }
  if (current_ != nullptr && before.size() == 1 && lookup_prefix(help_words, before[0]) == 0) {
    add(help_lengths);
    return out;
  }
  if (current_ == nullptr) {
    if (before.empty()) {
      add(command_names());
      return out;
    }
    const int index = lookup_prefix(command_names(), before[0]);
    if (index < 0) return out;
    if (before.size() == 1) {
      add(command_table()[static_cast<std::size_t>(index)]->options);
    } else {
      add(projection_words());
      add(planes);
    }
    return out;
  }
  if (before.empty()) {
    add(current_->options);
    add(projection_words());
    add(yes_no);
    add(help_words);
  } else {
    add(projection_words());
    add(planes);
  }
  return out;
}

}  // namespace igds
