// The examples of scripts/examples/ run by the real igds binary: their 4013 streams rendered by
// tek2plot, the hull's HP-GL read by hp2xx, their transcripts compared with the expected ones,
// and what each header promises checked on the surface it builds.
#include <doctest/doctest.h>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <regex>
#include <sstream>

#include "devices/layout.h"
#include "tests/e2e/examples_support.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"

namespace igds::test {

namespace {

// The numbers of an IGDSCHAR file (docs/disk.md), by variable.
struct CharFile {
  std::vector<int> status, sizes;  // STATUS; NOCUR NOSTR INTCU INTST
  std::vector<int> inppn_shape, inptg_shape, intpn_shape, patches_shape;
  std::vector<double> inppn, inptg, intpn, patches;
  std::vector<std::string> lines;
};

std::vector<int> integers(const std::string& line, std::size_t count) {
  std::vector<int> v;
  for (std::size_t i = 0; i < count; ++i) v.push_back(std::stoi(line.substr(5 * i, 5)));
  return v;
}

// Reads `count` F10.3 numbers, 8 a card, starting at card `at`.
std::vector<double> reals(const std::vector<std::string>& lines, std::size_t& at,
                          std::size_t count) {
  std::vector<double> v;
  while (v.size() < count) {
    REQUIRE(at < lines.size());
    const auto& line = lines[at++];
    for (std::size_t f = 0; f + 10 <= line.size() && v.size() < count; f += 10)
      v.push_back(std::stod(line.substr(f, 10)));
  }
  return v;
}

std::size_t product(const std::vector<int>& shape) {
  std::size_t n = 1;
  for (int s : shape) n *= static_cast<std::size_t>(s);
  return n;
}

CharFile read_char(const std::filesystem::path& path) {
  CharFile f;
  std::istringstream in(read_file(path));
  for (std::string line; std::getline(in, line);) f.lines.push_back(line);
  REQUIRE(f.lines.size() > 4);
  std::size_t at = 0;
  f.status = integers(f.lines[at++], 10);
  f.sizes = integers(f.lines[at++], 4);
  f.inppn_shape = integers(f.lines[at++], 2);
  f.inppn = reals(f.lines, at, product(f.inppn_shape));
  f.inptg_shape = integers(f.lines[at++], 2);
  f.inptg = reals(f.lines, at, product(f.inptg_shape));
  f.intpn_shape = integers(f.lines[at++], 3);
  f.intpn = reals(f.lines, at, product(f.intpn_shape));
  f.patches_shape = integers(f.lines[at++], 5);
  f.patches = reals(f.lines, at, product(f.patches_shape));
  return f;
}

// `bytes` with control and 8-bit bytes shown as \xNN.
std::string printable(std::string_view bytes) {
  std::string out;
  for (char c : bytes) {
    auto u = static_cast<unsigned char>(c);
    out += u >= 0x20 && u < 0x7F ? std::string(1, c) : fmt::format("\\x{:02X}", u);
  }
  return out;
}

// Runs an example on a fresh disk, then `then` (more command lines) on the same disk.
struct Ran {
  RunResult result;
  RunResult after;
};
Ran run_example(const Example& e, const TempDir& disk, const std::string& then = "") {
  Ran ran;
  put_inputs(e, disk.path());
  ran.result = run_igds({"--disk", disk.path().string(), "--term", "none", e.file.string()});
  if (!then.empty()) {
    write_file(disk.path() / "then.igds", then);
    ran.after = run_igds(
        {"--disk", disk.path().string(), "--term", "none", (disk.path() / "then.igds").string()});
  }
  return ran;
}

Example example_named(const std::string& name) {
  for (auto& e : examples())
    if (e.name == name) return e;
  FAIL("no example named " << name);
  return {};
}

}  // namespace

TEST_CASE("the 4013 decoder reads shortened 10-bit and 12-bit addresses, text and pages") {
  // (100,100) whole; (900,100) without HiY; (900,700) without HiX; text; a page; then 12-bit
  // (401,2) and (405,2), each with its Extra byte; then an address with no high bytes ever sent.
  auto d = decode_tek(
      "\x1d#d#D"
      "d<D"
      "5|D"
      "\x1f"
      "AB"
      "\x1b\x0c"
      "\x1d i`#D"
      "i`E");
  REQUIRE(d.pages.size() == 2);
  CHECK(d.errors.empty());
  REQUIRE(d.pages[0].segments.size() == 2);
  CHECK(d.pages[0].segments[0].a.x == 100);
  CHECK(d.pages[0].segments[0].b.x == 900);
  CHECK(d.pages[0].segments[0].b.y == 100);
  CHECK(d.pages[0].segments[1].b.y == 700);
  REQUIRE(d.pages[0].texts.size() == 1);
  CHECK(d.pages[0].texts[0].text == "AB");
  CHECK(d.pages[0].texts[0].at.x == 900);
  REQUIRE(d.pages[1].segments.size() == 1);
  CHECK(d.pages[1].segments[0].a.x == 100.25);
  CHECK(d.pages[1].segments[0].a.y == 0.5);
  CHECK(d.pages[1].segments[0].b.x == 101.25);
  CHECK(decode_tek("\x1d"
                   "D")
            .errors.size() == 1);
  CHECK(decode_tek("\x1d#d#D\x01").errors.size() == 1);
}

TEST_CASE("the examples are there, each with a picture page in its header") {
  auto list = examples();
  std::vector<std::string> names;
  for (const auto& e : list) names.push_back(e.name);
  CHECK(names == std::vector<std::string>{"abbreviations", "fig3-tangents", "fig6-multipatch",
                                          "fig7-9-projections", "hidden-lines", "hull",
                                          "marks-sphere", "pick-edit", "quasi-sphere",
                                          "wave-combs"});
  for (const auto& e : list) {
    CAPTURE(e.name);
    CHECK(e.picture_page >= 0);
  }
}

TEST_CASE("every example's 4013 stream is rendered by tek2plot without complaint") {
  IGDS_SKIP_UNLESS(have_program("tek2plot"), "tek2plot is not installed (plotutils)");
  for (const auto& e : examples()) {
    CAPTURE(e.name);
    TempDir disk;
    put_inputs(e, disk.path());
    auto r = run_igds({"--disk", disk.path().string(), "--term", "tek", e.file.string()});
    CHECK(r.status == 0);
    CHECK(r.err == "");
    // A 4013 is a 7-bit terminal (docs/devices.md, "Tektronix 4013"): APL characters must not reach
    // it as UTF-8.
    auto wide = std::find_if(r.out.begin(), r.out.end(),
                             [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
    if (wide != r.out.end()) {
      auto at = static_cast<std::size_t>(wide - r.out.begin());
      auto from = at < 30 ? 0 : at - 30;
      FAIL_CHECK("8-bit byte at offset " << at << " of the 4013 stream, after \""
                                         << printable(r.out.substr(from, at - from)) << "\"");
    }
    auto drawing = decode_tek(r.out);
    CHECK(drawing.errors == std::vector<std::string>{});
    // The screen as a person sees it: on no page is anything drawn over anything else.
    for (std::size_t page = 0; page < drawing.pages.size(); ++page) {
      CAPTURE(page);
      for (const auto& fault : screen_faults(drawing.pages[page])) FAIL_CHECK(fault);
    }
    REQUIRE(e.picture_page >= 0);
    REQUIRE(static_cast<std::size_t>(e.picture_page) < drawing.pages.size());
    // The page of the README's picture shows a drawing, not only text.
    CHECK(drawing.pages[e.picture_page].segments.size() > 20);

    auto tek = disk.path() / (e.name + ".tek");
    write_file(tek, r.out);
    // Page by page, as tek2plot counts them: each must parse, and show vectors where igds drew.
    for (std::size_t page = 0; page < drawing.pages.size(); ++page) {
      CAPTURE(page);
      auto svg =
          run({"tek2plot", "-T", "svg", "--page-number", std::to_string(page), tek.string()});
      CHECK(svg.status == 0);
      CHECK(svg.err == "");
      bool vectors = svg.out.find("<polyline") != std::string::npos ||
                     svg.out.find("<line") != std::string::npos;
      CHECK(vectors == !drawing.pages[page].segments.empty());
    }
    auto png = run(
        {"tek2plot", "-T", "png", "--page-number", std::to_string(e.picture_page), tek.string()});
    CHECK(png.status == 0);
    CHECK(png.err == "");
    CHECK(png.out.rfind("\x89PNG", 0) == 0);
  }
}

TEST_CASE("every example's transcript is the expected one") {
  for (const auto& e : examples()) {
    CAPTURE(e.name);
    TempDir disk;
    put_inputs(e, disk.path());
    auto r = run_igds({"--disk", disk.path().string(), "--term", "none", e.file.string()});
    CHECK(r.status == 0);
    CHECK(r.err == "");
    auto problem = compare_expected(e.name + ".txt", without_disk(r.out, disk.path()));
    CHECK_MESSAGE(problem.empty(), problem);
  }
}

TEST_CASE("hull: saved, written as IGDSCHAR cards, and plotted on HP-GL that hp2xx reads") {
  auto e = example_named("hull");
  TempDir disk;
  auto ran = run_example(e, disk);
  REQUIRE(ran.result.status == 0);
  CHECK(std::filesystem::exists(disk.path() / "HULL.IGDSDATA"));

  auto card = read_char(disk.path() / "HULL.IGDSCHAR");
  for (const auto& line : card.lines) CHECK(line.size() <= 80);
  CHECK(card.sizes == std::vector<int>{6, 5, 4, 3});
  CHECK(card.inppn_shape == std::vector<int>{30, 3});
  CHECK(card.intpn_shape == std::vector<int>{26, 17, 3});  // 6 + 4x5 curves, 5 + 3x4 stringers
  // The keel (first point of every interpolated section) stays on y = 0, z = 0.
  for (int i = 0; i < 26; ++i) {
    CAPTURE(i);
    CHECK(card.intpn[(i * 17) * 3 + 1] == doctest::Approx(0).epsilon(0.001));
    CHECK(card.intpn[(i * 17) * 3 + 2] == doctest::Approx(0).epsilon(0.001));
  }

  std::vector<std::filesystem::path> plots;
  for (const auto& entry : std::filesystem::directory_iterator(disk.path()))
    if (std::regex_match(entry.path().filename().string(), std::regex(R"(PLOT\d{4}\.HPGL)")))
      plots.push_back(entry.path());
  REQUIRE(plots.size() == 1);
  IGDS_SKIP_UNLESS(have_program("hp2xx"), "hp2xx is not installed");
  auto dump = run({"hp2xx", "-t", "-m", "hpgl", "-f", "-", plots[0].string()});
  CHECK(dump.status == 0);
  // hp2xx exits 0 even when it understood nothing: its log and its dump say whether it did.
  auto count_after = [&](const std::string& label) {
    auto at = dump.err.find(label);
    return at == std::string::npos ? -1 : std::atoi(dump.err.c_str() + at + label.size());
  };
  CHECK(count_after("HPGL commands read:") > 0);
  CHECK(count_after("HPGL command(s) ignored:") == 0);
  CHECK(count_after("Unexpected event(s):") == 0);
  std::size_t vectors = 0;
  for (std::size_t at = 0; (at = dump.out.find("PD", at)) != std::string::npos; ++at) ++vectors;
  CHECK(vectors > 100);
}

TEST_CASE("fig3-tangents: the bigger the modulus, the higher the arc") {
  TempDir disk;
  auto ran = run_example(example_named("fig3-tangents"), disk, "WRITE ARCS\nEND CMS\n");
  REQUIRE(ran.after.status == 0);
  auto card = read_char(disk.path() / "ARCS.IGDSCHAR");
  REQUIRE(card.intpn_shape == std::vector<int>{4, 18, 3});
  const double moduli[] = {0.5, 1, 2, 3};
  double last_rise = 0;
  for (int curve = 0; curve < 4; ++curve) {
    CAPTURE(curve);
    double rise = 0;
    for (int p = 0; p < 18; ++p) rise = std::max(rise, card.intpn[(curve * 18 + p) * 3 + 1]);
    // y(s) = m sin45 (s - s^2) on a unit chord: the top, at s = 1/2, is m sqrt(2)/8.
    CHECK(rise == doctest::Approx(moduli[curve] * std::numbers::sqrt2 / 8).epsilon(0.02));
    CHECK(rise > last_rise);
    last_rise = rise;
  }
}

TEST_CASE("fig6-multipatch: 3 x 4 patches that follow the wave") {
  TempDir disk;
  auto ran = run_example(example_named("fig6-multipatch"), disk, "WRITE WAVE\nEND CMS\n");
  REQUIRE(ran.after.status == 0);
  auto card = read_char(disk.path() / "WAVE.IGDSCHAR");
  CHECK(card.patches_shape == std::vector<int>{3, 4, 3, 4, 4});
  REQUIRE(card.intpn_shape == std::vector<int>{13, 17, 3});
  double worst = 0;
  for (std::size_t k = 0; k < card.intpn.size(); k += 3) {
    double x = card.intpn[k], y = card.intpn[k + 1], z = card.intpn[k + 2];
    double wave = 8 * std::sin(std::numbers::pi * x / 40) * std::cos(std::numbers::pi * y / 45);
    worst = std::max(worst, std::abs(z - wave));
  }
  CHECK(worst < 0.1);  // within 1.25 % of the wave's height of 8
}

TEST_CASE("hidden-lines: DISPLAY HIDDEN draws a part of what DISPLAY SURFACE draws") {
  const Example& e = example_named("hidden-lines");
  TempDir disk;
  auto r = run_igds({"--disk", disk.path().string(), "--term", "tek", e.file.string()});
  REQUIRE(r.status == 0);
  const auto drawing = decode_tek(r.out);
  REQUIRE(drawing.pages.size() == 4);
  // Page 1: every curve and stringer; page 3 (the README's): the same view, hidden lines removed.
  const auto& all = drawing.pages[1].segments;
  const auto& seen = drawing.pages[3].segments;
  auto ink = [](const std::vector<TekSegment>& segments) {
    double sum = 0;
    for (const auto& s : segments) sum += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
    return sum;
  };
  CHECK(ink(seen) < 0.9 * ink(all));
  CHECK(ink(seen) > 0.5 * ink(all));
  // Every end of a segment drawn in the picture's square (not a stroke of a character: the 4013
  // has no high minus) lies on a segment of the whole surface, within a 4013 point.
  const Box square = dialogue_layout().image;
  std::size_t looked = 0;
  for (const auto& s : seen) {
    auto inside = [&](TekPoint p) {
      return p.x >= square.x0 && p.x <= square.x1 && p.y >= square.y0 && p.y <= square.y1;
    };
    if (!inside(s.a) || !inside(s.b)) continue;
    ++looked;
    for (const TekPoint p : {s.a, s.b}) {
      double nearest = 1e9;
      for (const auto& t : all) nearest = std::min(nearest, distance(p, t));
      CHECK(nearest <= 1.0);
    }
  }
  CHECK(looked > 100);
}

TEST_CASE("wave-combs: the combs drawn in SVG and HP-GL, the same after a restart, UNDO and REDO") {
  TempDir disk;
  auto ran =
      run_example(example_named("wave-combs"), disk,
                  "EXPORT SVG AGAIN\nPLOT SELECTRIC\nUNDO\nREDO\nEXPORT SVG REDONE\n"
                  "DISPLAY SURFACE ORTHOGONAL XZ\nEXPORT SVG LINES\nPLOT SELECTRIC\nEND CMS\n");
  REQUIRE(ran.result.status == 0);
  REQUIRE(ran.after.status == 0);
  CHECK(ran.result.out.find("CURRENT IMAGE  COMBS, ORTHOGONAL XZ") != std::string::npos);
  // The session kept the image by its recipe: made again after the restart, and after UNDO and
  // REDO, it is the same picture, its scale said.
  const std::string wave = read_file(disk.path() / "WAVE.SVG");
  CHECK(read_file(disk.path() / "AGAIN.SVG") == wave);
  CHECK(read_file(disk.path() / "REDONE.SVG") == wave);
  CHECK(wave.find(">SCALE 100<") != std::string::npos);
  // The combs are drawn: far more points than the surface's lines alone (13 x 17 points, twice).
  auto points = [](const std::string& text) { return std::count(text.begin(), text.end(), ','); };
  const std::string lines = read_file(disk.path() / "LINES.SVG");
  CHECK(points(lines) >= 13 * 17);
  CHECK(points(wave) > points(lines) + 3 * 13 * 17);
  // PLOT draws them too: the first plot (the combs) has more pen-down strokes than the second.
  std::vector<std::filesystem::path> plots;
  for (const auto& entry : std::filesystem::directory_iterator(disk.path()))
    if (std::regex_match(entry.path().filename().string(), std::regex(R"(PLOT\d{4}\.HPGL)")))
      plots.push_back(entry.path());
  std::sort(plots.begin(), plots.end());
  REQUIRE(plots.size() == 2);
  auto strokes = [](const std::string& hpgl) {
    std::size_t n = 0;
    for (std::size_t at = 0; (at = hpgl.find("PD", at)) != std::string::npos; ++at) ++n;
    return n;
  };
  CHECK(strokes(read_file(plots[0])) > strokes(read_file(plots[1])));
}

TEST_CASE("pick-edit: its picks raise the crest alike under --term none, tek and xterm") {
  const Example& e = example_named("pick-edit");
  std::string cards_none;
  for (const std::string mode : {"none", "tek", "xterm"}) {
    CAPTURE(mode);
    TempDir disk;
    write_file(disk.path() / "then.igds", "WRITE WAVE\nEND CMS\n");
    const auto r = run_igds({"--disk", disk.path().string(), "--term", mode, e.file.string()});
    REQUIRE(r.status == 0);
    const auto then = run_igds(
        {"--disk", disk.path().string(), "--term", "none", (disk.path() / "then.igds").string()});
    REQUIRE(then.status == 0);
    // What the dialogue says, the 4013's texts in tek mode.
    std::string said = r.out;
    if (mode == "tek") {
      said.clear();
      for (const auto& page : decode_tek(r.out).pages)
        for (const auto& t : page.texts) said += t.text + "\n";
    }
    // PICK and CHANGE POINTS name the crest, and it goes 14 high (within a point), y kept.
    std::size_t named = 0;
    for (std::size_t at = 0; (at = said.find("POINT 3 AT 20 0 8\n", at)) != std::string::npos; ++at)
      ++named;
    // (A new page of tek mode begins with the last rows of the page before.)
    CHECK((mode == "tek" ? named >= 2 : named == 2));
    CHECK(said.find("POINT 3 AT 20 0 13.97\n") != std::string::npos);
    const auto card = read_char(disk.path() / "WAVE.IGDSCHAR");
    REQUIRE(card.inppn.size() == 60);
    CHECK(card.inppn[6] == doctest::Approx(20));
    CHECK(card.inppn[7] == 0);
    CHECK(std::abs(card.inppn[8] - 14) < 0.07);
    // The other points are where BUILD put them: 8 sin(pi x/40) cos(pi y/45) within 0.001.
    for (std::size_t k = 0; k < 60; k += 3) {
      if (k == 6) continue;
      const double x = card.inppn[k], y = card.inppn[k + 1], z = card.inppn[k + 2];
      CHECK(std::abs(z - 8 * std::sin(std::numbers::pi * x / 40) *
                             std::cos(std::numbers::pi * y / 45)) < 0.001);
    }
    // Every mode leaves the same surface, card for card.
    const std::string cards = read_file(disk.path() / "WAVE.IGDSCHAR");
    if (cards_none.empty()) cards_none = cards;
    CHECK(cards == cards_none);
  }
}

TEST_CASE("quasi-sphere: every interpolated point lies near the sphere of radius 100") {
  TempDir disk;
  auto ran = run_example(example_named("quasi-sphere"), disk, "WRITE OCTANT\nEND CMS\n");
  REQUIRE(ran.after.status == 0);
  CHECK(std::filesystem::exists(disk.path() / "SPHERE.IGDSIMAG"));
  auto card = read_char(disk.path() / "OCTANT.IGDSCHAR");
  REQUIRE(card.intpn_shape == std::vector<int>{17, 17, 3});
  double worst = 0;
  for (std::size_t k = 0; k < card.intpn.size(); k += 3) {
    double r = std::hypot(card.intpn[k], card.intpn[k + 1], card.intpn[k + 2]);
    worst = std::max(worst, std::abs(r - 100));
  }
  CHECK(worst < 0.1);  // 0.1 % of the radius
  // The pole: the last interpolated curve is one point.
  for (int p = 0; p < 17; ++p) {
    CAPTURE(p);
    CHECK(card.intpn[(16 * 17 + p) * 3 + 2] == doctest::Approx(100));
  }
}

TEST_CASE("abbreviations: the short forms did what their long forms say") {
  TempDir disk;
  auto ran = run_example(example_named("abbreviations"), disk);
  REQUIRE(ran.result.status == 0);
  for (const char* file : {"DOME.IGDSIMAG", "DOME.IGDSDATA", "DOME.IGDSCHAR"}) {
    CAPTURE(file);
    CHECK(std::filesystem::exists(disk.path() / file));
  }
  auto card = read_char(disk.path() / "DOME.IGDSCHAR");
  CHECK(card.sizes == std::vector<int>{3, 3, 4, 4});  // CHANGE GRID 4 4 before WRITE
  CHECK(card.status[0] == 0);                         // HELP SHORT was in force when WRITE ran
  // HELP LONG at the end is remembered for the next session.
  RunOptions typed;
  typed.input = "HELP\nEND CMS\n";
  auto next = run_igds({"--disk", disk.path().string(), "--term", "none"}, typed);
  CHECK(next.status == 0);
  CHECK(next.out.size() > 400);  // the long explanation, not one or two lines
}

}  // namespace igds::test
