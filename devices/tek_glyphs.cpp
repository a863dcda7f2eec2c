#include "devices/tek_glyphs.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace igds {

namespace {

// The strokes are written as text, items separated by ';', in cell units (tek_glyphs.h):
//   x,y x,y ...        a polyline
//   o cx,cy rx,ry      an ellipse, as a closed polygon of 16 sides
//   d x,y              a dot: a closed square of one unit around x,y
//   @name or @name+dx,dy   a part below, moved by dx,dy
// Metrics: baseline 0, x-height 9, capitals 14, descenders -5, the axis of the operators 6.5,
// the middle of the cell x = 6. APL's overstruck symbols (IBM APL2 Language Reference,
// Appendix A) are built of their parts, as the typeball built them.

struct Part {
  std::string_view name, strokes;
};

constexpr Part parts[] = {
    {"bar", "2,6.5 10,6.5"},
    {"widebar", "0.5,6.5 11.5,6.5"},
    {"stile", "6,-2 6,15"},
    {"slash", "2,-2 10,15"},
    {"backslash", "2,15 10,-2"},
    {"tilde", "1.5,6 3,7.5 4.5,8 6,7 7.5,6 9,5.5 10.5,7"},
    {"dots", "d 3.5,12; d 8.5,12"},
    {"star", "6,2.5 6,10.5; 2.5,4.5 9.5,8.5; 2.5,8.5 9.5,4.5"},
    {"circle", "o 6,6.5 5,5"},
    {"jot", "o 6,6.5 2.2,2.2"},
    {"underbar", "1,-3 11,-3"},
    {"overbar", "1,16.5 11,16.5"},
    {"quad", "1.5,-1 10.5,-1 10.5,14 1.5,14 1.5,-1"},
    {"delta", "6,14 11,0 1,0 6,14"},
    {"del", "1,14 11,14 6,0 1,14"},
    {"upcaret", "2,0 6,10 10,0"},
    {"downcaret", "2,10 6,0 10,10"},
    {"upshoe", "2,0 2,5 2.6,7.5 4,9.2 6,9.8 8,9.2 9.4,7.5 10,5 10,0"},
    {"downshoe", "2,10 2,5 2.6,2.5 4,0.8 6,0.2 8,0.8 9.4,2.5 10,5 10,10"},
    {"leftshoe", "10.5,11.5 6,11.5 3.5,10.8 1.9,9 1.3,6.5 1.9,4 3.5,2.2 6,1.5 10.5,1.5"},
    {"rightshoe", "1.5,11.5 6,11.5 8.5,10.8 10.1,9 10.7,6.5 10.1,4 8.5,2.2 6,1.5 1.5,1.5"},
    {"epsilon", "9.5,9 6,9 3.8,8.3 2.5,6.8 2,4.75 2.5,2.7 3.8,1.2 6,0.5 9.5,0.5; 2,4.75 8.5,4.75"},
    {"iota", "3.5,9 6,9 6,1.5 6.7,0.4 8,0 9.5,0.6"},
    {"rho", "o 6.5,4.5 3.5,4.5; 3,-5 3,4.5"},
    {"alpha",
     "10.5,9.5 9.6,6.5 8.3,3.2 6.8,1 5,0 3.4,0.3 2.2,1.8 1.6,4.5 2.2,7.2 3.4,8.7 5,9.2 6.8,8 "
     "8.3,5.8 9.6,2.5 10.5,0"},
    {"omega",
     "3,9 1.8,7 1.5,4 2,1.5 3.2,0 4.5,0 5.5,1.5 6,4.5 6.5,1.5 7.5,0 8.8,0 10,1.5 10.5,4 10.2,7 "
     "9,9"},
    {"less", "10,11.5 2,6.5 10,1.5"},
    {"greater", "2,11.5 10,6.5 2,1.5"},
    {"equal", "2,8.5 10,8.5; 2,4.5 10,4.5"},
    {"diamond", "6,11.5 10,6.5 6,1.5 2,6.5 6,11.5"},
    {"left", "1,6.5 11,6.5; 5,10.5 1,6.5 5,2.5"},
    {"right", "1,6.5 11,6.5; 7,10.5 11,6.5 7,2.5"},
    {"up", "6,-1 6,14; 2,10 6,14 10,10"},
    {"down", "6,14 6,-1; 2,3 6,-1 10,3"},
    {"base", "6,14 6,0; 1,0 11,0"},         // ⊥, decode
    {"represent", "1,14 11,14; 6,14 6,0"},  // ⊤, encode
    {"comma", "7,1.5 7,-0.5 5.5,-3"},
    {"quote", "6,14 6,10"},
    {"semicolon", "d 6,7; @comma"},
};

struct Definition {
  char32_t c;
  std::string_view strokes;
};

constexpr Definition definitions[] = {
    // Signs of igds's own texts and APL numbers.
    {U'\u00A8', "@dots"},                         // ¨ diaeresis (each)
    {U'\u00AF', "3,14 9,14"},                     // ¯ high minus
    {U'\u00B0', "o 6,12 2,2"},                    // ° degree
    {U'\u00B1', "2,9 10,9; 6,13 6,5; 2,2 10,2"},  // ± plus-minus
    {U'\u00B2', "3.5,14 4.5,15.3 6,15.8 7.5,15.3 8,14 7.5,12.8 3.5,10 8.5,10"},             // ²
    {U'\u00B3', "3.5,15.5 8,15.8 5.5,13.3 7.2,13 8.2,11.8 7.5,10.3 6,10 4.5,10.3 3.5,11"},  // ³
    {U'\u00B7', "d 6,6.5"},                   // · middle dot
    {U'\u00D7', "3,3.5 9,9.5; 3,9.5 9,3.5"},  // × times
    {U'\u00F7', "@bar; d 6,10; d 6,3"},       // ÷ divide
    {U'\u0394', "@delta"},                    // Δ Greek delta
    {U'\u03B1', "@alpha"},                    // α
    {U'\u03B5', "@epsilon"},                  // ε
    {U'\u03B9', "@iota"},                     // ι
    {U'\u03C0', "1.5,8.5 2.5,9.5 11,9.5; 4.5,9.5 4,4 3,0; 8.5,9.5 8.5,1.5 9.5,0"},  // π
    {U'\u03C1', "@rho"},                                                            // ρ
    {U'\u03C9', "@omega"},                                                          // ω
    {U'\u2013', "1.5,6.5 10.5,6.5"},                                                // – en dash
    {U'\u2014', "0,6.5 13,6.5"},                                                    // — em dash
    {U'\u2026', "d 2,0.5; d 6,0.5; d 10,0.5"},                                      // … ellipsis
    // Arrows.
    {U'\u2190', "@left"},   // ← assignment
    {U'\u2191', "@up"},     // ↑ take
    {U'\u2192', "@right"},  // → branch
    {U'\u2193', "@down"},   // ↓ drop
    // Mathematical operators APL uses.
    {U'\u2206', "@delta"},                                                 // ∆
    {U'\u2207', "@del"},                                                   // ∇
    {U'\u2208', "@epsilon"},                                               // ∈
    {U'\u220A', "@epsilon"},                                               // ∊ membership
    {U'\u2212', "@bar"},                                                   // − minus
    {U'\u2217', "@star"},                                                  // ∗ power
    {U'\u2218', "@jot"},                                                   // ∘ jot
    {U'\u221A', "1,7 3,8 6,-1 11.5,16"},                                   // √
    {U'\u2223', "@stile"},                                                 // ∣ residue
    {U'\u2227', "@upcaret"},                                               // ∧ and
    {U'\u2228', "@downcaret"},                                             // ∨ or
    {U'\u2229', "@upshoe"},                                                // ∩ intersection
    {U'\u222A', "@downshoe"},                                              // ∪ union
    {U'\u223C', "@tilde"},                                                 // ∼ not
    {U'\u2248', "@tilde+0,2; @tilde+0,-2"},                                // ≈
    {U'\u2260', "@equal; 8.5,12.5 3.5,0.5"},                               // ≠
    {U'\u2261', "2,10.5 10,10.5; @bar; 2,2.5 10,2.5"},                     // ≡ match
    {U'\u2262', "2,10.5 10,10.5; @bar; 2,2.5 10,2.5; 8.5,13.5 3.5,-0.5"},  // ≢ tally
    {U'\u2264', "10,13 2,9 10,5; 2,2.5 10,2.5"},                           // ≤
    {U'\u2265', "2,13 10,9 2,5; 2,2.5 10,2.5"},                            // ≥
    {U'\u2282', "@leftshoe"},                                              // ⊂ enclose
    {U'\u2283', "@rightshoe"},                                             // ⊃ disclose
    {U'\u2286', "@leftshoe+0,2; 1.5,1 10.5,1"},                            // ⊆ nest
    {U'\u2296', "@circle; @widebar"},                                      // ⊖ rotate first
    {U'\u22A2', "2,14 2,-1; 2,6.5 10.5,6.5"},                              // ⊢ right tack
    {U'\u22A3', "10,14 10,-1; 1.5,6.5 10,6.5"},                            // ⊣ left tack
    {U'\u22A4', "@represent"},                                             // ⊤ encode
    {U'\u22A5', "@base"},                                                  // ⊥ decode
    {U'\u22C4', "@diamond"},          // ⋄ statement separator
    {U'\u22C6', "@star"},             // ⋆ power
    {U'\u2308', "9.5,15 4,15 4,-2"},  // ⌈ ceiling
    {U'\u230A', "4,15 4,-2 9.5,-2"},  // ⌊ floor
    // The APL functional symbols (Unicode's names of the tacks are upside down: ⍎ is ⊥ and ∘).
    {U'\u2336', "2.5,14 9.5,14; 6,14 6,-1; 2.5,-1 9.5,-1"},                // ⌶ I-beam
    {U'\u2337', "3.5,-2 8.5,-2 8.5,15 3.5,15 3.5,-2"},                     // ⌷ squish quad
    {U'\u2338', "@quad; 3.5,8.5 8.5,8.5; 3.5,4.5 8.5,4.5"},                // ⌸ quad equal
    {U'\u2339', "@quad; 3.5,6.5 8.5,6.5; d 6,10; d 6,3"},                  // ⌹ domino
    {U'\u233A', "@quad; 6,10.5 9,6.5 6,2.5 3,6.5 6,10.5"},                 // ⌺ quad diamond
    {U'\u233B', "@quad; @jot"},                                            // ⌻ quad jot
    {U'\u233C', "@quad; o 6,6.5 3.5,3.5"},                                 // ⌼ quad circle
    {U'\u233D', "@circle; @stile"},                                        // ⌽ reverse
    {U'\u233E', "@circle; @jot"},                                          // ⌾ circle jot
    {U'\u233F', "@slash; @widebar"},                                       // ⌿ reduce first
    {U'\u2340', "@backslash; @widebar"},                                   // ⍀ scan first
    {U'\u2341', "@quad; 1.5,-1 10.5,14"},                                  // ⍁ quad slash
    {U'\u2342', "@quad; 1.5,14 10.5,-1"},                                  // ⍂ quad backslash
    {U'\u2343', "@quad; 8.5,10.5 3.5,6.5 8.5,2.5"},                        // ⍃ quad less
    {U'\u2344', "@quad; 3.5,10.5 8.5,6.5 3.5,2.5"},                        // ⍄ quad greater
    {U'\u2345', "@left; 9,10.5 9,2.5"},                                    // ⍅ leftwards vane
    {U'\u2346', "@right; 3,10.5 3,2.5"},                                   // ⍆ rightwards vane
    {U'\u2347', "@quad; 3,6.5 9,6.5; 5.5,9 3,6.5 5.5,4"},                  // ⍇ quad left arrow
    {U'\u2348', "@quad; 3,6.5 9,6.5; 6.5,9 9,6.5 6.5,4"},                  // ⍈ quad right arrow
    {U'\u2349', "@circle; @backslash"},                                    // ⍉ transpose
    {U'\u234A', "@base; @underbar"},                                       // ⍊ ⊥ underbar
    {U'\u234B', "@delta; @stile"},                                         // ⍋ grade up
    {U'\u234C', "@quad; 3.5,10 6,3 8.5,10"},                               // ⍌ quad down caret
    {U'\u234D', "@quad; 6,11 9,2.5 3,2.5 6,11"},                           // ⍍ quad delta
    {U'\u234E', "6,14 6,8.7; 6,4.3 6,0; 1,0 11,0; @jot"},                  // ⍎ execute
    {U'\u234F', "@up; 2,2 10,2"},                                          // ⍏ upwards vane
    {U'\u2350', "@quad; 6,1.5 6,11.5; 3.5,9 6,11.5 8.5,9"},                // ⍐ quad up arrow
    {U'\u2351', "@represent; @overbar"},                                   // ⍑ ⊤ overbar
    {U'\u2352', "@del; @stile"},                                           // ⍒ grade down
    {U'\u2353', "@quad; 3.5,3 6,10 8.5,3"},                                // ⍓ quad up caret
    {U'\u2354', "@quad; 3,11 9,11 6,2.5 3,11"},                            // ⍔ quad del
    {U'\u2355', "1,14 11,14; 6,14 6,8.7; 6,4.3 6,0; @jot"},                // ⍕ format
    {U'\u2356', "@down; 2,11 10,11"},                                      // ⍖ downwards vane
    {U'\u2357', "@quad; 6,11.5 6,1.5; 3.5,4 6,1.5 8.5,4"},                 // ⍗ quad down arrow
    {U'\u2358', "@quote; @underbar"},                                      // ⍘ quote underbar
    {U'\u2359', "@delta; @underbar"},                                      // ⍙ delta underbar
    {U'\u235A', "@diamond; @underbar"},                                    // ⍚ diamond underbar
    {U'\u235B', "@jot; @underbar"},                                        // ⍛ jot underbar
    {U'\u235C', "@circle; @underbar"},                                     // ⍜ circle underbar
    {U'\u235D', "@upshoe; @jot+0,3.3"},                                    // ⍝ lamp (comment)
    {U'\u235E', "@quad; 6,12 6,8.5"},                                      // ⍞ quote quad
    {U'\u235F', "@circle; 6,3 6,10; 3,4.75 9,8.25; 3,8.25 9,4.75"},        // ⍟ logarithm
    {U'\u2360', "@quad; d 6,9.5; d 6,3.5"},                                // ⍠ quad colon
    {U'\u2361', "@represent; @dots+0,5"},                                  // ⍡ ⊤ diaeresis
    {U'\u2362', "@del; @dots+0,5"},                                        // ⍢ del diaeresis
    {U'\u2363', "@star; @dots+0,1.5"},                                     // ⍣ power operator
    {U'\u2364', "@jot; @dots"},                                            // ⍤ rank
    {U'\u2365', "@circle; @dots+0,2.5"},                                   // ⍥ over
    {U'\u2366', "@downshoe; @stile"},                                      // ⍦ down shoe stile
    {U'\u2367', "@leftshoe; @stile"},                                      // ⍧ left shoe stile
    {U'\u2368', "@tilde; @dots"},                                          // ⍨ commute
    {U'\u2369', "@greater; @dots+0,2"},                                    // ⍩ greater diaeresis
    {U'\u236A', "@bar; @comma"},                                           // ⍪ catenate first
    {U'\u236B', "@del; @tilde+0,3"},                                       // ⍫ del tilde
    {U'\u236C', "o 6,6.5 3.5,6.5; @tilde"},                                // ⍬ zilde
    {U'\u236D', "@stile; @tilde"},                                         // ⍭ stile tilde
    {U'\u236E', "@semicolon; @underbar"},                                  // ⍮ semicolon underbar
    {U'\u236F', "@quad; 3.5,8.5 8.5,8.5; 3.5,4.5 8.5,4.5; 8,11.5 4,1.5"},  // ⍯ quad not equal
    {U'\u2370',
     "@quad; 4,9.5 4.5,11 6,11.7 7.5,11 8,9.5 7.5,8.2 6,7 6,4.5; d 6,2"},  // ⍰ quad question
    {U'\u2371', "@downcaret; @tilde+0,1"},                                 // ⍱ nor
    {U'\u2372', "@upcaret; @tilde+0,1"},                                   // ⍲ nand
    {U'\u2373', "@iota"},                                                  // ⍳ index
    {U'\u2374', "@rho"},                                                   // ⍴ shape
    {U'\u2375', "@omega"},                                                 // ⍵ right argument
    {U'\u2376', "@alpha; @underbar"},                                      // ⍶ alpha underbar
    {U'\u2377', "@epsilon; @underbar"},                                    // ⍷ find
    {U'\u2378', "@iota; @underbar"},                                       // ⍸ where
    {U'\u2379', "@omega; @underbar"},                                      // ⍹ omega underbar
    {U'\u237A', "@alpha"},                                                 // ⍺ left argument
    {U'\u2395', "@quad"},                                                  // ⎕ quad
    {U'\u25CB', "@circle"},                                                // ○ circle
};

[[noreturn]] void bad_table(char32_t c, std::string_view what) {
  throw std::logic_error("tek glyph U+" + std::to_string(static_cast<unsigned long>(c)) + ": " +
                         std::string(what));
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

// "x,y" at the start of `s`, which is left after it.
GlyphPoint pair(char32_t c, std::string_view& s) {
  s = trimmed(s);
  GlyphPoint p;
  auto r = std::from_chars(s.data(), s.data() + s.size(), p.x);
  if (r.ec != std::errc() || r.ptr == s.data() + s.size() || *r.ptr != ',') bad_table(c, s);
  const char* y = r.ptr + 1;
  r = std::from_chars(y, s.data() + s.size(), p.y);
  if (r.ec != std::errc()) bad_table(c, s);
  s.remove_prefix(static_cast<std::size_t>(r.ptr - s.data()));
  return p;
}

using Polylines = std::vector<std::vector<GlyphPoint>>;

// Appends the strokes written in `text`, moved by (dx, dy), to `out`.
void parse(char32_t c, std::string_view text, double dx, double dy, Polylines& out, int depth) {
  if (depth > 4) bad_table(c, "parts nested too deep");
  while (!text.empty()) {
    std::size_t end = std::min(text.find(';'), text.size());
    std::string_view item = trimmed(text.substr(0, end));
    text.remove_prefix(std::min(end + 1, text.size()));
    if (item.empty()) bad_table(c, "an empty stroke");
    if (item.front() == '@') {
      std::size_t plus = std::min(item.find('+'), item.size());
      std::string_view name = item.substr(1, plus - 1);
      auto part = std::find_if(std::begin(parts), std::end(parts),
                               [&](const Part& p) { return p.name == name; });
      if (part == std::end(parts)) bad_table(c, item);
      GlyphPoint by;
      if (plus < item.size()) {
        std::string_view rest = item.substr(plus + 1);
        by = pair(c, rest);
        if (!trimmed(rest).empty()) bad_table(c, item);
      }
      parse(c, part->strokes, dx + by.x, dy + by.y, out, depth + 1);
      continue;
    }
    std::vector<GlyphPoint> line;
    if (item.starts_with("o ")) {
      std::string_view rest = item.substr(2);
      GlyphPoint centre = pair(c, rest), radius = pair(c, rest);
      if (!trimmed(rest).empty()) bad_table(c, item);
      for (int k = 0; k <= 16; ++k) {
        double a = 2 * std::numbers::pi * (k % 16) / 16;
        line.push_back(
            {dx + centre.x + radius.x * std::cos(a), dy + centre.y + radius.y * std::sin(a)});
      }
    } else if (item.starts_with("d ")) {
      std::string_view rest = item.substr(2);
      GlyphPoint p = pair(c, rest);
      if (!trimmed(rest).empty()) bad_table(c, item);
      double x = dx + p.x, y = dy + p.y;
      line = {{x - 0.5, y - 0.5},
              {x + 0.5, y - 0.5},
              {x + 0.5, y + 0.5},
              {x - 0.5, y + 0.5},
              {x - 0.5, y - 0.5}};
    } else {
      std::string_view rest = item;
      while (!trimmed(rest).empty()) {
        GlyphPoint p = pair(c, rest);
        line.push_back({dx + p.x, dy + p.y});
      }
      if (line.size() < 2) bad_table(c, item);
    }
    out.push_back(std::move(line));
  }
}

// The table read once: all points in one array, the strokes as views of it.
struct Glyphs {
  std::vector<char32_t> characters;
  std::vector<std::size_t> first;  // by character: its first stroke; one more at the end
  std::vector<GlyphPoint> points;
  std::vector<GlyphStroke> strokes;

  Glyphs() {
    std::vector<Definition> sorted(std::begin(definitions), std::end(definitions));
    std::sort(sorted.begin(), sorted.end(),
              [](const Definition& a, const Definition& b) { return a.c < b.c; });
    std::vector<std::pair<std::size_t, std::size_t>> spans;  // offset and size in points
    for (const Definition& d : sorted) {
      if (!characters.empty() && characters.back() == d.c) bad_table(d.c, "defined twice");
      if (d.c < 0x80) bad_table(d.c, "ASCII is the terminal's own");
      characters.push_back(d.c);
      first.push_back(spans.size());
      Polylines lines;
      parse(d.c, d.strokes, 0, 0, lines, 0);
      for (const auto& line : lines) {
        spans.push_back({points.size(), line.size()});
        points.insert(points.end(), line.begin(), line.end());
      }
    }
    first.push_back(spans.size());
    for (auto [offset, size] : spans) strokes.push_back({points.data() + offset, size});
  }
};

const Glyphs& glyphs() {
  static const Glyphs all;
  return all;
}

}  // namespace

std::span<const GlyphStroke> tek_glyph(char32_t c) {
  const Glyphs& g = glyphs();
  auto it = std::lower_bound(g.characters.begin(), g.characters.end(), c);
  if (it == g.characters.end() || *it != c) return {};
  auto k = static_cast<std::size_t>(it - g.characters.begin());
  return std::span<const GlyphStroke>(g.strokes).subspan(g.first[k], g.first[k + 1] - g.first[k]);
}

bool has_tek_glyph(char32_t c) {
  return !tek_glyph(c).empty();
}

std::span<const char32_t> tek_glyph_characters() {
  return glyphs().characters;
}

bool draw_tek_glyph(Device& device, DevicePoint origin, char32_t c, int scale) {
  std::span<const GlyphStroke> strokes = tek_glyph(c);
  std::vector<DevicePoint> line;
  for (const GlyphStroke& stroke : strokes) {
    line.clear();
    for (GlyphPoint p : stroke)
      line.push_back({origin.x + static_cast<int>(std::lround(p.x * scale)),
                      origin.y + static_cast<int>(std::lround(p.y * scale))});
    device.polyline(line);
  }
  return !strokes.empty();
}

}  // namespace igds
