// Support for the end-to-end tests of the examples, the README and the xterm session: the example
// command files, expected transcripts, and a decoder of 4013 streams that says what igds drew.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tests/support/tek_decoder.h"

namespace igds::test {

// One command file of scripts/examples/.
struct Example {
  std::string name;            // "fig3-tangents"
  std::filesystem::path file;  // .../scripts/examples/fig3-tangents.igds
  int picture_page = -1;       // its header's "picture: page N" (tek2plot --page-number N)
  // scripts/examples/NAME.disk/: the files the example reads (a FIT deck), put on its fresh disk
  // before it runs; empty when it reads none.
  std::filesystem::path inputs;
};

// Copies the example's input files (Example::inputs) onto `disk`.
void put_inputs(const Example& example, const std::filesystem::path& disk);

// Every scripts/examples/*.igds, sorted by name.
std::vector<Example> examples();

// The lines of a command file as igds reads them: comment lines (first non-blank `*` or `⍝`)
// dropped and the rest of a line after `⍝` cut off, trailing blanks removed.
std::vector<std::string> command_lines(std::string_view file_text);

// Compares `actual` with tests/e2e/expected/`file`. Returns "" when they are equal, else a short
// account of the first difference. With IGDS_UPDATE_GOLDEN=1 in the environment the file is
// rewritten instead, a diff summary is printed, and "" is returned.
std::string compare_expected(const std::string& file, const std::string& actual);

// `text` with every occurrence of the disk's path replaced by <DISK>.
std::string without_disk(std::string text, const std::filesystem::path& disk);

}  // namespace igds::test
