// Golden device streams (tests/golden): byte for byte. IGDS_UPDATE_GOLDEN=1 rewrites them and
// prints what changed.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>

#include "devices/hpgl_plot.h"
#include "devices/svg.h"
#include "devices/tek_stream.h"
#include "tests/devices/support.h"
#include "tests/support/golden.h"
#include "tests/support/process.h"

namespace igds::test::devices {

// The golden images: small, one of each kind.
Image golden_input() {
  return input_image(3, 4);
}
Image golden_surface() {
  return surface_image(5, 4);
}

TEST_CASE("golden: Tektronix 4013 and 4014 streams") {
  check_golden("input_3x4.tek", tek_stream(golden_input(), {}));
  check_golden("surface_5x4.tek", tek_stream(golden_surface(), {}));
  check_golden("surface_5x4_4014.tek", tek_stream(golden_surface(), {12}));
  check_golden("erase.tek", erase_bytes(TermMode::tek, {}));
}

TEST_CASE("golden: HP-GL plots") {
  check_golden("input_3x4.hpgl", plot_hpgl(golden_input(), {}).hpgl);
  check_golden("surface_5x4.hpgl", plot_hpgl(golden_surface(), {}).hpgl);
  check_golden("surface_5x4_a3_absolute.hpgl", plot_hpgl(golden_surface(), {Paper::a3, true}).hpgl);
}

TEST_CASE("golden: SVG") {
  check_golden("input_3x4.svg", svg_of(golden_input()));
  check_golden("surface_5x4.svg", svg_of(golden_surface()));
}

}  // namespace igds::test::devices

namespace igds::test::devices {

TEST_CASE("a golden difference shows the first record that differs, expected and actual") {
  CHECK(first_difference("a\nb\n", "a\nb\n").empty());
  const std::string text = first_difference("a\nb\nc\n", "a\nB\nc\n");
  CHECK(text.find("record 2") != std::string::npos);
  CHECK(text.find("expected: b\\x0A") != std::string::npos);
  CHECK(text.find("actual:   B\\x0A") != std::string::npos);
  const std::string tek = first_difference(
      "\x1D"
      "abc\x1F"
      "READY",
      "\x1D"
      "abd\x1F"
      "READY");
  CHECK(tek.find("expected: \\x1Dabc") != std::string::npos);
  CHECK(tek.find("actual:   \\x1Dabd") != std::string::npos);
  CHECK(first_difference("IN;SP1;PD1,2;", "IN;SP1;PD1,3;").find("expected: PD1,2;") !=
        std::string::npos);
}

}  // namespace igds::test::devices

namespace igds::test::devices {

namespace {

// An SvgWriter given its polylines as moves and draws, one point at a time.
struct PointByPoint : Device {
  SvgWriter& svg;
  explicit PointByPoint(SvgWriter& s) : svg(s) {}
  void move(DevicePoint p) override { svg.move(p); }
  void draw(DevicePoint p) override { svg.draw(p); }
  void text(DevicePoint p, std::string_view line) override { svg.text(p, line); }
  void page() override { svg.page(); }
  void style(const Style& s) override { svg.style(s); }
};

}  // namespace

TEST_CASE("SVG: a polyline written at once is the element its moves and draws make") {
  const std::vector<DevicePath> paths{{{1, 2}, {1, 2}, {30, 40}, {30, 40}, {50, 7}},
                                      {{50, 7}, {60, 8}},  // goes on where the last ended
                                      {{9, 9}, {9, 9}},    // a point: nothing drawn
                                      {{-5, 1000}, {1023, 0}, {-2147483647, 2147483647}}};
  const std::vector<Style> styles{{}, {}, {2}, {3, Dash::dashed, 2}};
  StringOut once_text, point_text;
  SvgWriter at_once(once_text), by_point(point_text);
  PointByPoint points(by_point);
  for (int page = 0; page < 2; ++page) {
    for (std::size_t k = 0; k < paths.size(); ++k) {
      at_once.style(styles[k]);
      at_once.polyline(paths[k]);
      points.style(styles[k]);
      points.Device::polyline(paths[k]);
    }
    at_once.text({3, 4}, "A<B");
    by_point.text({3, 4}, "A<B");
    if (page == 0) at_once.page(), by_point.page();
  }
  at_once.finish();
  by_point.finish();
  const std::string document = once_text.take_text();
  CHECK(document == point_text.take_text());
  // The second page paints the first over, and draws again.
  CHECK(document.find("<rect width=\"1024\" height=\"780\" fill=\"white\" stroke=\"none\"/>") !=
        std::string::npos);
  CHECK(document.find("<polyline points=\"1,777 30,739 50,772 60,771\"/>") != std::string::npos);
  CHECK(document.find("-2147483647,") != std::string::npos);
}

TEST_CASE("SVG: a drawing's paths written at once, on the cores, are the elements path by path") {
  // Paths of every length up to hundreds of points, repeated points, paths that go on where the
  // last ended, paths of one place, empty paths, styles that change the attributes and styles
  // that do not: a document of megabytes. The second page's paths come in parts.
  PathList list;
  std::vector<Style> styles;
  DevicePoint last{0, 0};
  for (int k = 0; k < 6000; ++k) {
    const int n = k % 13 == 0 ? 0 : k % 7 == 0 ? 400 + k % 300 : k % 9 + 1;
    DevicePoint p = k % 5 == 0 ? last : DevicePoint{k % 1000, k % 700};
    for (int i = 0; i < n; ++i) {
      list.points.push_back(p);
      if (k % 17 == 0 && i < 3) continue;  // a path of one place, or repeats at its start
      if (i % 11 != 5) p = {(p.x + 7 * i + k) % 1024, (p.y + 3 * i + 1) % 780};
    }
    if (n > 0) last = list.points.back();
    list.starts.push_back(list.points.size());
    styles.push_back(k % 400 < 300 ? Style{}
                                   : Style{k % 400 < 350 ? 2 : 3, Dash::dashed, k % 2 + 1});
  }
  REQUIRE(list.points.size() > 300000);
  // The same paths in three lists, the second empty, as a drawing placed in parts holds them.
  PathParts whole, parts;
  whole.parts.push_back(list);
  parts.parts.resize(3);
  for (std::size_t k = 0; k < list.size(); ++k) {
    PathList& part = parts.parts[k < 2500 ? 0 : 2];
    part.points.insert(part.points.end(), list[k].begin(), list[k].end());
    part.starts.push_back(part.points.size());
  }
  REQUIRE(parts.size() == list.size());
  StringOut once_text, path_text;
  SvgWriter at_once(once_text), by_path(path_text);
  for (int page = 0; page < 2; ++page) {
    if (page == 0)
      at_once.paths(whole, styles);
    else
      at_once.paths(parts, styles);
    for (std::size_t k = 0; k < list.size(); ++k) {
      by_path.style(styles[k]);
      by_path.polyline(list[k]);
    }
    at_once.text({3, 4}, "A");
    by_path.text({3, 4}, "A");
    if (page == 0) at_once.page(), by_path.page();
  }
  at_once.finish();
  by_path.finish();
  const std::string document = once_text.take_text();
  CHECK(document.size() > (std::size_t{4} << 20));
  CHECK(document == path_text.take_text());
}

}  // namespace igds::test::devices
