// Test support: running programs (the real igds binary, tek2plot, hp2xx, ...) and scratch disks.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace igds::test {

struct RunResult {
  int status = -1;  // exit status, or 128 + signal number
  std::string out;  // standard output
  std::string err;  // standard error
};

struct RunOptions {
  std::string input;                       // standard input (then closed)
  std::filesystem::path cwd;               // working directory; empty: unchanged
  std::map<std::string, std::string> env;  // set in the child (an empty value unsets)
  double timeout_seconds = 120;            // killed with SIGKILL after this
};

// Runs `argv` (argv[0] looked up in PATH when it has no slash) and collects its output.
RunResult run(const std::vector<std::string>& argv, const RunOptions& options = {});

// Runs the igds binary of this build with `args`.
RunResult run_igds(const std::vector<std::string>& args, const RunOptions& options = {});

// The path of the igds binary of this build, and of the source tree.
std::filesystem::path igds_binary();
std::filesystem::path source_dir();

// True when the program can be found in PATH.
bool have_program(std::string_view name);

// A fresh folder under the system's temporary folder, removed with everything in it at the end.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& path);
void write_file(const std::filesystem::path& path, std::string_view text);

}  // namespace igds::test
