#include "interp/terminal.h"

#include <algorithm>
#include <cstdio>

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
  write_dialogue(line);
  write_dialogue("\n");
}

bool Terminal::wait_for_return() {
  // Only a person reading needs the pause; a command file goes on, and so does a person who has
  // already typed on.
  if (!input_ || input_->command_file() || !typed_ahead_.empty()) return true;
  out_.flush();
  if (!input_->gives_keys()) {
    const Event e = input_->line("");
    return e.kind == Event::Kind::line;
  }
  // Any key goes on; one that is not RETURN is the first of the next line.
  const Event e = input_->key(std::nullopt);
  if (e.kind != Event::Kind::key) return false;
  if (e.text != "\r" && e.text != "\n") typed_ahead_.push_back(e.text);
  return true;
}

void Terminal::document(std::string_view text) {
  if (mode_ != TermMode::tek) {
    while (!text.empty()) {
      const auto end = text.find('\n');
      say(text.substr(0, end));
      text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    }
    return;
  }
  const bool picture = screen_->shows_picture();
  out_.write(screen_->document_page());
  const bool go_on = write_pages(text);
  if (picture) {
    // A person reads the text before the picture comes back; a command file goes on.
    if (go_on && input_ && !input_->command_file()) {
      say(back_prompt);
      wait_for_return();
    }
    out_.write(screen_->end_document());
  }
}

bool Terminal::write_pages(std::string_view text) {
  bool go_on = true;
  while (!text.empty() && go_on) {
    const auto end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    // The last row of a full page asks for RETURN before the next page.
    const int rows = static_cast<int>(utf32(line).size()) / text_columns + 1;
    if (screen_->rows_left() <= rows && !text.empty() && input_ && !input_->command_file()) {
      say(more_prompt);
      go_on = wait_for_return();
      out_.write(screen_->clear());
    }
    say(line);
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
  out_.flush();
  Event e = input_->line(prompt);
  if (e.kind == Event::Kind::line) {
    // The transcript shows the line after its prompt, as on the screen.
    std::string shown = std::string(prompt) + e.text;
    shown.erase(shown.find_last_not_of(" \t") + 1);
    say(shown);
  }
  return e;
}

Event Terminal::pick(std::string_view prompt) {
  if (!input_) return {};
  if (mode_ == TermMode::tek && input_->gives_keys()) {
    write_dialogue(prompt);
    out_.write("\x1B\x1A");  // ESC SUB: GIN mode, the crosshair
    out_.flush();
    std::string report;
    while (report.size() < 5) {
      // A key already read after the last report (looking for its EOT) begins this one.
      Event e{Event::Kind::key, {}};
      if (!typed_ahead_.empty()) {
        e.text = std::move(typed_ahead_.front());
        typed_ahead_.erase(typed_ahead_.begin());
      } else {
        e = input_->key(std::nullopt);
      }
      if (e.kind != Event::Kind::key) return e;
      report += e.text;
    }
    // The terminator, when the terminal sends one (CR, or CR and EOT; the tty may have made
    // the CR a LF).
    for (int k = 0; k < 2; ++k) {
      Event e = input_->key(std::chrono::milliseconds(50));
      if (e.kind != Event::Kind::key) break;
      if (e.text != "\r" && e.text != "\n" && e.text != "\x04") {
        typed_ahead_.push_back(std::move(e.text));
        break;
      }
    }
    if (!prompt.empty()) write_dialogue("\n");  // the prompt's line ends
    const auto gin = decode_gin(report);
    // Bytes that are no report (keys typed fast before GIN mode was on) come back as a key.
    if (!gin) return {Event::Kind::key, std::move(report)};
    Event picked{Event::Kind::pick, std::string(1, gin->key)};
    picked.x = gin->x;
    picked.y = gin->y;
    return picked;
  }
  Event e = read_line(prompt);
  if (e.kind != Event::Kind::line) return e;
  // X Y [KEY]: two whole numbers on the screen, and the key (a blank when none is given).
  int x = 0, y = 0;
  char key[2] = {' ', 0};
  const int n = std::sscanf(e.text.c_str(), "%d %d %1s", &x, &y, key);
  if (n < 2 || x < 0 || y < 0 || x > 1023 || y > 779) return e;
  Event picked{Event::Kind::pick, key};
  picked.x = x;
  picked.y = y;
  return picked;
}

Event Terminal::edit_line(std::string_view prompt) {
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
