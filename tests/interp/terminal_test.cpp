// The terminal object driven by a script: lines edited key by key in tek mode (igds echoes them on
// its screen), Ctrl-C and the end of input as events, long texts paged, keys typed ahead kept.
#include "interp/terminal.h"

#include <doctest/doctest.h>
#include <unistd.h>

#include <string>
#include <utility>

#include "commands/picture.h"
#include "interp/input.h"
#include "tests/devices/support.h"
#include "tests/support/scripted.h"
#include "tests/support/tek_decoder.h"
#include "tests/support/tek_terminal.h"

namespace igds::test {

namespace {

struct Tek {
  StringOutput out;
  ScriptedSource keys{true, false};
  Terminal terminal{TermMode::tek, {}, out};
  Tek() {
    terminal.use_input(&keys);
    terminal.begin();
  }
  std::vector<std::string> rows() const {
    std::vector<std::string> out;
    for (const auto& r : terminal.screen()->rows()) out.push_back(utf8(r.text));
    return out;
  }
};

}  // namespace

TEST_CASE("tek mode: a line typed key by key, with a key taken back, echoed by igds") {
  Tek t;
  t.keys.type("1 2\b3 4\x7F\x7F 5\r");
  const Event e = t.terminal.read_line("POINTS? ");
  REQUIRE(e.kind == Event::Kind::line);
  CHECK(e.text == "1 3 5");
  CHECK(t.rows() == std::vector<std::string>{"POINTS? 1 3 5"});
  // Ctrl-U takes the whole line back.
  t.keys.type(
      "9 9 9\x15"
      "7\r");
  CHECK(t.terminal.read_line("POINTS? ").text == "7");
  for (const auto& page : decode_tek(t.out.text).pages)
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
}

TEST_CASE("tek mode: the APL prefix key, then a key, types its glyph") {
  Tek t;
  t.keys.type("`rINPPN`k\r");  // `k has no glyph: both keys as typed
  const Event e = t.terminal.read_line("      ");
  CHECK(e.text == "⍴INPPN`k");
  t.keys.type("X`[2`-3``\r");
  CHECK(t.terminal.read_line("      ").text == "X←2×3`");
}

namespace {

// A terminal in tek mode on xterm's Tek window (tests/support/tek_terminal.h).
struct Xterm {
  StringOutput out;
  TekKeys keys;
  Terminal terminal{TermMode::tek, {}, out};
  explicit Xterm(std::string terminator = "\r") : keys(out.text, std::move(terminator)) {
    terminal.use_input(&keys);
    terminal.begin();
  }
  std::vector<std::string> rows() const {
    std::vector<std::string> out;
    for (const auto& r : terminal.screen()->rows()) out.push_back(utf8(r.text));
    return out;
  }
};

std::chrono::steady_clock::time_point fake_now;
std::chrono::steady_clock::time_point now() {
  return fake_now;
}

}  // namespace

TEST_CASE("tek mode: a pick is the cross-hair, read after the mark of the status asked first") {
  for (const std::string terminator : {"", "\r", "\r\x04"}) {
    CAPTURE(terminator.size());
    Xterm t(terminator);
    t.keys.click(500, 300);
    t.keys.type("NOCUR\r");
    const Event e = t.terminal.pick("POINT? ");
    REQUIRE(e.kind == Event::Kind::pick);
    CHECK(e.text == " ");
    CHECK(e.x == 500);
    CHECK(e.y == 300);
    CHECK(e.layout == PickLayout::screen);  // where the person sees the picture
    // The status asked (ESC ENQ) before GIN mode (ESC SUB), the pick echoed after the prompt.
    CHECK(t.out.text.find("\x1B\x05\x1B\x1A") != std::string::npos);
    CHECK(t.rows() == std::vector<std::string>{"POINT? 500 300"});
    CHECK(t.terminal.read_line("      ").text == "NOCUR");
    // The space bar and RETURN pick where the cross-hair is, and so do the keys asked for.
    t.keys.point_at(100, 200);
    t.keys.type(" ");
    const Event space = t.terminal.pick("POINT? ");
    CHECK((space.kind == Event::Kind::pick && space.x == 100 && space.y == 200));
    t.keys.type("6");
    const Event six = t.terminal.pick("", "5678");
    CHECK((six.kind == Event::Kind::pick && six.text == "6"));
    CHECK(t.keys.left() == 0);
  }
}

TEST_CASE("tek mode: a line typed at a cross-hair question is a line, a number a position") {
  Xterm t;
  // The first key is the terminal's report, the others come as keys: one line all the same.
  t.keys.type("HELP\r");
  const Event help = t.terminal.pick("FIRST CORNER? ");
  REQUIRE(help.kind == Event::Kind::line);
  CHECK(help.text == "HELP");
  t.keys.type("512 400\r");
  const Event typed = t.terminal.pick("FIRST CORNER? ");
  REQUIRE(typed.kind == Event::Kind::pick);
  CHECK(typed.x == 512);
  CHECK(typed.y == 400);
  CHECK(typed.layout == PickLayout::screen);  // typed by a person looking at the screen
  CHECK(t.rows() == std::vector<std::string>{"FIRST CORNER? HELP", "FIRST CORNER? 512 400"});
  // Typed while igds was busy, before the cross-hair was up: read as a line, and the next pick
  // is in step.
  t.keys.type("abc\r", true);
  t.keys.click(10, 20);
  const Event early = t.terminal.pick("SECOND CORNER? ");
  REQUIRE(early.kind == Event::Kind::line);
  CHECK(early.text == "abc");
  const Event next = t.terminal.pick("SECOND CORNER? ");
  CHECK((next.kind == Event::Kind::pick && next.x == 10 && next.y == 20));
  // A control key picks nothing: the cross-hair again.
  t.keys.type("\t");
  t.keys.click(30, 40);
  const Event after_tab = t.terminal.pick("SECOND CORNER? ");
  CHECK((after_tab.kind == Event::Kind::pick && after_tab.x == 30));
  CHECK_FALSE(t.keys.terminal().gin());
  for (const auto& page : decode_tek(t.out.text).pages)
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
}

TEST_CASE("tek mode: keys sent with the cross-hair left up are a typed line, GIN mode left") {
  Xterm t;
  // The numeric keypad sends its keys as they are and leaves the cross-hair up: an address typed
  // on it is a position, never read as a report.
  t.keys.plain("512 400\r");
  const Event typed = t.terminal.pick("FIRST CORNER? ");
  REQUIRE(typed.kind == Event::Kind::pick);
  CHECK(typed.x == 512);
  CHECK(typed.y == 400);
  CHECK(typed.layout == PickLayout::screen);  // typed by a person looking at the screen
  CHECK_FALSE(t.keys.terminal().gin());
  // An arrow sends no report: dropped; the click after it picks.
  t.keys.plain("\x1B[A");
  t.keys.click(30, 40);
  const Event arrow = t.terminal.pick("SECOND CORNER? ");
  CHECK((arrow.kind == Event::Kind::pick && arrow.x == 30 && arrow.y == 40));
  // One key, then nothing for a while: the first of a line, edited once GIN mode is left.
  t.keys.plain("7");
  t.keys.type("00 100\r");
  const Event seven = t.terminal.pick("SECOND CORNER? ");
  CHECK((seven.kind == Event::Kind::pick && seven.x == 700 && seven.y == 100));
  CHECK(t.keys.left() == 0);
  CHECK(t.rows() == std::vector<std::string>{"FIRST CORNER? 512 400", "SECOND CORNER? 30 40",
                                             "SECOND CORNER? 700 100"});
  for (const auto& page : decode_tek(t.out.text).pages)
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
}

TEST_CASE("tek mode: Ctrl-C at the cross-hair: GIN mode left, its report dropped, the line ended") {
  Xterm t;
  // Ctrl-C pressed with the cross-hair up: xterm reports it as a key; the tty makes the Ctrl-C a
  // signal and the rest of the report (its address, its CR) keys.
  t.keys.type("\x03");
  t.keys.type("NOCUR\r");
  CHECK(t.terminal.pick("FIRST CORNER? ").kind == Event::Kind::interrupt);
  CHECK_FALSE(t.keys.terminal().gin());
  CHECK(t.terminal.read_line("      ").text == "NOCUR");
  CHECK(t.rows() == std::vector<std::string>{"FIRST CORNER? ", "      NOCUR"});
  // Ctrl-C before the cross-hair was up: the same.
  t.keys.type("\x03", true);
  t.keys.click(1, 2);
  CHECK(t.terminal.pick("FIRST CORNER? ").kind == Event::Kind::interrupt);
  const Event e = t.terminal.pick("FIRST CORNER? ");
  CHECK((e.kind == Event::Kind::pick && e.x == 1 && e.y == 2));
  // The end of the input at a cross-hair question is the end; nothing else is.
  CHECK(t.terminal.pick("FIRST CORNER? ").kind == Event::Kind::end);
}

TEST_CASE("tek mode: a double click picks once") {
  Xterm t;
  t.terminal.set_clock(&now);
  fake_now = {};
  t.keys.click(500, 300);
  t.keys.click(500, 300);  // the second click, found GIN mode on again at once
  t.keys.click(600, 300);
  CHECK(t.terminal.pick("").x == 500);
  CHECK(t.terminal.pick("").x == 600);
  // Clicks further apart in time are two picks.
  t.keys.click(600, 300);
  fake_now += double_click;
  CHECK(t.terminal.pick("").x == 600);
  CHECK(t.keys.left() == 0);
}

TEST_CASE("command files: a pick is a line X Y [KEY], on the page in every terminal mode") {
  for (const TermMode mode : {TermMode::none, TermMode::tek, TermMode::xterm}) {
    CAPTURE(int(mode));
    StringOutput out;
    ScriptedSource lines{false, true};
    Terminal terminal{mode, {}, out};
    terminal.use_input(&lines);
    lines.lines({"500 300 A", "12 34", "500", "2000 1"});
    Event e = terminal.pick("POINT? ");
    CHECK((e.kind == Event::Kind::pick && e.x == 500 && e.y == 300 && e.text == "A"));
    CHECK(e.layout == PickLayout::page);
    e = terminal.pick("POINT? ");
    CHECK((e.kind == Event::Kind::pick && e.x == 12 && e.y == 34 && e.text == " "));
    CHECK(e.layout == PickLayout::page);
    CHECK(terminal.pick("POINT? ").kind == Event::Kind::line);  // not a position
    CHECK(terminal.pick("POINT? ").kind == Event::Kind::line);  // off the screen
    CHECK(terminal.pick("POINT? ").kind == Event::Kind::end);
  }
}

TEST_CASE("a person's X Y typed on lines is on the screen as drawn") {
  for (const TermMode mode : {TermMode::none, TermMode::tek, TermMode::xterm}) {
    CAPTURE(int(mode));
    StringOutput out;
    ScriptedSource lines{false, false};
    Terminal terminal{mode, {}, out};
    terminal.use_input(&lines);
    lines.lines({"500 300"});
    const Event e = terminal.pick("POINT? ");
    CHECK((e.kind == Event::Kind::pick && e.x == 500 && e.y == 300));
    CHECK(e.layout == PickLayout::screen);
  }
}

TEST_CASE("tek mode: Ctrl-C and the end of the input are events of the wait") {
  Tek t;
  t.keys.type("1 2\x03");
  CHECK(t.terminal.read_line("POINTS? ").kind == Event::Kind::interrupt);
  t.keys.type("\x04");
  CHECK(t.terminal.read_line("POINTS? ").kind == Event::Kind::end);
  CHECK(t.terminal.read_line("POINTS? ").kind == Event::Kind::end);  // the script is done
}

TEST_CASE("tek mode: a long text stops at each full page for a person, and keys typed go on") {
  Tek t;
  std::string text;
  for (int i = 1; i <= 50; ++i) text += "LINE " + std::to_string(i) + "\n";
  // 50 lines take a page and a half of 34 rows: RETURN at the MORE of the first page; the next
  // line is typed at once.
  t.keys.type("\rE C\r");
  t.terminal.document(text);
  CHECK(t.keys.left() == 4);
  const Event e = t.terminal.read_line("");
  CHECK(e.text == "E C");
  // The second page starts with the text's next line, not with what was on the first.
  const auto rows = t.rows();
  REQUIRE(!rows.empty());
  CHECK(rows.front() == "LINE 34");
  const auto d = decode_tek(t.out.text);
  bool more = false;
  for (const auto& page : d.pages) {
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
    for (const auto& text_ : page.texts) more = more || text_.text == "MORE: PRESS RETURN";
  }
  CHECK(more);
  // Every line of the text was shown.
  std::string all;
  for (const auto& page : d.pages)
    for (const auto& text_ : page.texts) all += text_.text + "\n";
  for (int i = 1; i <= 50; ++i)
    CHECK(all.find("LINE " + std::to_string(i) + "\n") != std::string::npos);
}

TEST_CASE("command files: the line is echoed after its prompt, nothing waits") {
  StringOutput out;
  ScriptedSource file(false, true);
  Terminal terminal(TermMode::none, {}, out);
  terminal.use_input(&file);
  file.add_line("3 3");
  CHECK(terminal.read_line("NUMBER OF CURVES AND STRINGERS? ", "READY").text == "3 3");
  std::string text;
  for (int i = 0; i < 80; ++i) text += "X\n";
  terminal.document(text);
  CHECK(out.text.starts_with("READY\nNUMBER OF CURVES AND STRINGERS? 3 3\nX\n"));
  CHECK(out.text.find("MORE") == std::string::npos);
}

namespace {

// Output kept in a string, its flushes counted.
struct CountedOutput final : Output {
  std::string text;
  int flushes = 0;
  std::size_t flushed = 0;  // the length of `text` at the last flush
  void write(std::string_view bytes) override { text += bytes; }
  void flush() override { ++flushes, flushed = text.size(); }
};

// A pipe: what is written to `in` is read from `out`.
struct Pipe {
  int out = -1, in = -1;
  Pipe() {
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
    out = fds[0], in = fds[1];
  }
  ~Pipe() {
    if (in >= 0) ::close(in);
  }
  void send(std::string_view text) const {
    REQUIRE(::write(in, text.data(), text.size()) == static_cast<ssize_t>(text.size()));
  }
  void close_input() { ::close(std::exchange(in, -1)); }
};

}  // namespace

TEST_CASE("a pipe's answers read already go out together; a READY and a wait flush first") {
  Pipe pipe;
  FdSource source(pipe.out, true);
  CountedOutput out;
  Terminal terminal(TermMode::none, {}, out);
  terminal.use_input(&source);
  CHECK_FALSE(source.line_ready());
  pipe.send("A\n* a comment\nB\n* another\n");
  // Nothing read yet: the output goes out before the source reads (and might wait).
  CHECK(terminal.read_line("? ", "READY").text == "A");
  CHECK(out.flushes == 1);
  CHECK(out.flushed == std::string("READY\n").size());
  // B is there already: no flush, its echo stays with the rest.
  CHECK(source.line_ready());
  CHECK(terminal.read_line("? ").text == "B");
  CHECK(out.flushes == 1);
  // Only a comment is left: line() would wait, so everything is flushed first.
  CHECK_FALSE(source.line_ready());
  pipe.send("C");
  pipe.close_input();
  CHECK(terminal.read_line("? ").text == "C");
  CHECK(out.flushes == 2);
  CHECK(out.text == "READY\n? A\n? B\n? C\n");
  CHECK(out.flushed == std::string("READY\n? A\n? B\n").size());
  // At the end of the input nothing waits either; but a command's READY always goes out.
  CHECK(source.line_ready());
  CHECK(terminal.read_line("? ").kind == Event::Kind::end);
  CHECK(out.flushes == 2);
  CHECK(terminal.read_line("", "READY").kind == Event::Kind::end);
  CHECK(out.flushes == 3);
  CHECK(out.flushed == out.text.size());
  CHECK(out.text.ends_with("READY\n"));
}

}  // namespace igds::test

