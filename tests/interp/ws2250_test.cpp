// The 2250 workspace's conversation (interp/ws2250.h): a command chosen by a pick is the typed
// line, word for word; the workspace driven by the cross-hair's reports through the terminal;
// what the function keys show of a surface.
#include "interp/ws2250.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/process.h"
#include "tests/support/scripted.h"
#include "tests/support/tek_decoder.h"
#include "tests/support/tek_terminal.h"

namespace igds {
extern const Command build_command, display_command, store_command, end_command;
}

namespace igds::test {

namespace {

// One igds on a scratch disk, its terminal on a string.
struct Igds {
  TempDir dir;
  Disk disk{dir.path()};
  Session session{disk};
  StringOutput out;
  ScriptedSource input;
  Terminal terminal;
  Interpreter interpreter;
  Igds(TermMode mode, bool keys)
      : input(keys, !keys),
        terminal(mode, {}, out),
        interpreter(Options{}, disk, session, session.load(), terminal) {
    terminal.use_input(&input);
    terminal.begin();
  }
};

const Choice* option(const Command& command, std::string_view word) {
  return choose(command.options, word);
}

const std::vector<std::string> build_entries{"2 3", "1  0 0 0  0 10 0  0 20 0  10 0 0  10 10 5", "",
                                             "", "1 1"};

}  // namespace

TEST_CASE("a command chosen with its option is the typed line: questions, HELP, reports") {
  Igds typed(TermMode::none, false), chosen(TermMode::none, false);
  // Typed: the words of the command and option, then the same answers.
  std::vector<std::string> lines{"BUILD"};
  lines.insert(lines.end(), build_entries.begin(), build_entries.end());
  lines.insert(lines.end(), {"D SU", "HELP SHORT", "O XY", "D FI", "ST F", "E C"});
  typed.input.lines(lines);
  CHECK(typed.interpreter.converse() == Interpreter::Outcome::ended);

  // Chosen: the answers only.
  std::vector<std::string> answers = build_entries;
  answers.insert(answers.end(), {"HELP SHORT", "O XY"});
  chosen.input.lines(answers);
  CHECK_FALSE(chosen.interpreter.run_chosen(build_command, nullptr));
  CHECK_FALSE(chosen.interpreter.run_chosen(display_command, option(display_command, "SURFACE")));
  CHECK_FALSE(chosen.interpreter.run_chosen(display_command, option(display_command, "FIRST")));
  CHECK_FALSE(chosen.interpreter.run_chosen(store_command, option(store_command, "FIRST")));
  CHECK(chosen.interpreter.run_chosen(end_command, option(end_command, "CMS")) ==
        Interpreter::Outcome::ended);

  // The same dialogue but for READY and the command lines themselves.
  std::string expected;
  std::istringstream in(typed.out.text);
  for (std::string line; std::getline(in, line);) {
    const bool command_line = line == "READY" || line == "BUILD" || line == "D SU" ||
                              line == "D FI" || line == "ST F" || line == "E C";
    if (!command_line) expected += line + "\n";
  }
  CHECK(chosen.out.text == expected);
  CHECK(chosen.out.text.find("IMAGE NOT FOUND") != std::string::npos);
  CHECK(chosen.interpreter.error_count() == typed.interpreter.error_count());
  CHECK(chosen.interpreter.workspace().intpn.ravel == typed.interpreter.workspace().intpn.ravel);
  REQUIRE(chosen.interpreter.workspace().temp1);
  CHECK(chosen.interpreter.workspace().temp1->points.ravel ==
        typed.interpreter.workspace().temp1->points.ravel);
  // Saved after every command.
  CHECK(chosen.interpreter.saved());
}

TEST_CASE("a command chosen without its option asks for it, as the typed word alone does") {
  Igds chosen(TermMode::none, false);
  chosen.input.lines({"CMS"});
  CHECK(chosen.interpreter.run_chosen(end_command, nullptr) == Interpreter::Outcome::ended);
  CHECK(chosen.out.text.find("APL OR CMS?") != std::string::npos);
}

namespace {

// One igds on a scratch disk in xterm's Tek window (tests/support/tek_terminal.h).
struct Igds2250 {
  TempDir dir;
  Disk disk{dir.path()};
  Session session{disk};
  StringOutput out;
  TekKeys input{out.text};
  Terminal terminal{TermMode::tek, {}, out};
  Interpreter interpreter{Options{}, disk, session, session.load(), terminal};
  const std::vector<MenuItem> items = menu_items(false, menu_screen::label_columns);
  const MenuLayout layout = menu_layout(items.size());
  Igds2250() {
    terminal.use_input(&input);
    terminal.begin();
  }
  void click(std::string_view label) {
    const auto it = std::find_if(items.begin(), items.end(),
                                 [&](const MenuItem& i) { return i.label == label; });
    REQUIRE(it != items.end());
    const Box& b = layout.items[static_cast<std::size_t>(it - items.begin())];
    input.click(int((b.x0 + b.x1) / 2), int((b.y0 + b.y1) / 2));
  }
};

}  // namespace

TEST_CASE("the 2250 workspace driven by the cross-hair: help, RETURN, a miss, BUILD, END CMS") {
  Igds2250 t;
  t.click("ERASE");       // in the help environment: its explanation
  t.click("HELP");        // RETURN
  t.input.click(10, 10);  // no item there: ignored
  t.input.point_at(10, 10);
  t.input.type("6");  // no surface shown: a typed line, not a function key
  t.input.type("\r");
  t.click("BUILD");
  for (const auto& line : build_entries) t.input.type(line + "\r");
  t.input.type("LIST SURFACE\r");  // a command typed at the menu
  t.click("END CMS");
  CHECK(Workspace2250(t.interpreter, t.terminal).run() == Interpreter::Outcome::ended);
  const std::string& shown = t.out.text;
  CHECK(shown.find("IGDS WITH A 2250") != std::string::npos);
  CHECK(shown.find("ERASE clears the Tektronix screen") != std::string::npos);
  CHECK(shown.find("NUMBER OF CURVES AND STRINGERS?") != std::string::npos);
  CHECK(shown.find("INCORRECT COMMAND") != std::string::npos);  // the line 6
  CHECK(shown.find("NOCUR 2  NOSTR 3") != std::string::npos);   // LIST SURFACE
  CHECK(t.interpreter.workspace().nocur == 2);
  CHECK(t.interpreter.workspace().nostr == 3);
  CHECK(t.input.left() == 0);
  // A pick is echoed as the command it chose; READY once after each command.
  const auto d = decode_tek(shown);
  std::string all;
  for (const auto& page : d.pages)
    for (const auto& text : page.texts) all += text.text + "\n";
  CHECK(all.find("BUILD\nNUMBER OF CURVES AND STRINGERS?") != std::string::npos);
  CHECK(all.find("READY\nREADY") == std::string::npos);
}

TEST_CASE("the function keys' pictures of a surface: all, stringers, curves, points") {
  Igds t(TermMode::none, false);
  t.input.lines(build_entries);
  t.input.lines({"O XY"});
  CHECK_FALSE(t.interpreter.run_chosen(build_command, nullptr));
  CHECK_FALSE(t.interpreter.run_chosen(display_command, option(display_command, "SURFACE")));
  const ImageRef& image = t.interpreter.workspace().image;
  REQUIRE(image);
  // 3 curves of 5 points, 5 stringers of 3.
  const Picture all = surface_view(image, SurfaceKey::standard);
  const Picture stringers = surface_view(image, SurfaceKey::stringers);
  const Picture curves = surface_view(image, SurfaceKey::curves);
  const Picture points = surface_view(image, SurfaceKey::points);
  CHECK(segment_count(all) == 3 * 4 + 5 * 2);
  CHECK(segment_count(stringers) == 5 * 2);
  CHECK(segment_count(curves) == 3 * 4);
  CHECK(segment_count(points) == 0);
  CHECK(points.drawing.size() == 15);
  for (std::size_t j = 0; j < stringers.drawing.size(); ++j)
    CHECK(stringers.drawing.items()[j].id == Identity{Role::stringer, int(j) + 1});
  CHECK(stringers.caption == all.caption);
}

}  // namespace igds::test

