// What a command sees of the session: the workspace, the dialogue with the user, the disk and
// the devices. The interpreter implements it; commands never touch the terminal themselves.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devices/device.h"
#include "devices/hpgl_plot.h"
#include "devices/layout.h"
#include "devices/tek_stream.h"
#include "workspace/disk/disk.h"
#include "workspace/journal.h"
#include "workspace/kernels/interrupt.h"
#include "workspace/state.h"

namespace igds {

// The command-line options of igds (docs/interp.md, "Command line"), resolved at start.
struct Options {
  std::filesystem::path disk = ".";
  TermMode term = TermMode::none;
  TekOptions tek;
  std::string plotter;  // "": a new PLOTnnnn.HPGL on the disk per plot; "tty"; else a path
  // How long PLOT waits for a plotter (a device, a FIFO) that takes no bytes before it says the
  // plotter does not answer.
  std::chrono::milliseconds plotter_patience{30000};
  PlotOptions plot;
  bool strict = false;
};

// One word of the language and what it stands for: a command's option, a projection, a plane,
// an answer. `code` is the value the code receives (an enum of the declaring file), never the
// word's place in its list.
struct Choice {
  std::string_view word;
  int code = 0;
  std::string_view follows = {};  // what may follow it on the line, e.g. "[name]"
  std::string_view help = {};     // one line: what it stands for
};

// The first choice whose word starts with `typed`, case ignored (docs/interp.md, "The dialogue":
// the first entry in table order wins); nullptr when none does or `typed` is empty.
const Choice* choose(std::span<const Choice> choices, std::string_view typed);

// What the user is asked for: the prompt's words, the HELP SHORT text at that prompt (one or two
// lines), and the words that may answer it (offered by completion). HELP LONG at any prompt
// explains the command being run.
struct Prompt {
  std::string_view text;
  std::string_view short_help;
  std::span<const Choice> answers = {};
};

// Ctrl-C (workspace/kernels/interrupt.h: Interrupted, thrown by the questions and by long work
// alike) abandons the command: the state is as before it.
// End of input (Ctrl-D, end of a command file) in the middle of a command: the command abandoned
// as by Ctrl-C, then END.
struct EndOfInput {};

// The last reply as Context::ask_words gives it: views of the words that were waiting, or of a
// line typed, kept until the next reply.
class Reply {
 public:
  std::span<const std::string_view> of(std::vector<std::string> words) {
    words_ = std::move(words);
    views_.assign(words_.begin(), words_.end());
    return views_;
  }
  // `split(line, views)` puts the views of the line's words into `views`.
  template <class Split>
  std::span<const std::string_view> of(std::string line, Split split) {
    line_ = std::move(line);
    split(line_, views_);
    return views_;
  }

 private:
  std::string line_;
  std::vector<std::string> words_;
  std::vector<std::string_view> views_;
};

class Context {
 public:
  virtual ~Context() = default;

  virtual Workspace& workspace() = 0;
  virtual const Options& options() const = 0;
  virtual const Disk& disk() const = 0;
  // The states of the workspace after each command that changed it (UNDO, REDO).
  virtual Journal& journal() = 0;

  // The words of the next reply: the words still unread on the command line, if any (all of
  // them), else the words of a line read after showing `prompt`. HELP, HELP SHORT and HELP LONG
  // typed there are answered and the prompt is shown again. An empty line gives no words.
  // Throws Interrupted on Ctrl-C and EndOfInput at the end of input.
  std::vector<std::string> ask(const Prompt& prompt) {
    const std::span<const std::string_view> words = ask_words(prompt);
    return {words.begin(), words.end()};
  }
  // The same words as views, valid until the next question: an entry of a thousand points is
  // read where it was typed, no word of it copied.
  virtual std::span<const std::string_view> ask_words(const Prompt& prompt) = 0;
  // Puts words of the last reply back in front, so that the next ask() returns them without
  // prompting.
  virtual void unread(std::vector<std::string> words) = 0;
  // True while words are waiting to be read (from the command line or put back).
  virtual bool has_pending() const = 0;
  // True while the words waiting came from the command line itself (not from a reply typed at a
  // question): a bad one there ends the command, at a question it is asked again.
  virtual bool pending_from_command_line() const = 0;

  // A line for the user (information such as RESTORE's NOCUR NOSTR INTCU INTST).
  virtual void say(std::string_view line) = 0;
  // A long text (HELP LONG, a listing), line by line: shown whole, paged where the screen is
  // smaller than the text.
  virtual void document(std::string_view text) = 0;
  // An error report that does not end the command (INCORRECT ENTRY): printed like say(), and
  // counted as an error for --strict.
  virtual void report(std::string_view text) = 0;

  // Draws an image on the terminal as the terminal mode says.
  virtual void show(const ImageRef& image) = 0;
  // A position picked after `prompt`, in 4013 addresses (0..1023, 0..779), and the layout it is
  // in: the cross-hair of a Tek terminal (GIN mode) or a line `X Y` typed, on the screen as
  // drawn; a line `X Y` of a command file, on the page (PickLayout, devices/layout.h). nullopt
  // when the reply is not a pick. Throws Interrupted on Ctrl-C, EndOfInput at the end.
  virtual std::optional<PickedAddress> pick(const Prompt& prompt) = 0;
  // ERASE: a clean screen (a page), where there is a screen to erase.
  virtual void erase() = 0;
  // The plotter on the terminal line (--plotter tty): bytes already wrapped in ESC.( ... ESC.).
  virtual void send_to_terminal(std::string_view bytes) = 0;

  // END CMS (apl = false) or END APL (apl = true): the interpreter saves the session and leaves
  // or enters the APL environment once the command returns.
  virtual void end_session(bool apl) = 0;
};

}  // namespace igds
