#include "workspace/disk/lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <thread>

#include <fmt/format.h>

#include "workspace/disk/files.h"
#include "workspace/error.h"

namespace igds::disk {

namespace {

constexpr std::string_view lock_file = "BINSAVE.IGDSLOCK";

// The process number in a lock file, or "" when it holds anything else.
std::string process_number(const char* text, ssize_t n) {
  std::string digits(text, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!digits.empty() && (digits.back() == '\n' || digits.back() == ' ')) digits.pop_back();
  bool ok = !digits.empty() && digits.size() <= 10 &&
            std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
  return ok ? digits : "";
}

}  // namespace

DiskLock::DiskLock(const std::filesystem::path& dir, std::vector<std::string>& notices)
    : path_(dir / lock_file) {
  const std::string where = dir.string();
  auto refuse = [&](std::string_view reason) {
    return Report(fmt::format("DISK {} CANNOT BE LOCKED ({})", where, reason));
  };
  for (int attempt = 0;; ++attempt) {
    // O_NONBLOCK: a FIFO at the lock's name must not hang igds; O_NOFOLLOW: nor lead elsewhere.
    int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
    if (fd < 0) {
      if (errno == ELOOP) throw refuse(fmt::format("{} IS A SYMBOLIC LINK", lock_file));
      throw refuse(system_reason(errno));
    }
    struct stat mine;
    if (::fstat(fd, &mine) != 0) {
      const int error = errno;
      ::close(fd);
      throw refuse(system_reason(error));
    }
    // Only a plain file of igds's own is ever written or removed: never a FIFO, a device, or a
    // file that has a name elsewhere too.
    if (!S_ISREG(mine.st_mode) || mine.st_nlink != 1) {
      ::close(fd);
      throw refuse(S_ISREG(mine.st_mode) ? fmt::format("{} HAS ANOTHER NAME TOO", lock_file)
                                         : fmt::format("{} IS NOT A PLAIN FILE", lock_file));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      char buf[32] = {};
      ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
      ::close(fd);
      if (error != EWOULDBLOCK) throw refuse(system_reason(error));
      std::string holder = process_number(buf, n);
      // The holder writes its number just after locking: give it a moment.
      if (holder.empty() && attempt < 20) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        continue;
      }
      if (holder.empty())
        throw Report(fmt::format("DISK {} IN USE BY ANOTHER IGDS PROCESS", where));
      throw Report(fmt::format("DISK {} IN USE BY IGDS PROCESS {}", where, holder));
    }
    // A holder that ended removed the file after we opened it: lock the file now in its place.
    struct stat named;
    if (::lstat(path_.c_str(), &named) != 0 || mine.st_ino != named.st_ino ||
        mine.st_dev != named.st_dev) {
      ::close(fd);
      continue;
    }
    char buf[32] = {};
    ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
    if (n > 0) {
      std::string previous = process_number(buf, n);
      notices.push_back(previous.empty()
                            ? std::string("DISK LOCK LEFT BY AN IGDS THAT HAS ENDED, TAKEN OVER")
                            : fmt::format("DISK LOCK LEFT BY IGDS PROCESS {}, WHICH HAS ENDED, "
                                          "TAKEN OVER",
                                          previous));
    }
    const std::string pid = fmt::format("{}\n", ::getpid());
    int error = 0;
    if (::ftruncate(fd, 0) != 0 || ::lseek(fd, 0, SEEK_SET) != 0) {
      error = errno;
    } else if (long w = limited_write(fd, pid.data(), pid.size());
               w != static_cast<long>(pid.size())) {
      error = w < 0 ? errno : ENOSPC;
    }
    if (error != 0) {
      if (error == ENOSPC || error == EDQUOT) {
        // The flock is the lock; the number only helps a second igds say who holds it.
        room_ = false;
      } else {
        ::unlink(path_.c_str());
        ::close(fd);
        throw refuse(system_reason(error));
      }
    }
    fd_ = fd;
    return;
  }
}

DiskLock::~DiskLock() {
  if (fd_ >= 0) {
    // Unlinked while still locked, so that whoever locks next finds the file gone.
    ::unlink(path_.c_str());
    ::close(fd_);
  }
}

}  // namespace igds::disk
