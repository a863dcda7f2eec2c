// igds 2250 on a pseudo-terminal, driven as xterm's Tek window drives it: the cross-hair's GIN
// reports (key, HiX LoX HiY LoY, CR) on the menu's items, entries typed on the keyboard. The
// Tek stream igds writes is decoded: the menu, the help environment, BUILD, DISPLAY SURFACE
// with the function keys 5 to 8, STORE, DISPLAY FIRST, SAVE and END CMS.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "commands/menu.h"
#include "devices/menu_layout.h"
#include "tests/support/process.h"
#include "tests/support/pty.h"
#include "tests/support/tek_decoder.h"
#include "tests/support/tek_terminal.h"

namespace igds::test {

namespace {

const std::string gin_on = "\x1B\x1A";
const std::string more = "MORE: PRESS RETURN";

std::size_t count_of(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

// Waits for the cross-hair, pressing RETURN at every MORE not answered yet: a text longer than
// the text area beside the menu is paged, and how many pages it takes depends on the menu's width.
bool expect_gin(XtermPty& igds, std::size_t& answered) {
  for (int wait = 0; wait < 20; ++wait) {
    if (igds.expect_gin(1)) return true;
    if (const std::size_t mores = count_of(igds.pty().output(), more); mores > answered) {
      igds.pty().send("\r");
      answered = mores;
    }
  }
  return false;
}

std::map<std::string, std::string> xterm_env(const TempDir& home) {
  return {{"TERM", "xterm"},
          {"XTERM_VERSION", "XTerm(test)"},
          {"HOME", home.path().string()},
          {"IGDS_DISK", ""}};
}

struct Menu {
  std::vector<MenuItem> items = menu_items(false, menu_screen::label_columns);
  std::vector<MenuItem> help_items = menu_items(true, menu_screen::label_columns);
  MenuLayout layout = menu_layout(items.size());
  // A click of button l at the middle of the item labelled so (`dx` right of it: a click that
  // follows one at the middle at once would be the second of a double click).
  void click(XtermPty& igds, const std::string& label, bool help = false, int dx = 0) const {
    const auto& list = help ? help_items : items;
    const auto it =
        std::find_if(list.begin(), list.end(), [&](const MenuItem& i) { return i.label == label; });
    REQUIRE_MESSAGE(it != list.end(), label);
    const Box& b = layout.items[static_cast<std::size_t>(it - list.begin())];
    igds.click('l', int((b.x0 + b.x1) / 2) + dx, int((b.y0 + b.y1) / 2));
  }
};

// What igds drew between two moments: the Tek stream without xterm's window switches and the
// requests for the cross-hair and the terminal's status (ESC SUB, ESC ENQ, which the decoder
// does not know).
TekDrawing decoded(const std::string& bytes) {
  std::string tek = bytes;
  for (const std::string_view vt : {std::string_view("\x1B[?38h"), std::string_view("\x1B\x03"),
                                    std::string_view(gin_on), std::string_view("\x1B\x05")})
    for (auto at = tek.find(vt); at != std::string::npos; at = tek.find(vt))
      tek.erase(at, vt.size());
  return decode_tek(tek);
}

// The segments of a page inside the picture's square.
std::vector<TekSegment> in_picture(const TekPage& page, const Box& square) {
  std::vector<TekSegment> out;
  for (const auto& s : page.segments)
    if (s.a.x <= square.x1 && s.b.x <= square.x1 && s.a.y >= square.y0 && s.b.y >= square.y0)
      out.push_back(s);
  return out;
}

bool page_has(const TekPage& page, const std::string& text) {
  return std::any_of(page.texts.begin(), page.texts.end(),
                     [&](const TekText& t) { return t.text.find(text) != std::string::npos; });
}

// Consecutive segments joined end to start, split where they are not: the chains drawn.
std::vector<std::vector<TekSegment>> chains(const std::vector<TekSegment>& segments) {
  std::vector<std::vector<TekSegment>> out;
  for (const auto& s : segments) {
    const bool joined = !out.empty() && std::abs(out.back().back().b.x - s.a.x) < 0.5 &&
                        std::abs(out.back().back().b.y - s.a.y) < 0.5;
    if (joined)
      out.back().push_back(s);
    else
      out.push_back({s});
  }
  return out;
}

}  // namespace

TEST_CASE("igds 2250: the menu, the help environment, picks and typed entries, keys 5 to 8") {
  TempDir disk, home;
  const Menu menu;
  XtermPty igds({igds_binary().string(), "2250", "--disk", disk.path().string()}, xterm_env(home));
  // The help environment at start: the general explanation and the menu with RETURN.
  REQUIRE(igds.expect("\x1B[?38h"));
  REQUIRE(igds.expect("IGDS WITH A 2250"));
  std::size_t mores = 0;  // MOREs answered
  REQUIRE(expect_gin(igds, mores));
  {
    const TekDrawing d = decoded(igds.pty().output());
    REQUIRE_FALSE(d.pages.empty());
    const TekPage& page = d.pages.back();
    for (const auto& item : menu.help_items) CHECK_MESSAGE(page_has(page, item.label), item.label);
    CHECK(page_has(page, "RETURN"));
    // How a multi-line entry ends, said in HELP (on its first page when the menu is long).
    CHECK(igds.pty().output().find("an empty line") != std::string::npos);
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
  }
  // An item explains its command, with its HELP LONG text; a pick beside the menu is ignored.
  menu.click(igds, "BUILD", true);
  REQUIRE(igds.expect("BUILD defines a new current surface"));
  // Longer than the page: RETURN at MORE, then the cross-hair again.
  REQUIRE(igds.expect(more));
  REQUIRE(expect_gin(igds, mores));
  CHECK(igds.pty().output().find("Tangents are per unit of chord length") != std::string::npos);
  const std::size_t before_miss = igds.pty().output().size();
  const int enquiries = igds.terminal().enquiries();
  igds.click('l', 300, 500);
  REQUIRE(igds.expect_gin());
  // Nothing but the cross-hair again (the alpha cursor put back, the status asked, GIN mode).
  CHECK(igds.terminal().enquiries() == enquiries + 1);
  {
    const TekDrawing miss = decoded(igds.pty().output().substr(before_miss));
    CHECK(miss.pages.size() == 1);
    CHECK(miss.pages.back().segments.empty());
    CHECK(miss.pages.back().texts.empty());
  }
  // RETURN: the execution environment, the menu with HELP, READY.
  menu.click(igds, "RETURN", true);
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect_gin());
  {
    const TekDrawing d = decoded(igds.pty().output());
    REQUIRE_FALSE(d.pages.empty());
    const TekPage& page = d.pages.back();
    CHECK(page_has(page, "HELP"));
    CHECK_FALSE(page_has(page, "RETURN"));
    CHECK(page_has(page, "D SURFACE"));
  }

