// The HP-GL encoder, the plot order and the plot layout (devices/hpgl.h, devices/plot_order.h,
// devices/hpgl_plot.h).
#include "devices/hpgl.h"
#include "devices/plot_order.h"

#include <doctest/doctest.h>

#include <regex>

#include "tests/devices/support.h"

namespace igds::test::devices {

namespace {

// Every coordinate pair of PU/PD instructions, made absolute, in the order sent.
std::vector<DevicePoint> absolute_points(const std::string& hpgl) {
  std::vector<DevicePoint> out;
  bool relative = false;
  DevicePoint at{0, 0};
  static const std::regex instruction(R"(([A-Z]{2})([^;\x03]*)[;\x03])");
  for (auto it = std::sregex_iterator(hpgl.begin(), hpgl.end(), instruction);
       it != std::sregex_iterator(); ++it) {
    std::string op = (*it)[1], args = (*it)[2];
    if (op == "PA") relative = false;
    if (op == "PR") relative = true;
    if (op != "PU" && op != "PD") continue;
    std::vector<int> v;
    std::size_t pos = 0;
    while (pos < args.size()) {
      std::size_t end = args.find(',', pos);
      if (end == std::string::npos) end = args.size();
      v.push_back(std::stoi(args.substr(pos, end - pos)));
      pos = end + 1;
    }
    for (std::size_t i = 0; i + 1 < v.size(); i += 2) {
      at = relative ? DevicePoint{at.x + v[i], at.y + v[i + 1]} : DevicePoint{v[i], v[i + 1]};
      out.push_back(at);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("paper_named: A4 A3 LETTER B in any case") {
  CHECK(paper_named("a4") == Paper::a4);
  CHECK(paper_named("A3") == Paper::a3);
  CHECK(paper_named("Letter") == Paper::letter);
  CHECK(paper_named("b") == Paper::b);
  CHECK(!paper_named("A5"));
  CHECK(!paper_named(""));
  CHECK(!paper_named("A44"));
}

TEST_CASE("HpglEncoder: relative polylines, absolute after IN and after a label") {
  StringOut out;
  HpglEncoder h(hp7475a, false, out);
  h.move({1000, 2000});
  h.draw({1010, 2000});
  h.draw({1010, 2005});
  h.draw({1010, 2005});  // nothing
  h.move({1010, 2005});  // already there: nothing
  h.draw({1000, 2000});
  h.move({3000, 2000});
  h.draw({3000, 1000});
  h.text({500, 500}, "SURFACE");
  h.move({600, 600});
  h.draw({601, 600});
  h.finish();
  const std::string bytes = out.take_text();
  CHECK(bytes ==
        "IN;SP1;SI0.2,0.3;PU1000,2000;PR;PD10,0,0,5,-10,-5;PU2000,0;PD0,-1000;"
        "PA;PU500,500;LBSURFACE\x03PU600,600;PR;PD1,0;PU;SP0;");
  const PlotStats& s = h.stats();
  CHECK(s.vectors == 5);
  CHECK(s.pen_lifts == 4);
  CHECK(s.bytes == bytes.size());
  // Travel: from the origin, the two moves, to the label, from its estimated end, back.
  double label_end = 500 + std::lround(7 * 1.5 * 2.0 / 0.02488);
  double travel = std::hypot(1000, 2000) + 2000 + std::hypot(2500, 500) +
                  std::hypot(600 - label_end, 100) + std::hypot(601, 600);
  CHECK(s.pen_up_mm == doctest::Approx(travel * 0.02488));
}

TEST_CASE("HpglEncoder: the absolute twin sends the same points") {
  for (bool absolute : {false, true}) {
    StringOut out;
    HpglEncoder h(hp7475a, absolute, out);
    h.move({10, 20});
    h.draw({30, 40});
    h.draw({50, 40});
    h.move({0, 0});
    h.draw({5, 5});
    h.finish();
    const std::string bytes = out.take_text();
    CHECK(absolute_points(bytes) ==
          std::vector<DevicePoint>{{10, 20}, {30, 40}, {50, 40}, {0, 0}, {5, 5}});
    CHECK((bytes.find("PR;") == std::string::npos) == absolute);
  }
}

TEST_CASE("HpglEncoder: labels are printable and end with ETX") {
  StringOut out;
  HpglEncoder h(hp7475a, false, out);
  h.text({0, 0}, "A;B\x03\n");
  h.finish();
  CHECK(out.take_text() == "IN;SP1;SI0.2,0.3;PU0,0;LBA;B??\x03PU;SP0;");
}

namespace {

// The plot of `order` by draw_order and point by point (move to each polyline, draw each
// point), after a label (the pen's place only estimated) and with a pen change: the same bytes
// and statistics.
void check_draw_order(const PlotOrder& order, std::span<const Line> lines) {
  for (bool absolute : {false, true}) {
    std::string bytes[2];
    PlotStats stats[2];
    for (int by_point : {0, 1}) {
      StringOut out;
      HpglEncoder h(hp7475a, absolute, out);
      h.text({3, 4}, "A");
      h.style({.pen = 2});
      if (by_point) {
        for (std::size_t k = 0; k < order.size(); ++k)
          for (std::size_t s = order.starts[k]; s < order.starts[k + 1]; ++s) {
            const Stroke& stroke = order.strokes[s];
            if (s == order.starts[k]) h.move(stroke.begin(lines));
            for (std::size_t i = stroke.first; i <= stroke.last; ++i)
              h.draw(lines[stroke.line][stroke.reversed ? stroke.last + stroke.first - i : i]);
          }
      } else {
        h.draw_order(order, lines);
      }
      h.move({7, 7});
      h.draw({9, 9});
      h.finish();
      bytes[by_point] = out.take_text();
      stats[by_point] = h.stats();
    }
    CHECK(bytes[0] == bytes[1]);
    CHECK(stats[0].vectors == stats[1].vectors);
    CHECK(stats[0].pen_lifts == stats[1].pen_lifts);
    CHECK(stats[0].pen_up_mm == stats[1].pen_up_mm);
    CHECK(stats[0].bytes == stats[1].bytes);
  }
}

}  // namespace

TEST_CASE("HpglEncoder::draw_order: the plot of its strokes drawn point by point") {
  // Walks of every length (one segment, hundreds), repeats dropped by the order, strokes
  // reversed; `many` makes a plot of megabytes, written on the cores.
  for (int many : {300, 12000}) {
    CAPTURE(many);
    std::vector<DevicePath> paths;
    for (int k = 0; k < many; ++k) {
      DevicePath p;
      const int points = k % 7 == 0 ? k % 401 + 1 : k % 17 + 1;
      for (int i = 0; i <= points; ++i)
        p.push_back({(k * 37 + i * 11) % 5000, (k * 13 + i * i) % 4000});
      paths.push_back(p);
      if (k % 5 == 0) paths.push_back(DevicePath(p.rbegin(), p.rend()));
    }
    const std::vector<Line> lines(paths.begin(), paths.end());
    PlotOrder order;
    plot_order(lines, {0, 0}, order);
    REQUIRE(order.size() > 100);
    check_draw_order(order, lines);
  }
}

TEST_CASE("HpglEncoder::draw_order: any order, polylines that go on and points that repeat") {
  // Made by hand, not by plot_order: a polyline starting where the one before ended, points
  // repeated at a stroke's start and end (a polyline of one place), strokes that do not start
  // where the one before ended, and strokes longer than a chunk of the parallel writing.
  std::vector<DevicePath> paths;
  for (int k = 0; k < 4000; ++k) {
    DevicePath p;
    const int points = k % 9 == 0 ? 700 : k % 5 + 1;
    p.push_back({k % 300, k % 200});
    if (k % 4 == 0) p.push_back(p.back());
    for (int i = 1; i <= points; ++i)
      p.push_back({(k * 7 + i * (k % 3)) % 3000, (k * 3 + i) % 2000});
    if (k % 6 == 0) p.push_back(p.back());
    if (k % 11 == 0) p.assign(3, p.front());
    paths.push_back(p);
  }
  const std::vector<Line> lines(paths.begin(), paths.end());
  PlotOrder order;
  order.strokes.clear();
  for (std::size_t j = 0; j < lines.size(); ++j) {
    const std::size_t last = lines[j].size() - 1;
    order.strokes.push_back({j, 0, last, j % 3 == 1});
    // A polyline of one stroke or two; the second goes back along the first.
    if (j % 8 == 2) order.strokes.push_back({j, 0, last, j % 3 != 1});
    if (j % 10 == 0 || j % 10 == 3) continue;  // the next polyline goes on from here
    order.starts.push_back(order.strokes.size());
  }
  if (order.starts.back() != order.strokes.size()) order.starts.push_back(order.strokes.size());
  check_draw_order(order, lines);
}

TEST_CASE("plot_order: duplicates dropped, ends joined, nearest end first, reversed") {
  // A 2 x 2 patch wireframe drawn patch by patch: every inner edge twice.
  std::vector<DevicePath> patches;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      int x = 100 * i, y = 100 * j;
      patches.push_back({{x, y}, {x + 100, y}, {x + 100, y + 100}, {x, y + 100}, {x, y}});
    }
  auto ordered = plot_order(patches, {0, 0});
  std::size_t segments = 0;
  for (const auto& p : ordered) segments += p.size() - 1;
  CHECK(segments == 12);  // 16 drawn, 4 shared
  CHECK(pen_up_travel(ordered, {0, 0}, {0, 0}) <= pen_up_travel(patches, {0, 0}, {0, 0}));
  // Deterministic.
  CHECK(plot_order(patches, {0, 0}) == ordered);
  // Nearest end: a path far away whose end is near is reversed.
  std::vector<DevicePath> two{{{1000, 0}, {2000, 0}}, {{50, 1000}, {10, 10}}};
  auto o = plot_order(two, {0, 0});
  REQUIRE(o.size() == 2);
  CHECK(o[0] == DevicePath{{10, 10}, {50, 1000}});
  CHECK(o[1] == DevicePath{{1000, 0}, {2000, 0}});
  // Paths whose ends meet become one, whichever way they were drawn.
  std::vector<DevicePath> chain{{{0, 0}, {10, 0}}, {{20, 0}, {30, 0}}, {{20, 0}, {10, 0}}};
  auto c = plot_order(chain, {0, 0});
  REQUIRE(c.size() == 1);
  CHECK(c[0] == DevicePath{{0, 0}, {10, 0}, {20, 0}, {30, 0}});
  // Joined before the ordering: starting beside the joint does not split the path there.
  auto j = plot_order({{{10, 0}, {20, 0}}, {{0, 0}, {10, 0}}}, {10, 1});
  REQUIRE(j.size() == 1);
  CHECK(j[0] == DevicePath{{0, 0}, {10, 0}, {20, 0}});
  // A ring of pieces closes on itself; three ends at one point are left to the ordering.
  auto ring = plot_order({{{0, 0}, {10, 0}}, {{10, 10}, {10, 0}}, {{10, 10}, {0, 0}}}, {0, 0});
  REQUIRE(ring.size() == 1);
  CHECK(ring[0].size() == 4);
  CHECK(ring[0].front() == ring[0].back());
  auto star = plot_order({{{0, 0}, {5, 5}}, {{10, 0}, {5, 5}}, {{5, 5}, {5, 10}}}, {0, 0});
  std::size_t star_segments = 0;
  for (const auto& p : star) star_segments += p.size() - 1;
  CHECK(star_segments == 3);
  CHECK(star.size() == 2);
}

TEST_CASE("plot_order: many pieces, the grid search agrees with a plain search") {
  // Segments scattered on a lattice: the nearest end must be the true nearest every time.
  std::vector<DevicePath> paths;
  unsigned seed = 12345;
  auto next = [&] {
    return seed = seed * 1103515245u + 12345u, static_cast<int>((seed >> 8) % 5000);
  };
  for (int i = 0; i < 3000; ++i) {
    int x = next(), y = next();
    paths.push_back({{x, y}, {x + next() % 40, y + next() % 40 + 1}});
  }
  auto ordered = plot_order(paths, {0, 0});
  // Check the greedy rule step by step with a brute-force search over what was left.
  std::vector<DevicePath> left = paths;
  DevicePoint at{0, 0};
  for (const auto& p : ordered) {
    double best = 1e300;
    for (const auto& q : left)
      for (auto e : {q.front(), q.back()})
        best = std::min(best, std::hypot(double(e.x) - at.x, double(e.y) - at.y));
    CHECK(std::hypot(double(p.front().x) - at.x, double(p.front().y) - at.y) ==
          doctest::Approx(best));
    // Remove the segments of p from `left` (each piece here is one segment or a chain).
    for (std::size_t k = 0; k + 1 < p.size(); ++k)
      for (auto it = left.begin(); it != left.end(); ++it)
        if ((it->front() == p[k] && it->back() == p[k + 1]) ||
            (it->back() == p[k] && it->front() == p[k + 1])) {
          left.erase(it);
          break;
        }
    at = p.back();
  }
  CHECK(left.empty());
}

TEST_CASE("plot_hpgl: inside the paper, centred, landscape, aspect kept") {
  Image im = surface_image(6, 9);
  for (Paper paper : {Paper::a4, Paper::a3, Paper::letter, Paper::b}) {
    Plot plot = plot_hpgl(im, {paper});
    DevicePoint lim = hp7475a.limit(paper);
    CHECK(plot.hpgl.rfind("IN;SP1;", 0) == 0);
    CHECK(plot.hpgl.substr(plot.hpgl.size() - 7) == "PU;SP0;");
    CHECK(!plot.stats.clipped);
    auto pts = absolute_points(plot.hpgl);
    REQUIRE(!pts.empty());
    int x0 = 1 << 30, x1 = -1, y0 = 1 << 30, y1 = -1;
    for (auto p : pts) {
      CHECK((p.x >= 0 && p.x <= lim.x && p.y >= 0 && p.y <= lim.y));
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y),
      y1 = std::max(y1, p.y);
    }
    // The margin is kept; the drawing fills the height or the width left for it.
    double margin = plot_margin_mm / hp7475a.unit_mm;
    CHECK(x0 >= margin - 1);
    CHECK(y0 >= margin - 1);
    CHECK(y1 <= lim.y - margin + 1);
    CHECK(plot.stats.vectors == 6 * 8 + 9 * 5);
    CHECK(plot.stats.bytes == plot.hpgl.size());
    CHECK(plot.hpgl.find("LBSURFACE\x03") != std::string::npos);
  }
}

TEST_CASE("plot_hpgl: ordering never costs more pen-up travel than the drawing order") {
  for (const Image& im : {surface_image(6, 9), input_image(4, 4), flat_grid(30)}) {
    Picture pic = picture_of(im);
    PlotLayout layout = plot_layout(pic, {});
    Placed placed = place(pic.drawing, layout.at, {0, 0, 11040, 7721},
                          Rendering{.point = plot_point_mm / hp7475a.unit_mm});
    Plot plot = plot_hpgl(im, {});
    StringOut naive_plot;
    HpglEncoder naive(hp7475a, false, naive_plot);
    DevicePoint t = layout.text;
    for (const auto& line : pic.caption) {
      naive.text(t, line);
      t.y -= static_cast<int>(std::lround(layout.line));
    }
    for (std::size_t k = 0; k < placed.paths.size(); ++k) naive.polyline(placed.paths[k]);
    for (const auto& label : placed.texts) naive.text(label.at, label.text);  // point numbers
    naive.finish();
    CHECK(plot.stats.pen_up_mm <= naive.stats().pen_up_mm + 1e-9);
    CHECK(plot.stats.vectors == naive.stats().vectors);
    // On a grid the order is a serpentine: a small fraction of the drawing order's travel.
    if (im.desim.projection == Projection::orthogonal)
      CHECK(plot.stats.pen_up_mm < 0.2 * naive.stats().pen_up_mm);
  }
}

TEST_CASE("plot_placed: what lies outside the hard-clip limits is clipped and said") {
  Image im = surface_image(3, 3);
  Picture pic = picture_of(im);
  PlotLayout layout = plot_layout(pic, {});
  layout.at.scale *= 3;  // three times too large
  Plot plot = plot_placed(pic, layout, {});
  CHECK(plot.stats.clipped);
  for (auto p : absolute_points(plot.hpgl))
    CHECK((p.x >= 0 && p.x <= 11040 && p.y >= 0 && p.y <= 7721));
  CHECK(plot_summary("PLOT0001.HPGL", {1440, 12, 143.4, 11520, false}) ==
        "PLOT0001.HPGL: 1440 VECTORS, 12 PEN LIFTS, PEN-UP TRAVEL 143 MM, 11520 BYTES");
}

TEST_CASE("plot_hpgl: compact and deterministic on a 200 x 200 grid") {
  Image im = flat_grid(200);
  Plot a = plot_hpgl(im, {}), b = plot_hpgl(im, {});
  CHECK(a.hpgl == b.hpgl);
  CHECK(a.stats.vectors == 2 * 200 * 199);
  double per_vector = double(a.stats.bytes) / double(a.stats.vectors);
  CHECK(per_vector <= 8.0);
}

}  // namespace igds::test::devices
