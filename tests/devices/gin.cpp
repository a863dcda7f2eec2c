// The GIN report decoder (devices/gin.h): the key and the cross-hair's position, with each of
// xterm's ginTerminator settings, both address widths, a mouse button's high bit, and bytes
// that are no report; the reader's keys after the mark.
#include "devices/gin.h"

#include <doctest/doctest.h>

#include <string>

namespace igds::test {

namespace {

// A report as xterm's TekEnq writes it (Tekproc.c): key, HiX LoX HiY LoY, terminator.
std::string report(char key, int x, int y, std::string terminator = "") {
  std::string r{key};
  r += static_cast<char>(0x20 | (x >> 5));
  r += static_cast<char>(0x20 | (x & 31));
  r += static_cast<char>(0x20 | (y >> 5));
  r += static_cast<char>(0x20 | (y & 31));
  return r + terminator;
}

}  // namespace

TEST_CASE("GIN: every terminator is taken with the report, and nothing after it") {
  for (const std::string terminator : {"", "\r", "\r\x04", "\n", "\n\x04"}) {
    CAPTURE(terminator.size());
    const auto r = decode_gin(report('A', 500, 300, terminator) + "XY");
    REQUIRE(r);
    CHECK(r->key == 'A');
    CHECK_FALSE(r->button);
    CHECK(r->x == 500);
    CHECK(r->y == 300);
    CHECK(r->used == 5 + terminator.size());
  }
  // An EOT without the CR is no terminator of xterm's.
  CHECK(decode_gin(report('A', 1, 2, "\x04"))->used == 5);
}

TEST_CASE("GIN: the corners of the screen, and both address widths") {
  CHECK(decode_gin(report(' ', 0, 0))->x == 0);
  const auto top = decode_gin(report(' ', 1023, 779));
  CHECK(top->x == 1023);
  CHECK(top->y == 779);
  // A host drawing in 12 bits gets the middle of the 4 x 4 cell the 10-bit report names.
  const auto wide = decode_gin(report('5', 1023, 779), 12);
  CHECK(wide->x == 4094);
  CHECK(wide->y == 3118);
  CHECK(decode_gin(report('5', 0, 0), 12)->x == 2);
  CHECK(decode_gin(report('5', 500, 300), 12)->key == '5');
}

TEST_CASE("GIN: a mouse button comes with its high bit, which is dropped") {
  for (const char button : {'l', 'm', 'r'}) {
    const auto r = decode_gin(report(static_cast<char>(button | 0x80), 100, 200, "\r"));
    REQUIRE(r);
    CHECK(r->key == button);
    CHECK(r->button);
    CHECK(r->x == 100);
    CHECK(r->used == 6);
  }
}

TEST_CASE("GIN: bytes that are no report") {
  CHECK_FALSE(decode_gin(""));
  CHECK_FALSE(decode_gin("A"));
  CHECK_FALSE(decode_gin(report('A', 5, 5).substr(0, 4)));  // one address byte short
  CHECK_FALSE(decode_gin("A\r\r\r\r"));                     // control bytes for addresses
  CHECK_FALSE(decode_gin("Aabcd"));                         // LoY-like bytes, not a report's
  CHECK_FALSE(decode_gin(std::string("A \x7F  ")));
  CHECK_FALSE(decode_gin(std::string("A  \xC3\xA9", 5)));
  // Every single byte out of range in every place is refused.
  for (int place = 1; place <= 4; ++place)
    for (const int b : {0x00, 0x1F, 0x40, 0x80, 0xFF}) {
      std::string r = report('A', 0, 0);
      r[static_cast<std::size_t>(place)] = static_cast<char>(b);
      CHECK_FALSE(decode_gin(r));
    }
}

TEST_CASE("GIN reader: after the mark, arrows are dropped and plain keys are keys, not addresses") {
  const std::string mark = "4" + gin_address(100, 200) + "\r";
  // An arrow's sequences (CSI and SS3), then the click's report and what was typed after it.
  GinReader arrow(100, 200, 10);
  arrow.feed(mark + "\x1B[A\x1BOB" + report(static_cast<char>(0xEC), 30, 40, "\r") + "NEXT");
  REQUIRE(arrow.report());
  CHECK_FALSE(arrow.typed());
  CHECK(arrow.report()->x == 30);
  CHECK(arrow.report()->y == 40);
  CHECK(arrow.rest() == "NEXT");
  // Keys xterm sends as they are with the cross-hair up (the keypad, or keys pressed before it
  // read ESC SUB): typed, although "5 101" and a CR look like a report one byte on.
  GinReader split(100, 200, 10);
  split.feed(mark + "65 101\n" + report('H', 10, 20, "\r"));
  REQUIRE(split.done());
  CHECK(split.typed());
  CHECK_FALSE(split.report());
  CHECK(split.rest().starts_with("65 101\n"));
  // A report begun and not ended: waited for a moment, then a key.
  GinReader one(100, 200, 10);
  one.feed(mark + "5");
  CHECK_FALSE(one.done());
  CHECK(one.unsettled());
  one.settle();
  CHECK(one.typed());
  CHECK(one.rest() == "5");
  // Fed byte by byte, the same.
  GinReader bytes(100, 200, 10);
  for (const char c : mark + "\x1B[A" + report(' ', 7, 8, "\r")) bytes.feed(std::string(1, c));
  REQUIRE(bytes.report());
  CHECK(bytes.report()->x == 7);
}

TEST_CASE("GIN: a click's report is taken out of keys typed with the cross-hair up") {
  CHECK(without_clicks("5" + report(static_cast<char>(0xEC), 30, 40, "\r") + "12\n", 1) == "512\n");
  CHECK(without_clicks("5" + report(static_cast<char>(0xF2), 30, 40), 0) == "5");
  CHECK(without_clicks("\xC3\xA9 1 2\n", 1) == "\xC3\xA9 1 2\n");  // UTF-8 is no click
}

}  // namespace igds::test
