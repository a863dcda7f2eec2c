// Every device stream read by a real client: tek2plot for the 4013/4014 streams, hp2xx for the
// HP-GL plots, xmllint for the SVG.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <regex>

#include "devices/hpgl.h"
#include "devices/hpgl_plot.h"
#include "devices/layout.h"
#include "devices/tek4013.h"
#include "devices/tek_stream.h"
#include "tests/devices/support.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "workspace/images.h"

namespace igds::test::devices {

namespace {

std::vector<Image> sample_images() {
  std::vector<Image> images{input_image(3, 4), surface_image(5, 4), surface_image(2, 2),
                            input_image(6, 5), flat_grid(40)};
  Image isometric = surface_image(7, 3);
  isometric.desim = {1, Projection::isometric, {2, 45, 0}};
  images.push_back(isometric);
  return images;
}

// tek2plot's SVG of `stream`; it must read it without a word on stderr.
std::string tek2plot_svg(const std::string& stream) {
  TempDir dir;
  write_file(dir.path() / "s.tek", stream);
  RunOptions options;
  options.timeout_seconds = 60;
  RunResult r = run({"tek2plot", "-T", "svg", (dir.path() / "s.tek").string()}, options);
  CHECK(r.status == 0);
  CHECK(r.err == "");
  return r.out;
}

// The text lines of tek2plot's SVG, with their position.
std::vector<std::pair<Point2, std::string>> tek2plot_texts(const std::string& svg) {
  std::vector<std::pair<Point2, std::string>> out;
  static const std::regex text(
      R"(<text transform="translate\(([-0-9.]+),([-0-9.]+)\)[^>]*>([^<]*)</text>)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator();
       ++it)
    out.push_back({{std::stod((*it)[1]), std::stod((*it)[2])}, (*it)[3]});
  return out;
}

// What tek2plot must show for the polylines drawn at `unit` times the 4013's resolution: a
// 10-bit point (x, y) at (4x, 4y + 488), a 12-bit one at (x, y + 488).
std::vector<DevicePath> in_tek2plot_units(const std::vector<DevicePath>& paths, int unit) {
  std::vector<DevicePath> out = paths;
  int k = 4 / unit;
  for (auto& p : out)
    for (auto& q : p) q = {k * q.x, k * q.y + 488};
  return out;
}

}  // namespace

TEST_CASE("tek2plot: a 10-bit point (x, y) appears at (4x, 4y + 488)") {
  IGDS_SKIP_UNLESS(have_program("tek2plot"), "tek2plot (plotutils) is not installed");
  std::string s = cat({"\x1D", tek_address(100, 100), tek_address(500, 600), "\x1D",
                       tek_address(0, 0), tek_address(1023, 779), "\x1F"});
  auto paths = svg_paths(tek2plot_svg(s));
  CHECK(paths == std::vector<DevicePath>{{{400, 888}, {2000, 2888}}, {{0, 488}, {4092, 3604}}});
  std::string s12 = cat({"\x1D", tek_address(401, 402, 12), tek_address(4095, 3119, 12), "\x1F"});
  CHECK(svg_paths(tek2plot_svg(s12)) == std::vector<DevicePath>{{{401, 890}, {4095, 3607}}});
}

TEST_CASE("tek2plot reads every 4013 and 4014 stream, vertices where they were meant") {
  IGDS_SKIP_UNLESS(have_program("tek2plot"), "tek2plot (plotutils) is not installed");
  for (const Image& im : sample_images())
    for (int bits : {10, 12}) {
      int unit = bits == 12 ? 4 : 1;
      Recorder r;
      draw_tek_display(picture_of(im), r, unit);
      auto expected = in_tek2plot_units(r.drawn(), unit);
      for (const std::string& stream :
           {tek_stream(im, {bits}), display_bytes(im, TermMode::tek, {bits})}) {
        std::string svg = tek2plot_svg(stream);
        INFO(show(expected));
        CHECK(show(svg_paths(svg)) == show(expected));
        auto texts = tek2plot_texts(svg);
        REQUIRE(texts.size() == r.texts.size());
        for (std::size_t i = 0; i < texts.size(); ++i) {
          CHECK(texts[i].second == r.texts[i].line);
          CHECK(texts[i].first.x == doctest::Approx(4.0 * r.texts[i].at.x / unit));
          CHECK(std::abs(texts[i].first.y - (4.0 * r.texts[i].at.y / unit + 488)) <
                4 * tek_screen::line_height);
        }
      }
    }
  // A page alone.
  CHECK(svg_paths(tek2plot_svg(erase_bytes(TermMode::tek, {}))).empty());
}

