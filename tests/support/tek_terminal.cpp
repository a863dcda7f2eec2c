#include "tests/support/tek_terminal.h"

#include <fmt/format.h>

#include <chrono>

#include "devices/gin.h"

namespace igds::test {

std::string FakeTek::report(unsigned char key, int x, int y) const {
  std::string r(1, static_cast<char>(key));
  r.append(gin_address(x, y));
  r.append(terminator_);
  return r;
}

void FakeTek::control(char c) {
  // Every control character but ESC ends GIN mode and the bypass it puts the terminal in.
  gin_ = false;
  switch (c) {
    case '\x1D':  // GS: a graph mode, the first address whole
    case '\x1C':  // FS
      graph_ = true;
      lo_y_seen_ = false;
      break;
    case '\x1F':  // US: alpha mode, the cursor where the beam is
      graph_ = false;
      break;
    case '\r':
      graph_ = false;
      x_ = 0;
      break;
    case '\n':
      y_ -= 88;
      break;
    case '\b':
      x_ -= 56;
      break;
    default:
      break;
  }
}

std::string FakeTek::output(std::string_view bytes) {
  std::string answer;
  for (const char c : bytes) {
    const auto b = static_cast<unsigned char>(c);
    if (vt_) {  // a VT sequence (ESC [ ? 38 h): up to its final letter
      if ((b >= 'A' && b <= 'Z') || (b >= 'a' && b <= 'z')) vt_ = false;
      continue;
    }
    if (escape_) {
      escape_ = false;
      if (c == '[') {
        vt_ = true;
      } else if (c == '\x05') {  // ESC ENQ
        ++enquiries_;
        if (gin_) {
          gin_ = false;
          answer.append(gin_address(mouse_x_, mouse_y_));
          answer.append(terminator_);
        } else {
          answer += report(0x34, x_ >> 2, y_ >> 2);
        }
      } else if (c == '\x1A') {  // ESC SUB: GIN mode
        gin_ = true;
      } else if (c == '\x0C') {  // ESC FF: a page
        gin_ = false;
        graph_ = false;
        x_ = 0;
        y_ = 2992;
      }
      continue;
    }
    if (c == '\x1B') {
      escape_ = true;
      continue;
    }
    if (b < 0x20) {
      control(c);
      continue;
    }
    if (gin_ || b >= 0x80) continue;  // bypass: nothing drawn
    if (!graph_) {
      x_ += 56;  // a character in alpha mode
      continue;
    }
    // An address byte (xterm's getpoint).
    if (b < 0x40) {
      (lo_y_seen_ ? hi_x_ : hi_y_) = b & 0x1F;
    } else if (b < 0x60) {
      lo_x_ = b & 0x1F;
      x_ = hi_x_ << 7 | lo_x_ << 2 | (extra_ & 3);
      y_ = hi_y_ << 7 | lo_y_ << 2 | ((extra_ >> 2) & 3);
      lo_y_seen_ = false;
    } else {
      if (lo_y_seen_) extra_ = lo_y_ & 0x0F;
      lo_y_ = b & 0x1F;
      lo_y_seen_ = true;
    }
  }
  return answer;
}

std::string FakeTek::click(char button, int x, int y) {
  mouse_x_ = x;
  mouse_y_ = y;
  if (!gin_) return {};
  gin_ = false;
  return report(static_cast<unsigned char>(button | 0x80), x, y);
}

std::string FakeTek::type(std::string_view keys) {
  if (keys.empty() || !gin_) return std::string(keys);
  gin_ = false;
  std::string sent = report(static_cast<unsigned char>(keys[0]), mouse_x_, mouse_y_);
  sent.append(keys.substr(1));
  return sent;
}

// ---- TekKeys ------------------------------------------------------------------------------------

Event TekKeys::next(bool person_waits) {
  auto act = [&] {
    Action a = std::move(actions_.front());
    actions_.pop_front();
    std::string sent;
    if (a.kind == Action::point) tek_.point_at(a.x, a.y);
    if (a.kind == Action::click) sent = tek_.click('l', a.x, a.y);
    if (a.kind == Action::type) sent = tek_.type(a.keys);
    if (a.kind == Action::plain) sent = a.keys;
    // Through the tty: Ctrl-C a signal, and what waits to be read dropped (by igds, which reads
    // the interrupt, as by a tty), CR read as LF.
    for (const char c : sent) {
      if (c == '\x03') {
        interrupted_ = true;
        bytes_.clear();
      } else {
        bytes_ += c == '\r' ? '\n' : c;
      }
    }
  };
  while (!actions_.empty() && actions_.front().early) act();
  bytes_ += tek_.output(std::string_view(out_).substr(read_));
  read_ = out_.size();
  if (bytes_.empty() && !interrupted_ && person_waits) {
    while (!actions_.empty() && actions_.front().kind == Action::point) act();
    if (!actions_.empty()) act();
  }
  if (interrupted_) {
    interrupted_ = false;
    return {Event::Kind::interrupt, {}};
  }
  if (!bytes_.empty()) return {Event::Kind::key, {}};
  return {person_waits && actions_.empty() ? Event::Kind::end : Event::Kind::timeout, {}};
}

Event TekKeys::bytes(std::optional<std::chrono::milliseconds> timeout) {
  Event e = next(!timeout);
  if (e.kind == Event::Kind::key) e.text = std::exchange(bytes_, {});
  if (e.kind == Event::Kind::timeout && !timeout) e.kind = Event::Kind::end;
  return e;
}

Event TekKeys::key(std::optional<std::chrono::milliseconds> timeout) {
  Event e = bytes_.empty() ? next(!timeout) : Event{Event::Kind::key, {}};
  if (e.kind != Event::Kind::key) return e;
  const auto lead = static_cast<unsigned char>(bytes_[0]);
  std::size_t n = lead < 0xC0 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
  n = std::min(n, bytes_.size());
  e.text = bytes_.substr(0, n);
  bytes_.erase(0, n);
  return e;
}

Event TekKeys::line(std::string_view) {
  std::string text;
  for (;;) {
    Event e = key(std::nullopt);
    if (e.kind != Event::Kind::key) return e;
    if (e.text == "\r" || e.text == "\n") return {Event::Kind::line, text};
    text += e.text;
  }
}

// ---- XtermPty ---------------------------------------------------------------------------------

XtermPty::XtermPty(const std::vector<std::string>& argv,
                   const std::map<std::string, std::string>& env, std::string terminator)
    : pty_(argv, env), tek_(std::move(terminator)) {}

void XtermPty::log(char direction, std::string_view bytes) {
  if (bytes.empty()) return;
  transcript_ += direction == '<' ? "\n< " : "\n> ";
  for (const char c : bytes) {
    const auto b = static_cast<unsigned char>(c);
    if (b >= 0x20 && b < 0x7F)
      transcript_ += c;
    else
      transcript_ += fmt::format("<{:02X}>", b);
  }
}

std::string XtermPty::transcript(std::size_t last) const {
  return transcript_.size() > last ? transcript_.substr(transcript_.size() - last) : transcript_;
}

void XtermPty::send(const std::string& bytes) {
  log('<', bytes);
  pty_.send_raw(bytes);
}

void XtermPty::pump(int timeout_ms) {
  pty_.pump(timeout_ms);
  const std::string& out = pty_.output();
  if (read_ == out.size()) return;
  log('>', std::string_view(out).substr(read_));
  const std::string answer = tek_.output(std::string_view(out).substr(read_));
  read_ = out.size();
  if (!answer.empty()) {
    log('<', answer);
    pty_.send_raw(answer);
  }
}

bool XtermPty::expect(std::string_view text, double timeout_seconds) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
  for (;;) {
    pump(0);
    if (auto at = pty_.output().find(text, mark_); at != std::string::npos) {
      mark_ = at + text.size();
      return true;
    }
    if (std::chrono::steady_clock::now() >= deadline) return false;
    pump(20);
  }
}

bool XtermPty::expect_gin(double timeout_seconds) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
  for (;;) {
    pump(0);
    if (tek_.gin()) {
      mark_ = pty_.output().size();
      return true;
    }
    if (std::chrono::steady_clock::now() >= deadline) return false;
    pump(20);
  }
}

}  // namespace igds::test
