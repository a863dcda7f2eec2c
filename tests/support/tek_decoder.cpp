#include "tests/support/tek_decoder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace igds::test {

TekDrawing decode_tek(std::string_view s) {
  // The 4013's alpha cell and home position (xterm's TEKHOME for the large font).
  constexpr double cell_w = 14, cell_h = 22, home_y = 748;
  enum class Mode { alpha, graph, point };
  TekDrawing d;
  d.pages.emplace_back();
  Mode mode = Mode::alpha;
  TekPoint beam{0, home_y};
  bool first_address = true;  // the next complete address after GS is a dark move
  int hi_y = -1, lo_y = -1, hi_x = -1, extra = -1;
  bool extra_now = false;  // an Extra byte came with the address being received
  enum class Last { none, hi, lo } last = Last::none;
  bool in_text = false;

  auto error = [&](std::size_t at, std::string what) {
    if (d.errors.size() < 20) d.errors.push_back(fmt::format("byte {}: {}", at, what));
  };
  auto put_text = [&](std::string_view bytes) {
    auto& texts = d.pages.back().texts;
    if (!in_text) {
      texts.push_back({beam, ""});
      in_text = true;
    }
    texts.back().text += bytes;
  };
  auto newline = [&] {
    beam.y -= cell_h;
    if (beam.y < 0) beam.y = home_y;
    in_text = false;
  };

  for (std::size_t i = 0; i < s.size(); ++i) {
    auto c = static_cast<unsigned char>(s[i]);
    if (c == 0x1B) {  // ESC sequences
      if (i + 1 >= s.size()) {
        error(i, "ESC at the end of the stream");
        break;
      }
      auto n = static_cast<unsigned char>(s[++i]);
      if (n == 0x0C) {  // page
        d.pages.emplace_back();
        mode = Mode::alpha;
        beam = {0, home_y};
        in_text = false;
      } else if (n == '[') {  // an xterm control sequence (switching windows): skip it
        while (i + 1 < s.size() && !(s[i + 1] >= 0x40 && s[i + 1] <= 0x7E)) ++i;
        ++i;
      } else if (n == 0x03 || n == 0x05 || n == 0x17 || n == 0x0E || n == 0x0F ||
                 (n >= '8' && n <= ';') || (n >= 0x60 && n <= 0x6F)) {
        // switch back to VT, enquiry, hard copy, APL set on/off, character size, line style
      } else {
        error(i, fmt::format("unknown ESC 0x{:02X}", n));
      }
      continue;
    }
    if (c == 0x1D || c == 0x1C) {  // GS graph, FS point plot
      mode = c == 0x1D ? Mode::graph : Mode::point;
      first_address = true;
      last = Last::none;
      in_text = false;
      continue;
    }
    if (c == 0x1F) {  // US alpha at the beam
      mode = Mode::alpha;
      in_text = false;
      continue;
    }
    if (c == '\r') {
      mode = Mode::alpha;
      beam.x = 0;
      in_text = false;
      continue;
    }
    if (c == '\n') {
      mode = Mode::alpha;
      newline();
      continue;
    }
    if (c == 0x07 || c == 0x00) continue;  // bell, padding
    if (c == 0x08) {
      beam.x = std::max(0.0, beam.x - cell_w);
      in_text = false;
      continue;
    }
    if (mode == Mode::alpha) {
      if (c < 0x20) {
        error(i, fmt::format("control byte 0x{:02X} in alpha mode", c));
        continue;
      }
      if (c >= 0x80) {  // a UTF-8 sequence: one character
        std::size_t len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
        put_text(s.substr(i, len));
        i += len - 1;
      } else {
        if (beam.x + cell_w > 1024) {
          beam.x = 0;
          newline();
        }
        put_text(s.substr(i, 1));
      }
      beam.x += cell_w;
      continue;
    }
    // Graph or point mode: address bytes (docs/devices.md, "Tektronix 4013").
    if (c < 0x20 || c >= 0x80) {
      error(i, fmt::format("byte 0x{:02X} inside graph data", c));
      continue;
    }
    int tag = c & 0x60, value = c & 0x1F;
    if (tag == 0x20) {
      if (last == Last::lo)
        hi_x = value;
      else
        hi_y = value;
      last = Last::hi;
    } else if (tag == 0x60) {
      if (last == Last::lo) {  // two in a row: the first was the 12-bit Extra byte
        extra = lo_y;
        extra_now = true;
      }
      lo_y = value;
      last = Last::lo;
    } else {  // LoX completes the address
      if (hi_y < 0 || lo_y < 0 || hi_x < 0) {
        error(i, "an address completed before its high bytes were ever sent");
        last = Last::none;
        continue;
      }
      TekPoint p;
      if (extra_now) {
        p.x = ((hi_x << 7) | (value << 2) | (extra & 3)) / 4.0;
        p.y = ((hi_y << 7) | (lo_y << 2) | ((extra >> 2) & 3)) / 4.0;
      } else {
        p.x = (hi_x << 5) | value;
        p.y = (hi_y << 5) | lo_y;
      }
      extra_now = false;
      last = Last::none;
      if (mode == Mode::point) {
        d.pages.back().segments.push_back({p, p});
      } else if (!first_address) {
        d.pages.back().segments.push_back({beam, p});
      }
      first_address = false;
      beam = p;
    }
  }
  return d;
}

