// The README cannot go stale: its sessions are typed into the real igds and must come out word
// for word, its command lines are run (and their output compared where it is shown), its table
// of abbreviations is checked against the command table, and its links and pictures must exist.
#include <doctest/doctest.h>
#include <fmt/core.h>

#include <regex>
#include <sstream>

#include "commands/command.h"
#include "commands/view.h"
#include "tests/e2e/examples_support.h"
#include "tests/support/process.h"
#include "tests/support/tek_decoder.h"

namespace igds::test {

namespace {

struct Block {
  std::string info;  // the fence's info string: "igds" for a session, "console" for commands
  std::vector<std::string> lines;
  int line_number = 0;  // of the opening fence
};

std::vector<std::string> readme_lines() {
  std::istringstream in(read_file(source_dir() / "README.md"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<Block> fenced_blocks(const std::vector<std::string>& lines) {
  std::vector<Block> blocks;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("```", 0) != 0) continue;
    Block b;
    b.info = lines[i].substr(3);
    b.line_number = static_cast<int>(i) + 1;
    for (++i; i < lines.size() && lines[i].rfind("```", 0) != 0; ++i) b.lines.push_back(lines[i]);
    blocks.push_back(std::move(b));
  }
  return blocks;
}

// What was typed in a session as igds --term none shows it: the line after READY, the words
// after a question (a line of capitals ending in "?"), the line after the APL prompt's six blanks.
std::string typed_lines(const std::vector<std::string>& session) {
  static const std::regex question(R"(([A-Z][A-Z0-9 ,/'()-]*\?)(?: (.*))?)");
  std::string typed;
  for (std::size_t i = 0; i < session.size(); ++i) {
    std::smatch m;
    if (i > 0 && session[i - 1] == "READY")
      typed += session[i] + "\n";
    else if (std::regex_match(session[i], m, question))
      typed += m[2].str() + "\n";
    else if (session[i].rfind("      ", 0) == 0 && session[i].size() > 6 && session[i][6] != ' ')
      typed += session[i].substr(6) + "\n";
  }
  return typed;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  return text;
}

// "WORD (ABBR)" pairs in a piece of the README.
std::vector<std::pair<std::string, std::string>> abbreviations_in(const std::string& text) {
  static const std::regex pair(R"(([A-Z]{2,}) \(([A-Z]+)\))");
  std::vector<std::pair<std::string, std::string>> found;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), pair); it != std::sregex_iterator();
       ++it)
    found.emplace_back((*it)[1].str(), (*it)[2].str());
  return found;
}

// `abbr` is the shortest prefix that `lookup` resolves to `word`.
template <class Lookup>
void check_shortest(const std::string& word, const std::string& abbr, Lookup lookup) {
  CAPTURE(word);
  CAPTURE(abbr);
  CHECK(word.rfind(abbr, 0) == 0);
  CHECK(lookup(abbr) == lookup(word));
  if (abbr.size() > 1) CHECK(lookup(abbr.substr(0, abbr.size() - 1)) != lookup(word));
}

}  // namespace

TEST_CASE("the README starts with the two-line quick start") {
  auto lines = readme_lines();
  REQUIRE(lines.size() > 4);
  CHECK(lines[2] == "    scripts/run     # set up, build and start igds");
  CHECK(lines[3].rfind("    scripts/test    # set up, build and run every test", 0) == 0);
}

TEST_CASE("the README's sessions are what igds answers, line for line") {
  TempDir disk;  // the sessions follow one another on one disk, as the README tells them
  int sessions = 0;
  for (const auto& block : fenced_blocks(readme_lines())) {
    if (block.info != "igds") continue;
    ++sessions;
    CAPTURE(block.line_number);
    RunOptions typed;
    typed.input = typed_lines(block.lines);
    auto r = run_igds({"--disk", disk.path().string(), "--term", "none"}, typed);
    CHECK(r.status == 0);
    CHECK(r.err == "");
    CHECK(without_disk(r.out, disk.path()) == joined(block.lines));
  }
  CHECK(sessions >= 2);
}

