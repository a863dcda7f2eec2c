// The cross-hair stays in step whatever is typed or clicked, and however fast: igds on a
// pseudo-terminal that answers as xterm's Tek window does (tests/support/tek_terminal.h), driven
// by a seeded random mix of clicks, typed lines, keys before the cross-hair is up, and Ctrl-C
// (pressed in GIN mode it is a report whose key the tty turns into SIGINT), each at a random
// moment of igds's work. Whatever the order in which they meet, no report's bytes may ever be
// read as a command, the input never ends but at the end, and igds answers a pick afterwards.
// IGDS_GIN_SEED=N runs seed N alone (the seeds of a run are in its messages).
#include <doctest/doctest.h>
#include <signal.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "commands/menu.h"
#include "devices/menu_layout.h"
#include "tests/e2e/e2e_support.h"
#include "tests/support/process.h"
#include "tests/support/tek_decoder.h"
#include "tests/support/tek_terminal.h"

namespace igds::test {

namespace {

std::vector<unsigned> seeds() {
  if (const char* one = std::getenv("IGDS_GIN_SEED"); one && *one)
    return {static_cast<unsigned>(std::strtoul(one, nullptr, 10))};
  return {1, 2, 3, 4};
}

std::map<std::string, std::string> env_of(const TempDir& home) {
  return {{"TERM", "xterm"},
          {"XTERM_VERSION", "XTerm(test)"},
          {"HOME", home.path().string()},
          {"IGDS_DISK", ""}};
}

// What must never be seen: a report's bytes read as a line (the clicks are at places whose
// address bytes are all punctuation, and only letters and digits are typed), an end of input that
// was none, text over text.
void check_in_step(const std::string& tek) {
  CHECK(tek.find("END OF INPUT") == std::string::npos);
  const TekDrawing d = decode_tek(tek);
  for (const auto& page : d.pages) {
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
    for (std::size_t k = 1; k < page.texts.size(); ++k) {
      const std::string& report = page.texts[k].text;
      if (!report.starts_with("INCORRECT COMMAND") && !report.starts_with("INCORRECT ENTRY"))
        continue;
      std::string_view line = page.texts[k - 1].text;
      if (const auto prompt = line.rfind("? "); prompt != std::string_view::npos)
        line.remove_prefix(prompt + 2);
      CAPTURE(line);
      CHECK(std::all_of(line.begin(), line.end(), [](char c) {
        return c == ' ' || (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z');
      }));
    }
  }
}

// Places whose address bytes are all punctuation (five-bit halves 1..15 and 26..31), between
// `low` and `high`, in a random order.
std::vector<int> punctuated(int low, int high, std::mt19937& random) {
  std::vector<int> out;
  for (int v = low; v < high; ++v) {
    const auto mark = [](int half) { return (half >= 1 && half <= 15) || half >= 26; };
    if (mark(v >> 5) && mark(v & 31)) out.push_back(v);
  }
  std::shuffle(out.begin(), out.end(), random);
  return out;
}

// The Tek stream without the requests decode_tek does not know (the window switches, ESC ENQ,
// ESC SUB).
std::string tek_of(std::string out) {
  for (const std::string_view vt : {std::string_view("\x1B[?38h"), std::string_view("\x1B\x03"),
                                    std::string_view("\x1B\x1A"), std::string_view("\x1B\x05")})
    for (auto at = out.find(vt); at != std::string::npos; at = out.find(vt))
      out.erase(at, vt.size());
  return out;
}

}  // namespace

TEST_CASE(
    "tek mode, ZOOM PICK: random clicks, lines, early keys and Ctrl-C keep the cross-hair in "
    "step") {
  TempDir disk, home;
  REQUIRE(run_commands(disk, std::string(saddle_build) + "DISPLAY INPUT ORTHOGONAL XY\n").status ==
          0);
  for (const unsigned seed : seeds()) {
    MESSAGE("seed " << seed);
    CAPTURE(seed);
    std::mt19937 random(seed);
    XtermPty igds({igds_binary().string(), "--term", "tek", "--disk", disk.path().string()},
                  env_of(home));
    if (!igds.expect("READY", 30)) FAIL(igds.transcript(20000));
    // Clicks at places of their own: two corners always differ in x and in y.
    const std::vector<int> xs = punctuated(40, 580, random), ys = punctuated(40, 580, random);
    std::size_t next = 0;
    for (int step = 0; step < 80; ++step) {
      switch (std::uniform_int_distribution<int>(0, 9)(random)) {
        case 0:
        case 1:
          igds.type("ZOOM PICK\r");
          break;
        case 2:
        case 3:
        case 4:
          igds.click('l', xs[next % xs.size()], ys[next % ys.size()]);
          ++next;
          break;
        case 5:
          igds.type("H S\r");
          break;
        case 6:
          // A corner typed as its address, at once.
          igds.type(std::to_string(xs[next % xs.size()]) + " " +
                    std::to_string(ys[next % ys.size()]) + "\r");
          ++next;
          break;
        case 7:
          igds.type("\x03");
          break;
        default:
          // Nothing: igds works on meanwhile.
          break;
      }
      igds.pump(std::uniform_int_distribution<int>(0, 25)(random));
    }
    // Whatever the last action was: Ctrl-C (which drops what was typed ahead), READY, and igds
    // answers in step.
    igds.skip_output();
    igds.type("\x03");
    if (!igds.expect("READY")) FAIL(igds.transcript(20000));
    igds.pump(100);
    igds.type("ZOOM PICK\r");
    if (!igds.expect("FIRST CORNER?")) FAIL(igds.transcript(20000));
    if (!igds.expect_gin()) FAIL(igds.transcript(20000));
    igds.click('l', 100, 101);
    if (!igds.expect("SECOND CORNER?")) FAIL(igds.transcript(20000));
    if (!igds.expect_gin()) FAIL(igds.transcript(20000));
    igds.click('l', 300, 302);
    if (!igds.expect("READY")) FAIL(igds.transcript(20000));
    igds.type("LIST IMAGES\r");
    if (!igds.expect("ZOOMED TO")) FAIL(igds.transcript(20000));
    igds.type("\r");  // the listing's page, when it has one of its own
    if (!igds.expect("READY")) FAIL(igds.transcript(20000));
    igds.type("END CMS\r");
    CHECK(igds.pty().wait(30) == 0);
    check_in_step(tek_of(igds.pty().output()));
  }
}

TEST_CASE("igds 2250: random picks, function keys, typed lines and Ctrl-C keep the menu in step") {
  const auto items = menu_items(false, menu_screen::label_columns);
  const MenuLayout layout = menu_layout(items.size());
  auto middle = [&](std::string_view label, int dx) {
    for (std::size_t k = 0; k < items.size(); ++k)
      if (items[k].label == label) {
        const Box& b = layout.items[k];
        return std::pair<int, int>(int((b.x0 + b.x1) / 2) + dx, int((b.y0 + b.y1) / 2));
      }
    FAIL("no item " << label);
    return std::pair<int, int>();
  };
  TempDir disk, home;
  REQUIRE(
      run_commands(disk, std::string(saddle_build) + "DISPLAY SURFACE ORTHOGONAL XY\n").status ==
      0);
  for (const unsigned seed : seeds()) {
    MESSAGE("seed " << seed);
    CAPTURE(seed);
    std::mt19937 random(seed);
    XtermPty igds({igds_binary().string(), "2250", "--disk", disk.path().string()}, env_of(home));
    if (!igds.expect("IGDS WITH A 2250", 30)) FAIL(igds.transcript(20000));
    // The items that ask nothing or one question, and a miss beside the menu.
    const std::vector<std::string_view> safe = {"ERASE", "D FIRST",   "HELP",     "UNDO",
                                                "REDO",  "D SURFACE", "ST FIRST", "LIST"};
    for (int step = 0; step < 80; ++step) {
      const int dx = std::uniform_int_distribution<int>(-40, 40)(random);
      switch (std::uniform_int_distribution<int>(0, 11)(random)) {
        case 0:
        case 1:
        case 2: {
          const auto [x, y] = middle(safe[random() % safe.size()], dx);
          igds.click('l', x, y);
          break;
        }
        case 3: {
          const auto [x, y] = middle("HELP", dx);  // RETURN in the help environment
          igds.click('l', x, y);
          break;
        }
        case 4:
          igds.click('l', 300, 300 + dx);
          break;
        case 5:
          igds.point_at(300, 400);
          igds.type(std::string(1, "5678"[random() % 4]));
          break;
        case 6:
          igds.type("H S\r");
          break;
        case 7:
          igds.type("O XY\r");  // the projection, when asked; else INCORRECT ENTRY, or ignored
          break;
        case 8:
          igds.type("\x03");
          break;
        case 9:
          igds.type("\r");
          break;
        default:
          break;
      }
      igds.pump(std::uniform_int_distribution<int>(0, 25)(random));
    }
    // Ctrl-C, then RETURN and HELP's RETURN in case a page or the help environment is up: the
    // menu answers a pick.
    igds.point_at(300, 300);  // beside the menu: RETURN there picks nothing
    igds.type("\x03");
    for (int k = 0; k < 3; ++k) {
      igds.pump(200);
      igds.type("\r");
    }
    if (!igds.expect_gin()) FAIL(igds.transcript(20000));
    {
      const auto [x, y] = middle("HELP", 0);
      igds.click('l', x, y);  // RETURN if the help environment is up, else HELP
    }
    if (!igds.expect_gin()) FAIL(igds.transcript(20000));
    if (igds.pty().output().rfind("IGDS WITH A 2250") > igds.pty().output().rfind("READY")) {
      const auto [x, y] = middle("HELP", 30);
      igds.click('l', x, y);  // back to work
      if (!igds.expect("READY")) FAIL(igds.transcript(20000));
      if (!igds.expect_gin()) FAIL(igds.transcript(20000));
    }
    {
      const auto [x, y] = middle("END CMS", 0);
      igds.click('l', x, y);
    }
    CHECK(igds.pty().wait(30) == 0);
    check_in_step(tek_of(igds.pty().output()));
  }
}

TEST_CASE("igds 2250: a double click chooses once; two clicks apart in time choose twice") {
  TempDir disk, home;
  XtermPty igds({igds_binary().string(), "2250", "--disk", disk.path().string()}, env_of(home));
  const auto items = menu_items(false, menu_screen::label_columns);
  const MenuLayout layout = menu_layout(items.size());
  auto at = [&](std::string_view label) {
    for (std::size_t k = 0; k < items.size(); ++k)
      if (items[k].label == label) return layout.items[k];
    FAIL("no item " << label);
    return Box{};
  };
  const Box ret = at("HELP"), undo = at("UNDO");
  REQUIRE(igds.expect_gin(30));
  igds.click('l', int(ret.x0 + ret.x1) / 2, int(ret.y0 + ret.y1) / 2);
  REQUIRE(igds.expect("READY"));
  // The second click of a double click finds GIN mode on again at once: dropped.
  const int ux = int(undo.x0 + undo.x1) / 2, uy = int(undo.y0 + undo.y1) / 2;
  REQUIRE(igds.expect_gin());
  const auto clicked = std::chrono::steady_clock::now();
  igds.click('l', ux, uy);
  REQUIRE(igds.expect("NOTHING TO UNDO"));
  REQUIRE(igds.expect_gin());
  const bool at_once = std::chrono::steady_clock::now() - clicked < double_click / 2;
  igds.click('l', ux, uy);
  REQUIRE(igds.expect_gin());
  // Another item, away from the first: chosen.
  igds.click('l', int(ret.x0 + ret.x1) / 2 + 20, int(ret.y0 + ret.y1) / 2);  // HELP
  REQUIRE(igds.expect("IGDS WITH A 2250"));
  // The cross-hair came back within half the double-click time (on a machine that slow it
  // cannot tell, and says so).
  if (at_once)
    CHECK(igds.pty().output().find("NOTHING TO UNDO") ==
          igds.pty().output().rfind("NOTHING TO UNDO"));
  else
    MESSAGE("the cross-hair came back too late to tell a double click");
  REQUIRE(igds.expect_gin());
  const auto [x, y] = std::pair<int, int>(int(ret.x0 + ret.x1) / 2 - 20, int(ret.y0 + ret.y1) / 2);
  igds.click('l', x, y);  // RETURN
  REQUIRE(igds.expect("READY"));
  REQUIRE(igds.expect_gin());
  const Box end = at("END CMS");
  igds.click('l', int(end.x0 + end.x1) / 2, int(end.y0 + end.y1) / 2);
  CHECK(igds.pty().wait(30) == 0);
}

}  // namespace igds::test
