// The Tek screen igds manages (devices/tek_screen.h): its stream decoded as a terminal shows it,
// page by page, with nothing drawn over anything, no word cut at the edge, nothing off the screen.
#include "devices/tek_screen.h"

#include <doctest/doctest.h>

#include <set>
#include <sstream>
#include <string>

#include "commands/picture.h"
#include "tests/devices/support.h"
#include "tests/support/tek_decoder.h"

namespace igds::test {

namespace {

// Everything a screen sent, kept to be decoded.
struct Shown {
  std::string bytes;
  void operator+=(const std::string& b) { bytes += b; }
  TekDrawing decoded() const { return decode_tek(bytes); }
};

void check_no_faults(const TekDrawing& d) {
  CHECK(d.errors.empty());
  for (std::size_t p = 0; p < d.pages.size(); ++p) {
    CAPTURE(p);
    for (const auto& fault : screen_faults(d.pages[p])) FAIL_CHECK(fault);
  }
}

// The words of a text (runs between blanks). An APL character is drawn as strokes, not as text,
// so it ends a word as a blank does.
std::set<std::string> words(std::string_view text) {
  std::string ascii;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      ascii += text[i];
    } else if ((c & 0xC0) == 0xC0) {
      ascii += ' ';
    }
  }
  std::set<std::string> out;
  std::istringstream in(ascii);
  for (std::string w; in >> w;) out.insert(w);
  return out;
}

// Every word shown on any page is a word of `said`: none was cut at the edge of the screen.
void check_words_whole(const TekDrawing& d, std::string_view said) {
  const auto all = words(said);
  for (const auto& page : d.pages)
    for (const auto& text : page.texts)
      for (const auto& w : words(text.text)) CHECK_MESSAGE(all.count(w), "a cut word: " << w);
}

std::shared_ptr<const Picture> picture(const Image& image) {
  return std::make_shared<const Picture>(picture_of(image));
}

}  // namespace

TEST_CASE("the Tek screen: dialogue wrapped at blanks, and a new page when it is full") {
  for (int bits : {10, 12}) {
    CAPTURE(bits);
    TekScreen screen({bits}, true);
    Shown out;
    out += screen.begin();
    std::string said;
    for (int i = 0; i < 60; ++i) {
      const std::string line = "POINTS? " + std::to_string(i) +
                               " 1000.25 ¯2000.5 3000.125  4000.0625 5000.03125 6000.015625 "
                               "70000.0078125 8 9 10 11 12";
      said += line + "\n";
      out += screen.text(line + "\n");
    }
    const TekDrawing d = bits == 10 ? out.decoded() : decode_tek(out.bytes);
    if (bits == 12) continue;  // the decoder reads 12-bit streams in 4013 points: same checks
    check_no_faults(d);
    check_words_whole(d, said);
    // 60 lines of two rows on 34-row pages, three rows carried to each new page.
    CHECK(d.pages.size() >= 4);
    CHECK(screen.pages() == static_cast<int>(d.pages.size()) - 1);
    // The rows start at the left margin, one line height apart, from the top baseline.
    const auto rows = screen.rows();
    REQUIRE(!rows.empty());
    CHECK(rows.front().x == 0);
    CHECK(rows.front().y == 734);
  }
}

