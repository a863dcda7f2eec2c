// The 2250 menu (commands/menu.h): the manual's items in its order (section 5), then every
// command of the table that the manual's menu lacks, made from the records; each label an
// abbreviation that means its item when typed.
#include "commands/menu.h"
#include "devices/menu_layout.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace igds::test {

namespace {

std::string joined(std::string_view command, const Choice* option) {
  std::string w(command);
  if (option) w.append(1, ' ').append(option->word);
  return w;
}

std::string words(const MenuItem& item) {
  return item.command ? joined(item.command->name, item.option) : item.label;
}

}  // namespace

TEST_CASE("2250 menu: the manual's items in the manual's order, then the commands added") {
  // Manual section 5: END APL END CMS BUILD CH POINT CH TANG CH GRID D INPUT D SURFACE D FILE
  // D FIRST D SECOND ST FILE ST FIRST ST SECOND SAVE RESTORE PLOT WRITE HELP/RETURN.
  const std::vector<std::string> manual{
      "END APL",        "END CMS",       "BUILD",           "CHANGE POINTS", "CHANGE TANGENTS",
      "CHANGE GRID",    "DISPLAY INPUT", "DISPLAY SURFACE", "DISPLAY FILE",  "DISPLAY FIRST",
      "DISPLAY SECOND", "STORE FILE",    "STORE FIRST",     "STORE SECOND",  "SAVE",
      "RESTORE",        "PLOT",          "WRITE",           "HELP"};
  for (const bool help : {false, true}) {
    CAPTURE(help);
    const auto items = menu_items(help, 10);
    REQUIRE(items.size() > manual.size());
    for (std::size_t i = 0; i + 1 < manual.size(); ++i) CHECK(words(items[i]) == manual[i]);
    CHECK(words(items[manual.size() - 1]) == (help ? "RETURN" : "HELP"));
    CHECK(items[manual.size() - 1].help() == !help);
    // After them, the options of the manual's commands that its menu lacks, then every other
    // command of the table once (its option asked on the keyboard), in table order.
    std::vector<std::string> expected;
    for (const Command* c : command_table()) {
      const std::string name(c->name);
      for (const Choice& o : c->options) {
        const std::string both = joined(name, &o);
        const bool manual_command = std::any_of(
            manual.begin(), manual.end(), [&](const auto& m) { return m.starts_with(name + " "); });
        if (manual_command && std::find(manual.begin(), manual.end(), both) == manual.end() &&
            !(name == "HELP"))
          expected.push_back(both);
      }
    }
    for (const Command* c : command_table()) {
      const std::string name(c->name);
      if (std::none_of(manual.begin(), manual.end(), [&](const std::string& m) {
            return m == name || m.starts_with(name + " ");
          }))
        expected.push_back(name);
    }
    std::vector<std::string> added;
    for (std::size_t i = manual.size(); i < items.size(); ++i) added.push_back(words(items[i]));
    CHECK(added == expected);
    CHECK(std::find(added.begin(), added.end(), "ERASE") != added.end());
    CHECK(std::find(added.begin(), added.end(), "EXPORT") != added.end());
    CHECK(std::find(added.begin(), added.end(), "CHANGE TWISTS") != added.end());
    CHECK(std::find(added.begin(), added.end(), "DISPLAY PICTURE") != added.end());
    CHECK(std::find(added.begin(), added.end(), "DISPLAY COMBS") != added.end());
    CHECK(std::find(added.begin(), added.end(), "PICK") != added.end());
    // One column beside the picture, as on the 2250.
    CHECK(items.size() <= static_cast<std::size_t>(menu_screen::rows));
  }
}

TEST_CASE("2250 menu: labels fit their boxes and mean their item when typed") {
  const auto items = menu_items(false, 10);
  for (const MenuItem& item : items) {
    CAPTURE(item.label);
    CHECK(item.label.size() <= 10);
    REQUIRE(item.command);
    std::istringstream in(item.label);
    std::string first, second;
    in >> first >> second;
    CHECK(find_command(first) == item.command);
    if (item.option) CHECK(choose(item.command->options, second) == item.option);
  }
  // As the manual writes them where the words do not fit.
  CHECK(items[6].label == "D INPUT");
  CHECK(items[7].label == "D SURFACE");
  CHECK(items[12].label == "ST FIRST");
  CHECK(items[0].label == "END APL");
  CHECK(items[2].label == "BUILD");
  // Wider boxes take the words whole.
  CHECK(menu_items(false, 16)[7].label == "DISPLAY SURFACE");
}

}  // namespace igds::test
