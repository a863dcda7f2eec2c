// The 4013 encoder (devices/tek4013.h) and what DISPLAY and ERASE send (devices/tek_stream.h).
#include "devices/tek4013.h"

#include <doctest/doctest.h>

#include "devices/layout.h"
#include "devices/tek_stream.h"
#include "tests/devices/support.h"

namespace igds::test::devices {

TEST_CASE("tek_address: the whole address, 10 and 12 bits") {
  CHECK(tek_address(100, 100) == "#d#D");
  CHECK(tek_address(0, 0) == std::string("\x20\x60\x20\x40"));
  CHECK(tek_address(1023, 779) == std::string("\x38\x6B\x3F\x5F"));
  // LoY 0x7F (y & 31 == 31) is a legal byte and passes unchanged.
  CHECK(tek_address(0, 31) == std::string("\x20\x7F\x20\x40"));
  // 12 bits: HiY Extra LoY HiX LoX; (4093, 3118): y = 3118 = 11000 01011 10, x = 11111 11111 01.
  CHECK(tek_address(4093, 3118, 12) ==
        std::string{0x20 | 24, char(0x60 | (2 << 2) | 1), 0x60 | 11, 0x20 | 31, 0x40 | 31});
  CHECK(tek_address(400, 400, 12) == std::string{0x20 | 3, 0x60, 0x60 | 4, 0x20 | 3, 0x40 | 4});
}

TEST_CASE("TekEncoder: shortened addresses inside a polyline") {
  TekEncoder t;
  t.move({100, 100});
  CHECK(t.bytes() == "\x1D#d#D");
  t.draw({101, 100});  // only x's low bits changed: LoX alone
  CHECK(t.bytes().substr(5) == "E");
  t.draw({101, 101});  // LoY changed: LoY LoX
  CHECK(t.bytes().substr(6) == "eE");
  t.draw({140, 101});  // HiX changed: LoY is sent again so that the high byte is read as HiX
  CHECK(t.bytes().substr(8) == "e$L");
  t.draw({140, 140});  // HiY and LoY changed, HiX not: HiY LoY LoX
  CHECK(t.bytes().substr(11) == "$lL");
  t.draw({140, 140});  // nothing to draw: nothing sent
  t.move({140, 140});  // already there in graph mode: nothing sent
  CHECK(t.bytes().size() == 14);
  t.move({0, 0});  // a dark move: GS and the whole address
  CHECK(t.bytes().substr(14) == "\x1D\x20\x60\x20\x40");
  auto d = decode_tek(t.bytes(), 10);
  REQUIRE(d.paths.size() == 1);
  CHECK(d.paths[0] == DevicePath{{100, 100}, {101, 100}, {101, 101}, {140, 101}, {140, 140}});
}

TEST_CASE("TekEncoder: 12-bit addresses always carry Extra and LoY") {
  TekEncoder t(12);
  t.move({400, 400});
  t.draw({401, 400});
  t.draw({402, 402});
  std::string b = t.bytes();
  CHECK(b == cat({"\x1D", tek_address(400, 400, 12), "\x61\x64\x44", "\x6A\x64\x44"}));
  auto d = decode_tek(b, 12);
  REQUIRE(d.paths.size() == 1);
  CHECK(d.paths[0] == DevicePath{{400, 400}, {401, 400}, {402, 402}});
}

TEST_CASE("TekEncoder: the first address after text or a page is whole") {
  TekEncoder t;
  t.move({100, 100});
  t.draw({101, 100});
  t.text({780, 734}, "SURFACE");
  t.move({101, 100});
  t.draw({102, 100});
  std::string b = t.bytes();
  auto after_text = b.substr(b.find("SURFACE") + 7);
  CHECK(after_text == cat({"\x1D", tek_address(101, 100), "F"}));
  t.page();
  t.move({102, 100});
  b = t.bytes();
  CHECK(b.substr(b.size() - 11) == std::string("\x1B\x0C\x1B"
                                               "8\x1B`\x1D") +
                                       tek_address(102, 100));
}

TEST_CASE("TekEncoder: text is printable 7-bit and starts where the beam was put") {
  TekEncoder t;
  t.text({780, 500}, "A\nB\x01\xC3\xA9");
  CHECK(t.bytes() == cat({"\x1D", tek_address(780, 500), "\x1F", "A?B???"}));
  auto d = decode_tek(t.bytes(), 10);
  REQUIRE(d.texts.size() == 1);
  CHECK(d.texts[0].first == DevicePoint{780, 500});
  CHECK(d.ends_in_alpha);
}

namespace {

// Graph data never holds CR or LF, every byte is 7-bit, and there is one GS per polyline.
void check_stream(const std::string& s, std::size_t polylines) {
  std::size_t gs = 0;
  bool graph = false;
  for (char c : s) {
    CHECK(static_cast<unsigned char>(c) < 0x80);
    if (c == '\x1D') ++gs, graph = true;
    if (c == '\x1F' || c == '\x1B') graph = false;
    if (graph) CHECK((c != '\r' && c != '\n'));
  }
  CHECK(gs == polylines);
}

}  // namespace

TEST_CASE("display_bytes: tek mode draws without erasing and ends in alpha mode") {
  for (const Image& im : {surface_image(5, 4), input_image(3, 4)}) {
    Recorder r;
    DevicePoint cursor = draw_tek_display(picture_of(im), r, 1);
    std::string s = display_bytes(im, TermMode::tek, {});
    CHECK(s.find("\x1B\x0C") == std::string::npos);  // DISPLAY never erases (storage tube)
    REQUIRE(!s.empty());
    CHECK(s.back() == '\x1F');
    // One GS per polyline and per text line, one to put the alpha cursor back.
    check_stream(s, r.drawn().size() + r.texts.size() + 1);
    auto d = decode_tek(s, 10);
    CHECK(d.paths == r.drawn());
    REQUIRE(d.texts.size() == r.texts.size());
    for (std::size_t i = 0; i < r.texts.size(); ++i) {
      CHECK(d.texts[i].first == r.texts[i].at);
      CHECK(d.texts[i].second == r.texts[i].line);
    }
    // The dialogue goes on at the text column, on the line below the description.
    CHECK(d.beam == cursor);
    // (The point numbers of an input image are texts too, in the picture.)
    const int caption = static_cast<int>(picture_of(im).caption.size());
    CHECK(cursor == DevicePoint{tek_screen::text_x,
                                tek_screen::text_top - tek_screen::line_height * caption});
  }
}

TEST_CASE("display_bytes: the image in the square 0..767, the description right of it") {
  Image im = surface_image(7, 9);
  Recorder r;
  draw_tek_display(picture_of(im), r, 1);
  int x0 = 9999, y0 = 9999, x1 = -1, y1 = -1;
  for (const auto& p : r.drawn())
    for (auto q : p)
      x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y),
      y1 = std::max(y1, q.y);
  CHECK(x0 >= tek_screen::image_margin);
  CHECK(y0 >= tek_screen::image_margin);
  CHECK(x1 <= 767 - tek_screen::image_margin);
  CHECK(y1 <= 767 - tek_screen::image_margin);
  // Centred, and as large as the square allows in one direction.
  CHECK(std::abs((x0 + x1) - 767) <= 1);
  CHECK(std::abs((y0 + y1) - 767) <= 1);
  CHECK((x1 - x0 >= 767 - 2 * tek_screen::image_margin - 1 ||
         y1 - y0 >= 767 - 2 * tek_screen::image_margin - 1));
  REQUIRE(r.texts.size() == 3);
  CHECK(r.texts[0].line == "SURFACE");
  CHECK(r.texts[1].line == "ASSONOMETRIC");
  CHECK(r.texts[2].line == "110 130 120");
  for (const auto& t : r.texts) {
    CHECK(t.at.x >= 780);
    CHECK(t.at.x + tek_screen::char_width * static_cast<int>(t.line.size()) <= 1024);
    CHECK(t.at.y <= 767);
  }
}