double distance(TekPoint p, const TekSegment& s) {
  double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (s.a.x + t * dx), p.y - (s.a.y + t * dy));
}

namespace {

struct Cell {
  double x0, y0, x1, y1;
  char32_t c;
  std::size_t text;  // which text it belongs to
};

// The cells of a page's characters (one per character; UTF-8 sequences count once).
std::vector<Cell> cells_of(const TekPage& page) {
  std::vector<Cell> cells;
  for (std::size_t t = 0; t < page.texts.size(); ++t) {
    const auto& text = page.texts[t];
    double x = text.at.x;
    for (std::size_t i = 0; i < text.text.size();) {
      const auto b = static_cast<unsigned char>(text.text[i]);
      const std::size_t n = b < 0x80 ? 1 : b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : 2;
      if (text.text[i] != ' ')
        cells.push_back({x, text.at.y - 4, x + 14, text.at.y + 16, static_cast<char32_t>(b), t});
      x += 14;
      i += n;
    }
  }
  return cells;
}

bool overlap(const Cell& a, const Cell& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// Whether a segment passes through the inside of a cell (Liang-Barsky on the open box).
bool crosses(const TekSegment& s, const Cell& c) {
  double t0 = 0, t1 = 1;
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {s.a.x - c.x0, c.x1 - s.a.x, s.a.y - c.y0, c.y1 - s.a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] <= 0) return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0)
      t0 = std::max(t0, r);
    else
      t1 = std::min(t1, r);
    if (t0 >= t1) return false;
  }
  return true;
}

}  // namespace

std::vector<std::string> screen_faults(const TekPage& page) {
  std::vector<std::string> faults;
  auto fault = [&](std::string what) {
    if (faults.size() < 20) faults.push_back(std::move(what));
  };
  const auto cells = cells_of(page);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell& a = cells[i];
    if (a.x0 < 0 || a.x1 > 1024 || a.y0 < 0 || a.y1 > 780)
      fault(fmt::format("text \"{}\" off the screen at ({}, {})", page.texts[a.text].text, a.x0,
                        a.y0 + 4));
    for (std::size_t j = i + 1; j < cells.size(); ++j)
      if (cells[j].text != a.text && overlap(a, cells[j]))
        fault(fmt::format("text \"{}\" over text \"{}\"", page.texts[cells[j].text].text,
                          page.texts[a.text].text));
  }
  // A point number of DISPLAY INPUT (digits in the picture's square, left of the captions): its
  // own picture keeps clear of it (tests/commands/workbench_test.cpp), but an image DISPLAYed
  // over it without ERASE draws across it, as on the storage tube.
  auto point_number = [&](const Cell& c) {
    const auto& t = page.texts[c.text];
    return t.at.x < 600 && t.at.y >= 184 && !t.text.empty() &&
           std::all_of(t.text.begin(), t.text.end(),
                       [](char ch) { return ch >= '0' && ch <= '9'; });
  };
  for (const auto& s : page.segments) {
    for (const TekPoint& p : {s.a, s.b})
      if (p.x < 0 || p.x > 1023 || p.y < 0 || p.y > 767)
        fault(fmt::format("a vector off the screen at ({}, {})", p.x, p.y));
    for (const Cell& c : cells)
      if (!point_number(c) && crosses(s, c))
        fault(fmt::format("a vector ({}, {})-({}, {}) through text \"{}\"", s.a.x, s.a.y, s.b.x,
                          s.b.y, page.texts[c.text].text));
  }
  return faults;
}

}  // namespace igds::test
