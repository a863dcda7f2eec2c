// The APL characters as strokes in the 4013's alpha cell (devices/tek_glyphs.h), and a test
// sheet of all of them that tek2plot must read. IGDS_TEK_GLYPH_SHEET=folder keeps the sheet
// there (glyphs.tek, and glyphs-1.png at the true size, glyphs-2.png three times as large).
#include "devices/tek_glyphs.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include "devices/tek4013.h"
#include "tests/devices/support.h"
#include "tests/support/process.h"

namespace igds::test::devices {

namespace {

// The characters igds must be able to show: APL's symbols (IBM APL2 and the Unicode APL block)
// and the signs of its own texts.
constexpr std::u32string_view required =
    U"¯⍴⍳⍝×÷←→⌈⌊∣⍟○≤≥≠∧∨⍲⍱∼↑↓⌽⊖⍉∊⍋⍒⊥⊤⌹⍎⍕∇∆⍞⎕∘⍬⍨⋄⍵⍺⊂⊃∪∩⍷≡≢⍪⍣⌿⍀¨…"
    U"⌶⌷⌸⌺⌻⌼⌾⍁⍂⍃⍄⍅⍆⍇⍈⍊⍌⍍⍏⍐⍑⍓⍔⍖⍗⍘⍙⍚⍛⍜⍠⍡⍢⍤⍥⍦⍧⍩⍫⍭⍮⍯⍰⍶⍸⍹"
    U"⊢⊣⊆⋆∗−·";

// Characters drawn alike on purpose: the Greek letters and their APL forms, two stars.
bool same_on_purpose(char32_t a, char32_t b) {
  static constexpr std::u32string_view alike[] = {U"∆Δ", U"∊∈ε", U"⍳ι", U"⍴ρ", U"⍺α", U"⍵ω", U"∗⋆"};
  for (auto group : alike)
    if (group.find(a) != group.npos && group.find(b) != group.npos) return true;
  return false;
}

std::string utf8(char32_t c) {
  std::string s;
  if (c < 0x80) {
    s += static_cast<char>(c);
  } else if (c < 0x800) {
    s += static_cast<char>(0xC0 | (c >> 6));
    s += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    s += static_cast<char>(0xE0 | (c >> 12));
    s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (c & 0x3F));
  }
  return s;
}

// Two pages of 4013 bytes: every glyph at its true size in rows of text cells, between ASCII
// letters of the terminal's own font; then every glyph three times as large, with the cell's
// corners, baseline and capital height marked.
std::string glyph_sheet() {
  TekEncoder tek;
  tek.page();
  const auto all = tek_glyph_characters();
  const int columns = 60, left = 28;
  int y = 740;
  tek.text({left, y}, "IGDS APL GLYPHS, 14 X 22 CELLS (ASCII FROM THE TERMINAL: Hxg|)");
  y -= 2 * tek_cell_height;
  for (std::size_t k = 0; k < all.size(); k += columns, y -= 2 * tek_cell_height) {
    tek.text({left, y}, "Hx");
    int x = left + 2 * tek_cell_width;
    for (std::size_t j = k; j < std::min(all.size(), k + columns); ++j, x += tek_cell_width)
      draw_tek_glyph(tek, {x, y}, all[j]);
    tek.text({x, y}, "g|");
  }
  // The same line as APL shows it: Z<-(rho A) iota B  /  lamp comment.
  tek.text({left, y}, "Z");
  int x = left + tek_cell_width;
  for (char32_t c : std::u32string_view(U"←(⍴A)⍳⌈/B÷2 ⍝ ¯1.5×⍵")) {
    if (c < 0x80) {
      if (c != U' ') tek.text({x, y}, std::string(1, static_cast<char>(c)));
    } else {
      draw_tek_glyph(tek, {x, y}, c);
    }
    x += tek_cell_width;
  }

  tek.page();
  const int scale = 3, cw = scale * tek_cell_width, ch = scale * tek_cell_height, per_row = 24;
  for (std::size_t k = 0; k < all.size(); ++k) {
    int cx = 4 + static_cast<int>(k % per_row) * cw;
    int cy = 779 - ch - static_cast<int>(k / per_row) * (ch + 4) - 6 * scale;
    // The cell's lower corners and its baseline and capital height, as ticks at the left.
    tek.polyline(std::vector<DevicePoint>{{cx, cy - 5 * scale}, {cx + 2, cy - 5 * scale}});
    tek.polyline(std::vector<DevicePoint>{{cx, cy}, {cx + 4, cy}});
    tek.polyline(std::vector<DevicePoint>{{cx, cy + 14 * scale}, {cx + 4, cy + 14 * scale}});
    draw_tek_glyph(tek, {cx, cy}, all[k], scale);
  }
  tek.alpha_at({0, 0});
  return tek.take();
}

}  // namespace

