// The 2250 workspace's screen (devices/menu_layout.h): every menu item has a box inside the
// screen, no box overlaps another, the picture, its caption or the text area; a point maps to
// the item whose box holds it and to none elsewhere.
#include "devices/menu_layout.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "devices/tek_screen.h"
#include "tests/devices/support.h"
#include "tests/support/tek_decoder.h"

namespace igds::test {

namespace {

bool overlap(const Box& a, const Box& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

bool inside(const Box& a, const Box& outer) {
  return a.x0 >= outer.x0 && a.x1 <= outer.x1 && a.y0 >= outer.y0 && a.y1 <= outer.y1;
}

}  // namespace

TEST_CASE("menu layout: boxes inside the screen, apart from each other and from the rest") {
  // xterm's Tek window shows x 0..1023, y 0..767 (docs/devices.md, "Tektronix 4013").
  const Box screen{0, 0, 1023, 767};
  for (const std::size_t n : {1u, 19u, 23u, 29u, 31u, 32u, 45u, 62u}) {
    CAPTURE(n);
    const MenuLayout l = menu_layout(n);
    REQUIRE(l.items.size() == n);
    for (std::size_t i = 0; i < n; ++i) {
      CAPTURE(i);
      CHECK(inside(l.items[i], screen));
      CHECK(inside(l.items[i], l.menu));
      // A label of label_columns characters fits in its box, a line high.
      CHECK(l.items[i].x1 - l.items[i].x0 >=
            menu_screen::label_columns * tek_screen::char_width + 4);
      CHECK(l.items[i].y1 - l.items[i].y0 >= tek_screen::line_height - 2);
      for (std::size_t j = i + 1; j < n; ++j) CHECK_FALSE(overlap(l.items[i], l.items[j]));
    }
    for (const Box& other : {l.picture, l.caption, l.text}) {
      CHECK(inside(other, screen));
      CHECK_FALSE(overlap(l.menu, other));
    }
    CHECK_FALSE(overlap(l.picture, l.text));
    CHECK_FALSE(overlap(l.picture, l.caption));
    CHECK_FALSE(overlap(l.caption, l.text));
    // The dialogue rows and the caption lines of the TekScreen stay in their boxes.
    CHECK(l.screen.dialogue_columns * tek_screen::char_width <= l.text.x1);
    CHECK(l.screen.caption_x + int(caption_width) * tek_screen::char_width <= l.caption.x1);
    CHECK(l.screen.dialogue_top + 16 <= l.text.y1);
    CHECK(l.screen.image.x1 < l.caption.x0);
  }
  // The manual's menu and igds's additions in one column, the picture as big as in tek mode.
  const MenuLayout l = menu_layout(30);
  CHECK(l.items.front().x0 == l.items.back().x0);
  CHECK(l.picture.x1 - l.picture.x0 == doctest::Approx(583));
}

TEST_CASE("menu layout: a point picks the item under it, none between or beside the boxes") {
  const MenuLayout l = menu_layout(40);
  for (std::size_t k = 0; k < l.items.size(); ++k) {
    const Box& b = l.items[k];
    CHECK(item_at(l, int((b.x0 + b.x1) / 2), int((b.y0 + b.y1) / 2)) == int(k));
    CHECK(item_at(l, int(b.x0), int(b.y0)) == int(k));  // the edges belong to it
    CHECK(item_at(l, int(b.x1), int(b.y1)) == int(k));
  }
  // Between two boxes of a column, on the picture, in the text area, off the menu.
  const Box& a = l.items[0];
  CHECK(item_at(l, int(a.x0) + 5, int(a.y0) - 1) == -1);
  CHECK(item_at(l, 300, 500) == -1);
  CHECK(item_at(l, 10, 10) == -1);
  CHECK(item_at(l, 1023, 779) == -1);
  CHECK(item_at(l, -5, -5) == -1);
}

TEST_CASE("menu drawing: a box and a label per item, each with its item's identity") {
  const MenuLayout l = menu_layout(3);
  const std::vector<std::string> labels{"END APL", "BUILD", "D SURFACE"};
  const Drawing2 d = menu_drawing(l, labels);
  REQUIRE(d.size() == 6);
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& box = d.items()[2 * k];
    const auto& text = d.items()[2 * k + 1];
    CHECK(box.kind == Drawing2::Kind::polyline);
    CHECK(box.closed);
    CHECK(box.id == Identity{Role::menu, int(k)});
    CHECK(text.kind == Drawing2::Kind::text);
    CHECK(d.text(text) == labels[k]);
    const Point2 at = d.points(text)[0];
    CHECK(item_at(l, int(at.x), int(at.y)) == int(k));
  }
}

TEST_CASE("the Tek screen with the menu as its frame: on every page, never written over") {
  const MenuLayout l = menu_layout(23);
  std::vector<std::string> labels;
  for (int k = 0; k < 23; ++k) labels.push_back("ITEM " + std::to_string(k));
  TekScreen screen({}, true);
  screen.set_frame(std::make_shared<const Drawing2>(menu_drawing(l, labels)), l.screen);
  std::string bytes = screen.repaint();
  std::string words;
  for (int i = 0; i < 30; ++i)
    words += "A LINE OF DIALOGUE LONG ENOUGH TO BE WRAPPED " + std::to_string(i) + " ";
  bytes += screen.text(words + "\n");
  bytes +=
      screen.picture(std::make_shared<const Picture>(picture_of(devices::surface_image(9, 9))));
  for (int i = 0; i < 12; ++i) bytes += screen.text("READY\n");
  bytes += screen.document_page(true);
  bytes += screen.text(words + "\n");
  bytes += screen.end_document();
  const TekDrawing d = decode_tek(bytes);
  CHECK(d.errors.empty());
  REQUIRE(d.pages.size() >= 4);
  for (std::size_t p = 1; p < d.pages.size(); ++p) {
    CAPTURE(p);
    const TekPage& page = d.pages[p];
    for (const auto& label : labels) {
      const bool shown = std::any_of(page.texts.begin(), page.texts.end(),
                                     [&](const TekText& t) { return t.text == label; });
      CHECK_MESSAGE(shown, label);
    }
    for (const auto& fault : screen_faults(page)) FAIL_CHECK(fault);
    // Text other than the labels stays left of the menu.
    for (const auto& t : page.texts)
      if (!t.text.starts_with("ITEM"))
        CHECK(t.at.x + 14.0 * static_cast<double>(t.text.size()) <= l.menu.x0);
  }
}

}  // namespace igds::test