TEST_CASE("the Tek screen: a picture with its caption, the dialogue below it, DISPLAYs stacked") {
  TekScreen screen({10}, true);
  Shown out;
  out += screen.begin();
  out += screen.text("READY\nDISPLAY SURFACE ASSONOMETRIC 110 130 120\n");
  out += screen.picture(picture(devices::surface_image(6, 7)));
  out += screen.text("READY\nDISPLAY INPUT CONIC 12.5 -40 1000\n");
  out += screen.picture(picture(devices::input_image(6, 7)));
  out += screen.text("READY\n");
  TekDrawing d = out.decoded();
  check_no_faults(d);
  // The first page had only dialogue; the picture started the second, which kept the command.
  REQUIRE(d.pages.size() == 2);
  const auto& page = d.pages[1];
  CHECK(!page.segments.empty());
  auto has = [&](std::string_view text, double x) {
    return std::any_of(page.texts.begin(), page.texts.end(),
                       [&](const TekText& t) { return t.text == text && t.at.x == x; });
  };
  CHECK(has("DISPLAY SURFACE ASSONOMETRIC 110 130 120", 0));
  // Both captions, one below the other in the column right of the picture.
  CHECK(has("SURFACE", 600));
  CHECK(has("INPUT", 600));
  // Vectors in the picture's square, and the caption's high minus (-40 is ¯40, as the echo
  // shows it), a stroke in the column.
  bool high_minus = false;
  for (const auto& s : page.segments) {
    for (const TekPoint& p : {s.a, s.b}) CHECK(((p.x <= 583 && p.y >= 184) || p.x >= 600));
    high_minus = high_minus || (s.a.x >= 600 && s.a.y == s.b.y && s.a.x != s.b.x);
  }
  CHECK(high_minus);
  // The dialogue is below the picture, across the whole screen.
  for (const auto& t : page.texts)
    if (t.at.x == 0) CHECK(t.at.y <= 160);
  CHECK(screen.rows_per_page() == 8);

  // The dialogue fills the rows below the picture: a new page with the picture again.
  for (int i = 0; i < 20; ++i) out += screen.text("POINTS? 1 2 3 4\n");
  d = out.decoded();
  check_no_faults(d);
  CHECK(d.pages.size() > 3);
  CHECK(!d.pages.back().segments.empty());
  CHECK(std::any_of(d.pages.back().texts.begin(), d.pages.back().texts.end(),
                    [](const TekText& t) { return t.text == "INPUT" && t.at.x == 600; }));

  // ERASE: a clean page, the picture no longer on it.
  out += screen.erase();
  out += screen.text("READY\n");
  d = out.decoded();
  CHECK(d.pages.back().segments.empty());
  CHECK(!screen.shows_picture());
  CHECK(screen.rows_per_page() == 34);
}

TEST_CASE("the Tek screen: what is typed is echoed, a word crossing the edge moves down") {
  TekScreen screen({10}, true);
  Shown out;
  out += screen.begin();
  out += screen.text("POINTS? ");
  const std::string typed =
      "1 0 0 0  10 0 2  20 0 0  30 0 2  40 0 0  50 0 2  60 0 0  70 0 2  "
      "80 0 0  90 0 2  100 0 0";
  for (std::size_t i = 0; i < typed.size(); ++i) out += screen.type(typed.substr(i, 1));
  CHECK(utf8(screen.typed()) == typed);
  // Taken back: the page again without the last three characters.
  for (int i = 0; i < 3; ++i) out += screen.untype();
  CHECK(utf8(screen.typed()) == typed.substr(0, typed.size() - 3));
  const TekDrawing before_end = out.decoded();
  out += screen.text("\n");
  const TekDrawing d = out.decoded();
  check_no_faults(d);
  // The last page shows the line as it was finally typed, wrapped at a blank: the second row
  // starts with the word that did not fit, and ends where the typing ended.
  const auto rows = screen.rows();
  REQUIRE(rows.size() == 2);
  CHECK(utf8(rows[0].text).starts_with("POINTS? 1 0 0 0"));
  CHECK(utf8(rows[1].text).ends_with("90 0 2  100 "));
  CHECK(rows[0].text.size() <= 73);
  // Every word of the final page is whole (pages before it showed words being typed).
  const auto& page = before_end.pages.back();
  for (const auto& t : page.texts)
    for (const auto& w : words(t.text))
      CHECK_MESSAGE(words("POINTS? " + typed).count(w), "a cut word: " << w);
}

TEST_CASE("the Tek screen: APL characters are strokes in their cells") {
  TekScreen screen({10}, true);
  Shown out;
  out += screen.begin();
  out += screen.text("POINTS? 1 ¯3.5 0 ⍴ ⍝ done\n");
  const TekDrawing d = out.decoded();
  check_no_faults(d);
  // The ASCII characters as alpha text, each APL character drawn as vectors.
  CHECK(!d.pages[0].segments.empty());
  for (const auto& t : d.pages[0].texts)
    for (char c : t.text) CHECK(static_cast<unsigned char>(c) < 0x80);
}