namespace igds::test {

namespace {

// A tek terminal with DISPLAY SURFACE's picture up.
struct WithPicture : Tek {
  WithPicture() {
    terminal.show(std::make_shared<const Picture>(picture_of(devices::surface_image(6, 7))), "");
  }
  std::string text_of(const TekPage& page) const {
    std::string all;
    for (const auto& t : page.texts) all += t.text + "\n";
    return all;
  }
};

}  // namespace

TEST_CASE("tek mode: long output below a picture stops at MORE before lines go unread") {
  WithPicture t;
  REQUIRE(t.terminal.screen()->rows_per_page() == 8);
  // Twelve rows of a result: the first page's rows are read at MORE before the page turns.
  t.keys.type("\r");
  for (int i = 1; i <= 12; ++i) t.terminal.print("ROW " + std::to_string(i));
  CHECK(t.keys.left() == 0);  // RETURN was asked for once
  const auto d = decode_tek(t.out.text);
  std::size_t more_page = d.pages.size();
  for (std::size_t p = 0; p < d.pages.size(); ++p)
    if (t.text_of(d.pages[p]).find("MORE: PRESS RETURN") != std::string::npos) more_page = p;
  REQUIRE(more_page < d.pages.size());
  // The page with MORE shows rows 1 to 7 and the picture; every row was on some page.
  const std::string before = t.text_of(d.pages[more_page]);
  for (int i = 1; i <= 7; ++i)
    CHECK(before.find("ROW " + std::to_string(i) + "\n") != std::string::npos);
  CHECK(!d.pages[more_page].segments.empty());
  CHECK(t.text_of(d.pages.back()).find("ROW 12") != std::string::npos);
  CHECK(!d.pages.back().segments.empty());
  // A command file never waits.
  StringOutput out;
  ScriptedSource file(false, true);
  Terminal batch(TermMode::tek, {}, out);
  batch.use_input(&file);
  batch.show(std::make_shared<const Picture>(picture_of(devices::surface_image(6, 7))), "");
  for (int i = 1; i <= 30; ++i) batch.say("ROW " + std::to_string(i));
  CHECK(out.text.find("MORE") == std::string::npos);
}

TEST_CASE("tek mode: a line set out in columns is cut at the width, never broken at a blank") {
  Tek t;
  std::string row;
  for (int i = 0; i < 12; ++i) row += " 1.2345678";  // 120 characters, a column every 10
  t.terminal.print(row);
  t.terminal.print(row);
  const auto rows = t.rows();
  REQUIRE(rows.size() == 4);
  CHECK(rows[0].size() == 73);
  CHECK(rows[0] == rows[2]);  // each row cut at the same place: the columns stay in line
  CHECK(rows[1] == rows[3]);
  // The same line said as prose is wrapped at blanks.
  Tek prose;
  prose.terminal.say(row);
  CHECK(prose.rows().front().size() < 73);
}

TEST_CASE("tek mode: HELP SHORT below the picture keeps it; a long text gets a page of its own") {
  WithPicture t;
  const int pages = t.terminal.screen()->pages();
  t.terminal.document(
      "A border point k and tx ty tz, and at a corner 1 (along the curve) or 0 "
      "(along the stringer); AUTO: all from the points; an empty line ends.");
  CHECK(t.terminal.screen()->pages() == pages);  // no page: the picture stays
  CHECK(t.terminal.screen()->shows_picture());
  std::string long_text;
  for (int i = 0; i < 10; ++i) long_text += "LINE " + std::to_string(i) + "\n";
  t.keys.type("\r");
  t.terminal.document(long_text);
  CHECK(t.out.text.find("PRESS RETURN TO GO BACK TO THE PICTURE") != std::string::npos);
  CHECK(t.terminal.screen()->shows_picture());
}

TEST_CASE("tek mode: Ctrl-C at a pause is the next wait's interrupt") {
  Tek t;
  std::string text;
  for (int i = 1; i <= 50; ++i) text += "LINE " + std::to_string(i) + "\n";
  t.keys.type("\x03");
  t.keys.type("N\r");
  t.terminal.document(text);
  // The rest of the text is not shown; the next question gives the interrupt, then goes on.
  CHECK(t.out.text.find("LINE 50") == std::string::npos);
  CHECK(t.terminal.read_line("? ").kind == Event::Kind::interrupt);
  CHECK(t.terminal.read_line("? ").text == "N");
}

}  // namespace igds::test
