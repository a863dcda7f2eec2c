// Helpers of the end-to-end tests: igds run on command files against a scratch disk.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/process.h"

namespace igds::test {

// A 3 x 3 saddle with tangents at point 1, interpolated 2 x 2 (a command file fragment).
inline const char* const saddle_build = R"(BUILD
3 3
1  0 0 0   0 10 2   0 20 0
4  10 0 2  10 10 0  10 20 2
7  20 0 0  20 10 2  20 20 0

1 0 1 0 1
1 1 0 0 0

2 2
)";

// Standard input for igds, and optionally its environment and working directory.
inline RunOptions with_input(std::string input, std::map<std::string, std::string> env = {},
                             std::filesystem::path cwd = {}) {
  RunOptions options;
  options.input = std::move(input);
  options.env = std::move(env);
  options.cwd = std::move(cwd);
  options.timeout_seconds = 60;
  return options;
}

// Runs igds --term none --disk DISK on `commands` written to a command file (plus `extra`
// arguments before it).
inline RunResult run_commands(const TempDir& disk, const std::string& commands,
                              std::vector<std::string> extra = {}) {
  TempDir files;
  const auto path = files.path() / "commands.igds";
  write_file(path, commands);
  std::vector<std::string> args{"--term", "none", "--disk", disk.path().string()};
  args.insert(args.end(), extra.begin(), extra.end());
  args.push_back(path.string());
  return run_igds(args, with_input(""));
}

}  // namespace igds::test
