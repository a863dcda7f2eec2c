#include "devices/svg.h"

#include <fmt/format.h>

#include <algorithm>

#include "devices/layout.h"
#include "workspace/numbers/decimal.h"

namespace igds {

namespace {

int flip(int y) {
  return tek_screen::height - 1 - y;
}

// " x,y" (or "x,y" without the blank) of the 4013 point p: a polyline's points are most of the
// document.
char* put_point(char* out, bool blank, DevicePoint p) {
  if (blank) *out++ = ' ';
  return put_pair(out, p.x, flip(p.y));
}

// The background: the whole screen white (`more`: attributes besides, inside the group).
std::string background(std::string_view more = "") {
  using namespace tek_screen;
  return fmt::format("<rect width=\"{}\" height=\"{}\" fill=\"white\"{}/>\n", width, height, more);
}

// The colour of pen n (docs/devices.md, "Pens and dashes"), of lines and texts alike: the
// plotter's six pens, a pen above 6 drawn with pen 6 as PLOT draws it.
std::string_view colour_of(int pen) {
  static constexpr std::string_view colours[] = {"black", "red",     "green",
                                                 "blue",  "magenta", "cyan"};
  return colours[static_cast<std::size_t>(std::clamp(pen, 1, 6) - 1)];
}

// The attributes of polylines in `style`: "" for pen 1, solid, weight 1.
std::string attributes_of(const Style& style) {
  std::string a;
  if (style.pen != 1) a += fmt::format(" stroke=\"{}\"", colour_of(style.pen));
  switch (style.dash) {
    case Dash::solid:
      break;
    case Dash::dashed:
      a += " stroke-dasharray=\"8 4\"";
      break;
    case Dash::chain:
      a += " stroke-dasharray=\"12 3 2 3\"";
      break;
    case Dash::dotted:
      a += " stroke-dasharray=\"1 3\"";
      break;
  }
  if (style.weight > 1) a += fmt::format(" stroke-width=\"{}\"", style.weight);
  return a;
}

}  // namespace

SvgWriter::SvgWriter(TextOut& out) : out_(&out) {
  using namespace tek_screen;
  out_->put(
      fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
                  "viewBox=\"0 0 {0} {1}\">\n"
                  "{3}"
                  "<g fill=\"none\" stroke=\"black\" stroke-width=\"1\" stroke-linejoin=\"round\" "
                  "stroke-linecap=\"round\" font-family=\"monospace\" font-size=\"{2}\">\n",
                  width, height, line_height - 4, background()));
}

void SvgWriter::start_polyline() {
  out_->put("<polyline points=\"");
  out_->commit(put_point(out_->room(32), false, at_));
  drawing_ = true;
}

// The attributes in force are those of the whole polyline: style() closes it before they change.
void SvgWriter::close_polyline() {
  if (drawing_) {
    out_->put('"');
    out_->put(attributes_);
    out_->put("/>\n");
  }
  drawing_ = false;
}

void SvgWriter::move(DevicePoint p) {
  if (at_known_ && at_ == p) return;
  close_polyline();
  at_ = p;
  at_known_ = true;
}

void SvgWriter::draw(DevicePoint p) {
  if (!at_known_) {
    move(p);
    return;
  }
  if (at_ == p) return;
  if (!drawing_) start_polyline();
  out_->commit(put_point(out_->room(32), true, p));
  at_ = p;
}

void SvgWriter::polyline(std::span<const DevicePoint> points) {
  if (points.empty()) return;
  move(points.front());
  std::size_t i = 1;
  while (i < points.size() && points[i] == at_) ++i;
  if (i == points.size()) return;
  if (!drawing_) start_polyline();
  // At most 24 bytes a point, written in place, as many points at a time as the output has
  // room for.
  constexpr std::size_t most = TextOut::max_room / 24;
  DevicePoint at = at_;
  while (i < points.size()) {
    char* out = out_->room(24 * std::min(points.size() - i, most));
    for (const std::size_t end = std::min(points.size(), i + most); i < end; ++i) {
      const DevicePoint p = points[i];
      if (p == at) continue;
      out = put_point(out, true, p);
      at = p;
    }
    out_->commit(out);
  }
  at_ = at;
}

