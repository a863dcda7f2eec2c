#include "devices/svg.h"

#include <fmt/format.h>

#include <algorithm>

#include "devices/layout.h"

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

void append_point(std::string& out, bool blank, DevicePoint p) {
  char buffer[32];
  out.append(buffer, put_point(buffer, blank, p));
}

}  // namespace

SvgWriter::SvgWriter() {
  using namespace tek_screen;
  body_ = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\">\n"
      "<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
      "<g fill=\"none\" stroke=\"black\" stroke-width=\"1\" stroke-linejoin=\"round\" "
      "stroke-linecap=\"round\" font-family=\"monospace\" font-size=\"{2}\">\n",
      width, height, line_height - 4);
  head_ = body_.size();
}

void SvgWriter::start_polyline() {
  body_ += "<polyline points=\"";
  append_point(body_, false, at_);
  drawing_ = true;
}

// The attributes in force are those of the whole polyline: style() closes it before they change.
void SvgWriter::close_polyline() {
  if (drawing_) {
    body_ += '"';
    body_ += attributes_;
    body_ += "/>\n";
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
  append_point(body_, true, p);
  at_ = p;
}

void SvgWriter::polyline(std::span<const DevicePoint> points) {
  if (points.empty()) return;
  move(points.front());
  std::size_t i = 1;
  while (i < points.size() && points[i] == at_) ++i;
  if (i == points.size()) return;
  if (!drawing_) start_polyline();
  // At most 24 bytes a point, formatted into a block on the stack and appended a block at a
  // time (growing the document to the most a polyline could take would first fill it with
  // zeros, many times what is written).
  constexpr std::size_t most = 170;
  char block[24 * most];
  DevicePoint at = at_;
  while (i < points.size()) {
    char* out = block;
    for (const std::size_t end = std::min(points.size(), i + most); i < end; ++i) {
      const DevicePoint p = points[i];
      if (p == at) continue;
      out = put_point(out, true, p);
      at = p;
    }
    body_.append(block, out);
  }
  at_ = at;
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
  fmt::format_to(std::back_inserter(body_),
                 "<text x=\"{}\" y=\"{}\" fill=\"black\" stroke=\"none\">{}</text>\n", p.x,
                 flip(p.y), escaped);
}

void SvgWriter::style(const Style& style) {
  static constexpr std::string_view colours[] = {"black",   "red",  "green",  "blue",
                                                 "magenta", "cyan", "orange", "brown"};
  std::string a;
  if (style.pen != 1)
    a += fmt::format(" stroke=\"{}\"",
                     colours[static_cast<std::size_t>(std::max(style.pen, 1) - 1) % 8]);
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
  if (a == attributes_) return;
  close_polyline();
  attributes_ = std::move(a);
}

void SvgWriter::page() {
  close_polyline();
  body_.resize(head_);
  at_known_ = false;
}

std::string SvgWriter::document() {
  close_polyline();
  body_ += "</g>\n</svg>\n";
  return std::move(body_);
}

std::string svg_of(const Picture& picture) {
  SvgWriter svg;
  draw_tek_display(picture, svg, 1);
  return svg.document();
}

}  // namespace igds