namespace igds::test {

TEST_CASE("an animated display: the same bytes as at once, a key pressed ends the pace") {
  auto image = std::make_shared<const Image>([] {
    Image im;
    im.desim = {1, Projection::orthogonal, {1, 0, 0}};
    im.points = Array({3, 4, 2});
    for (std::size_t i = 0; i < im.points.ravel.size(); ++i)
      im.points.ravel[i] = static_cast<double>(i % 7) + static_cast<double>(i / 8);
    return im;
  }());
  auto picture = std::make_shared<const Picture>(surface_view(image, SurfaceKey::stringers));
  std::string at_once, paced;
  for (const int frames : {1, 6}) {
    Igds t(TermMode::tek, true);
    t.input.type("x");  // pressed during the first pause
    t.terminal.replace_picture(picture, frames, std::chrono::milliseconds(1));
    CHECK(t.input.left() == (frames == 1 ? 1u : 0u));  // the key is taken (and dropped) by the pace
    (frames == 1 ? at_once : paced) = t.out.text;
  }
  CHECK(paced == at_once);
  const TekDrawing d = decode_tek(paced);
  CHECK(d.errors.empty());
  REQUIRE_FALSE(d.pages.empty());
  CHECK(d.pages.back().segments.size() == segment_count(*picture));
}

}  // namespace igds::test
