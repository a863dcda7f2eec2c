#include "commands/menu.h"

#include <algorithm>
#include <array>

namespace igds {

extern const Command build_command, change_command, restore_command, display_command, plot_command,
    store_command, save_command, write_command, end_command, help_command;

namespace {

// The manual's menu (section 5), in its order: a command and the place of the option in the
// command's declared options (-1: the command alone). Its labels are checked against the
// manual's words in tests/commands/menu_test.cpp.
struct ManualItem {
  const Command* command;
  int option;
};
const std::array<ManualItem, 19> manual_menu{{
    {&end_command, 0},       // APL
    {&end_command, 1},       // CMS
    {&build_command, -1},    //
    {&change_command, 2},    // POINTS
    {&change_command, 1},    // TANGENTS
    {&change_command, 0},    // GRID
    {&display_command, 3},   // INPUT
    {&display_command, 4},   // SURFACE
    {&display_command, 2},   // FILE
    {&display_command, 0},   // FIRST
    {&display_command, 1},   // SECOND
    {&store_command, 2},     // FILE
    {&store_command, 0},     // FIRST
    {&store_command, 1},     // SECOND
    {&save_command, -1},     //
    {&restore_command, -1},  //
    {&plot_command, -1},     // the keyboard is asked
    {&write_command, -1},    //
    {&help_command, -1},     // RETURN in the help environment
}};

// The shortest beginning of the command's word that no other command's word begins with.
std::string_view short_name(const Command& command) {
  for (std::size_t n = 1; n < command.name.size(); ++n) {
    const std::string_view head = command.name.substr(0, n);
    const bool shared = std::any_of(
        command_table().begin(), command_table().end(),
        [&](const Command* other) { return other != &command && other->name.starts_with(head); });
    if (!shared) return head;
  }
  return command.name;
}

}  // namespace

bool MenuItem::help() const {
  return command == &help_command;
}

std::string menu_label(const Command& command, const Choice* option, std::size_t columns) {
  if (!option) return std::string(command.name.substr(0, columns));
  bool fits = true;
  for (const Choice& o : command.options)
    fits = fits && command.name.size() + 1 + o.word.size() <= columns;
  std::string label(fits ? command.name : short_name(command));
  label += ' ';
  label += option->word;
  return label.substr(0, columns);
}

std::vector<MenuItem> menu_items(bool help_environment, std::size_t columns) {
  std::vector<MenuItem> items;
  auto add = [&](const Command* command, const Choice* option) {
    MenuItem item{command, option, menu_label(*command, option, columns)};
    if (help_environment && item.help()) item = {nullptr, nullptr, return_word};
    items.push_back(std::move(item));
  };
  for (const ManualItem& m : manual_menu)
    add(m.command,
        m.option < 0 ? nullptr : &m.command->options[static_cast<std::size_t>(m.option)]);
  // Then what igds added, so that the menu stays one column beside the picture: the options of
  // the manual's commands that its menu lacks (CHANGE TWISTS, DISPLAY PICTURE), then each later
  // command once, its option asked on the keyboard as PLOT's is.
  auto in_manual = [](const Command* command, int option) {
    return std::any_of(manual_menu.begin(), manual_menu.end(), [&](const ManualItem& m) {
      return m.command == command && (option < 0 || m.option < 0 || m.option == option);
    });
  };
  for (const Command* command : command_table()) {
    if (!in_manual(command, -1)) continue;
    for (std::size_t k = 0; k < command->options.size(); ++k)
      if (!in_manual(command, static_cast<int>(k))) add(command, &command->options[k]);
  }
  for (const Command* command : command_table())
    if (!in_manual(command, -1)) add(command, nullptr);
  return items;
}

}  // namespace igds
