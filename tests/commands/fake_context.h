// A Context for driving commands in tests: scripted reply lines, a recorded dialogue, a scratch
// disk.
#pragma once

#include <deque>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/context.h"

namespace igds::test {

class FakeContext final : public Context {
 public:
  explicit FakeContext(std::filesystem::path dir) : disk_(dir) { options_.disk = dir; }

  // Lines the user will type, in order; a line "^C" is Ctrl-C.
  void type(std::vector<std::string> lines) {
    for (auto& l : lines) typed_.push_back(std::move(l));
  }
  // Runs a command line, as the interpreter does (without HELP and READY).
  void run(const Command& command, int option, std::vector<std::string> words = {}) {
    pending_ = std::move(words);
    command.run(*this, option);
  }

  Workspace ws;
  std::vector<std::string> prompts;  // every prompt shown
  std::vector<std::string> said;     // say() and report() lines
  std::vector<Image> shown;
  int reports = 0;
  int ends = -1;  // end_session: 1 APL, 0 CMS

  Workspace& workspace() override { return ws; }
  const Options& options() const override { return options_; }
  const Disk& disk() const override { return disk_; }
  std::vector<std::string> ask(const Prompt& prompt) override {
    if (!pending_.empty()) return std::exchange(pending_, {});
    prompts.emplace_back(prompt.text);
    if (typed_.empty()) throw EndOfInput{};
    std::string line = typed_.front();
    typed_.pop_front();
    if (line == "^C") throw Abandon{};
    std::vector<std::string> words;
    std::istringstream in(line);
    for (std::string w; in >> w;) words.push_back(w);
    return words;
  }
  void unread(std::vector<std::string> words) override {
    words.insert(words.end(), pending_.begin(), pending_.end());
    pending_ = std::move(words);
  }
  bool has_pending() const override { return !pending_.empty(); }
  void say(std::string_view line) override { said.emplace_back(line); }
  void report(std::string_view text) override {
    said.emplace_back(text);
    ++reports;
  }
  void show(const ImageRef& image) override { shown.push_back(*image); }
  void erase() override {}
  void send_to_terminal(std::string_view) override {}
  void end_session(bool apl) override { ends = apl ? 1 : 0; }

  std::size_t unread_lines() const { return typed_.size(); }

 private:
  Options options_;
  Disk disk_;
  std::deque<std::string> typed_;
  std::vector<std::string> pending_;
};

}  // namespace igds::test
