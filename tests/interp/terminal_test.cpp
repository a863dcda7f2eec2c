// The terminal object driven by a script: lines edited key by key in tek mode (igds echoes them on
// its screen), Ctrl-C and the end of input as events, long texts paged, keys typed ahead kept.
#include "interp/terminal.h"

#include <doctest/doctest.h>

#include "tests/support/scripted.h"
#include "tests/support/tek_decoder.h"

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

TEST_CASE("tek mode: a pick is GIN mode, the crosshair's report decoded") {
  Tek t;
  // Key A at x 500 (15, 20 in 5-bit halves) and y 300 (9, 12), then xterm's CR; then a line.
  t.keys.type("A/4),\rNOCUR\r");
  const Event e = t.terminal.pick("POINT? ");
  REQUIRE(e.kind == Event::Kind::pick);
  CHECK(e.text == "A");
  CHECK(e.x == 500);
  CHECK(e.y == 300);
  CHECK(t.out.text.find("\x1B\x1A") != std::string::npos);
  CHECK(t.terminal.read_line("      ").text == "NOCUR");
  // No terminator at all: the next key is kept for the next line.
  t.keys.type("  ! !X\r");
  const Event corner = t.terminal.pick("POINT? ");
  CHECK(corner.x == 1);
  CHECK(corner.y == 1);
  CHECK(t.terminal.read_line("      ").text == "X");
  // Ctrl-C instead of a pick.
  t.keys.type("\x03");
  CHECK(t.terminal.pick("POINT? ").kind == Event::Kind::interrupt);
}

TEST_CASE("command files: a pick is a line X Y [KEY]") {
  StringOutput out;
  ScriptedSource lines{false, true};
  Terminal terminal{TermMode::none, {}, out};
  terminal.use_input(&lines);
  lines.lines({"500 300 A", "12 34", "500", "2000 1"});
  Event e = terminal.pick("POINT? ");
  CHECK((e.kind == Event::Kind::pick && e.x == 500 && e.y == 300 && e.text == "A"));
  e = terminal.pick("POINT? ");
  CHECK((e.kind == Event::Kind::pick && e.x == 12 && e.y == 34 && e.text == " "));
  CHECK(terminal.pick("POINT? ").kind == Event::Kind::line);  // not a position
  CHECK(terminal.pick("POINT? ").kind == Event::Kind::line);  // off the screen
  CHECK(terminal.pick("POINT? ").kind == Event::Kind::end);
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

}  // namespace igds::test
