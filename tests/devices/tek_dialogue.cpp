// The dialogue on the Tek screen: CR LF line ends, long lines broken at the right edge, and a
// line that would fall below the bottom going back to the top left, so that no terminal or
// decoder ever wraps it into the right half of the screen.
#include <doctest/doctest.h>

#include <string>

#include "devices/layout.h"
#include "devices/picture.h"
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
    CHECK(home == home_bytes(TermMode::tek, {bits}));
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
  dialogue.displayed(image);
  CHECK(dialogue.text(std::string(20, 'Y')) == std::string(17, 'Y') + "\r\nYYY");
}

TEST_CASE("the Tek dialogue after a DISPLAY starts below the description, as the stream says") {
  const Image image = test::devices::surface_image(3, 4);
  const auto lines = describe(image.desim, description_width).size();
  REQUIRE(lines >= 2);
  TekDialogue dialogue({10});
  dialogue.home();
  dialogue.displayed(image);
  // From the line below the description, the lines left before the bottom are fewer by as many.
  std::string many;
  for (int i = 0; i < 40; ++i) many += "L\n";
  const std::string out = dialogue.text(many);
  const int below = static_cast<int>(tek_screen::text_top / tek_screen::line_height - lines);
  CHECK(count(out.substr(0, out.find(dialogue.home())), "\r\n") == below);
}

}  // namespace igds
