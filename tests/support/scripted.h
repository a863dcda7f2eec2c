// A terminal without a terminal: input events from a script, output into a string, so that the
// conversation and the Tek screen can be tested without a pseudo-terminal.
#pragma once

#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "interp/terminal.h"

namespace igds::test {

// Output kept in a string.
struct StringOutput final : Output {
  std::string text;
  void write(std::string_view bytes) override { text += bytes; }
};

// Events in order: lines (`line`), keys one by one (`keys`, each character a key, "\x03" an
// interrupt, "\x04" the end), or the end when the script is done.
class ScriptedSource final : public EventSource {
 public:
  // `keys`: the source gives keys (tek mode at a terminal); else lines. `command_file`: a command
  // file (lines echoed by the terminal, nothing waits for a person).
  ScriptedSource(bool keys, bool command_file) : keys_(keys), command_file_(command_file) {}
  void add_line(std::string text) { events_.push_back({Event::Kind::line, std::move(text)}); }
  void lines(const std::vector<std::string>& texts) {
    for (const auto& t : texts) add_line(t);
  }
  void type(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
      // One UTF-8 character a key.
      const auto lead = static_cast<unsigned char>(text[i]);
      const std::size_t n = lead < 0xC0 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
      std::string key(text.substr(i, n));
      i += n;
      if (key == "\x03")
        events_.push_back({Event::Kind::interrupt, {}});
      else if (key == "\x04")
        events_.push_back({Event::Kind::end, {}});
      else
        events_.push_back({Event::Kind::key, key});
    }
  }
  void interrupt() { events_.push_back({Event::Kind::interrupt, {}}); }
  std::size_t left() const { return events_.size(); }

  Event line(std::string_view) override {
    if (keys_) {
      std::string text;
      for (;;) {
        Event e = next();
        if (e.kind != Event::Kind::key) return e;
        if (e.text == "\r" || e.text == "\n") return {Event::Kind::line, text};
        text += e.text;
      }
    }
    return next();
  }
  Event key(std::optional<std::chrono::milliseconds>) override { return next(); }
  bool gives_keys() const override { return keys_; }
  bool command_file() const override { return command_file_; }

 private:
  Event next() {
    if (events_.empty()) return {Event::Kind::end, {}};
    Event e = std::move(events_.front());
    events_.pop_front();
    return e;
  }
  bool keys_, command_file_;
  std::deque<Event> events_;
};

}  // namespace igds::test
