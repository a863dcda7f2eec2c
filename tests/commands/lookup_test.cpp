// The command table and its lookup: what every one- and two-letter abbreviation means (a new
// command or option that changes the meaning of an abbreviation of the manual fails here), and
// every word of the language declared once.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "commands/answers.h"
#include "commands/command.h"
#include "commands/view.h"
#include "devices/tek_screen.h"
#include "tests/support/process.h"

namespace igds::test {

namespace {

std::vector<Choice> names() {
  std::vector<Choice> all;
  for (const Command* c : command_table()) all.push_back({c->name});
  return all;
}

// Every abbreviation of one or two letters A-Z that resolves, and what it resolves to.
std::map<std::string, std::string> resolved(std::span<const Choice> words) {
  std::map<std::string, std::string> out;
  std::vector<std::string> typed;
  for (char a = 'A'; a <= 'Z'; ++a) {
    typed.emplace_back(1, a);
    for (char b = 'A'; b <= 'Z'; ++b) typed.push_back(std::string{a, b});
  }
  for (const auto& t : typed)
    if (const Choice* c = choose(words, t)) out[t] = std::string(c->word);
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

TEST_CASE("choose takes the first entry that starts with the letters typed") {
  const std::array<Choice, 3> words{{{"STORE"}, {"SAVE"}, {"SECOND"}}};
  auto word = [&](std::string_view typed) {
    const Choice* c = choose(words, typed);
    return c ? std::string(c->word) : std::string("-");
  };
  CHECK(word("S") == "STORE");
  CHECK(word("SA") == "SAVE");
  CHECK(word("sa") == "SAVE");
  CHECK(word("Sec") == "SECOND");
  CHECK(word("SECOND") == "SECOND");
  CHECK(word("SECONDS") == "-");
  CHECK(word("X") == "-");
  CHECK(word("") == "-");
  CHECK(choose({}, "S") == nullptr);
  CHECK(find_command("sa")->name == "SAVE");
  CHECK(find_command("Q") == nullptr);
}

TEST_CASE("the command table is the manual's, then the project's additions") {
  std::vector<std::string_view> got;
  for (const Command* c : command_table()) got.push_back(c->name);
  const std::vector<std::string_view> expected{
      "BUILD", "CHANGE", "RESTORE", "DISPLAY", "PLOT", "STORE", "SAVE", "WRITE", "END",    "HELP",
      "ERASE", "EXPORT", "FIT",     "PUNCH",   "LIST", "UNDO",  "REDO", "ZOOM",  "IMPORT", "PICK"};
  CHECK(got == expected);
}

TEST_CASE("every one- and two-letter abbreviation of a command") {
  CHECK(resolved(names()) ==
        table("B=BUILD C=CHANGE D=DISPLAY E=END F=FIT H=HELP I=IMPORT L=LIST P=PLOT R=RESTORE "
              "S=STORE U=UNDO W=WRITE Z=ZOOM BU=BUILD CH=CHANGE DI=DISPLAY EN=END ER=ERASE "
              "EX=EXPORT FI=FIT HE=HELP IM=IMPORT LI=LIST PI=PICK PL=PLOT PU=PUNCH RE=RESTORE "
              "SA=SAVE ST=STORE UN=UNDO WR=WRITE ZO=ZOOM"));
  // REDO comes after RESTORE: R and RE stay RESTORE, RED is REDO.
  CHECK(find_command("RED")->name == "REDO");
  CHECK(find_command("RES")->name == "RESTORE");
}

TEST_CASE("every one- and two-letter abbreviation of an option, and of the words answered") {
  CHECK(command("BUILD").options.empty());
  CHECK(command("RESTORE").options.empty());
  CHECK(command("SAVE").options.empty());
  CHECK(command("WRITE").options.empty());
  CHECK(command("ERASE").options.empty());
  CHECK(command("FIT").options.empty());
  CHECK(command("PUNCH").options.empty());
  CHECK(command("ZOOM").options.empty());
  CHECK(command("PICK").options.empty());
  CHECK(command("UNDO").options.empty());
  CHECK(command("REDO").options.empty());
  CHECK(resolved(command("CHANGE").options) ==
        table("G=GRID P=POINTS T=TANGENTS GR=GRID PO=POINTS TA=TANGENTS TW=TWISTS"));
  CHECK(resolved(command("DISPLAY").options) ==
        table("C=COMBS F=FIRST H=HIDDEN I=INPUT P=PICTURE S=SECOND CO=COMBS FI=FIRST HI=HIDDEN "
              "IN=INPUT "
              "PI=PICTURE SE=SECOND SU=SURFACE"));
  CHECK(resolved(command("PLOT").options) == table("E=EBCDIC S=SELECTRIC EB=EBCDIC SE=SELECTRIC"));
  CHECK(resolved(command("STORE").options) == table("F=FIRST S=SECOND FI=FIRST SE=SECOND"));
  CHECK(resolved(command("END").options) == table("A=APL C=CMS AP=APL CM=CMS"));
  CHECK(resolved(command("HELP").options) == table("L=LONG S=SHORT LO=LONG SH=SHORT"));
  CHECK(resolved(command("EXPORT").options) ==
        table("D=DUCT H=HPGL I=IGES S=SVG T=TEK DU=DUCT HP=HPGL IG=IGES ST=STEP SV=SVG TE=TEK"));
  CHECK(resolved(command("LIST").options) ==
        table("F=FILES I=IMAGES P=POINTS S=SURFACE T=TANGENTS FI=FILES IM=IMAGES PO=POINTS "
              "SU=SURFACE TA=TANGENTS"));
  CHECK(resolved(projection_choices()) ==
        table("A=ASSONOMETRIC C=CONIC I=ISOMETRIC O=ORTHOGONAL AS=ASSONOMETRIC AX=AXONOMETRIC "
              "CO=CONIC IS=ISOMETRIC OR=ORTHOGONAL"));
  CHECK(resolved(yes_no()) == table("N=NO Y=YES NO=NO YE=YES"));
}

TEST_CASE("the abbreviations of the manual's examples") {
  auto option = [](std::string_view c, std::string_view o) {
    return std::string(choose(command(c).options, o)->word);
  };
  CHECK(find_command("S")->name == "STORE");
  CHECK(option("STORE", "FI") == "FIRST");
  CHECK(option("STORE", "FIL") == "FILE");
  CHECK(option("DISPLAY", "S") == "SECOND");
  CHECK(option("DISPLAY", "SU") == "SURFACE");
}

TEST_CASE("every command declares its help once, in the house style") {
  for (const Command* c : command_table()) {
    CAPTURE(c->name);
    // The summary fits the right column of HELP LONG's list, on a line or two.
    CHECK(!c->summary.empty());
    CHECK(c->summary.size() <= 2 * (72 - 26));
    CHECK(c->summary.find('\n') == std::string_view::npos);
    CHECK(c->long_help.size() > c->summary.size());
    CHECK(static_cast<bool>(c->run));
    // HELP SHORT: a paragraph of a line or two on the 4013 screen (73 columns).
    const std::string_view help = c->option_prompt.short_help;
    CHECK(help.find('\n') == std::string_view::npos);
    CHECK(lay_out(help, 73).size() <= 2);
    // HELP LONG: paragraphs, one a line, which the terminal lays out at the screen's width: no
    // line of prose is broken by hand (followed by more prose), so the 2250's narrower screen
    // and a wide terminal lay it out as well as the 4013's.
    const std::string_view text = c->long_help;
    std::size_t start = 0;
    bool prose = false;
    while (start < text.size()) {
      const auto end = std::min(text.find('\n', start), text.size());
      const std::string_view line = text.substr(start, end - start);
      const bool this_prose = !line.empty() && line[0] != ' ' && !line.ends_with(':');
      CHECK_MESSAGE(!(prose && this_prose && line[0] >= 'a' && line[0] <= 'z'), line);
      prose = this_prose;
      start = end + 1;
    }
    if (!c->option_prompt.text.empty()) {
      CHECK(c->option_prompt.text.back() == '?');
      CHECK(!c->option_prompt.short_help.empty());
    }
    for (const Prompt* q : c->questions) {
      CAPTURE(q->text);
      CHECK(q->text.find('?') != std::string_view::npos);
      CHECK(!q->short_help.empty());
      CHECK(q->short_help.find('\n') == std::string_view::npos);
      CHECK(lay_out(q->short_help, 73).size() <= 2);
    }
  }
  for (std::string_view line : {help_overview()}) CHECK(!line.empty());
}

TEST_CASE("every word of the language is spelled in one source file: its declaration's") {
  // The words and the files that declare them: a command's in commands/<command>.cpp (two
  // commands may both have a FIRST), the projections and planes in commands/view.cpp, the
  // answers in commands/answers.cpp.
  std::map<std::string, std::set<std::string>> declared;
  for (const Command* c : command_table()) {
    std::string file = "commands/" + std::string(c->name) + ".cpp";
    for (char& ch : file) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    declared[std::string(c->name)].insert(file);
    for (const Choice& o : c->options) declared[std::string(o.word)].insert(file);
  }
  for (auto set : {projection_choices(), plane_choices()})
    for (const Choice& c : set) declared[std::string(c.word)].insert("commands/view.cpp");
  for (const Choice& c : yes_no()) declared[std::string(c.word)].insert("commands/answers.cpp");
  // HPGL is also the type of the files PLOT writes (PLOTnnnn.HPGL).
  declared["HPGL"].insert("commands/plot.cpp");
  // CONIC is also the name of the manual's APL function (section 7.1) that END APL gives.
  declared["CONIC"].insert("interp/apl_functions.cpp");
  // FIT too (section 7.2): the APL function is the grid's interpolation, the command Marks's fit.
  declared["FIT"].insert("interp/apl_functions.cpp");
  // And RESTORE (section 7): the APL function reads the session, the command an IGDSDATA file.
  declared["RESTORE"].insert("interp/apl_functions.cpp");
  std::set<std::string> words;
  for (const auto& [word, files] : declared) words.insert(word);
  // Every string literal of the sources (raw strings, the help texts, are prose and left out).
  const std::regex literal(R"re("((?:[^"\\\n]|\\.)*)")re");
  std::map<std::string, std::set<std::string>> spelled;
  for (const char* folder : {"commands", "interp", "devices", "workspace"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(source_dir() / folder)) {
      const auto ext = entry.path().extension();
      if (ext != ".cpp" && ext != ".h") continue;
      // Other languages with words of their own: APL's system commands ()SAVE, )ERASE) and the
      // labels of the exchange files (an IGES entity named SURFACE).
      const std::string relative = entry.path().lexically_relative(source_dir()).string();
      if (relative.starts_with("interp/apl/") || relative.starts_with("workspace/exchange/"))
        continue;
      std::string text = read_file(entry.path());
      // Comments out first (a word may be talked about), then raw strings (help texts).
      const std::regex comment(R"re((^|\s)//[^\n]*)re");
      text = std::regex_replace(text, comment, "$1");
      for (auto at = text.find("R\"("); at != std::string::npos; at = text.find("R\"(", at)) {
        const auto end = text.find(")\"", at);
        text.erase(at, end == std::string::npos ? std::string::npos : end + 2 - at);
      }
      for (std::sregex_iterator it(text.begin(), text.end(), literal), none; it != none; ++it) {
        const std::string word = (*it)[1];
        if (words.count(word))
          spelled[word].insert(entry.path().lexically_relative(source_dir()).string());
      }
    }
  }
  for (const auto& spelling : spelled) {
    const std::string& word = spelling.first;
    CAPTURE(word);
    for (const auto& file : spelling.second)
      CHECK_MESSAGE(declared[word].count(file), word << " is spelled in " << file);
  }
  // And each is declared, not only spelled: a command's words in its command's file.
  CHECK(spelled["GRID"] == std::set<std::string>{"commands/change.cpp"});
  CHECK(spelled["CONIC"] == std::set<std::string>{"commands/view.cpp", "interp/apl_functions.cpp"});
  CHECK(spelled["XZ"] == std::set<std::string>{"commands/view.cpp"});
}

}  // namespace igds::test