namespace {

struct Hp2xx {
  std::string dump;
  Hp2xxLog log;
};

Hp2xx hp2xx(const std::string& hpgl) {
  TempDir dir;
  write_file(dir.path() / "p.hpgl", hpgl);
  RunOptions options;
  options.timeout_seconds = 60;
  RunResult r =
      run({"hp2xx", "-t", "-m", "hpgl", "-f", "-", (dir.path() / "p.hpgl").string()}, options);
  CHECK(r.status == 0);
  Hp2xx h{r.out, read_hp2xx_log(r.err)};
  INFO(r.err);
  CHECK(h.log.commands > 0);
  CHECK(h.dump.find("PD") != std::string::npos);
  return h;
}

}  // namespace

TEST_CASE("hp2xx reads every plot: within the paper, the same drawing absolute or relative") {
  IGDS_SKIP_UNLESS(have_program("hp2xx"), "hp2xx is not installed");
  for (const Image& im : sample_images())
    for (Paper paper : {Paper::a4, Paper::a3, Paper::letter, Paper::b}) {
      Plot relative = plot_hpgl(im, {paper, false});
      Plot absolute = plot_hpgl(im, {paper, true});
      CHECK(relative.stats.vectors == absolute.stats.vectors);
      CHECK(relative.stats.pen_up_mm == doctest::Approx(absolute.stats.pen_up_mm));
      Hp2xx a = hp2xx(relative.hpgl), b = hp2xx(absolute.hpgl);
      CHECK(a.dump == b.dump);
      DevicePoint lim = hp7475a.limit(paper);
      CHECK(a.log.x0 >= 0);
      CHECK(a.log.y0 >= 0);
      CHECK(a.log.x1 <= lim.x);
      CHECK(a.log.y1 <= lim.y);
      CHECK(a.log.x1 > a.log.x0);
    }
}

TEST_CASE("hp2xx reads a clipped plot: nothing beyond the hard-clip limits") {
  IGDS_SKIP_UNLESS(have_program("hp2xx"), "hp2xx is not installed");
  Picture pic = picture_of(surface_image(4, 4));
  PlotLayout layout = plot_layout(pic, {});
  layout.at.scale *= 2.5;
  Plot plot = plot_placed(pic, layout, {});
  CHECK(plot.stats.clipped);
  Hp2xx h = hp2xx(plot.hpgl);
  CHECK(h.log.x0 >= 0);
  CHECK(h.log.y0 >= 0);
  CHECK(h.log.x1 <= 11040);
  CHECK(h.log.y1 <= 7721);
}

namespace {

// A picture whose label starts near the right of the drawing and is far too long for the room
// beside it, in colour 2, and a short one that fits.
Picture long_label() {
  Picture pic;
  const double square[] = {0, 0, 100, 0, 100, 100, 0, 100, 0, 0};
  pic.drawing.add_polyline(Point2View(square, 5));
  pic.drawing.add_text(
      {90, 50}, "A LABEL FAR TOO LONG FOR THE ROOM BESIDE IT, ON ANY DEVICE AT ALL", 1, {.pen = 2});
  pic.drawing.add_text({10, 10}, "SHORT", 1);
  pic.caption = {"PICTURE", "LONG", "ORTHOGONAL XY"};
  return pic;
}

}  // namespace

