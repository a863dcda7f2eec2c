// An igds process that keeps running while a test looks at it: started with a pipe on its
// standard input and output, read without blocking, ended by closing its input or by SIGKILL.
// (tests/support/process.h runs a program to its end; these tests need it alive.)
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace igds::test {

class LiveIgds {
 public:
  // Runs `binary args...`; standard input is a pipe (keep_input) or /dev/null. With `as_user`
  // (root only), igds runs as that user and group number, for whom permissions count.
  LiveIgds(const std::filesystem::path& binary, const std::vector<std::string>& args,
           bool keep_input, int as_user = -1) {
    int out[2], in[2] = {-1, -1};
    // Close-on-exec: no other child keeps these pipes open (an input never ending).
    if (::pipe2(out, O_CLOEXEC) != 0 || (keep_input && ::pipe2(in, O_CLOEXEC) != 0))
      throw std::runtime_error("pipe");
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("fork");
    if (pid_ == 0) {
      int null = ::open("/dev/null", O_RDWR);
      ::dup2(keep_input ? in[0] : null, 0);
      ::dup2(out[1], 1);
      ::dup2(null, 2);  // dup2 clears close-on-exec on 0, 1 and 2 only
      if (as_user >= 0 && (::setgid(static_cast<gid_t>(as_user)) != 0 ||
                           ::setuid(static_cast<uid_t>(as_user)) != 0))
        ::_exit(126);
      std::vector<std::string> all{binary.string()};
      all.insert(all.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (auto& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    ::close(out[1]);
    out_ = out[0];
    ::fcntl(out_, F_SETFL, ::fcntl(out_, F_GETFL) | O_NONBLOCK);
    if (keep_input) {
      ::close(in[0]);
      in_ = in[1];
    }
  }
  ~LiveIgds() {
    if (pid_ > 0) kill();
    if (out_ >= 0) ::close(out_);
    if (in_ >= 0) ::close(in_);
  }
  LiveIgds(const LiveIgds&) = delete;
  LiveIgds& operator=(const LiveIgds&) = delete;

  pid_t pid() const { return pid_; }

  // Reads what is there now; returns everything read so far.
  const std::string& output() {
    char buf[4096];
    for (;;) {
      ssize_t n = ::read(out_, buf, sizeof buf);
      if (n <= 0) break;
      out_text_.append(buf, static_cast<std::size_t>(n));
    }
    return out_text_;
  }

  // Waits until the output holds `text` (true) or `seconds` pass (false).
  bool wait_for(const std::string& text, double seconds) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (output().find(text) == std::string::npos) {
      if (std::chrono::steady_clock::now() > deadline) return false;
      pollfd p{out_, POLLIN, 0};
      ::poll(&p, 1, 10);
    }
    return true;
  }

  // Writes `text` to igds's standard input (kept by keep_input).
  void send(std::string_view text) {
    while (!text.empty()) {
      ssize_t n = ::write(in_, text.data(), text.size());
      if (n <= 0) throw std::runtime_error("write to igds");
      text.remove_prefix(static_cast<std::size_t>(n));
    }
  }

  // Ends input (as Ctrl-D) and waits for the exit status.
  int finish() {
    if (in_ >= 0) ::close(in_);
    in_ = -1;
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    output();
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

  void kill() {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
    output();
  }

 private:
  pid_t pid_ = -1;
  int out_ = -1, in_ = -1;
  std::string out_text_;
};

}  // namespace igds::test