TEST_CASE("tek glyphs: every required character has one, and ASCII has none") {
  for (char32_t c : required) {
    INFO("U+", std::hex, static_cast<unsigned>(c), " ", utf8(c));
    CHECK(has_tek_glyph(c));
    CHECK(!tek_glyph(c).empty());
  }
  for (char32_t c = 0; c < 0x80; ++c) CHECK(!has_tek_glyph(c));
  for (char32_t c : {U'é', U'中', U'\u2400', U'\U0001F600', char32_t(0x110000)})
    CHECK(!has_tek_glyph(c));
  auto all = tek_glyph_characters();
  CHECK(std::is_sorted(all.begin(), all.end()));
  CHECK(std::adjacent_find(all.begin(), all.end()) == all.end());
}

TEST_CASE("tek glyphs: strokes inside the cell, and no two symbols drawn alike") {
  for (char32_t c : tek_glyph_characters()) {
    INFO("U+", std::hex, static_cast<unsigned>(c), " ", utf8(c));
    for (const GlyphStroke& stroke : tek_glyph(c)) {
      CHECK(stroke.size() >= 2);
      for (GlyphPoint p : stroke) {
        CHECK(p.x >= 0);
        CHECK(p.x <= 13);
        CHECK(p.y >= -6);
        CHECK(p.y <= 21);
      }
    }
  }
  auto all = tek_glyph_characters();
  auto same = [](std::span<const GlyphStroke> a, std::span<const GlyphStroke> b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!std::equal(a[i].begin(), a[i].end(), b[i].begin(), b[i].end(),
                      [](GlyphPoint p, GlyphPoint q) { return p.x == q.x && p.y == q.y; }))
        return false;
    return true;
  };
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      if (same_on_purpose(all[i], all[j])) continue;
      INFO(utf8(all[i]), " and ", utf8(all[j]));
      CHECK(!same(tek_glyph(all[i]), tek_glyph(all[j])));
    }
}

TEST_CASE("tek glyphs: drawn at a cell's corner, rounded, at either resolution") {
  Recorder r;
  CHECK(draw_tek_glyph(r, {100, 200}, U'×'));
  REQUIRE(r.paths.size() == 2);
  CHECK(r.paths[0] == DevicePath{{103, 204}, {109, 210}});  // 3,3.5 9,9.5: halves away from 0
  Recorder big;
  CHECK(draw_tek_glyph(big, {400, 800}, U'×', 4));
  REQUIRE(big.paths.size() == 2);
  CHECK(big.paths[0] == DevicePath{{412, 814}, {436, 838}});
  Recorder none;
  CHECK(!draw_tek_glyph(none, {0, 0}, U'A'));
  CHECK(none.paths.empty());
  // A dot is a square of one point, never a vector of length zero that the encoder would drop.
  Recorder dot;
  CHECK(draw_tek_glyph(dot, {0, 0}, U'·'));
  REQUIRE(dot.paths.size() == 1);
  CHECK(dot.paths[0].size() == 5);
  CHECK(dot.paths[0][0] != dot.paths[0][2]);
}

TEST_CASE("tek glyphs: the test sheet is a 4013 stream that tek2plot renders") {
  std::string sheet = glyph_sheet();
  TempDir dir;
  std::filesystem::path folder = dir.path();
  if (const char* keep = std::getenv("IGDS_TEK_GLYPH_SHEET")) folder = keep;
  std::filesystem::create_directories(folder);
  write_file(folder / "glyphs.tek", sheet);
  if (!have_program("tek2plot")) {
    MESSAGE("tek2plot is not installed (plotutils): the sheet is not rendered");
    return;
  }
  for (int page : {1, 2}) {
    RunResult svg = run({"tek2plot", "-T", "svg", "--page-number", std::to_string(page),
                         (folder / "glyphs.tek").string()});
    CHECK(svg.status == 0);
    CHECK(svg.err.empty());
    CHECK(svg.out.find("<svg") != std::string::npos);
    RunResult png = run({"tek2plot", "-T", "png", "--bitmap-size", "1600x1600", "--page-number",
                         std::to_string(page), (folder / "glyphs.tek").string()});
    CHECK(png.status == 0);
    CHECK(png.err.empty());
    CHECK(png.out.starts_with("\x89PNG"));
    write_file(folder / ("glyphs-" + std::to_string(page) + ".png"), png.out);
  }
}

}  // namespace igds::test::devices
