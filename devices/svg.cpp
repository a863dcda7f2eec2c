#include "devices/svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "devices/layout.h"

namespace igds {

namespace {

int flip(int y) {
  return tek_screen::height - 1 - y;
}

// " x,y" (or "x,y" without the blank) appended by std::to_chars: a polyline's points are most of
// the document, and fmt with a runtime format string costs several times the digits.
void append_point(std::string& out, bool blank, int x, int y) {
  char buffer[32];  // a blank, two ints of at most 11 characters, a comma
  buffer[0] = ' ';
  char* p = buffer + (blank ? 1 : 0);
  p = std::to_chars(p, p + 11, x).ptr;
  *p++ = ',';
  p = std::to_chars(p, p + 11, y).ptr;
  out.append(buffer, static_cast<std::size_t>(p - buffer));
}

}  // namespace

void SvgWriter::close_polyline() {
  if (drawing_) {
    body_ += "<polyline points=\"";
    body_ += points_;
    body_ += '"';
    body_ += attributes_;
    body_ += "/>\n";
  }
  drawing_ = false;
  points_.clear();
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
  if (!drawing_) append_point(points_, false, at_.x, flip(at_.y));
  append_point(points_, true, p.x, flip(p.y));
  drawing_ = true;
  at_ = p;
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
  body_.clear();
  at_known_ = false;
}

std::string SvgWriter::document() {
  close_polyline();
  using namespace tek_screen;
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\">\n"
      "<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
      "<g fill=\"none\" stroke=\"black\" stroke-width=\"1\" stroke-linejoin=\"round\" "
      "stroke-linecap=\"round\" font-family=\"monospace\" font-size=\"{2}\">\n"
      "{3}</g>\n</svg>\n",
      width, height, line_height - 4, body_);
}

std::string svg_of(const Picture& picture) {
  SvgWriter svg;
  draw_tek_display(picture, svg, 1);
  return svg.document();
}

}  // namespace igds