TEST_CASE("the Tek screen: a long text on a page of its own, then the picture page again") {
  TekScreen screen({10}, true);
  Shown out;
  out += screen.begin();
  out += screen.picture(picture(devices::surface_image(4, 4)));
  out += screen.text("POINTS? ");
  out += screen.document_page();
  CHECK(screen.in_document());
  CHECK(screen.rows_per_page() == 34);
  for (int i = 0; i < 30; ++i) out += screen.text("A LINE OF HELP\n");
  out += screen.end_document();
  CHECK_FALSE(screen.in_document());
  const TekDrawing d = out.decoded();
  check_no_faults(d);
  REQUIRE(d.pages.size() == 4);
  CHECK(d.pages[2].segments.empty());   // the text's page
  CHECK(!d.pages[3].segments.empty());  // the picture again, and the question it was at
  CHECK(std::any_of(d.pages[3].texts.begin(), d.pages[3].texts.end(),
                    [](const TekText& t) { return t.text.starts_with("POINTS?"); }));
}

TEST_CASE("the Tek window of --term xterm shows pictures only, in the full square") {
  TekScreen screen({10}, false);
  Shown out;
  out += screen.picture(picture(devices::surface_image(5, 4)));
  out += screen.picture(picture(devices::input_image(3, 4)));
  const TekDrawing d = out.decoded();
  check_no_faults(d);
  bool large = false;
  for (const auto& s : d.pages.back().segments) large = large || s.a.x > 600 || s.b.x > 600;
  CHECK(large);
  CHECK(std::count_if(d.pages.back().texts.begin(), d.pages.back().texts.end(),
                      [](const TekText& t) { return t.at.x == 780; }) >= 6);
}

}  // namespace igds::test

namespace igds::test {

TEST_CASE("text as paragraphs laid out at a screen's width, each row hung where it belongs") {
  const std::string text =
      "DISPLAY makes a new current image and draws it on the left of the screen.\n"
      "\n"
      "  CONIC x y z         perspective from the view point x y z towards the centre\n"
      "  DISPLAY INPUT [projection [parameters]]   the input points, the border\n"
      " 1. NUMBER OF CURVES AND STRINGERS? NOCUR and NOSTR, whole numbers\n"
      "                          projects and draws the input or the surface\n"
      "  BUILD\n";
  // At 56 columns: the explanation's column when it leaves half the row (CONIC's), else four
  // more than the term (DISPLAY INPUT's); after a list's number; an indented paragraph at its
  // indent.
  const std::vector<std::string> expected = {
      "DISPLAY makes a new current image and draws it on the",
      "left of the screen.",
      "",
      "  CONIC x y z         perspective from the view point x",
      "                      y z towards the centre",
      "  DISPLAY INPUT [projection [parameters]]   the input",
      "      points, the border",
      " 1. NUMBER OF CURVES AND STRINGERS? NOCUR and NOSTR,",
      "    whole numbers",
      "                          projects and draws the input",
      "                          or the surface",
      "  BUILD"};
  CHECK(lay_out(text, 56) == expected);
  // Narrower, no hang takes more than half the row: the summary's later rows at 20, not 26.
  const auto narrow = lay_out(text, 40);
  CHECK(narrow.back() == "  BUILD");
  CHECK(narrow[narrow.size() - 2].find_first_not_of(' ') == 20);
  // A paragraph that fits is one row as written; a word longer than a row is cut.
  CHECK(lay_out("  D SU O XY", 73) == std::vector<std::string>{"  D SU O XY"});
  CHECK(lay_out(std::string(20, 'X'), 8) ==
        std::vector<std::string>{"XXXXXXXX", "XXXXXXXX", "XXXX"});
  // Every row of a help text fits the 2250's 61 columns and the 4013's 73.
  for (const int columns : {61, 73})
    for (const auto& row : lay_out(text, columns))
      CHECK(utf32(row).size() <= static_cast<std::size_t>(columns));
  CHECK(lay_out("", 73).empty());
}

}  // namespace igds::test
