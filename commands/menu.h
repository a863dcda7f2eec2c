// The menu of the 2250 workspace (manual section 5): the commands and their options as light-pen
// items, made from the command records (commands/command.h), never written a second time. The
// manual's items come first in its order (END APL, END CMS, BUILD, CH POINT ... WRITE, HELP or
// RETURN), then every command of the table the manual's menu does not have, one item per option,
// in table order: a command added to the table appears in the menu by itself.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "commands/command.h"

namespace igds {

struct MenuItem {
  // The command and its option, chosen at once; `option` nullptr for a command without options
  // or one whose option is asked (PLOT's keyboard, HELP's length). `command` nullptr: RETURN,
  // which leaves the help environment.
  const Command* command = nullptr;
  const Choice* option = nullptr;
  std::string label;
  bool help() const;  // the HELP item (it enters the help environment)
};

// The items, with labels of at most `columns` characters: in the help environment the HELP
// item is RETURN.
std::vector<MenuItem> menu_items(bool help_environment, std::size_t columns);

// A label as the manual's menu writes them: the command's word and the option's when they fit
// in `columns` for every option of the command; else the command cut to the shortest beginning
// no other command has (D INPUT, ST FIRST), and the option cut if it must be.
std::string menu_label(const Command& command, const Choice* option, std::size_t columns);

// The word of the item that leaves the help environment.
inline constexpr const char* return_word = "RETURN";

}  // namespace igds