TEST_CASE("display_bytes: 12 bits is the same picture at four times the resolution") {
  Image im = surface_image(5, 6);
  Recorder r10, r12;
  draw_tek_display(picture_of(im), r10, 1);
  draw_tek_display(picture_of(im), r12, 4);
  auto d = decode_tek(display_bytes(im, TermMode::tek, {12}), 12);
  CHECK(d.paths == r12.drawn());
  REQUIRE(r10.drawn().size() == r12.drawn().size());
  for (std::size_t i = 0; i < r10.drawn().size(); ++i)
    for (std::size_t k = 0; k < r10.drawn()[i].size(); ++k) {
      CHECK(std::abs(r12.drawn()[i][k].x - 4 * r10.drawn()[i][k].x) <= 2);
      CHECK(std::abs(r12.drawn()[i][k].y - 4 * r10.drawn()[i][k].y) <= 2);
    }
}

TEST_CASE("display_bytes and erase_bytes by terminal mode") {
  Image im = surface_image(3, 3);
  std::string tek = display_bytes(im, TermMode::tek, {});
  CHECK(display_bytes(im, TermMode::xterm, {}) == "\x1B[?38h" + tek + "\x1F\x1B\x03");
  CHECK(display_bytes(im, TermMode::none, {}).empty());
  CHECK(erase_bytes(TermMode::tek, {}) == std::string("\x1B\x0C\x1B"
                                                      "8\x1B`"));
  CHECK(erase_bytes(TermMode::xterm, {}) == std::string("\x1B[?38h\x1B\x0C\x1B"
                                                        "8\x1B`\x1F\x1B\x03"));
  CHECK(erase_bytes(TermMode::none, {}).empty());
}

TEST_CASE("tek_stream: a page, then what DISPLAY draws") {
  Image im = input_image(3, 4);
  std::string s = tek_stream(im, {});
  CHECK(s.rfind("\x1B\x0C\x1B"
                "8\x1B`",
                0) == 0);
  CHECK(s.substr(6) == display_bytes(im, TermMode::tek, {}));
  CHECK(decode_tek(s, 10).pages == 1);
}

TEST_CASE("Tek streams of images that cannot be drawn are still complete") {
  Image bad;
  bad.points = Array({3, 2});  // not planes x rows x 2
  std::string s = tek_stream(bad, {});
  auto d = decode_tek(s, 10);
  CHECK(d.paths.empty());
  CHECK(d.texts.size() == 3);
  Image huge = surface_image(3, 3);
  huge.points.ravel[0] = 1e308;
  huge.points.ravel[3] = -1e308;
  huge.points.ravel[5] = std::nan("");
  auto h = decode_tek(tek_stream(huge, {}), 10);
  for (const auto& p : h.paths)
    for (auto q : p) CHECK((q.x >= 0 && q.x <= 1023 && q.y >= 0 && q.y <= 779));
}

}  // namespace igds::test::devices