TEST_CASE("the README's command lines run, and print what the README shows") {
  TempDir cwd;  // the current folder is the disk, as for a user who has not set IGDS_DISK
  std::filesystem::create_directory_symlink(source_dir() / "scripts", cwd.path() / "scripts");
  RunOptions options;
  options.cwd = cwd.path();
  options.env = {{"IGDS_DISK", ""}};
  int commands = 0, pictures = 0;
  for (const auto& block : fenced_blocks(readme_lines())) {
    if (block.info != "console") continue;
    for (std::size_t i = 0; i < block.lines.size(); ++i) {
      if (block.lines[i].rfind("$ ", 0) != 0) continue;
      std::string command = block.lines[i].substr(2);
      std::vector<std::string> shown;
      for (std::size_t j = i + 1; j < block.lines.size() && block.lines[j].rfind("$ ", 0) != 0; ++j)
        shown.push_back(block.lines[j]);
      CAPTURE(command);
      // scripts/test and scripts/bench would build and test all over again inside this test;
      // scripts/run is only setup and build around the binary, which is run instead.
      REQUIRE(command.rfind("scripts/test", 0) != 0);
      REQUIRE(command.rfind("scripts/bench", 0) != 0);
      std::string shell =
          std::regex_replace(command, std::regex(R"(\bscripts/run\b)"), igds_binary().string());
      ++commands;
      auto r = run({"sh", "-c", shell}, options);
      CHECK(r.status == 0);
      CHECK(r.err == "");
      CHECK(r.out == joined(shown));
      // A page rendered by tek2plot shows a picture, not only dialogue.
      std::smatch page;
      if (std::regex_search(command, page,
                            std::regex(R"(tek2plot .*--page-number (\d+) (\S+\.tek))"))) {
        const TekDrawing d = decode_tek(read_file(cwd.path() / page[2].str()));
        const auto n = static_cast<std::size_t>(std::stoi(page[1].str()));
        REQUIRE(n < d.pages.size());
        CHECK(d.pages[n].segments.size() > 100);
        ++pictures;
      }
    }
  }
  CHECK(commands >= 4);
  CHECK(pictures >= 1);
}

TEST_CASE("the README's table of abbreviations is the command table's") {
  auto lines = readme_lines();
  std::vector<std::string> listed;
  for (const auto& line : lines) {
    if (line.rfind("| ", 0) != 0) continue;
    auto cells = line.substr(2);
    auto bar = cells.find(" | ");
    auto pairs = abbreviations_in(cells.substr(0, bar));
    if (pairs.size() != 1) continue;  // not a command row
    const auto& [name, abbr] = pairs[0];
    auto table = command_table();
    auto lookup = [&](const std::string& typed) {
      const Command* c = find_command(typed);
      return c ? static_cast<int>(std::find(table.begin(), table.end(), c) - table.begin()) : -1;
    };
    check_shortest(name, abbr, lookup);
    int index = lookup(name);
    REQUIRE(index >= 0);
    listed.push_back(name);
    const auto options = table[static_cast<std::size_t>(index)]->options;
    auto option_pairs =
        abbreviations_in(cells.substr(bar + 3, cells.find(" | ", bar + 3) - bar - 3));
    CHECK(option_pairs.size() == options.size());
    for (const auto& [option, short_form] : option_pairs)
      check_shortest(option, short_form, [&](const std::string& typed) {
        const Choice* c = choose(options, typed);
        return c ? static_cast<int>(c - options.data()) : -1;
      });
  }
  std::vector<std::string> all;
  for (const auto* c : command_table()) all.emplace_back(c->name);
  CHECK(listed == all);

  // The projections' paragraph.
  std::string projections;
  for (const auto& line : lines)
    if (line.rfind("Projections:", 0) == 0 || !projections.empty()) {
      if (line.empty()) break;
      projections += line + " ";
    }
  auto pairs = abbreviations_in(projections);
  CHECK(pairs.size() == 4);
  for (const auto& [word, abbr] : pairs)
    check_shortest(word, abbr, [](const std::string& typed) {
      const Choice* c = choose(projection_choices(), typed);
      return c ? c->code : -1;
    });
}

TEST_CASE("the README's links and pictures exist, and every example is shown") {
  auto text = read_file(source_dir() / "README.md");
  static const std::regex link(R"(\]\(([^)#:]+)\))");
  int links = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator();
       ++it) {
    auto target = (*it)[1].str();
    CAPTURE(target);
    CHECK(std::filesystem::exists(source_dir() / target));
    ++links;
  }
  CHECK(links > 10);
  for (const auto& e : examples()) {
    CAPTURE(e.name);
    CHECK(text.find(fmt::format("![{0}](scripts/examples/{0}.png)", e.name)) != std::string::npos);
  }
}

}  // namespace igds::test