  // BUILD picked, its questions answered on the keyboard: 2 curves of 3 points, 1 1 inserted.
  menu.click(igds, "BUILD");
  REQUIRE(igds.expect("NUMBER OF CURVES AND STRINGERS?"));
  igds.pty().send("2 3\r");
  REQUIRE(igds.expect("POINTS?"));
  igds.pty().send("1  0 0 0  0 10 0  0 20 0  10 0 0  10 10 5  10 20 0\r");
  REQUIRE(igds.expect("POINTS?"));
  igds.pty().send("\r");
  REQUIRE(igds.expect("TANGENTS?"));
  igds.pty().send("\r");
  REQUIRE(igds.expect("INTERPOLATED CURVES AND STRINGERS?"));
  igds.pty().send("1 1\r");
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect_gin());

  // D SURFACE: the projection typed; 3 curves of 5 points, 5 stringers of 3.
  menu.click(igds, "D SURFACE");
  REQUIRE(igds.expect("PROJECTION?"));
  igds.pty().send("O XY\r");
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect_gin());
  const Box square = menu.layout.picture;
  auto after_key = [&](char key) {
    const std::size_t from = igds.pty().output().size();
    igds.point_at(300, 400);
    igds.type(std::string(1, key));
    REQUIRE(igds.expect_gin());
    const TekDrawing d = decoded(igds.pty().output().substr(from));
    REQUIRE_FALSE(d.pages.empty());
    for (const auto& error : d.errors) FAIL_CHECK(error);
    return d.pages.back();
  };
  {
    // 6: the stringers one after the other, from the first (y = 0, the lowest) up.
    const TekPage page = after_key('6');
    CHECK(page_has(page, "D SURFACE"));  // the menu stays
    const auto drawn = chains(in_picture(page, square));
    REQUIRE(drawn.size() == 5);
    for (std::size_t j = 0; j < drawn.size(); ++j) {
      CHECK(drawn[j].size() == 2);
      CHECK(std::abs(drawn[j].front().a.y - drawn[j].back().b.y) < 1);  // along x
      if (j > 0) CHECK(drawn[j].front().a.y > drawn[j - 1].front().a.y);
    }
  }
  {
    // 7: the curves one after the other, from the first (x = 0, the leftmost) on.
    const TekPage page = after_key('7');
    const auto drawn = chains(in_picture(page, square));
    REQUIRE(drawn.size() == 3);
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      CHECK(drawn[i].size() == 4);
      CHECK(std::abs(drawn[i].front().a.x - drawn[i].back().b.x) < 1);  // along y
      if (i > 0) CHECK(drawn[i].front().a.x > drawn[i - 1].front().a.x);
    }
  }
  {
    // 8: the 15 points alone, each a dot (the smallest square the screen draws), no line
    // between two of them.
    const TekPage page = after_key('8');
    const auto drawn = in_picture(page, square);
    for (const auto& s : drawn) CHECK(std::hypot(s.a.x - s.b.x, s.a.y - s.b.y) <= 2);
    CHECK(chains(drawn).size() == 15);
  }
  {
    // 5: the default display again, curves and stringers: 3 x 4 + 5 x 2 segments.
    const TekPage page = after_key('5');
    CHECK(in_picture(page, square).size() == 22);
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
  }

  // HELP from the execution environment: the explanation on a page of its own, then RETURN
  // gives back the picture that was on the screen.
  menu.click(igds, "HELP");
  REQUIRE(igds.expect("IGDS WITH A 2250"));
  REQUIRE(expect_gin(igds, mores));
  CHECK(in_picture(decoded(igds.pty().output()).pages.back(), square).empty());
  menu.click(igds, "RETURN", true, 30);
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect_gin());
  CHECK(in_picture(decoded(igds.pty().output()).pages.back(), square).size() == 22);

  // ST FIRST, D FIRST, SAVE with a name typed, END CMS.
  menu.click(igds, "ST FIRST");
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect_gin());
  menu.click(igds, "D FIRST");
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect_gin());
  menu.click(igds, "SAVE");
  REQUIRE(igds.expect("FILE NAME?"));
  igds.pty().send("TWIST\r");
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect_gin());
  menu.click(igds, "END CMS");
  CHECK(igds.pty().wait(20) == 0);
  CHECK(std::filesystem::exists(disk.path() / "TWIST.IGDSDATA"));
  // Back to the VT window it started in.
  CHECK(igds.pty().output().ends_with(std::string("\x1F\x1B\x03")));
}

TEST_CASE("igds 2250 without a terminal that has a cross-hair says how to run it") {
  TempDir disk;
  const RunResult r = run_igds({"2250", "--disk", disk.path().string()}, [] {
    RunOptions o;
    o.input = "";
    o.timeout_seconds = 30;
    return o;
  }());
  CHECK(r.status == 1);
  CHECK(r.err.find("xterm -t -e igds 2250") != std::string::npos);
  CHECK(r.err.find("not a terminal") != std::string::npos);
  // At a terminal that is no xterm.
  TempDir home;
  PtySession dumb({igds_binary().string(), "2250", "--disk", disk.path().string()},
                  {{"TERM", "dumb"}, {"XTERM_VERSION", ""}, {"HOME", home.path().string()}});
  CHECK(dumb.expect("TERM=dumb"));
  CHECK(dumb.wait(20) == 1);
}

}  // namespace igds::test