void SvgWriter::paths(const PathParts& paths, std::span<const Style> styles) {
  // A path's bytes depend only on the writer's state when it starts: whether it ends the
  // element before (and with which attributes) and starts one. That is found path by path, in
  // order; the points are then written on the cores (put_each) in chunks, each needing only the
  // point before it.
  struct Opening {
    std::size_t close = 0;  // 1 + the attributes of the element it ends; 0: none
    bool start = false;     // it starts an element: at its first point, before its first vector
  };
  std::vector<std::string> attributes{attributes_};
  std::vector<Opening> openings(paths.size());
  const Style* last = nullptr;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    Opening& o = openings[k];
    auto close = [&] {
      if (drawing_) o.close = attributes.size();
      drawing_ = false;
    };
    if (!last || !(styles[k] == *last)) {
      last = &styles[k];
      pen_ = styles[k].pen;
      std::string a = attributes_of(styles[k]);
      if (a != attributes_) {
        close();
        attributes_ = std::move(a);
        attributes.push_back(attributes_);
      }
    }
    const std::span<const DevicePoint> points = paths[k];
    if (points.empty()) continue;
    if (!(at_known_ && at_ == points.front())) close();
    at_ = points.front(), at_known_ = true;
    if (std::all_of(points.begin(), points.end(), [&](DevicePoint p) { return p == at_; }))
      continue;
    o.start = !drawing_;
    drawing_ = true;
    at_ = points.back();
  }
  struct Chunk {
    std::size_t path, first, last;  // the path's points first .. last - 1
  };
  constexpr std::size_t chunk_points = 150;
  std::vector<Chunk> chunks;
  std::size_t longest = 0;
  for (const std::string& a : attributes) longest = std::max(longest, a.size());
  for (std::size_t k = 0; k < paths.size(); ++k) {
    const std::size_t n = paths[k].size();
    if (n == 0 && openings[k].close == 0) continue;
    for (std::size_t i = 0; i < std::max<std::size_t>(n, 1); i += chunk_points)
      chunks.push_back({k, i, std::min(n, i + chunk_points)});
  }
  // An element's end and the next's start (attributes of at most a hundred bytes, a point), then
  // 24 bytes a point.
  const std::size_t most = longest + 64 + 24 * chunk_points;
  put_each(*out_, chunks.size(), most, [&](char* w, std::size_t c) {
    const Chunk& chunk = chunks[c];
    const std::span<const DevicePoint> points = paths[chunk.path];
    if (chunk.first == 0) {
      const Opening& o = openings[chunk.path];
      if (o.close > 0) {
        const std::string& a = attributes[o.close - 1];
        *w++ = '"';
        w = std::copy(a.begin(), a.end(), w);
        w = std::copy_n("/>\n", 3, w);
      }
      if (o.start) {
        constexpr std::string_view element = "<polyline points=\"";
        w = put_point(std::copy(element.begin(), element.end(), w), false, points.front());
      }
    }
    if (chunk.first == chunk.last) return w;
    DevicePoint at = points[chunk.first == 0 ? 0 : chunk.first - 1];
    for (std::size_t i = chunk.first; i < chunk.last; ++i) {
      if (points[i] == at) continue;
      at = points[i];
      w = put_point(w, true, at);
    }
    return w;
  });
}

void SvgWriter::text(DevicePoint p, std::string_view line) {
  close_polyline();
  at_known_ = false;
  std::string escaped;
  for (char c : line) {
    if (c == '<')
      escaped += "&lt;";
    else if (c == '>')
      escaped += "&gt;";
    else if (c == '&')
      escaped += "&amp;";
    else
      escaped += (c >= 0x20 && c < 0x7F) ? c : '?';
  }
  out_->put(fmt::format("<text x=\"{}\" y=\"{}\" fill=\"{}\" stroke=\"none\">{}</text>\n", p.x,
                        flip(p.y), colour_of(pen_), escaped));
}

void SvgWriter::style(const Style& style) {
  pen_ = style.pen;
  std::string a = attributes_of(style);
  if (a == attributes_) return;
  close_polyline();
  attributes_ = std::move(a);
}

void SvgWriter::page() {
  close_polyline();
  out_->put(background(" stroke=\"none\""));
  at_known_ = false;
}

void SvgWriter::finish() {
  close_polyline();
  out_->put("</g>\n</svg>\n");
}

void write_svg(const Picture& picture, TextOut& out) {
  SvgWriter svg(out);
  draw_tek_display(picture, svg, 1);
  svg.finish();
}

std::string svg_of(const Picture& picture) {
  StringOut out;
  write_svg(picture, out);
  return out.take_text();
}

}  // namespace igds
