// A Context for driving commands in tests: scripted reply lines (split into words by the
// interpreter's own word splitting), a recorded dialogue, what reaches the terminal, a disk.
#pragma once

#include <cstdio>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/context.h"
#include "interp/words.h"

namespace igds::test {

class FakeContext final : public Context {
 public:
  explicit FakeContext(std::filesystem::path dir, Workspace workspace = {})
      : ws(std::move(workspace)), disk_(dir) {
    opts.disk = dir;
  }

  // Lines the user will type, in order; a line "^C" is Ctrl-C.
  void type(std::vector<std::string> lines) {
    for (auto& l : lines) typed_.push_back(std::move(l));
  }
  // Runs a command line, as the interpreter does (without HELP and READY).
  // `option` is the option's word, "" for a command without options.
  void run(const Command& command, std::string_view option, std::vector<std::string> words = {}) {
    pending_ = std::move(words);
    on_line_ = true;
    const Choice* chosen = option.empty() ? nullptr : choose(command.options, option);
    REQUIRE((option.empty() || chosen));
    command.run(*this, chosen);
  }

  Workspace ws;
  Options opts;                      // the command line's options, as the test sets them
  std::vector<std::string> prompts;  // every prompt shown
  std::vector<std::string> said;     // say() and report() lines
  std::vector<Image> shown;
  int reports = 0;
  int ends = -1;  // end_session: 1 APL, 0 CMS
  int erases = 0;
  std::string terminal;          // bytes sent to the terminal as they are
  bool picks_on_screen = false;  // pick(): a person's X Y, not a command file's
  Journal undo_journal{ws};  // UNDO and REDO's; a test records steps in it as the interpreter does

  Workspace& workspace() override { return ws; }
  const Options& options() const override { return opts; }
  const Disk& disk() const override { return disk_; }
  std::span<const std::string_view> ask_words(const Prompt& prompt) override {
    if (!pending_.empty()) return reply_.of(std::exchange(pending_, {}));
    prompts.emplace_back(prompt.text);
    if (typed_.empty()) throw EndOfInput{};
    std::string line = typed_.front();
    typed_.pop_front();
    if (line == "^C") throw Interrupted{};
    on_line_ = false;
    // The interpreter's own word splitting: blanks and commas, comments dropped.
    return reply_.of(std::move(line), [](std::string_view text, std::vector<std::string_view>& w) {
      split_words(text, w);
    });
  }
  void unread(std::vector<std::string> words) override {
    words.insert(words.end(), pending_.begin(), pending_.end());
    pending_ = std::move(words);
  }
  bool has_pending() const override { return !pending_.empty(); }
  bool pending_from_command_line() const override { return !pending_.empty() && on_line_; }
  void say(std::string_view line) override { said.emplace_back(line); }
  void document(std::string_view text) override {
    while (!text.empty()) {
      const auto end = text.find('\n');
      said.emplace_back(text.substr(0, end));
      text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    }
  }
  void report(std::string_view text) override {
    said.emplace_back(text);
    ++reports;
  }
  void show(const ImageRef& image) override { shown.push_back(*image); }
  // A typed line `X Y` is a pick, as from a command file (interp/terminal.h): on the page, or on
  // the screen when `picks_on_screen` is set (a person at the terminal); any other line is not
  // one.
  std::optional<PickedAddress> pick(const Prompt& prompt) override {
    prompts.emplace_back(prompt.text);
    if (typed_.empty()) throw EndOfInput{};
    std::string line = typed_.front();
    typed_.pop_front();
    if (line == "^C") throw Interrupted{};
    int x = 0, y = 0;
    if (std::sscanf(line.c_str(), "%d %d", &x, &y) != 2) return std::nullopt;
    return PickedAddress{{x, y}, picks_on_screen ? PickLayout::screen : PickLayout::page};
  }
  void erase() override { ++erases; }
  void send_to_terminal(std::string_view bytes) override { terminal += bytes; }
  void end_session(bool apl) override { ends = apl ? 1 : 0; }
  Journal& journal() override { return undo_journal; }

  std::size_t unread_lines() const { return typed_.size(); }

 private:
  Disk disk_;
  std::deque<std::string> typed_;
  std::vector<std::string> pending_;
  Reply reply_;
  bool on_line_ = false;
};

// What a command run in `ctx` reported ("" when it reported nothing).
inline std::string report_of(FakeContext& ctx, const Command& c, std::string_view option,
                             std::vector<std::string> words = {}) {
  try {
    ctx.run(c, option, std::move(words));
  } catch (const Error& r) {
    return r.what();
  }
  return "";
}

}  // namespace igds::test
