// The Tek screen as a person at the terminal sees it: a whole session typed key by key into
// igds --term tek on a pseudo-terminal (igds reads the keys and echoes them itself), its stream
// decoded page by page. Nothing is drawn over anything, no word or number is cut at the edge of
// the screen, nothing is off the screen.
#include <doctest/doctest.h>

#include <set>
#include <sstream>

#include "tests/e2e/e2e_support.h"
#include "tests/support/process.h"
#include "tests/support/pty.h"
#include "tests/support/tek_decoder.h"

namespace igds::test {

namespace {

// Each step: what igds shows last before it waits, and what is typed then.
struct Step {
  std::string wait_for;
  std::string keys;
};

// A session with long entries, HELP LONG at a question and at READY, several DISPLAYs in a row,
// a CHANGE chain, errors, a mistyped key taken back, and APL's high minus.
const std::vector<Step> session{
    {"READY", "BUILD\r"},
    {"STRINGERS?", "4 5\r"},
    {"POINTS?", "1 0 0 0  10 0 5.657  20 0 8  30 0 5.657  40 0 0  0 10 0  10 10 4.333\r"},
    {"POINTS?", "8 20 10 6.128  30 10 4.333  40 10 0  0 20 0  10 20 0.982  20 20 1.389\r"},
    {"POINTS?",
     "14 30 20 0.982  40 20 0  0 30 0  10 30 \xC2\xAF"
     "2.828  20 30 \xC2\xAF"
     "4\r"},
    {"POINTS?",
     "19 30 30 \xC2\xAF"
     "2.828  40 30 0 7\b\r"},
    {"POINTS?", "HELP LONG\r"},
    {"POINTS?", "\r"},
    {"TANGENTS?", "1 1 0 0\r"},  // a corner without its flag: refused with the reason
    {"TANGENTS?", "1 1 0 0 1\r"},
    {"TANGENTS?",
     "5 1 0 \xC2\xAF"
     "0.5\r"},
    {"TANGENTS?", "\r"},
    {"STRINGERS?", "3 3\r"},
    {"READY", "DISPLAY SURFACE ASSONOMETRIC 110 130 120\r"},
    {"READY",
     "DISPLAY INPUT CONIC 80 \xC2\xAF"
     "60 40\r"},
    {"READY", "D SU O XY\r"},
    {"READY", "D SU A 110 130 121\r"},
    {"READY", "CHANGE POINTS\r"},
    {"POINTS?", "10 40 10 2\r"},
    {"POINTS?", "\r"},
    {"(Y OR N)", "DISPLAY\r"},  // a command where Y or N is awaited
    {"(Y OR N)", "N\r"},
    {"(Y OR N)", "4 4\r"},
    {"READY", "HELP LONG\r"},
    {"BACK TO THE PICTURE", "\r"},
    {"READY", "HELP SHORT\r"},
    {"READY", "DISPLAY SURFACE ISOMETRIC 3 30\r"},
    {"READY", "SAVE WAVE\r"},
    {"READY", "END CMS\r"},
};

// The words of a text: runs between blanks; an APL character, drawn as strokes, ends a word.
std::set<std::string> words(std::string_view text) {
  std::string ascii;
  for (char c : text) ascii += static_cast<unsigned char>(c) < 0x80 ? c : ' ';
  std::set<std::string> out;
  std::istringstream in(ascii);
  for (std::string w; in >> w;) out.insert(w);
  return out;
}

}  // namespace

TEST_CASE("a session typed at the Tek screen: nothing over anything, no word cut at the edge") {
  TempDir disk, home;
  PtySession igds({igds_binary().string(), "--term", "tek", "--disk", disk.path().string()},
                  {{"TERM", "tek4014"}, {"HOME", home.path().string()}, {"IGDS_DISK", ""}});
  std::string typed;
  std::size_t mores = 0;  // MOREs answered: how many pages a long text takes is the screen's
  for (const auto& step : session) {
    CAPTURE(step.wait_for);
    bool seen = false;
    for (int wait = 0; wait < 20 && !seen; ++wait) {
      // A prompt at the start of its row (a help text quotes the prompts, indented).
      const bool prompt =
          step.wait_for == "READY" || step.wait_for == "POINTS?" || step.wait_for == "TANGENTS?";
      seen = igds.expect(prompt ? "\x1F" + step.wait_for : step.wait_for, 1);
      std::size_t shown = 0;
      for (auto at = igds.output().find("MORE:"); at != std::string::npos;
           at = igds.output().find("MORE:", at + 1))
        ++shown;
      if (!seen && shown > mores) {
        igds.send("\r");
        mores = shown;
      }
    }
    if (!seen) {
      std::string shown;
      for (char c :
           igds.output().substr(igds.output().size() > 1500 ? igds.output().size() - 1500 : 0))
        shown += (c >= 0x20 && c < 0x7F) ? c : (c == 0x1F ? '|' : '.');
      FAIL(step.keys << " // " << shown);
    }
    // Key by key, as a person types.
    for (char c : step.keys) igds.send(std::string(1, c));
    typed += step.keys;
  }
  CHECK(igds.wait() == 0);

  // What a person reads must be igds's own words and the typed ones, whole: the words of the
  // same session in a plain terminal, and of the pauses of the Tek screen.
  std::string lines;
  for (const auto& step : session) {
    // The pauses of the Tek screen's long texts are not lines.
    if (step.wait_for == "MORE" || step.wait_for == "BACK TO THE PICTURE") continue;
    std::string line;
    for (char c : step.keys) {
      if (c == '\b')
        line.pop_back();
      else if (c != '\r')
        line += c;
    }
    lines += line + "\n";
  }
  TempDir plain_disk;
  const std::string plain = run_commands(plain_disk, lines).out;
  std::set<std::string> known = words(plain);
  for (const auto& w : words("MORE: PRESS RETURN PRESS RETURN TO GO BACK TO THE PICTURE"))
    known.insert(w);
  // The captions of the pictures, which a plain terminal writes as one line.
  for (const auto& w : words("INPUT SURFACE CONIC ASSONOMETRIC ISOMETRIC ORTHOGONAL XY AXIS Z "
                             "ANGLE 30 110 130 120 80 -60 40"))
    known.insert(w);
  // The point numbers DISPLAY INPUT writes beside the points (4 x 5 of them at most here).
  for (int k = 1; k <= 4 * 5; ++k) known.insert(std::to_string(k));

  const TekDrawing d = decode_tek(igds.output());
  CHECK(d.errors.empty());
  REQUIRE(d.pages.size() > 4);
  int pictures = 0;
  for (std::size_t p = 0; p < d.pages.size(); ++p) {
    CAPTURE(p);
    for (const auto& fault : screen_faults(d.pages[p])) FAIL_CHECK(fault);
    if (!d.pages[p].segments.empty()) ++pictures;
  }
  CHECK(pictures >= 3);
  // The last state of each page: characters typed one by one are whole words once the line
  // ends, so only whole lines are checked: the words of every text on the last page shown
  // before each new page.
  for (const auto& page : d.pages)
    for (const auto& text : page.texts)
      for (const auto& w : words(text.text))
        if (!known.count(w)) {
          // A word being typed may be seen half-way on a page that a redraw then replaced.
          bool part_of_typed = typed.find(w) != std::string::npos;
          CHECK_MESSAGE(part_of_typed, "a word neither igds's nor typed: " << w);
        }
  // The reasons of the reports are there, whole.
  CHECK(plain.find("INCORRECT ENTRY: POINT 1 IS A CORNER: GIVE 1 (CURVE) OR 0 (STRINGER)") !=
        std::string::npos);
  CHECK(plain.find("INCORRECT PARAMETER: THE THREE ANGLES MUST ADD UP TO 360") !=
        std::string::npos);
  CHECK(plain.find("INCORRECT ENTRY: DISPLAY IS A COMMAND: ANSWER Y OR N FIRST") !=
        std::string::npos);
}

}  // namespace igds::test
