// Driving a program through a pseudo-terminal, as a person at a terminal would (forkpty).
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace igds::test {

class PtySession {
 public:
  // Starts `argv` on a new pseudo-terminal; `env` is set in the child (an empty value unsets).
  PtySession(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
             const std::filesystem::path& cwd = {});
  ~PtySession();  // kills the program if it still runs
  PtySession(const PtySession&) = delete;
  PtySession& operator=(const PtySession&) = delete;

  // Types `text` (use "\r" for Enter, "\x03" for Ctrl-C, "\x04" for Ctrl-D).
  void send(std::string_view text);
  // Bytes as a terminal sends them in one write (a cross-hair's report).
  void send_raw(std::string_view bytes);
  // Reads what the program wrote, waiting `timeout_ms` at most for something.
  void pump(int timeout_ms) { read_some(timeout_ms); }
  // Waits until `text` appears in the output after the last match; true when it did before
  // `timeout_seconds`. The next expect() looks after it.
  bool expect(std::string_view text, double timeout_seconds = 10);
  // Reads the program's output until `ready()` holds; false when it did not before
  // `timeout_seconds`.
  bool wait_until(const std::function<bool()>& ready, double timeout_seconds = 10);
  // Waits for the program to end: its exit status, or -1 after the timeout.
  int wait(double timeout_seconds = 10);
  // Everything the program wrote so far.
  const std::string& output() const { return output_; }
  // The program's process.
  pid_t pid() const { return pid_; }

 private:
  bool read_some(int timeout_ms);
  pid_t pid_ = -1;
  int master_ = -1;
  std::string output_;
  std::size_t mark_ = 0;
  int status_ = -1;
};

}  // namespace igds::test
