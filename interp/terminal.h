// The terminal: one object, made at start and handed to whoever needs it, through which
// everything igds shows and reads goes. It delivers events (a typed line, a key, an interrupt,
// the end of the input, a timeout) from the input in use, and owns the screen: in the tek and
// xterm modes a TekScreen (devices/tek_screen.h) that knows what is drawn where; in tek mode on a
// terminal igds reads keys and echoes them itself, so that it always knows where the next
// character goes.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "devices/gin.h"
#include "devices/layout.h"
#include "devices/tek_screen.h"
#include "devices/tek_stream.h"

namespace igds {

struct Event {
  enum class Kind { line, key, pick, interrupt, end, timeout };
  Kind kind = Kind::end;
  // line: the line, without its end; key: the key's bytes (one character); pick: the key that
  // made it.
  std::string text;
  int x = 0, y = 0;                        // pick: the position in 4013 addresses (0..1023, 0..779)
  PickLayout layout = PickLayout::screen;  // pick: the layout x y are in (devices/layout.h)
};

// Where input comes from: a command file or a pipe, the keyboard (lines through GNU Readline or
// keys one by one), or a script in the tests.
class EventSource {
 public:
  virtual ~EventSource() = default;
  // The next line. Sources that show what is typed themselves (Readline) show `prompt` first;
  // the others leave the prompt to the terminal.
  virtual Event line(std::string_view prompt) = 0;
  // The next key, waiting at most `timeout` (forever when not given); only for sources that give
  // keys.
  virtual Event key(std::optional<std::chrono::milliseconds> timeout) = 0;
  // Bytes as the terminal sent them (a cross-hair's report is no UTF-8): those read already and
  // not given yet, else the next ones, waiting at most `timeout`. Only for sources that give
  // keys.
  virtual Event bytes(std::optional<std::chrono::milliseconds> timeout) { return key(timeout); }
  // Bytes read that belong to what follows: given again, first, as keys.
  virtual void unread(std::string bytes) { (void)bytes; }
  // Keys one by one (a terminal in tek mode): the terminal edits and echoes the line itself.
  virtual bool gives_keys() const { return false; }
  // It shows what is typed and its prompts (Readline, a terminal's own echo).
  virtual bool echoes() const { return false; }
  // A command file or a pipe: lines are echoed after their prompt so that the output reads like
  // the session, --strict applies, and nothing waits for a person.
  virtual bool command_file() const = 0;
  // The next line is read already: line() returns it without waiting for input.
  virtual bool line_ready() const { return false; }
};

// Where output goes: the standard output, or a string in the tests.
class Output {
 public:
  virtual ~Output() = default;
  virtual void write(std::string_view bytes) = 0;
  // Everything written so far reaches the terminal (before igds waits for input).
  virtual void flush() {}
  // True once a write failed (a closed pipe, a full device): nobody reads igds any more.
  virtual bool failed() const { return false; }
};

class Terminal {
 public:
  Terminal(TermMode mode, TekOptions tek, Output& out);

  TermMode mode() const { return mode_; }
  bool output_failed() const { return out_.failed(); }
  // The input in use: the command files one after the other, then the keyboard.
  void use_input(EventSource* input) { input_ = input; }
  EventSource* input() const { return input_; }
  bool command_file() const { return input_ && input_->command_file(); }

  // The start of the session (tek mode: the alpha cursor to the first line).
  void begin();
  // A line of dialogue. In tek mode, when it would turn the page while lines the person has not
  // read are on it (a long APL result below the picture), it waits at MORE first.
  void say(std::string_view line);
  // A line set out in columns by whoever made it (an APL result, a caret under its error): on
  // the Tek screen cut at the width when it is longer, never broken at a blank.
  void print(std::string_view line);
  // The characters of a row of text: the Tek screen's (where a document goes), else the
  // terminal's width (set_columns).
  int columns() const;
  void set_columns(int columns) { columns_ = columns; }
  // A text written as paragraphs (HELP, listings), laid out at the screen's width (lay_out,
  // devices/tek_screen.h). In tek mode, with a picture on the screen, a text of a few rows goes
  // below it, a longer one on a page of its own; when it is longer than the screen and a person
  // reads it, it stops at each full page (MORE) and, the picture waiting, at its end until
  // RETURN.
  void document(std::string_view text);
  // DISPLAY: the picture on the screen, or (none mode, where `picture` may be null) `line`
  // saying what it shows.
  void show(std::shared_ptr<const Picture> picture, std::string_view line);
  // ERASE.
  void erase();
  // Bytes for the terminal as they are (a plotter on the terminal line).
  void raw(std::string_view bytes);

