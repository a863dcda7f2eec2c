// The command line of igds and the automatic terminal mode.
#include "interp/command_line.h"

#include <doctest/doctest.h>

namespace igds::test {

TEST_CASE("options, files and -") {
  auto line =
      parse_command_line({"4013", "--disk", "/tmp/d", "--term=tek", "--tek", "4014", "--plotter",
                          "tty", "--paper", "a3", "--strict", "a.igds", "b.igds", "-"});
  CHECK_FALSE(line.device_2250);
  CHECK(line.disk == "/tmp/d");
  CHECK(line.term == TermMode::tek);
  CHECK(line.options.tek.bits == 12);
  CHECK(line.options.plotter == "tty");
  CHECK(line.options.plot.paper == Paper::a3);
  CHECK(line.options.strict);
  CHECK(line.files == std::vector<std::string>{"a.igds", "b.igds"});
  CHECK(line.then_interactive);
}

TEST_CASE("defaults") {
  auto line = parse_command_line({});
  CHECK_FALSE(line.disk);
  CHECK_FALSE(line.term);
  CHECK(line.options.tek.bits == 10);
  CHECK(line.options.plotter.empty());
  CHECK(line.options.plot.paper == Paper::a4);
  CHECK_FALSE(line.options.strict);
  CHECK(line.files.empty());
  CHECK_FALSE(line.then_interactive);
  CHECK(parse_command_line({"2250"}).device_2250);
  CHECK(parse_command_line({"--help"}).help);
  CHECK(parse_command_line({"--version"}).version);
  // The device type only counts in the first place; later it is a file name.
  CHECK(parse_command_line({"a", "2250"}).files == std::vector<std::string>{"a", "2250"});
  CHECK(parse_command_line({"--", "--odd"}).files == std::vector<std::string>{"--odd"});
}

TEST_CASE("command lines that are refused") {
  for (auto args : std::vector<std::vector<std::string>>{{"--bogus"},
                                                         {"-x"},
                                                         {"--disk"},
                                                         {"--disk", "--term", "none", "-"},
                                                         {"--term", "vt100"},
                                                         {"--tek", "4015"},
                                                         {"--paper", "A0"},
                                                         {"-", "a.igds"},
                                                         {"--strict=1"}}) {
    CAPTURE(args.front());
    CHECK_THROWS_AS(parse_command_line(args), UsageError);
  }
  CHECK(usage_text().starts_with("usage: igds [4013|2250]"));
  CHECK_THROWS_WITH_AS(parse_command_line({"--disk", "--term", "none"}), "--disk needs a value",
                       UsageError);
  CHECK(parse_command_line({"--disk=--odd"}).disk == "--odd");
}

TEST_CASE("the automatic terminal mode") {
  CHECK(choose_term(false, "xterm", "390") == TermMode::tek);
  CHECK(choose_term(true, "tek4014", "390") == TermMode::tek);
  CHECK(choose_term(true, "xterm-256color", "390") == TermMode::xterm);
  CHECK(choose_term(true, "dumb", "XTerm(379)") == TermMode::tek);  // xterm -t, no tek terminfo
  CHECK(choose_term(true, "dumb", nullptr) == TermMode::none);
  CHECK(choose_term(true, "xterm-256color", nullptr) == TermMode::none);
  CHECK(choose_term(true, nullptr, nullptr) == TermMode::none);
}

}  // namespace igds::test
