// Shared by the device tests and the end-to-end device tests: sample images, a device that
// records what it is given, an independent 4010/4014 decoder, and readers of the SVG that
// tek2plot writes and of the log and dump of hp2xx.
#pragma once

#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <optional>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

#include "commands/picture.h"
#include "devices/device.h"
#include "devices/hpgl_plot.h"
#include "devices/svg.h"
#include "devices/tek_stream.h"
#include "workspace/state.h"

namespace igds::test::devices {

// A surface image of `planes` curves of `rows` points: a sheared, slightly bent grid.
inline Image surface_image(std::size_t planes, std::size_t rows) {
  Image im;
  im.desim = {1, Projection::assonometric, {110, 130, 120}};
  im.points = Array({planes, rows, 2});
  for (std::size_t c = 0; c < planes; ++c)
    for (std::size_t r = 0; r < rows; ++r) {
      double u = static_cast<double>(r), v = static_cast<double>(c);
      im.points.ravel[2 * (c * rows + r)] = 10 * u + 2.5 * v;
      im.points.ravel[2 * (c * rows + r) + 1] = 8 * v + 0.05 * u * u;
    }
  return im;
}

// The flat XY grid of the benchmarks: `n` x `n` points, ORTHOGONAL XY.
inline Image flat_grid(std::size_t n) {
  Image im;
  im.desim = {1, Projection::orthogonal, {1, 0, 0}};
  im.points = Array({n, n, 2});
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t r = 0; r < n; ++r) {
      im.points.ravel[2 * (c * n + r)] = static_cast<double>(r);
      im.points.ravel[2 * (c * n + r) + 1] = static_cast<double>(c);
    }
  return im;
}

// An input image of NOCUR x NOSTR points with three border tangents.
inline Image input_image(std::size_t nocur, std::size_t nostr) {
  Image im = surface_image(nocur, nostr);
  im.desim = {0, Projection::conic, {12.5, -40, 1e3}};
  im.arrows = Array({3, 4});
  im.arrows.ravel = {0,
                     0,
                     3,
                     1,
                     10,
                     0,
                     0,
                     -4,
                     im.points.ravel[2 * (nostr - 1)],
                     im.points.ravel[2 * (nostr - 1) + 1],
                     1,
                     0.5};
  return im;
}

// The devices draw pictures; the sample images become pictures as DISPLAY makes them.
inline std::string display_bytes(const Image& im, TermMode mode, TekOptions tek) {
  return igds::display_bytes(picture_of(im), mode, tek);
}
inline std::string tek_stream(const Image& im, TekOptions tek) {
  return igds::tek_stream(picture_of(im), tek);
}
inline Plot plot_hpgl(const Image& im, const PlotOptions& options) {
  return igds::plot_hpgl(picture_of(im), options);
}
inline std::string svg_of(const Image& im) {
  return igds::svg_of(picture_of(im));
}

// A Device that keeps the polylines and text it is given.
struct Recorder : Device {
  struct Text {
    DevicePoint at;
    std::string line;
  };
  std::vector<DevicePath> paths;
  std::vector<Style> styles;  // each path's style
  std::vector<Text> texts;
  int pages = 0;
  Style current;
  void style(const Style& s) override { current = s; }
  void move(DevicePoint p) override {
    if (!paths.empty() && paths.back().back() == p && styles.back() == current) return;
    paths.push_back({p});
    styles.push_back(current);
  }
  void draw(DevicePoint p) override {
    if (paths.empty()) {
      paths.push_back({p});
      styles.push_back(current);
    }
    if (!(paths.back().back() == p)) paths.back().push_back(p);
  }
  void text(DevicePoint p, std::string_view line) override {
    texts.push_back({p, std::string(line)});
  }
  void page() override { ++pages; }
  // The polylines of at least two points (what a screen shows).
  std::vector<DevicePath> drawn() const {
    std::vector<DevicePath> out;
    for (const auto& p : paths)
      if (p.size() >= 2) out.push_back(p);
    return out;
  }
  // The styles of drawn(), path by path.
  std::vector<Style> drawn_styles() const {
    std::vector<Style> out;
    for (std::size_t k = 0; k < paths.size(); ++k)
      if (paths[k].size() >= 2) out.push_back(styles[k]);
    return out;
  }
};

// What a 4010 (10 bits) or a 4014 (12 bits) does with a stream, decoded independently of the
// encoder: graph-mode polylines, alpha text with the beam position where it started, pages.
struct TekDecoded {
  std::vector<DevicePath> paths;  // one per dark move followed by vectors
  std::vector<char> dashes;       // each path's 4014 line style: '`' solid, 'a' .. 'd' dashes
  std::vector<std::pair<DevicePoint, std::string>> texts;
  int pages = 0;
  bool ends_in_alpha = true;
  std::optional<DevicePoint> beam;  // the last address received
};

