// The dialogue on the Tek screen: CR LF line ends, long lines broken at the right edge, and a
// line that would fall below the bottom going back to the top left, so that no terminal or
// decoder ever wraps it into the right half of the screen.
#include <doctest/doctest.h>

#include <string>

#include "commands/picture.h"
#include "devices/layout.h"
#include "devices/terminal.h"
#include "tests/devices/support.h"

namespace igds {

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("the Tek dialogue: lines end in CR LF and go back to the top left at the bottom") {
  for (int bits : {10, 12}) {
    CAPTURE(bits);
    TekDialogue dialogue({bits});
    const std::string home = dialogue.home();
    // A dark move to the top left, then alpha mode: nothing drawn, nothing erased.
    const auto decoded = test::devices::decode_tek(home, bits);
    CHECK(decoded.paths.empty());
    CHECK(decoded.pages == 0);
    CHECK(decoded.ends_in_alpha);
    REQUIRE(decoded.beam);
    const int unit = bits == 12 ? 4 : 1;
    CHECK(decoded.beam->x == 0);
    CHECK(decoded.beam->y == tek_screen::text_top * unit);
    std::string lines;
    for (int i = 0; i < 100; ++i) lines += "READY\n";
    const std::string out = dialogue.text(lines);
    // 34 lines fit between the top baseline (734) and the bottom: 33 CR LF, then the top again.
    const int per_screen = tek_screen::text_top / tek_screen::line_height + 1;
    CHECK(per_screen == 34);
    CHECK(count(out, "\r\n") == 100 - 100 / per_screen);
    CHECK(count(out, home) == 100 / per_screen);
    CHECK(out.find('\n') == out.find("\r\n") + 1);
    const auto first_home = out.find(home);
    CHECK(count(out.substr(0, first_home), "\r\n") == per_screen - 1);
  }
}

TEST_CASE("the Tek dialogue: a line too long for the screen is broken at its right edge") {
  TekDialogue dialogue({10});
  dialogue.home();
  const std::string out = dialogue.text(std::string(100, 'X') + "\n");
  // 73 characters of 14 points fit in 1024 points.
  CHECK(out == std::string(73, 'X') + "\r\n" + std::string(27, 'X') + "\r\n");

  // After a DISPLAY the dialogue goes on beside the description: 17 characters fit there.
  const Image image = test::devices::surface_image(3, 4);
  dialogue.displayed(picture_of(image));
  CHECK(dialogue.text(std::string(20, 'Y')) == std::string(17, 'Y') + "\r\nYYY");
}

TEST_CASE("the Tek dialogue after a DISPLAY goes on where the stream leaves the alpha cursor") {
  for (const Image& image :
       {test::devices::surface_image(3, 4), test::devices::input_image(3, 4)}) {
    // Where display_bytes really leaves the beam, decoded from the stream.
    const auto decoded =
        test::devices::decode_tek(display_bytes(picture_of(image), TermMode::tek, {10}), 10);
    REQUIRE(decoded.ends_in_alpha);
    REQUIRE(decoded.beam);
    CHECK(decoded.beam->x == tek_screen::text_x);
    TekDialogue dialogue({10});
    dialogue.home();
    dialogue.displayed(picture_of(image));
    // From there, the lines the dialogue writes before it goes back to the top are those left
    // above the bottom baseline.
    std::string many;
    for (int i = 0; i < 40; ++i) many += "L\n";
    const std::string out = dialogue.text(many);
    const int bottom = tek_screen::text_top % tek_screen::line_height;
    const int left = (decoded.beam->y - bottom) / tek_screen::line_height;
    CHECK(count(out.substr(0, out.find(TekDialogue({10}).home())), "\r\n") == left);
  }
}

}  // namespace igds
