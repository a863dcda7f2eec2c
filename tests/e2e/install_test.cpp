// What `cmake --install` and the Debian package put on a machine (docs/install.md): the tree,
// the manual page generated from the command declarations, the bash completion. The package
// itself is built, installed, used and removed by `scripts/package --check` (run by scripts/test).
#include <doctest/doctest.h>

#include <filesystem>
#include <set>

#include "commands/command.h"
#include "interp/command_line.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"

namespace igds::test {

namespace fs = std::filesystem;

namespace {

fs::path build_dir() {
  return igds_binary().parent_path();
}

std::set<std::string> files_under(const fs::path& root) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (!e.is_directory()) out.insert(e.path().lexically_relative(root).string());
  return out;
}

}  // namespace

TEST_CASE("cmake --install: the program, its launcher, its pages, its completion, its documents") {
  TempDir prefix;
  auto r = run({"cmake", "--install", build_dir().string(), "--prefix", prefix.path().string()});
  REQUIRE_MESSAGE(r.status == 0, (r.out + r.err));
  std::set<std::string> expected{"bin/igds",
                                 "bin/igds-tek",
                                 "share/bash-completion/completions/igds",
                                 "share/doc/igds/README.md",
                                 "share/doc/igds/changelog.gz",
                                 "share/doc/igds/copyright",
                                 "share/man/man1/igds.1.gz",
                                 "share/man/man1/igds-tek.1.gz"};
  for (const auto& e : fs::directory_iterator(source_dir() / "docs"))
    if (e.path().extension() == ".md")
      expected.insert("share/doc/igds/docs/" + e.path().filename().string());
  const fs::path examples = source_dir() / "scripts" / "examples";
  for (const auto& e : fs::recursive_directory_iterator(examples))
    if (!e.is_directory())
      expected.insert("share/doc/igds/examples/" + e.path().lexically_relative(examples).string());
  CHECK(files_under(prefix.path()) == expected);
  // The installed igds runs, and its launcher finds it beside itself.
  auto version = run({(prefix.path() / "bin" / "igds").string(), "--version"});
  CHECK(version.status == 0);
  CHECK(version.out.find("kernels: ") != std::string::npos);
  CHECK(read_file(prefix.path() / "bin" / "igds-tek").find("$here/igds") != std::string::npos);
}

TEST_CASE("igds(1): rendered without a warning, every command and option in it") {
  IGDS_SKIP_UNLESS(have_program("groff"), "groff is not installed");
  const fs::path page = build_dir() / "igds.1.gz";
  REQUIRE(fs::exists(page));
  auto r =
      run({"sh", "-c",
           "zcat '" + page.string() + "' | groff -k -man -ww -Tutf8 -rLL=200n 2>&1 >/dev/null"});
  CHECK(r.status == 0);
  CHECK(r.out == "");
  auto text = run({"sh", "-c", "zcat '" + page.string() + "' | groff -k -man -Tascii -rLL=200n"});
  REQUIRE(text.status == 0);
  // Overstriking (bold) out: the words as a reader sees them.
  std::string plain;
  for (std::size_t i = 0; i < text.out.size(); ++i) {
    if (i + 2 < text.out.size() && text.out[i + 1] == '\b') continue;
    if (text.out[i] == '\b') continue;
    plain += text.out[i];
  }
  for (const char* section : {"NAME", "SYNOPSIS", "DESCRIPTION", "OPTIONS", "COMMANDS", "FILES",
                              "ENVIRONMENT", "EXIT STATUS", "EXAMPLES", "SEE ALSO"})
    CHECK_MESSAGE(plain.find(std::string("\n") + section + "\n") != std::string::npos, section);
  for (const Command* c : command_table()) {
    for (const auto& form : command_syntax(*c))
      CHECK_MESSAGE(plain.find(form) != std::string::npos, form);
    for (const Choice& o : c->options) CHECK(plain.find(std::string(o.word)) != std::string::npos);
  }
  for (const OptionSpec& o : command_line_options())
    CHECK_MESSAGE(plain.find(std::string(o.name)) != std::string::npos, o.name);
}