  // The next line after `prompt`; `above` is a line written before the prompt (READY), which
  // Readline shows as the first line of its prompt. Ends with Event::line, interrupt or end.
  Event read_line(std::string_view prompt, std::string_view above = {});

  // A position picked on the screen (Event::pick: the position in 4013 addresses and the key
  // that made it, a blank for a mouse button), after `prompt`. On a Tek terminal typing keys:
  // GIN mode, the cross-hair, read in step whatever comes (devices/gin.h, GinReader). A mouse
  // button, the space bar, RETURN or one of `pick_keys` picks; any other printable key begins a
  // typed line, edited and echoed as at any question (keys typed before the cross-hair was up
  // do too); the second click of a double click is dropped. From a command file or a line
  // source, a line. A line `X Y [KEY]` is a pick there too; any other line comes back as
  // Event::line, an interrupt or the end of the input as themselves. A pick after a prompt is
  // echoed after it as `X Y`. A command file's pick is on the page (PickLayout::page), any
  // other on the screen as drawn.
  Event pick(std::string_view prompt, std::string_view pick_keys = {});

  // What the time is (the tests set their own).
  using Clock = std::chrono::steady_clock;
  void set_clock(Clock::time_point (*now)()) { now_ = now; }

  // The 2250 workspace (tek mode): `menu` drawn on every page and `layout` keeping the picture,
  // its caption and the dialogue clear of it, from the next page on.
  void frame(std::shared_ptr<const Drawing2> menu, const TekLayout& layout);
  // The help environment's page: `text` on a page of its own (paged as document() pages), which
  // stays until help_done() gives back the page as it was before help().
  void help(std::string_view text);
  void help_done();
  // The current picture replaced by `picture`, the dialogue kept (the 2250's function keys).
  // `frames` > 1: the picture's bytes go in that many parts, `pause` apart, and all that is
  // left at once as soon as a key is pressed (the key is dropped).
  void replace_picture(std::shared_ptr<const Picture> picture, int frames,
                       std::chrono::milliseconds pause);

  // The screen of the tek and xterm modes (nullptr in none mode).
  const TekScreen* screen() const { return screen_.get(); }

 private:
  void write_dialogue(std::string_view text);
  // A line of dialogue in tek mode, after MORE when it is due; false when the input ended or
  // Ctrl-C came at MORE.
  bool write_row(std::string_view line, bool set_out);
  // The lines of `text`, stopping at each full page for a person (MORE); false when the input
  // ended at a stop.
  bool write_pages(std::string_view text);
  Event edit_line(std::string_view prompt);
  bool wait_for_return();
  // The cross-hair of a Tek terminal typing keys (pick()).
  Event cross_hair(std::string_view prompt, std::string_view pick_keys);
  // GIN mode left and the terminal's answers until a new mark read and dropped (a report sent
  // meanwhile among them, and the answer to the status `asked` at the cross-hair's place); the
  // keys typed meanwhile kept. Event::Kind::key, or the end of the input, or an interrupt that
  // came meanwhile.
  Event::Kind leave_gin(std::string_view asked = {});
  // A line typed at a cross-hair question: `X Y [KEY]` a pick in `layout`, else the line.
  static Event typed_pick(Event e, PickLayout layout);

  TermMode mode_;
  Output& out_;
  std::unique_ptr<TekScreen> screen_;
  EventSource* input_ = nullptr;
  bool told_how_to_see_ = false;
  std::vector<std::string> typed_ahead_;  // keys typed at a pause, for the next line
  Clock::time_point (*now_)() = &Clock::now;
  int columns_ = 80;                     // none and xterm modes: the terminal's width
  int unseen_ = 0;                       // tek mode: rows written since the person last typed
  std::optional<Event::Kind> held_;      // Ctrl-C or the end met at a pause, for the next wait
  std::optional<GinReport> last_click_;  // the last pick by a mouse button, and when it came
  Clock::time_point last_click_at_{};
};

}  // namespace igds
