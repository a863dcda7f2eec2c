#include "devices/terminal.h"

#include "devices/layout.h"
#include "devices/tek4013.h"

namespace igds {

namespace {

int unit_of(TekOptions tek) {
  return tek.bits == 12 ? 4 : 1;
}

// The image and its description, the alpha cursor left at the start of the line below the
// description, where the dialogue goes on.
void draw_display(const Picture& picture, TekEncoder& tek, int unit) {
  DevicePoint cursor = draw_tek_display(picture, tek, unit);
  tek.alpha_at(cursor);
}

// xterm: into the Tek window and, at the end, alpha mode and back to the VT window.
std::string for_xterm(std::string stream) {
  return "\x1b[?38h" + stream + std::string{tek_us, tek_esc, tek_etx};
}

}  // namespace

std::string display_bytes(const Picture& picture, TermMode mode, TekOptions tek) {
  if (mode == TermMode::none) return {};
  TekEncoder encoder(tek.bits);
  draw_display(picture, encoder, unit_of(tek));
  if (mode == TermMode::xterm) return for_xterm(encoder.take());
  return encoder.take();
}

std::string erase_bytes(TermMode mode, TekOptions tek) {
  if (mode == TermMode::none) return {};
  TekEncoder encoder(tek.bits);
  encoder.page();
  if (mode == TermMode::xterm) return for_xterm(encoder.take());
  return encoder.take();
}

std::string TekDialogue::home() {
  baseline_ = tek_screen::text_top;
  x_ = 0;
  column_ = 0;
  TekEncoder encoder(tek_.bits);
  encoder.alpha_at({0, tek_screen::text_top * unit_of(tek_)});
  return encoder.take();
}

void TekDialogue::new_line(std::string& out) {
  // The lowest baseline whose characters are still on the screen.
  constexpr int bottom = tek_screen::text_top % tek_screen::line_height;
  if (baseline_ - tek_screen::line_height >= bottom) {
    out += "\r\n";
    baseline_ -= tek_screen::line_height;
    x_ = 0;
    column_ = 0;
  } else {
    out += home();
  }
}

std::string TekDialogue::text(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 16);
  for (char c : text) {
    if (c == '\n') {
      new_line(out);
      continue;
    }
    if (x_ + (column_ + 1) * tek_screen::char_width > tek_screen::width) new_line(out);
    out += c;
    ++column_;
  }
  return out;
}

void TekDialogue::displayed(const Picture& picture) {
  const DevicePoint at = below_description(picture.caption.size(), 1);
  baseline_ = at.y;
  x_ = at.x;
  column_ = 0;
}

std::string tek_stream(const Picture& picture, TekOptions tek) {
  TekEncoder encoder(tek.bits);
  encoder.page();
  draw_display(picture, encoder, unit_of(tek));
  return encoder.take();
}

}  // namespace igds
