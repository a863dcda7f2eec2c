#include "interp/terminal.h"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "devices/gin.h"
#include "devices/tek4013.h"
#include "interp/apl/keyboard.h"

namespace igds {

namespace {

// xterm: into the Tek window and, at the end, alpha mode and back to the VT window.
std::string for_xterm(std::string_view bytes) {
  return "\x1b[?38h" + std::string(bytes) + std::string{tek_us, tek_esc, tek_etx};
}

constexpr std::string_view more_prompt = "MORE: PRESS RETURN";
// Rows of dialogue a new page keeps of the last one (devices/tek_screen.cpp).
constexpr int carried_rows = 3;
constexpr std::string_view back_prompt = "PRESS RETURN TO GO BACK TO THE PICTURE";

// Control keys of the line editor in tek mode.
constexpr char backspace = '\b', rubout = 0x7F, kill_line = 0x15, end_of_input = 0x04;

}  // namespace

Terminal::Terminal(TermMode mode, TekOptions tek, Output& out) : mode_(mode), out_(out) {
  if (mode != TermMode::none) screen_ = std::make_unique<TekScreen>(tek, mode == TermMode::tek);
}

void Terminal::begin() {
  if (mode_ == TermMode::tek) out_.write(screen_->begin());
}

void Terminal::write_dialogue(std::string_view text) {
  if (mode_ == TermMode::tek)
    out_.write(screen_->text(text));
  else
    out_.write(text);
}

void Terminal::say(std::string_view line) {
  if (mode_ == TermMode::tek) {
    write_row(line, false);
    return;
  }
  write_dialogue(line);
  write_dialogue("\n");
}

void Terminal::print(std::string_view line) {
  if (mode_ == TermMode::tek) {
    write_row(line, true);
    return;
  }
  write_dialogue(line);
  write_dialogue("\n");
}

bool Terminal::write_row(std::string_view line, bool set_out) {
  // A line that would turn the page while rows the person has not read would go with the old
  // page (a new page keeps its last rows only) waits for RETURN first, on the page's last row.
  const int rows = screen_->rows_of(line, set_out);
  bool go_on = true;
  if (screen_->rows_left() - 1 < rows && unseen_ > carried_rows && input_ &&
      !input_->command_file() && typed_ahead_.empty() && !held_) {
    write_dialogue(more_prompt);
    write_dialogue("\n");
    go_on = wait_for_return();
    unseen_ = 0;
    out_.write(screen_->clear());
  }
  std::string ended(line);
  ended += '\n';
  out_.write(screen_->text(ended, set_out));
  unseen_ += rows;
  return go_on;
}

bool Terminal::wait_for_return() {
  last_click_.reset();  // a person answering in between makes the next click no double click's
  // Only a person reading needs the pause; a command file goes on, and so does a person who has
  // already typed on.
  if (!input_ || input_->command_file() || !typed_ahead_.empty()) return true;
  out_.flush();
  const Event e = input_->gives_keys() ? input_->key(std::nullopt) : input_->line("");
  if (e.kind == Event::Kind::line) return true;
  if (e.kind != Event::Kind::key) {
    // Ctrl-C or the end of the input at a pause: the next wait gives it (the command is
    // abandoned there, or igds ends).
    if (e.kind == Event::Kind::interrupt || e.kind == Event::Kind::end) held_ = e.kind;
    return false;
  }
  // Any key goes on; one that is not RETURN is the first of the next line.
  if (e.text != "\r" && e.text != "\n") typed_ahead_.push_back(e.text);
  return true;
}

int Terminal::columns() const {
  return mode_ == TermMode::tek ? screen_->columns() : columns_;
}

void Terminal::document(std::string_view text) {
  if (mode_ != TermMode::tek) {
    for (const auto& row : lay_out(text, columns_)) say(row);
    return;
  }
  const bool picture = screen_->shows_picture();
  if (picture && !screen_->in_document()) {
    // A short text (HELP SHORT at a question) below the picture, which stays: HELP never erases.
    const auto rows = lay_out(text, screen_->columns());
    if (static_cast<int>(rows.size()) <= screen_->rows_per_page() / 2) {
      for (const auto& row : rows) say(row);
      return;
    }
  }
  out_.write(screen_->document_page());
  const bool go_on = write_pages(text);
  if (picture) {
    // A person reads the text before the picture comes back; a command file goes on.
    if (go_on && input_ && !input_->command_file() && !held_) {
      say(back_prompt);
      wait_for_return();
    }
    out_.write(screen_->end_document());
  }
}

bool Terminal::write_pages(std::string_view text) {
  bool go_on = true;
  for (const auto& row : lay_out(text, screen_->columns())) {
    go_on = write_row(row, false) && go_on;
    if (held_) break;  // Ctrl-C at a pause: the rest is not shown
  }
  return go_on;
}

void Terminal::frame(std::shared_ptr<const Drawing2> menu, const TekLayout& layout) {
  if (mode_ != TermMode::tek) return;
  screen_->set_frame(std::move(menu), layout);
}

void Terminal::help(std::string_view text) {
  if (mode_ != TermMode::tek) {
    document(text);
    return;
  }
  out_.write(screen_->in_document() ? screen_->clear() : screen_->document_page(true));
  write_pages(text);
}

void Terminal::help_done() {
  if (mode_ == TermMode::tek) out_.write(screen_->end_document());
}

void Terminal::replace_picture(std::shared_ptr<const Picture> picture, int frames,
                               std::chrono::milliseconds pause) {
  if (mode_ != TermMode::tek) return;
  TekScreen::Parts parts = screen_->replace_picture(std::move(picture));
  out_.write(parts.before);
  const std::string_view bytes = parts.picture;
  const std::size_t n = static_cast<std::size_t>(std::max(1, frames));
  std::size_t sent = 0;
  for (std::size_t k = 1; k < n && input_; ++k) {
    const std::size_t upto = bytes.size() * k / n;
    out_.write(bytes.substr(sent, upto - sent));
    sent = upto;
    out_.flush();
    // The pause is a wait for a key: one pressed ends the pace.
    const Event e = input_->gives_keys() ? input_->key(pause) : Event{Event::Kind::timeout, {}};
    if (e.kind != Event::Kind::timeout) break;
  }
  out_.write(bytes.substr(sent));
  out_.write(parts.after);
  out_.flush();
}

void Terminal::show(std::shared_ptr<const Picture> picture, std::string_view line) {
  switch (mode_) {
    case TermMode::tek:
      out_.write(screen_->picture(std::move(picture)));
      return;
    case TermMode::xterm:
      out_.write(for_xterm(screen_->picture(std::move(picture))));
      return;
    case TermMode::none:
      if (!told_how_to_see_) {
        told_how_to_see_ = true;
        say("IMAGES ARE NOT DRAWN ON THIS TERMINAL. TO SEE THEM RUN IGDS IN AN XTERM");
        say("(xterm -t -e igds), OR WRITE THEM TO FILES WITH EXPORT SVG, TEK OR HPGL.");
      }
      say(line);
      return;
  }
}

void Terminal::erase() {
  switch (mode_) {
    case TermMode::tek:
      out_.write(screen_->erase());
      return;
    case TermMode::xterm:
      out_.write(for_xterm(screen_->erase()));
      return;
    case TermMode::none:
      return;
  }
}

void Terminal::raw(std::string_view bytes) {
  out_.write(bytes);
}

Event Terminal::read_line(std::string_view prompt, std::string_view above) {
  if (!input_) return {};
  last_click_.reset();
  if (held_) return {*std::exchange(held_, std::nullopt), {}};
  struct Seen {
    int& unseen;
    ~Seen() { unseen = 0; }
  } seen{unseen_};
  if (input_->echoes() && !input_->gives_keys()) {
    // Readline shows READY and the prompt itself.
    std::string shown = above.empty() ? std::string() : std::string(above) + "\n";
    out_.flush();
    return input_->line(shown + std::string(prompt));
  }
  if (!above.empty()) say(above);
  if (input_->gives_keys()) return edit_line(prompt);
  if (!input_->command_file()) {
    write_dialogue(prompt);
    out_.flush();
    return input_->line(prompt);
  }
  // What was written reaches the terminal at each READY, so that a file's progress shows command
  // by command, and before igds waits for input; the answers to a command's questions read
  // already (a BUILD's lines of points) go out together.
  if (!above.empty() || !input_->line_ready()) out_.flush();
  Event e = input_->line(prompt);
  if (e.kind == Event::Kind::line) {
    // The transcript shows the line after its prompt, as on the screen.
    std::string shown = std::string(prompt) + e.text;
    shown.erase(shown.find_last_not_of(" \t") + 1);
    say(shown);
  }
  return e;
}

Event Terminal::typed_pick(Event e, PickLayout layout) {
  if (e.kind != Event::Kind::line) return e;
  // X Y [KEY]: two whole numbers on the screen, and the key (a blank when none is given).
  int x = 0, y = 0;
  char key[2] = {' ', 0};
  char more[2] = {0, 0};
  const int n = std::sscanf(e.text.c_str(), "%d %d %1s %1s", &x, &y, key, more);
  if (n < 2 || n > 3 || x < 0 || y < 0 || x > 1023 || y > 779) return e;
  Event picked{Event::Kind::pick, key};
  picked.x = x;
  picked.y = y;
  picked.layout = layout;
  return picked;
}

Event Terminal::pick(std::string_view prompt, std::string_view pick_keys) {
  if (!input_) return {};
  if (held_) return {*std::exchange(held_, std::nullopt), {}};
  struct Seen {
    int& unseen;
    ~Seen() { unseen = 0; }
  } seen{unseen_};
  if (mode_ == TermMode::tek && input_->gives_keys()) return cross_hair(prompt, pick_keys);
  // A command file's X Y names a place on the page whatever the mode; a person's, on the screen.
  return typed_pick(read_line(prompt), command_file() ? PickLayout::page : PickLayout::screen);
}

namespace {

// What a terminal's answer may take to come whole once it has begun (its bytes are sent in one
// write), and to come at all after a request.
constexpr std::chrono::milliseconds answer_rest{30}, answer_limit{2000};
constexpr std::string_view gin_on = "\x1B\x1A", alpha_mode = "\x1F";

// `keys` without the answers to the status asked at `places` (a status byte, the place's
// address, the terminator), which came before the answer waited for last.
std::string without_answers(std::string keys, const std::vector<std::string>& places,
                            std::size_t terminator) {
  for (const std::string& address : places)
    for (auto at = keys.find(address, 1); at != std::string::npos; at = keys.find(address, at)) {
      std::size_t end = at + address.size();
      for (std::size_t k = 0; k < terminator && end < keys.size(); ++k)
        if (keys[end] == (k == 0 ? '\r' : '\x04') || (k == 0 && keys[end] == '\n')) ++end;
      keys.erase(at - 1, end - (at - 1));
      at = std::max<std::size_t>(at - 1, 1);
    }
  return keys;
}

}  // namespace

Event::Kind Terminal::leave_gin(std::string_view asked) {
  // Any control character ends GIN mode; the mark is put aside of the last one, so that an
  // answer to that one still on its way is not taken for it. Ctrl-C meanwhile may make a tty
  // drop what it holds, the answer perhaps: the status is asked again, a point further aside,
  // and the answers to the earlier requests that did come are dropped (the cross-hair's too,
  // when Ctrl-C came before it).
  GinReader reader(0, 0, 10);
  bool interrupted = false;
  std::string read;                  // all bytes read here
  std::vector<std::string> earlier;  // the places asked before the last
  if (!asked.empty()) earlier.emplace_back(asked);
  for (int aside = 1; !reader.marked(); ++aside) {
    DevicePoint at;
    std::string request(alpha_mode);
    request += screen_->enquire(at, aside);
    out_.write(request);
    out_.flush();
    reader = GinReader(at.x, at.y, 10);
    reader.feed(read);
    earlier.push_back(gin_address(at.x, at.y));
    const auto deadline = now_() + answer_limit;
    Event e;
    while (!reader.marked() && now_() < deadline) {
      e = input_->bytes(reader.unsettled() ? answer_rest : answer_limit);
      if (e.kind == Event::Kind::end) return Event::Kind::end;
      if (e.kind == Event::Kind::interrupt) break;
      if (e.kind == Event::Kind::timeout && reader.unsettled()) reader.settle();
      if (e.kind == Event::Kind::key) {
        read += e.text;
        reader.feed(e.text);
      }
    }
    if (e.kind != Event::Kind::interrupt && !reader.marked()) break;  // no answer: none comes
    interrupted = interrupted || e.kind == Event::Kind::interrupt;
  }
  // A report that left before GIN mode did is dropped, or what the tty left of one whose key
  // was Ctrl-C (its address and terminator); the keys typed meanwhile are kept.
  earlier.pop_back();
  const std::string answered =
      without_answers(std::string(reader.ahead()), earlier,
                      static_cast<std::size_t>(std::max(0, reader.terminator())));
  std::string_view keys = answered;
  if (reader.marked()) {
    const std::size_t t = static_cast<std::size_t>(reader.terminator());
    auto report_at = [&](std::size_t from) {
      if (keys.size() < from + 4 + t) return false;
      for (std::size_t i = from; i < from + 4; ++i)
        if (keys[i] < 0x20 || keys[i] > 0x3F) return false;
      return t == 0 || keys[from + 4] == '\r' || keys[from + 4] == '\n';
    };
    if (report_at(1))
      keys.remove_prefix(5 + t);
    else if (report_at(0))
      keys.remove_prefix(4 + t);
  }
  std::string kept(keys);
  kept += reader.after_mark();
  input_->unread(std::move(kept));
  return interrupted ? Event::Kind::interrupt : Event::Kind::key;
}

Event Terminal::cross_hair(std::string_view prompt, std::string_view pick_keys) {
  write_dialogue(prompt);
  for (;;) {
    // Keys typed before the question was asked answer it: a typed line, no cross-hair.
    const Event waiting = typed_ahead_.empty() ? input_->bytes(std::chrono::milliseconds(0))
                                               : Event{Event::Kind::key, {}};
    if (waiting.kind == Event::Kind::interrupt) {
      write_dialogue("\n");
      return waiting;
    }
    if (waiting.kind == Event::Kind::end) {
      write_dialogue("\n");
      return waiting;
    }
    if (waiting.kind == Event::Kind::key) {
      input_->unread(waiting.text);
      return typed_pick(edit_line({}), PickLayout::screen);
    }
    DevicePoint at;
    std::string request = screen_->enquire(at);
    request += gin_on;
    out_.write(request);
    out_.flush();
    GinReader reader(at.x, at.y, screen_->bits());
    const std::string mark = gin_address(at.x, at.y);
    Event e;
    while (!reader.done()) {
      // Before the mark or between reports nothing limits the wait: a person is choosing.
      e = input_->bytes(reader.unsettled() ? std::optional(answer_rest) : std::nullopt);
      if (e.kind == Event::Kind::timeout) {
        reader.settle();
        continue;
      }
      if (e.kind != Event::Kind::key) break;
      reader.feed(e.text);
      // Keys typed before the cross-hair was up: the answer is being typed.
      if (reader.marked() && !reader.ahead().empty()) break;
    }
    if (e.kind == Event::Kind::interrupt || e.kind == Event::Kind::end) {
      // Ctrl-C: the terminal's report of it (the key, then its address) is read and dropped,
      // and the question abandoned on a line of its own.
      if (e.kind == Event::Kind::interrupt && leave_gin(mark) == Event::Kind::end)
        e.kind = Event::Kind::end;
      write_dialogue("\n");
      return e;
    }
    if (!reader.done() || reader.typed()) {
      // Keys typed before the cross-hair was up, or sent with it left up: a typed line, once
      // GIN mode is left (a click meanwhile is no key of it). Ctrl-C meanwhile abandons it.
      std::string typed(reader.ahead());
      if (reader.typed()) typed += without_clicks(reader.rest(), reader.terminator());
      const Event::Kind left = leave_gin(mark);
      if (left != Event::Kind::key) {
        write_dialogue("\n");
        return {left, {}};
      }
      input_->unread(std::move(typed));
      return typed_pick(edit_line({}), PickLayout::screen);
    }
    const GinReport report = *reader.report();
    input_->unread(std::string(reader.rest()));
    const Clock::time_point when = now_();
    if (report.button && last_click_ && second_click(*last_click_, last_click_at_, report, when))
      continue;  // a double click's second: the cross-hair again
    const char key = report.key;
    const bool picks = report.button || key == ' ' || key == '\r' || key == '\n' ||
                       (key != 0 && pick_keys.find(key) != std::string_view::npos);
    if (!picks && !(key > ' ' && key < 0x7F)) continue;  // a control key: the cross-hair again
    if (!picks) {
      // The first key of a typed line: GIN mode is over, the rest comes as keys.
      typed_ahead_.insert(typed_ahead_.begin(), std::string(1, key));
      return typed_pick(edit_line({}), PickLayout::screen);
    }
    if (report.button) {
      last_click_ = report;
      last_click_at_ = when;
    }
    Event picked{Event::Kind::pick, std::string(1, report.button ? ' ' : key)};
    picked.x = report.x;
    picked.y = report.y;
    if (!prompt.empty()) write_dialogue(fmt::format("{} {}\n", picked.x, picked.y));
    return picked;
  }
}

Event Terminal::edit_line(std::string_view prompt) {
  last_click_.reset();
  write_dialogue(prompt);
  std::string line;
  bool prefix = false;  // the APL prefix key was typed: the next key is a glyph's
  for (;;) {
    out_.flush();
    Event e;
    if (!typed_ahead_.empty()) {
      e = {Event::Kind::key, std::move(typed_ahead_.front())};
      typed_ahead_.erase(typed_ahead_.begin());
    } else {
      e = input_->key(std::nullopt);
    }
    if (e.kind != Event::Kind::key) {
      if (e.kind == Event::Kind::interrupt || e.kind == Event::Kind::end) write_dialogue("\n");
      return e;
    }
    const char c = e.text.empty() ? 0 : e.text[0];
    if (c == '\r' || c == '\n') {
      write_dialogue("\n");
      return {Event::Kind::line, line};
    }
    if (c == backspace || c == rubout) {
      if (line.empty()) continue;
      // One character back (a UTF-8 character is several bytes).
      std::size_t cut = line.size() - 1;
      while (cut > 0 && (static_cast<unsigned char>(line[cut]) & 0xC0) == 0x80) --cut;
      line.erase(cut);
      out_.write(screen_->untype());
      continue;
    }
    if (c == kill_line) {
      while (!screen_->typed().empty()) out_.write(screen_->untype());
      line.clear();
      continue;
    }
    if (c == end_of_input && line.empty()) {
      write_dialogue("\n");
      return {Event::Kind::end, {}};
    }
    if (static_cast<unsigned char>(c) < 0x20) continue;  // other control keys do nothing
    if (prefix) {
      // ` then a key: its APL glyph, else both keys as typed.
      prefix = false;
      const std::string_view glyph = apl::prefix_glyph(c);
      if (c == apl::prefix_key)
        e.text = std::string(1, apl::prefix_key);  // `` is ` itself
      else
        e.text = glyph.empty() ? std::string(1, apl::prefix_key) + e.text : std::string(glyph);
    } else if (c == apl::prefix_key) {
      prefix = true;
      continue;
    }
    line += e.text;
    out_.write(screen_->type(e.text));
  }
}

}  // namespace igds