TEST_CASE("long texts are cut before the caption on every device, and the caption says so") {
  const Picture pic = long_label();
  // The Tek layout (EXPORT TEK, SVG, the Tek window): the label ends before x = 780 - 7; the
  // short one is whole; TEXTS CUT follows the caption.
  Recorder r;
  const DevicePoint below = draw_tek_display(pic, r, 1);
  std::vector<std::string> lines;
  for (const auto& t : r.texts) {
    lines.push_back(t.line);
    if (t.at.x < 780) CHECK(t.at.x + 14 * int(t.line.size()) <= 780 - 7);
  }
  CHECK(std::find(lines.begin(), lines.end(), "SHORT") != lines.end());
  CHECK(std::find(lines.begin(), lines.end(), "TEXTS CUT") != lines.end());
  CHECK(below.y == 734 - 4 * 22);
  // The 4013 stream as tek2plot reads it: no text past x = 780 (4 x 780 in its units) but the
  // caption's, and none wrapped to the left margin over the picture.
  const std::string stream = tek_stream(pic, {10});
  if (have_program("tek2plot")) {
    for (const auto& text : tek2plot_texts(tek2plot_svg(stream))) {
      const std::string& line = text.second;
      CAPTURE(line);
      if (text.first.x < 4 * 780)
        CHECK(text.first.x + 4 * 14 * double(line.size()) <= 4 * (780 - 7));
    }
  }
  // SVG: the same places, the label in its colour.
  const std::string svg = svg_of(pic);
  CHECK(svg.find(">TEXTS CUT</text>") != std::string::npos);
  CHECK(svg.find("fill=\"red\" stroke=\"none\">A LABE</text>") != std::string::npos);
  // HP-GL: the label ends before the caption's strip, on the paper; PLOT says it was cut.
  for (Paper paper : {Paper::a4, Paper::a3}) {
    const PlotLayout layout = plot_layout(pic, {paper, true});
    const Plot plot = plot_placed(pic, layout, {paper, true});
    CHECK(plot.stats.texts_cut);
    CHECK(!plot.stats.clipped);
    CHECK(plot.hpgl.find("LBTEXTS CUT") != std::string::npos);
    const std::size_t label = plot.hpgl.find("LBA LABEL");
    REQUIRE(label != std::string::npos);
    const std::size_t end = plot.hpgl.find('\x03', label);
    CHECK(end - label - 2 < 40);
    const int x = std::stoi(plot.hpgl.substr(plot.hpgl.rfind("PU", label) + 2));
    CHECK(x + layout.advance * double(end - label - 2) <= layout.text.x);
    if (have_program("hp2xx")) {
      const Hp2xx h = hp2xx(plot.hpgl);
      CHECK(h.log.x1 <= hp7475a.limit(paper).x);
    }
  }
}

TEST_CASE("xmllint reads the SVG; its coordinates are the Tek ones, y flipped") {
  IGDS_SKIP_UNLESS(have_program("xmllint"), "xmllint (libxml2-utils) is not installed");
  for (const Image& im : sample_images()) {
    std::string svg = svg_of(im);
    TempDir dir;
    write_file(dir.path() / "i.svg", svg);
    RunResult r = run({"xmllint", "--noout", (dir.path() / "i.svg").string()});
    CHECK(r.status == 0);
    CHECK(r.err == "");
    auto decoded = decode_tek(tek_stream(im, {}), 10);
    std::vector<DevicePath> flipped = decoded.paths;
    for (auto& p : flipped)
      for (auto& q : p) q.y = 779 - q.y;
    auto paths = svg_paths(svg);
    // Closed squares and rings are polylines in our SVG: compare as drawn.
    CHECK(paths == flipped);
    CHECK(svg.find("viewBox=\"0 0 1024 780\"") != std::string::npos);
    for (const auto& [at, line] : decoded.texts) {
      if (line.empty()) continue;
      CHECK(svg.find(fmt::format("<text x=\"{}\" y=\"{}\"", at.x, 779 - at.y)) !=
            std::string::npos);
      CHECK(svg.find(">" + line + "</text>") != std::string::npos);
    }
  }
}

