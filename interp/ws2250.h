// The 2250 workspace (manual section 5) in xterm's Tek window, the cross-hair as the light pen:
// the menu always on the screen, a command and its option picked at once, what else a command
// needs typed on the keyboard at the same prompts as the 4013's, the help environment, and the
// function keys of DISPLAY SURFACE. The conversation itself is the Interpreter's (run_chosen):
// only the way of choosing a command differs.
#pragma once

#include <chrono>
#include <memory>
#include <vector>

#include "commands/menu.h"
#include "devices/menu_layout.h"
#include "interp/interpreter.h"
#include "interp/terminal.h"

namespace igds {

// The pace of the animated displays (keys 6 and 7): the picture in at most `animation_frames`
// parts `animation_pause` apart, so at most 3 s whatever the grid; a small grid shows one
// segment per part.
inline constexpr int animation_frames = 60;
inline constexpr std::chrono::milliseconds animation_pause{50};

// What the function keys show of a surface image (manual section 5): 5 the default display, 6
// the stringers drawn one after the other, 7 the curves, 8 the points alone.
enum class SurfaceKey { standard = '5', stringers = '6', curves = '7', points = '8' };
Picture surface_view(const ImageRef& image, SurfaceKey key);
// Segments of the lines of a picture (the parts of an animation).
std::size_t segment_count(const Picture& picture);

class Workspace2250 {
 public:
  Workspace2250(Interpreter& interpreter, Terminal& terminal);

  // The help environment first, then picks until END CMS or the end of the input.
  Interpreter::Outcome run();

 private:
  // The help environment until RETURN; false when the input ended there.
  bool help_environment();
  void use_menu(bool help);
  bool surface_shown() const;
  void function_key(SurfaceKey key);

  Interpreter& interpreter_;
  Terminal& terminal_;
  MenuLayout layout_;
  std::vector<MenuItem> items_, help_items_;
  std::shared_ptr<const Drawing2> menu_, help_menu_;
};

// The general explanation of the help environment.
std::string_view workspace_2250_help();

}  // namespace igds
