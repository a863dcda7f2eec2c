#include "interp/ws2250.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "commands/picture.h"
#include "interp/words.h"

namespace igds {

namespace {

constexpr std::string_view general_help =
    "IGDS WITH A 2250: THE LIGHT PEN IS THE CROSS-HAIR\n"
    "\n"
    "The menu on the right is always on the screen: move the cross-hair onto an item with the "
    "mouse and click (or press the space bar). An item is a command and its option at once (D "
    "SURFACE is DISPLAY SURFACE). A command may be typed too, ended by RETURN.\n"
    "\n"
    "Two environments. In this one, the help environment, picking an item explains its "
    "command; RETURN goes to the execution environment, where picking an item runs it and "
    "HELP comes back here (the picture on the screen then is given back when you return).\n"
    "\n"
    "What a command needs besides its option (names, numbers, points, tangents, a projection) "
    "is asked at the bottom of the screen and typed on the keyboard, ended by RETURN; HELP "
    "typed there explains the question. An entry of several lines (POINTS?, TANGENTS?) is "
    "ended by an empty line (the 2250's key 0). Ctrl-C gives up the command in progress.\n"
    "\n"
    "While DISPLAY SURFACE's picture is up, keys pressed with the cross-hair: 5 the default "
    "display, 6 the points joined one after the other along the stringers, 7 along the curves "
    "(both drawn at a visible pace, in 3 seconds at most; any key shows the rest at once), 8 "
    "the points alone.\n"
    "\n"
    "The workspace, the disk and the session are those of igds 4013: a session of one "
    "continues the other. END CMS leaves igds.";

}  // namespace

std::string_view workspace_2250_help() {
  return general_help;
}

Picture surface_view(const ImageRef& image, SurfaceKey key) {
  Picture full = picture_of(image);
  if (key == SurfaceKey::standard) return full;
  Picture out;
  out.caption = full.caption;
  const Drawing2& d = full.drawing;
  for (const auto& item : d.items()) {
    if (item.kind != Drawing2::Kind::polyline) continue;
    const Role role = item.id.role;
    if (key == SurfaceKey::points && role == Role::curve) {
      for (std::size_t k = 0; k < item.count; ++k) {
        const Point2 p = d.points(item)[k];
        if (std::isfinite(p.x) && std::isfinite(p.y))
          out.drawing.add_mark(p, MarkShape::dot, 1, item.style, {Role::point, 0});
      }
    }
    if ((key == SurfaceKey::stringers && role == Role::stringer) ||
        (key == SurfaceKey::curves && role == Role::curve))
      out.drawing.add_polyline(d.points(item), item.style, item.id);
  }
  return out;
}

std::size_t segment_count(const Picture& picture) {
  std::size_t n = 0;
  for (const auto& item : picture.drawing.items())
    if (item.kind == Drawing2::Kind::polyline && item.count > 1) n += item.count - 1;
  return n;
}

Workspace2250::Workspace2250(Interpreter& interpreter, Terminal& terminal)
    : interpreter_(interpreter),
      terminal_(terminal),
      items_(menu_items(false, menu_screen::label_columns)),
      help_items_(menu_items(true, menu_screen::label_columns)) {
  layout_ = menu_layout(items_.size());
  auto labels = [](const std::vector<MenuItem>& items) {
    std::vector<std::string> out;
    for (const auto& item : items) out.push_back(item.label);
    return out;
  };
  menu_ = std::make_shared<const Drawing2>(menu_drawing(layout_, labels(items_)));
  help_menu_ = std::make_shared<const Drawing2>(menu_drawing(layout_, labels(help_items_)));
}

void Workspace2250::use_menu(bool help) {
  terminal_.frame(help ? help_menu_ : menu_, layout_.screen);
}

bool Workspace2250::help_environment() {
  use_menu(true);
  terminal_.help(general_help);
  for (;;) {
    const Event e = terminal_.pick("");
    if (e.kind == Event::Kind::end) return false;
    if (e.kind != Event::Kind::pick) continue;
    const int k = item_at(layout_, e.x, e.y);
    if (k < 0) continue;  // no item there: the cross-hair again
    const MenuItem& item = help_items_[static_cast<std::size_t>(k)];
    if (!item.command) break;  // RETURN
    terminal_.help(item.help() ? general_help : item.command->long_help);
  }
  use_menu(false);
  terminal_.help_done();
  terminal_.say("READY");
  return true;
}

bool Workspace2250::surface_shown() const {
  const ImageRef& image = interpreter_.workspace().image;
  return image && image->desim.what == 1 && terminal_.screen() &&
         terminal_.screen()->shows_picture();
}

void Workspace2250::function_key(SurfaceKey key) {
  auto picture = std::make_shared<const Picture>(surface_view(interpreter_.workspace().image, key));
  const bool animated = key == SurfaceKey::stringers || key == SurfaceKey::curves;
  const int frames =
      animated ? static_cast<int>(std::min<std::size_t>(segment_count(*picture), animation_frames))
               : 1;
  terminal_.replace_picture(std::move(picture), frames, animation_pause);
}

Interpreter::Outcome Workspace2250::run() {
  if (!help_environment()) return Interpreter::Outcome::input_ended;
  for (;;) {
    // With DISPLAY SURFACE's picture up, the keys 5 to 8 are function keys; any other key
    // begins a command typed on the keyboard.
    const Event e = terminal_.pick("", surface_shown() ? "5678" : "");
    if (e.kind == Event::Kind::end) return Interpreter::Outcome::input_ended;
    if (terminal_.output_failed()) return Interpreter::Outcome::ended;
    if (e.kind == Event::Kind::line) {
      // An empty line is no command: the cross-hair again, as READY waits again.
      if (split_words(e.text).empty()) continue;
      if (auto outcome = interpreter_.run_line(e.text)) return *outcome;
      terminal_.say("READY");
      continue;
    }
    if (e.kind != Event::Kind::pick) continue;  // Ctrl-C: the cross-hair again
    if (e.text.size() == 1 && e.text[0] >= '5' && e.text[0] <= '8' && surface_shown()) {
      function_key(static_cast<SurfaceKey>(e.text[0]));
      continue;
    }
    const int k = item_at(layout_, e.x, e.y);
    if (k < 0) continue;
    const MenuItem& item = items_[static_cast<std::size_t>(k)];
    if (item.help()) {
      if (!help_environment()) return Interpreter::Outcome::input_ended;
      continue;
    }
    // The pick's echo: the command chosen, as if typed.
    terminal_.say(item.option ? fmt::format("{} {}", item.command->name, item.option->word)
                              : std::string(item.command->name));
    if (auto outcome = interpreter_.run_chosen(*item.command, item.option)) return *outcome;
    terminal_.say("READY");
  }
}

}  // namespace igds
