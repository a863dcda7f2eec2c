// HELP [SHORT | LONG] (manual 4.10 and 6): explanations at READY, made from the declarations
// of the commands. At any other question the interpreter answers HELP itself, with the
// question's short help or the command's long help.
#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "commands/answers.h"
#include "commands/command.h"

namespace igds {

extern const Command help_command;

namespace {

enum Option { short_help, long_help };  // STATUS[1]: 0 SHORT, 1 LONG

constexpr Choice options[] = {
    {"SHORT", short_help, {}, "a line or two on what is awaited (and keep to that)"},
    {"LONG", long_help, {}, "a full explanation (and keep to that)"},
};

std::string make_overview() {
  std::string text =
      "IGDS - Interactive Design of Interpolated Surfaces\n"
      "\n"
      "A surface is defined by a rectangular grid of input points: NOCUR curves crossing NOSTR "
      "stringers, with the tangents at the border of the grid. IGDS interpolates it with "
      "bicubic Coons patches, inserting INTCU curves and INTST stringers between the input "
      "ones, and shows projections of it. The commands, typed after READY:\n"
      "\n";
  // Each command's forms, then what it does in the column at 26.
  constexpr std::size_t column = 26;
  for (const Command* c : command_table()) {
    const auto forms = command_syntax(*c);
    for (std::size_t i = 0; i < forms.size(); ++i) {
      std::string line = "  " + forms[i];
      if (i + 1 < forms.size() || line.size() + 1 > column) {
        text += line + "\n";
        if (i + 1 < forms.size()) continue;
        line.clear();
      }
      line.append(column - line.size(), ' ');
      text += line + std::string(c->summary) + "\n";
    }
  }
  text +=
      "\n"
      "Any word may be cut short: the first entry of the list that starts with the letters "
      "typed wins (S is STORE, SA is SAVE, D SU is DISPLAY SURFACE). What is not on the line is "
      "asked for. Numbers may be written the APL way (¯3.5 is minus 3.5). Lines starting with * "
      "or ⍝ are comments. Ctrl-C gives up the command in progress. HELP SHORT makes HELP answer "
      "in a line or two, HELP LONG in full (the setting is kept from one session to the next).\n"
      "\n"
      "A small session:\n"
      "  BUILD\n"
      "  NUMBER OF CURVES AND STRINGERS? 2 2\n"
      "  POINTS? 1 0 0 0  0 10 0  10 0 0  10 10 5\n"
      "  POINTS?\n"
      "  TANGENTS?\n"
      "  INTERPOLATED CURVES AND STRINGERS? 5 5\n"
      "  READY\n"
      "  DISPLAY SURFACE ASSONOMETRIC 110 130 120\n"
      "  READY\n"
      "  SAVE TWIST";
  return text;
}

// What HELP says of the current surface's Marks modes (AUTO tangents, MARKS twists), if any.
void say_surface_modes(Context& ctx, const Workspace& ws) {
  if (!ws.has_input() || (!ws.auto_tangents() && !ws.marks_twists())) return;
  ctx.say(fmt::format("THE CURRENT SURFACE HAS {}{}{}.",
                      ws.auto_tangents() ? "TANGENTS AUTO (MARKS'S RULE)" : "",
                      ws.auto_tangents() && ws.marks_twists() ? " AND " : "",
                      ws.marks_twists() ? "TWISTS MARKS" : ""));
}

void run_help(Context& ctx, const Choice* option) {
  expect_no_more_words(ctx);
  Workspace& ws = ctx.workspace();
  if (option) ws.status[0] = option->code == long_help ? 1 : 0;
  if (ws.status[0] == 1) {
    ctx.document(help_overview());
    say_surface_modes(ctx, ws);
    return;
  }
  std::string names;
  for (const Command* command : command_table()) {
    names += names.empty() ? "" : " ";
    names += command->name;
  }
  ctx.document("Type a command: " + names +
               ".\nA first letter is enough (S is STORE); HELP LONG explains them all.");
  say_surface_modes(ctx, ws);
}

}  // namespace

std::string_view help_overview() {
  static const std::string overview = make_overview();
  return overview;
}

std::string_view help_word() {
  return help_command.name;
}

std::span<const Choice> help_lengths() {
  return options;
}

std::vector<std::string> command_syntax(const Command& c) {
  if (c.options.empty())
    return {c.follows.empty() ? std::string(c.name) : fmt::format("{} {}", c.name, c.follows)};
  // The options in groups of those followed by the same words, in the order they first come.
  std::vector<std::string_view> follows;
  for (const Choice& o : c.options)
    if (std::find(follows.begin(), follows.end(), o.follows) == follows.end())
      follows.push_back(o.follows);
  std::vector<std::string> forms;
  for (std::string_view f : follows) {
    std::string words;
    for (const Choice& o : c.options)
      if (o.follows == f) {
        if (!words.empty()) words += '|';
        words += o.word;
      }
    forms.push_back(fmt::format("{} {}{}{}", c.name, words, f.empty() ? "" : " ", f));
  }
  return forms;
}

HelpRequest help_request(std::span<const std::string_view> words) {
  if (words.empty() || words.size() > 2) return {};
  const Choice help_word{help_command.name};
  if (!choose({&help_word, 1}, words[0])) return {};
  if (words.size() == 1) return {true, -1};
  const Choice* length = choose(options, words[1]);
  if (!length) return {};
  return {true, length->code};
}

extern const Command help_command{
    .name = "HELP",
    .options = options,
    .follows = {},
    // No question: HELP alone answers in the length in force (STATUS[1]).
    .option_prompt = {},
    .summary = "explains what is awaited, in a line or two or in full",
    .long_help =
        "HELP explains. At READY it lists the commands (SHORT) or explains IGDS and every command "
        "(LONG); at any question it says what the question awaits (SHORT) or explains the command "
        "being run (LONG).\n"
        "\n"
        "  HELP        answers in the length in force\n"
        "  HELP SHORT  a line or two, and keeps to that from now on\n"
        "  HELP LONG   in full, and keeps to that from now on\n"
        "\n"
        "The length in force is STATUS[1] (1 LONG, 0 SHORT): LONG in a very first session, then "
        "whatever was chosen last, from one session to the next. After the answer the same "
        "question is asked again.",
    .questions = {},
    .run = run_help,
};

}  // namespace igds
