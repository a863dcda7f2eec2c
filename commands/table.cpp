#include <array>

#include "commands/command.h"

namespace igds {

extern const Command build_command;
extern const Command change_command;
extern const Command restore_command;
extern const Command display_command;
extern const Command plot_command;
extern const Command store_command;
extern const Command save_command;
extern const Command write_command;
extern const Command end_command;
extern const Command help_command;
extern const Command erase_command;
extern const Command export_command;
extern const Command fit_command;
extern const Command punch_command;
extern const Command list_command;
extern const Command undo_command;
extern const Command redo_command;
extern const Command zoom_command;
extern const Command import_command;
extern const Command pick_command;

std::span<const Command* const> command_table() {
  // The order is part of the language: `S` is STORE because STORE comes before SAVE.
  static const std::array<const Command*, 20> table{
      &build_command, &change_command, &restore_command, &display_command, &plot_command,
      &store_command, &save_command,   &write_command,   &end_command,     &help_command,
      &erase_command, &export_command, &fit_command,     &punch_command,   &list_command,
      &undo_command,  &redo_command,   &zoom_command,    &import_command,  &pick_command,
  };
  return table;
}

}  // namespace igds