TEST_CASE("a DUCT picture's dashes and colours: 4014 line styles, HP-GL pens and types, SVG") {
  // The hand-written picture (tests/workspace/data): solid, dashed and chain-dashed lines and
  // arcs in colours 1 to 5.
  const Image im =
      picture_image("HAND", read_file(source_dir() / "tests/workspace/data/hand_written.ductpic"),
                    {Projection::orthogonal, {1, 0, 0}});
  Recorder r;
  draw_tek_display(picture_of(im), r, 1);
  const std::vector<Style> styles = r.drawn_styles();
  auto code = [](Dash dash) {
    return dash == Dash::solid ? '`' : dash == Dash::dotted ? 'a' : dash == Dash::chain ? 'b' : 'c';
  };
  // The stream decoded here: every path where it was meant, in its line style.
  const std::string stream = tek_stream(im, {10});
  const TekDecoded d = decode_tek(stream, 10);
  REQUIRE(d.paths == r.drawn());
  REQUIRE(d.dashes.size() == styles.size());
  int solid = 0, dashed = 0, chain = 0;
  for (std::size_t k = 0; k < styles.size(); ++k) {
    CHECK(d.dashes[k] == code(styles[k].dash));
    solid += d.dashes[k] == '`';
    dashed += d.dashes[k] == 'c';
    chain += d.dashes[k] == 'b';
  }
  CHECK(solid > 0);
  CHECK(dashed > 0);
  CHECK(chain > 0);
  // tek2plot draws the same vectors, the dashed ones dashed.
  if (have_program("tek2plot")) {
    const std::string svg = tek2plot_svg(stream);
    CHECK(show(svg_paths(svg)) == show(in_tek2plot_units(r.drawn(), 1)));
    CHECK(svg.find("stroke-dasharray") != std::string::npos);
  }
  // HP-GL: a pen per colour, LT2 dashed and LT4 chain-dashed; hp2xx reads it.
  const Plot plot = plot_hpgl(im, {});
  for (const char* instruction : {"SP2;", "SP3;", "SP4;", "SP5;", "LT2;", "LT4;", "LT;"})
    CHECK(plot.hpgl.find(instruction) != std::string::npos);
  // SVG: strokes in colour and dash arrays.
  const std::string svg = svg_of(im);
  for (const char* attribute : {"stroke=\"red\"", "stroke=\"magenta\"", "stroke-dasharray=\"8 4\"",
                                "stroke-dasharray=\"12 3 2 3\""})
    CHECK(svg.find(attribute) != std::string::npos);
  // Texts in their pens' colours on both: the title in colour 2, ORIGIN in colour 1.
  const std::size_t title = plot.hpgl.find("LBIGDS HAND");
  REQUIRE(title != std::string::npos);
  CHECK(plot.hpgl.substr(plot.hpgl.rfind("SP", title), 4) == "SP2;");
  CHECK(svg.find("fill=\"red\" stroke=\"none\">IGDS HAND") != std::string::npos);
  CHECK(svg.find("fill=\"black\" stroke=\"none\">ORIGIN<") != std::string::npos);
  IGDS_SKIP_UNLESS(have_program("hp2xx"), "hp2xx is not installed");
  hp2xx(plot.hpgl);
}

}  // namespace igds::test::devices

namespace igds::test::devices {

TEST_CASE("pens above 6: SVG draws them in pen 6's colour, as the plotter plots them with pen 6") {
  Picture pic;
  const double line[] = {0, 0, 10, 10};
  for (int pen : {2, 6, 7, 9}) pic.drawing.add_polyline(Point2View(line, 2), Style{.pen = pen});
  const std::string svg = igds::svg_of(pic);
  std::size_t cyan = 0;
  for (std::size_t at = 0; (at = svg.find("stroke=\"cyan\"", at)) != std::string::npos; ++at)
    ++cyan;
  CHECK(cyan == 3);
  CHECK(svg.find("stroke=\"red\"") != std::string::npos);
  const Plot plot = igds::plot_hpgl(pic, {});
  CHECK(plot.hpgl.find("SP6;") != std::string::npos);
  CHECK(plot.hpgl.find("SP7;") == std::string::npos);
  CHECK(plot.hpgl.find("SP9;") == std::string::npos);
}

}  // namespace igds::test::devices
