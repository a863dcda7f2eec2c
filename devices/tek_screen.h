// The Tektronix screen as igds manages it (docs/devices.md, "The Tek screen"): the picture in
// its square, the captions of the DISPLAYs in the column beside it, and the dialogue where
// neither is, wrapped at word boundaries. Nothing is ever written over anything else on one
// page: when the dialogue reaches the bottom, a new page is started and what belongs on it (the
// current picture, its caption, the last lines of dialogue) is drawn again. A storage tube
// could not do that; xterm's Tek window redraws a page at no cost.
//
// The screen is a model: every call returns the bytes that make the terminal show the change,
// and the model can be read back (tests, picks). It does no input or output itself.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "devices/layout.h"
#include "devices/tek4013.h"
#include "devices/tek_stream.h"
#include "workspace/drawing/drawing.h"

namespace igds {

class TekScreen {
 public:
  // `dialogue`: the dialogue is on this screen too (tek mode); false for the Tek window of
  // --term xterm, which shows pictures only.
  TekScreen(TekOptions tek, bool dialogue);

  // The start of a session: the alpha cursor to the first line, nothing erased.
  std::string begin();

  // Dialogue text, UTF-8; '\n' ends a line. Lines are wrapped at blanks (a word longer than a
  // line is cut), or, `set_out` in columns by whoever wrote them (an APL result), cut at the
  // width; a new page is started when the page is full.
  std::string text(std::string_view text, bool set_out = false);
  // One character typed on the line being edited (igds echoes what is typed in tek mode), and
  // taking the last one back. A character that moves a word to the next line, and any erasing,
  // redraw the page.
  std::string type(std::string_view character);
  std::string untype();
  // The characters typed on the current line since the last text() or end of line.
  const std::u32string& typed() const { return typed_; }

  // DISPLAY: the picture drawn over what the square shows, its caption below the captions
  // already in the column; a new page when the dialogue is in the way or the column is full.
  std::string picture(std::shared_ptr<const Picture> picture);
  // ERASE: a clean page; the current picture no longer belongs on the screen.
  std::string erase();
  // A page of its own for a long text (HELP LONG, a listing) over the full screen, and back to
  // the page as it was afterwards.
  // `always`: a page of its own even without a picture (the 2250's help environment, which
  // gives back the page as it was when it ends).
  std::string document_page(bool always = false);
  std::string end_document();
  bool in_document() const { return in_document_; }

  // A drawing on every page before anything else (the 2250's menu) and the layout that keeps the
  // picture, the captions and the dialogue clear of it. Takes effect at the next page.
  void set_frame(std::shared_ptr<const Drawing2> frame, const TekLayout& layout);

  // The current picture replaced by `picture` on a page of its own, the dialogue kept (the
  // 2250's function keys): the page's bytes in three parts, so that the picture's may be sent
  // at a pace of its own.
  struct Parts {
    std::string before, picture, after;
  };
  Parts replace_picture(std::shared_ptr<const Picture> picture);

  // The same page once more (after a terminal was cleared by something else).
  std::string repaint();
  // A new page without the dialogue (the picture stays when it is shown): the next page of a
  // long text.
  std::string clear();

  // The alpha cursor put where the dialogue goes on (`aside` points to its right: a place it
  // was not put before) and the terminal asked for its status (ESC ENQ), whose answer carries
  // that place: `at`, in 4013 points. The answer marks where the keys typed before it end
  // (devices/gin.h, GinReader).
  std::string enquire(DevicePoint& at, int aside = 0);
  // Where the next character of the dialogue goes, in 4013 points.
  DevicePoint next_character() const;

  // Characters of a row of dialogue (of a document's page when one is up).
  int columns() const { return flow().columns; }
  // Rows `line` takes in the dialogue (`set_out` as text() has it).
  int rows_of(std::string_view line, bool set_out = false) const;
  // Rows of dialogue still free on the page, and on a new page.
  int rows_left() const;
  int rows_per_page() const;
  bool shows_picture() const { return picture_ != nullptr; }
  int bits() const { return options_.bits; }

  // What the page shows: each row of text with the baseline-left point of its first character,
  // in 4013 points.
  struct Row {
    int x = 0, y = 0;
    std::u32string text;
  };
  std::vector<Row> rows() const;
  int pages() const { return pages_; }  // pages started (ESC FF) so far

 private:
  struct Flow {
    int x = 0, top = 0, columns = 0, rows = 0;
  };
  Flow flow() const;
  // A line of the dialogue, and whether it is set out in columns (text()).
  struct Line : std::u32string {
    bool set_out = false;
  };
  // `line` wrapped into rows of `columns` characters at blanks, or cut when it is `set_out`.
  static std::vector<std::u32string> wrap(const std::u32string& line, int columns,
                                          bool set_out = false);
  int rows_of_lines() const;
  // Sends the characters of `text` at row `row`, column `column` of the flow.
  void emit(int row, int column, std::u32string_view text);
  // The characters of `text` from (x, y), in 4013 points.
  void draw_text(int x, int y, std::u32string_view text);
  // A caption line at baseline `y` of the caption column.
  void draw_caption(int y, const std::string& line);
  // The page again: the picture and captions that belong on it, then the dialogue lines.
  void new_page();
  // A new page keeping of the dialogue the line being written, whole, and before it the last
  // lines that fit in `carry` rows, with `reserve` rows free after them.
  void turn_page(int reserve, int carry);
  // Room for `more` rows after the last line: a new page if there is not.
  void make_room(int more);
  // Appends to the open line and shows the change, redrawing when rows already shown change.
  void append(std::u32string_view text);
  void draw_picture_and_captions();
  void draw_frame();
  void draw_dialogue();
  // The alpha cursor to (x, y) in 4013 points, unless it is there already.
  void move_cursor(int x, int y);
  std::string take() { return tek_.take(); }
  DevicePoint at(int x, int y) const { return {unit_ * x, unit_ * y}; }

  TekOptions options_;
  int unit_;
  bool dialogue_;
  TekEncoder tek_;
  TekLayout layout_;
  std::shared_ptr<const Picture> picture_;  // the current picture, while it is on the screen
  std::vector<std::string> captions_;       // the caption column of this page, line by line
  std::vector<Line> lines_;                 // the dialogue of this page, line by line
  bool setting_out_ = false;                // the text being written is set out in columns
  bool open_ = false;                       // the last line is still being written
  std::u32string typed_;
  bool in_document_ = false;
  std::vector<Line> saved_lines_;  // the dialogue before a document
  bool saved_open_ = false;
  int pages_ = 0;
  std::shared_ptr<const Drawing2> frame_;  // drawn first on every page (the 2250's menu)
  std::optional<DevicePoint> cursor_;      // where the alpha cursor is, in 4013 points, when known
};

// Text written as paragraphs, one a line (never broken by hand at some width), laid out in rows
// of at most `columns` characters (docs/devices.md, "Text on the screen"): each paragraph broken
// at blanks, its later rows indented to its hang: after a list's number ("1. "); for an indented
// term and its explanation (two blanks or more apart), the explanation's column, or four more
// than the term when that leaves less than half the row; else its own indent. A word longer than
// a row is cut. UTF-8.
std::vector<std::string> lay_out(std::string_view paragraphs, int columns);

// UTF-8 to code points and back (a malformed byte is U+FFFD).
std::u32string utf32(std::string_view utf8);
std::string utf8(std::u32string_view text);

}  // namespace igds
