// lookup_prefix and the table: what every one- and two-letter abbreviation means. A new command
// or option that changes the meaning of an abbreviation of the manual fails here.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>

#include "commands/command.h"

namespace igds::test {

namespace {

std::vector<std::string_view> names() {
  std::vector<std::string_view> all;
  for (const Command* c : command_table()) all.push_back(c->name);
  return all;
}

// Every abbreviation of one or two letters A-Z that resolves, and what it resolves to.
std::map<std::string, std::string> resolved(std::span<const std::string_view> words) {
  std::map<std::string, std::string> out;
  std::vector<std::string> typed;
  for (char a = 'A'; a <= 'Z'; ++a) {
    typed.emplace_back(1, a);
    for (char b = 'A'; b <= 'Z'; ++b) typed.push_back(std::string{a, b});
  }
  for (const auto& t : typed) {
    int i = lookup_prefix(words, t);
    if (i >= 0) out[t] = std::string(words[static_cast<std::size_t>(i)]);
  }
  return out;
}

std::map<std::string, std::string> table(std::string_view text) {
  std::map<std::string, std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    auto end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    auto item = text.substr(start, end - start);
    auto eq = item.find('=');
    out[std::string(item.substr(0, eq))] = std::string(item.substr(eq + 1));
    start = end + 1;
  }
  return out;
}

const Command& command(std::string_view name) {
  for (const Command* c : command_table()) {
    if (c->name == name) return *c;
  }
  FAIL("no command " << name);
  throw;
}

}  // namespace

TEST_CASE("lookup_prefix takes the first entry that starts with the letters typed") {
  const std::array<std::string_view, 3> words{"STORE", "SAVE", "SECOND"};
  CHECK(lookup_prefix(words, "S") == 0);
  CHECK(lookup_prefix(words, "SA") == 1);
  CHECK(lookup_prefix(words, "sa") == 1);
  CHECK(lookup_prefix(words, "Sec") == 2);
  CHECK(lookup_prefix(words, "SECOND") == 2);
  CHECK(lookup_prefix(words, "SECONDS") == -1);
  CHECK(lookup_prefix(words, "X") == -1);
  CHECK(lookup_prefix(words, "") == -1);
  CHECK(lookup_prefix({}, "S") == -1);
}

TEST_CASE("the command table is the manual's, then the project's additions") {
  const std::vector<std::string_view> expected{"BUILD", "CHANGE", "RESTORE", "DISPLAY",
                                               "PLOT",  "STORE",  "SAVE",    "WRITE",
                                               "END",   "HELP",   "ERASE",   "EXPORT"};
  CHECK(names() == expected);
}

TEST_CASE("every one- and two-letter abbreviation of a command") {
  CHECK(resolved(names()) ==
        table("B=BUILD C=CHANGE D=DISPLAY E=END H=HELP P=PLOT R=RESTORE S=STORE W=WRITE "
              "BU=BUILD CH=CHANGE DI=DISPLAY EN=END ER=ERASE EX=EXPORT HE=HELP PL=PLOT "
              "RE=RESTORE SA=SAVE ST=STORE WR=WRITE"));
}

TEST_CASE("every one- and two-letter abbreviation of an option") {
  CHECK(command("BUILD").options.empty());
  CHECK(command("RESTORE").options.empty());
  CHECK(command("SAVE").options.empty());
  CHECK(command("WRITE").options.empty());
  CHECK(command("ERASE").options.empty());
  CHECK(resolved(command("CHANGE").options) ==
        table("G=GRID P=POINTS T=TANGENTS GR=GRID PO=POINTS TA=TANGENTS"));
  CHECK(resolved(command("DISPLAY").options) ==
        table("F=FIRST I=INPUT S=SECOND FI=FIRST IN=INPUT SE=SECOND SU=SURFACE"));
  CHECK(resolved(command("PLOT").options) == table("E=EBCDIC S=SELECTRIC EB=EBCDIC SE=SELECTRIC"));
  CHECK(resolved(command("STORE").options) == table("F=FIRST S=SECOND FI=FIRST SE=SECOND"));
  CHECK(resolved(command("END").options) == table("A=APL C=CMS AP=APL CM=CMS"));
  CHECK(resolved(command("HELP").options) == table("L=LONG S=SHORT LO=LONG SH=SHORT"));
  CHECK(resolved(command("EXPORT").options) == table("H=HPGL S=SVG T=TEK HP=HPGL SV=SVG TE=TEK"));
}

TEST_CASE("the abbreviations of the manual's examples") {
  auto option = [](std::string_view c, std::string_view o) {
    return std::string(
        command(c).options[static_cast<std::size_t>(lookup_prefix(command(c).options, o))]);
  };
  CHECK(names()[static_cast<std::size_t>(lookup_prefix(names(), "S"))] == "STORE");
  CHECK(option("STORE", "FI") == "FIRST");
  CHECK(option("STORE", "FIL") == "FILE");
  CHECK(option("DISPLAY", "S") == "SECOND");
  CHECK(option("DISPLAY", "SU") == "SURFACE");
}

TEST_CASE("every command declares its help once, in the house style") {
  for (const Command* c : command_table()) {
    CAPTURE(c->name);
    CHECK(!c->short_help.empty());
    CHECK(c->long_help.size() > c->short_help.size());
    CHECK(static_cast<bool>(c->run));
    for (std::string_view help : {c->short_help, c->option_prompt.short_help}) {
      CHECK(std::count(help.begin(), help.end(), '\n') <= 1);  // one or two lines
      CHECK(help.size() <= 200);
    }
    if (!c->option_prompt.text.empty()) {
      CHECK(c->option_prompt.text.back() == '?');
      CHECK(!c->option_prompt.short_help.empty());
    }
  }
}

}  // namespace igds::test
