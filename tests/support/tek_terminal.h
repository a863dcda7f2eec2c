// xterm's Tek window as a program on the other side of the line sees it, for the tests: what it
// answers to igds's output (ESC ENQ: its status and the alpha cursor's address), GIN mode on at
// ESC SUB and off at the report or at a control character, and what a click or a key sends in
// GIN mode and out of it (xterm's Tekproc.c and input.c; docs/devices.md, "The cross-hair").
// TekKeys is an input on such a terminal for the Terminal object; XtermPty drives igds itself
// on a pseudo-terminal.
#pragma once

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "interp/terminal.h"
#include "tests/support/pty.h"

namespace igds::test {

class FakeTek {
 public:
  // `terminator`: xterm's ginTerminator ("", "\r" or "\r\x04").
  explicit FakeTek(std::string terminator = "\r") : terminator_(std::move(terminator)) {}

  // igds's output, as it comes; returns what the terminal answers (to ESC ENQ).
  std::string output(std::string_view bytes);
  bool gin() const { return gin_; }
  // A mouse button (l m r) at (x, y), in 4013 points: its report when GIN mode is on (then
  // off), else nothing (xterm rings the bell).
  std::string click(char button, int x, int y);
  // Keys: in GIN mode the first is a report at the cross-hair (then GIN mode is off), the rest
  // go as typed.
  std::string type(std::string_view keys);
  // Where the mouse is (the cross-hair when a key is pressed).
  void point_at(int x, int y) {
    mouse_x_ = x;
    mouse_y_ = y;
  }
  int enquiries() const { return enquiries_; }

 private:
  std::string report(unsigned char key, int x, int y) const;
  void control(char c);

  std::string terminator_;
  bool gin_ = false;
  int mouse_x_ = 512, mouse_y_ = 390;
  // The parser: after ESC, in a graph mode reading an address, the alpha cursor (12-bit).
  bool escape_ = false, graph_ = false, vt_ = false;
  int x_ = 0, y_ = 2992, hi_y_ = 0, lo_y_ = 0, hi_x_ = 0, lo_x_ = 0, extra_ = 0;
  bool lo_y_seen_ = false;
  int enquiries_ = 0;
};

// Keys from a person at such a terminal, for a Terminal in tek mode writing to `out`: before
// each wait the terminal reads what igds wrote (and answers it), then the next action of the
// script is done, as the person would, in GIN mode or not as the terminal is then.
class TekKeys final : public EventSource {
 public:
  explicit TekKeys(const std::string& out, std::string terminator = "\r")
      : out_(out), tek_(std::move(terminator)) {}
  // A click of button l at (x, y).
  void click(int x, int y) { actions_.push_back({Action::click, {}, x, y, false}); }
  // Keys typed ("\x03" an interrupt). `early`: before the terminal has read what igds wrote
  // last (typed while igds was busy, before the cross-hair came up).
  void type(std::string keys, bool early = false) {
    actions_.push_back({Action::type, std::move(keys), 0, 0, early});
  }
  void point_at(int x, int y) { actions_.push_back({Action::point, {}, x, y, false}); }
  // Keys xterm sends as they are, GIN mode left on: the numeric keypad's, or keys pressed after
  // the terminal answered ESC ENQ and before it read ESC SUB.
  void plain(std::string keys) {
    actions_.push_back({Action::plain, std::move(keys), 0, 0, false});
  }
  std::size_t left() const { return actions_.size() + bytes_.size(); }
  const FakeTek& terminal() const { return tek_; }

  Event line(std::string_view) override;
  Event key(std::optional<std::chrono::milliseconds> timeout) override;
  Event bytes(std::optional<std::chrono::milliseconds> timeout) override;
  void unread(std::string bytes) override { bytes_.insert(0, bytes); }
  bool gives_keys() const override { return true; }
  bool command_file() const override { return false; }

 private:
  struct Action {
    enum Kind { click, type, point, plain } kind;
    std::string keys;
    int x, y;
    bool early;
  };
  // Reads igds's output and does the next action when nothing is waiting; an interrupt, the
  // end of the script, or bytes.
  Event next(bool wait);

  const std::string& out_;
  std::size_t read_ = 0;
  FakeTek tek_;
  std::deque<Action> actions_;
  std::string bytes_;
  bool interrupted_ = false;
};

// igds on a pseudo-terminal that answers as xterm's Tek window does: every wait reads igds's
// output and answers it.
class XtermPty {
 public:
  XtermPty(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
           std::string terminator = "\r");
  PtySession& pty() { return pty_; }
  const FakeTek& terminal() const { return tek_; }
  // Reads igds's output for `timeout_ms` at most and answers it.
  void pump(int timeout_ms);
  // Waits, answering, until `text` is in the output after the last match.
  bool expect(std::string_view text, double timeout_seconds = 10);
  // What igds wrote so far is not looked at by the next expect().
  void skip_output() {
    pump(0);
    mark_ = pty_.output().size();
  }
  // Waits, answering, until the cross-hair is up.
  bool expect_gin(double timeout_seconds = 10);
  // What a click or a key sends depends on what the terminal has read by then: igds's output
  // is read first.
  void click(char button, int x, int y) {
    pump(0);
    send(tek_.click(button, x, y));
  }
  void type(std::string_view keys) {
    pump(0);
    send(tek_.type(keys));
  }
  void point_at(int x, int y) { tek_.point_at(x, y); }
  // Both directions in order, readable: what a failing test shows.
  std::string transcript(std::size_t last = 4000) const;

 private:
  void send(const std::string& bytes);
  void log(char direction, std::string_view bytes);

  PtySession pty_;
  FakeTek tek_;
  std::size_t read_ = 0, mark_ = 0;
  std::string transcript_;
};

}  // namespace igds::test
