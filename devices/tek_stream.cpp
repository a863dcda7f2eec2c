#include "devices/tek_stream.h"

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

std::string tek_stream(const Picture& picture, TekOptions tek) {
  TekEncoder encoder(tek.bits);
  encoder.page();
  draw_display(picture, encoder, unit_of(tek));
  return encoder.take();
}

}  // namespace igds