inline TekDecoded decode_tek(std::string_view s, int bits) {
  TekDecoded d;
  bool graph = false, dark = false, after_lo_y = false;
  int hi_y = 0, lo_y = 0, hi_x = 0, extra = 0;
  int pending_lo = -1;  // a 0x60..0x7F byte not yet known to be LoY or Extra
  char dash = '`';
  std::string* text = nullptr;
  for (std::size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == 0x1B && i + 1 < s.size()) {
      if (s[i + 1] == '\x0C') {
        ++d.pages;
        graph = false;
        text = nullptr;
      }
      if (s[i + 1] >= '`' && s[i + 1] <= 'd' && s[i + 1] != dash) {
        dash = s[i + 1];
        // Vectors after the change are in the new style: a path of their own from the beam.
        if (graph && !dark && d.beam) {
          d.paths.push_back({*d.beam});
          d.dashes.push_back(dash);
        }
      }
      ++i;
      continue;
    }
    if (c == 0x1D) {
      graph = dark = true;
      after_lo_y = false;
      pending_lo = -1;
      text = nullptr;
      continue;
    }
    if (c == 0x1F) {
      graph = false;
      text = nullptr;
      continue;
    }
    if (!graph) {
      if (c >= 0x20 && c < 0x7F) {
        if (!text) {
          d.texts.push_back({d.beam.value_or(DevicePoint{-1, -1}), ""});
          text = &d.texts.back().second;
        }
        *text += static_cast<char>(c);
      }
      continue;
    }
    if (c >= 0x60 && c < 0x80) {
      // Two low-Y-class bytes in a row: the first was Extra (4014).
      if (pending_lo >= 0 && bits == 12) extra = pending_lo & 31;
      pending_lo = c;
      lo_y = c & 31;
      after_lo_y = true;
    } else if (c >= 0x20 && c < 0x40) {
      if (after_lo_y)
        hi_x = c & 31;
      else
        hi_y = c & 31;
      after_lo_y = false;
      pending_lo = -1;
    } else if (c >= 0x40 && c < 0x60) {
      int lo_x = c & 31;
      DevicePoint p = bits == 12 ? DevicePoint{(hi_x << 7) | (lo_x << 2) | (extra & 3),
                                               (hi_y << 7) | (lo_y << 2) | ((extra >> 2) & 3)}
                                 : DevicePoint{(hi_x << 5) | lo_x, (hi_y << 5) | lo_y};
      if (dark || d.paths.empty()) {
        d.paths.push_back({p});
        d.dashes.push_back(dash);
      } else
        d.paths.back().push_back(p);
      dark = false;
      after_lo_y = false;
      pending_lo = -1;
      d.beam = p;
    }
  }
  d.ends_in_alpha = !graph;
  std::vector<DevicePath> drawn;
  std::vector<char> dashes;
  for (std::size_t k = 0; k < d.paths.size(); ++k)
    if (d.paths[k].size() >= 2) {
      drawn.push_back(std::move(d.paths[k]));
      dashes.push_back(d.dashes[k]);
    }
  d.paths = std::move(drawn);
  d.dashes = std::move(dashes);
  return d;
}

// The polylines of an SVG document: <polyline>, <polygon> (closed again) and <line>, with the
// coordinates as written, rounded to integers.
inline std::vector<DevicePath> svg_paths(const std::string& svg) {
  std::vector<DevicePath> out;
  static const std::regex element(R"(<(polyline|polygon|line)\s([^>]*)>)");
  static const std::regex points_attr(R"(points="([^"]*)\")");
  static const std::regex number(R"(-?[0-9.]+(e-?[0-9]+)?)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), element);
       it != std::sregex_iterator(); ++it) {
    std::string kind = (*it)[1], attrs = (*it)[2];
    std::vector<double> v;
    if (kind == "line") {
      for (const char* a : {"x1", "y1", "x2", "y2"}) {
        std::smatch m;
        std::regex r(std::string("\\b") + a + R"(="([^"]*)\")");
        if (std::regex_search(attrs, m, r)) v.push_back(std::strtod(m[1].str().c_str(), nullptr));
      }
    } else {
      std::smatch m;
      if (!std::regex_search(attrs, m, points_attr)) continue;
      std::string pts = m[1];
      for (auto n = std::sregex_iterator(pts.begin(), pts.end(), number);
           n != std::sregex_iterator(); ++n)
        v.push_back(std::strtod(n->str().c_str(), nullptr));
    }
    DevicePath path;
    for (std::size_t i = 0; i + 1 < v.size(); i += 2)
      path.push_back(
          {static_cast<int>(std::lround(v[i])), static_cast<int>(std::lround(v[i + 1]))});
    if (kind == "polygon" && !path.empty()) path.push_back(path.front());
    out.push_back(std::move(path));
  }
  return out;
}

// The strings one after the other (std::string's operator+ on a literal trips g++ 12's
// -Wrestrict).
inline std::string cat(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (auto p : parts) s.append(p);
  return s;
}

// Polylines as text, for the messages of failed checks.
inline std::string show(const std::vector<DevicePath>& paths) {
  std::string s;
  for (const auto& p : paths) {
    s += "[";
    for (auto q : p)
      s.append(" ").append(std::to_string(q.x)).append(",").append(std::to_string(q.y));
    s += " ]\n";
  }
  return s;
}

// hp2xx's log: how many HP-GL commands it read, and the coordinate range of the drawing.
struct Hp2xxLog {
  long commands = -1;
  double x0 = 0, y0 = 0, x1 = -1, y1 = -1;
};
inline Hp2xxLog read_hp2xx_log(const std::string& log) {
  Hp2xxLog l;
  std::smatch m;
  if (std::regex_search(log, m, std::regex(R"(HPGL commands read:\s*([0-9]+))")))
    l.commands = std::stol(m[1]);
  if (std::regex_search(
          log, m,
          std::regex(
              R"(Coordinate range: \(([-0-9.]+), ([-0-9.]+)\) \.\.\. \(([-0-9.]+), ([-0-9.]+)\))"))) {
    l.x0 = std::stod(m[1]), l.y0 = std::stod(m[2]);
    l.x1 = std::stod(m[3]), l.y1 = std::stod(m[4]);
  }
  return l;
}

}  // namespace igds::test::devices