TEST_CASE("the bash completion: options, their values, command files") {
  IGDS_SKIP_UNLESS(have_program("bash"), "bash is not installed");
  const fs::path script = build_dir() / "igds.bash";
  TempDir dir;
  write_file(dir.path() / "hull.igds", "");
  write_file(dir.path() / "notes.txt", "");
  auto complete = [&](const std::string& words) {
    auto r = run({"bash", "-c",
                  "cd '" + dir.path().string() + "' && source '" + script.string() +
                      "' && COMP_WORDS=(" + words + ") && COMP_CWORD=$((${#COMP_WORDS[@]}-1)) " +
                      "&& _igds && echo \"${COMPREPLY[*]}\""});
    CHECK(r.status == 0);
    return r.out.substr(0, r.out.find('\n'));
  };
  CHECK(complete("igds --te") == "--term --tek");
  CHECK(complete("igds --term ''") == "xterm tek none");
  CHECK(complete("igds --paper L") == "LETTER");
  CHECK(complete("igds 2") == "2250");
  CHECK(complete("igds h") == "hull.igds");
  CHECK(complete("igds n") == "");
  // Every option of the table, and the table is what igds accepts.
  for (const OptionSpec& o : command_line_options()) {
    CHECK(complete("igds " + std::string(o.name)) == std::string(o.name));
    for (auto v : o.values) {
      CAPTURE(v);
      CHECK_NOTHROW(parse_command_line({std::string(o.name), std::string(v)}));
    }
  }
}

TEST_CASE("igds-tek: xterm -t with the 4013's window around igds, or what to install") {
  const std::string launcher = (source_dir() / "scripts" / "igds-tek").string();
  TempDir bin;
  RunOptions no_xterm;
  no_xterm.env = {{"PATH", bin.path().string() + ":/usr/bin:/bin"}, {"DISPLAY", ":1"}};
  // An xterm that only says how it was called.
  write_file(bin.path() / "xterm", "#!/bin/sh\nprintf '%s|' \"$@\"\n");
  fs::permissions(bin.path() / "xterm", fs::perms::owner_all);
  // Installed: bin/igds-tek runs the bin/igds beside it.
  TempDir installed;
  fs::copy_file(launcher, installed.path() / "igds-tek");
  write_file(installed.path() / "igds", "#!/bin/sh\n");
  fs::permissions(installed.path() / "igds", fs::perms::owner_all);
  auto r =
      run({(installed.path() / "igds-tek").string(), "--disk", "/tmp/x", "hull.igds"}, no_xterm);
  CHECK(r.status == 0);
  CHECK(r.out ==
        "-t|-title|igds|-xrm|XTerm*tekGeometry: 1024x780|-xrm|XTerm*ginTerminator: "
        "CRonly|-xrm|XTerm*tek4014.fontLarge: 10x20|-e|" +
            (installed.path() / "igds").string() + "|--disk|/tmp/x|hull.igds|");
  RunOptions no_display = no_xterm;
  no_display.env["DISPLAY"] = "";
  r = run({(installed.path() / "igds-tek").string()}, no_display);
  CHECK(r.status == 1);
  CHECK(r.err.find("no X display") != std::string::npos);
  // No igds anywhere: said before any window opens.
  TempDir lone;
  fs::copy_file(launcher, lone.path() / "igds-tek");
  r = run({"/bin/sh", (lone.path() / "igds-tek").string()}, no_xterm);
  CHECK(r.status == 1);
  CHECK(r.err.find("igds is not installed") != std::string::npos);
  CHECK(r.out == "");
  fs::remove(bin.path() / "xterm");
  RunOptions nothing;
  nothing.env = {{"PATH", bin.path().string()}, {"DISPLAY", ":1"}};
  r = run({"/bin/sh", (installed.path() / "igds-tek").string()}, nothing);
  CHECK(r.status == 1);
  CHECK(r.err.find("xterm is not installed") != std::string::npos);
}

}  // namespace igds::test
