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
bool expect_gin(PtySession& igds, std::size_t& answered) {
  for (int page = 0; page < 20; ++page) {
    // Whichever comes first: a MORE not answered yet, or the cross-hair.
    bool gin = false;
    if (!igds.wait_until([&] {
          return count_of(igds.output(), more) > answered || (gin = igds.expect(gin_on, 0));
        }))
      return false;
    if (gin) return true;
    // Counted before the RETURN: sending it reads on, maybe up to the next MORE.
    answered = count_of(igds.output(), more);
    igds.send("\r");
  }
  return false;
}

std::map<std::string, std::string> xterm_env(const TempDir& home) {
  return {{"TERM", "xterm"},
          {"XTERM_VERSION", "XTerm(test)"},
          {"HOME", home.path().string()},
          {"IGDS_DISK", ""}};
}

// xterm's report of `key` at (x, y), with ginTerminator CR.
std::string report(char key, int x, int y) {
  std::string r{key};
  r += static_cast<char>(0x20 | (x >> 5));
  r += static_cast<char>(0x20 | (x & 31));
  r += static_cast<char>(0x20 | (y >> 5));
  r += static_cast<char>(0x20 | (y & 31));
  return r + "\r";
}

struct Menu {
  std::vector<MenuItem> items = menu_items(false, menu_screen::label_columns);
  std::vector<MenuItem> help_items = menu_items(true, menu_screen::label_columns);
  MenuLayout layout = menu_layout(items.size());
  // A mouse button's report (xterm sets the high bit) at the middle of the item labelled so.
  std::string click(const std::string& label, bool help = false) const {
    const auto& list = help ? help_items : items;
    const auto it =
        std::find_if(list.begin(), list.end(), [&](const MenuItem& i) { return i.label == label; });
    REQUIRE_MESSAGE(it != list.end(), label);
    const Box& b = layout.items[static_cast<std::size_t>(it - list.begin())];
    return report(static_cast<char>('l' | 0x80), int((b.x0 + b.x1) / 2), int((b.y0 + b.y1) / 2));
  }
};

// What igds drew between two moments: the Tek stream without xterm's window switches and the
// requests for the cross-hair (ESC SUB, which the decoder does not know).
TekDrawing decoded(const std::string& bytes) {
  std::string tek = bytes;
  for (const std::string_view vt :
       {std::string_view("\x1B[?38h"), std::string_view("\x1B\x03"), std::string_view(gin_on)})
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
  PtySession igds({igds_binary().string(), "2250", "--disk", disk.path().string()},
                  xterm_env(home));
  // The help environment at start: the general explanation and the menu with RETURN.
  REQUIRE(igds.expect("\x1B[?38h"));
  REQUIRE(igds.expect("IGDS WITH A 2250"));
  std::size_t mores = 0;  // MOREs answered
  REQUIRE(expect_gin(igds, mores));
  {
    const TekDrawing d = decoded(igds.output());
    REQUIRE_FALSE(d.pages.empty());
    const TekPage& page = d.pages.back();
    for (const auto& item : menu.help_items) CHECK_MESSAGE(page_has(page, item.label), item.label);
    CHECK(page_has(page, "RETURN"));
    // How a multi-line entry ends, said in HELP (on its first page when the menu is long).
    CHECK(igds.output().find("an empty line") != std::string::npos);
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
  }
  // An item explains its command, with its HELP LONG text; a pick beside the menu is ignored.
  igds.send(menu.click("BUILD", true));
  REQUIRE(igds.expect("BUILD defines a new current surface"));
  // Longer than the page: RETURN at MORE, then the cross-hair again.
  REQUIRE(igds.expect(more));
  REQUIRE(expect_gin(igds, mores));
  CHECK(igds.output().find("Tangents are per unit of chord length") != std::string::npos);
  const std::size_t before_miss = igds.output().size();
  igds.send(report('l', 300, 500));
  REQUIRE(igds.expect(gin_on));
  CHECK(igds.output().size() - before_miss == gin_on.size());  // nothing but the cross-hair
  // RETURN: the execution environment, the menu with HELP, READY.
  igds.send(menu.click("RETURN", true));
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect(gin_on));
  {
    const TekDrawing d = decoded(igds.output());
    REQUIRE_FALSE(d.pages.empty());
    const TekPage& page = d.pages.back();
    CHECK(page_has(page, "HELP"));
    CHECK_FALSE(page_has(page, "RETURN"));
    CHECK(page_has(page, "D SURFACE"));
  }

  // BUILD picked, its questions answered on the keyboard: 2 curves of 3 points, 1 1 inserted.
  igds.send(menu.click("BUILD"));
  REQUIRE(igds.expect("NUMBER OF CURVES AND STRINGERS?"));
  igds.send("2 3\r");
  REQUIRE(igds.expect("POINTS?"));
  igds.send("1  0 0 0  0 10 0  0 20 0  10 0 0  10 10 5  10 20 0\r");
  REQUIRE(igds.expect("POINTS?"));
  igds.send("\r");
  REQUIRE(igds.expect("TANGENTS?"));
  igds.send("\r");
  REQUIRE(igds.expect("INTERPOLATED CURVES AND STRINGERS?"));
  igds.send("1 1\r");
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect(gin_on));

  // D SURFACE: the projection typed; 3 curves of 5 points, 5 stringers of 3.
  igds.send(menu.click("D SURFACE"));
  REQUIRE(igds.expect("PROJECTION?"));
  igds.send("O XY\r");
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect(gin_on));
  const Box square = menu.layout.picture;
  auto after_key = [&](char key) {
    const std::size_t from = igds.output().size();
    igds.send(report(key, 300, 400));
    REQUIRE(igds.expect(gin_on));
    const TekDrawing d = decoded(igds.output().substr(from));
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
  igds.send(menu.click("HELP"));
  REQUIRE(igds.expect("IGDS WITH A 2250"));
  REQUIRE(expect_gin(igds, mores));
  CHECK(in_picture(decoded(igds.output()).pages.back(), square).empty());
  igds.send(menu.click("RETURN", true));
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect(gin_on));
  CHECK(in_picture(decoded(igds.output()).pages.back(), square).size() == 22);

  // ST FIRST, D FIRST, SAVE with a name typed, END CMS.
  igds.send(menu.click("ST FIRST"));
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect(gin_on));
  igds.send(menu.click("D FIRST"));
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect(gin_on));
  igds.send(menu.click("SAVE"));
  REQUIRE(igds.expect("FILE NAME?"));
  igds.send("TWIST\r");
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect(gin_on));
  igds.send(menu.click("END CMS"));
  CHECK(igds.wait(20) == 0);
  CHECK(std::filesystem::exists(disk.path() / "TWIST.IGDSDATA"));
  // Back to the VT window it started in.
  CHECK(igds.output().ends_with(std::string("\x1F\x1B\x03")));
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
