#include "workspace/disk/files.h"

#include <dirent.h>
#include <fcntl.h>
#include <linux/fs.h>
#include <stdio.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <utility>

#include <fmt/format.h>

#include "workspace/kernels/interrupt.h"

namespace igds::disk {

namespace {

std::optional<std::size_t> write_limit;
std::size_t bytes_written = 0;  // by this process's file writes, for the tests

// One write(2) or pwrite(2) of at most n bytes by write_some(m), honouring the test limit (ENOSPC
// once it is used up) and counting what it wrote; what the call returned.
template <class Write>
ssize_t limited(std::size_t n, const Write& write_some) {
  if (write_limit) {
    if (*write_limit == 0) {
      errno = ENOSPC;
      return -1;
    }
    n = std::min(n, *write_limit);
  }
  const ssize_t done = write_some(n);
  if (done > 0) {
    bytes_written += static_cast<std::size_t>(done);
    if (write_limit) *write_limit -= static_cast<std::size_t>(done);
  }
  return done;
}

// An open descriptor closed on every path; close() errors are reported by finish().
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }
  void finish() {
    int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && errno != EINTR) throw IoError(errno);
  }

 private:
  int fd_;
};

// pwritev(2) of as many runs as it takes, at `at` in the file, honouring the test limit.
void write_runs(int fd, std::span<const std::string_view> runs, std::uint64_t at) {
  std::size_t k = 0, offset = 0;  // the next byte: run k, at offset
  while (k < runs.size()) {
    if (offset == runs[k].size()) {
      ++k;
      offset = 0;
      continue;
    }
    ssize_t done;
    if (write_limit) {
      done = limited(runs[k].size() - offset, [&](std::size_t m) {
        return ::pwrite(fd, runs[k].data() + offset, m, static_cast<off_t>(at));
      });
    } else {
      iovec v[64];
      int n = 0;
      for (std::size_t j = k; j < runs.size() && n < 64; ++j) {
        const std::size_t from = j == k ? offset : 0;
        if (runs[j].size() == from) continue;
        v[n].iov_base = const_cast<char*>(runs[j].data() + from);
        v[n].iov_len = runs[j].size() - from;
        ++n;
      }
      done = ::pwritev(fd, v, n, static_cast<off_t>(at));
      if (done > 0) bytes_written += static_cast<std::size_t>(done);
    }
    if (done < 0) {
      if (errno == EINTR) continue;
      throw IoError(errno);
    }
    auto left = static_cast<std::size_t>(done);
    at += left;
    while (left > 0) {
      const std::size_t here = std::min(left, runs[k].size() - offset);
      offset += here;
      left -= here;
      if (offset == runs[k].size() && k + 1 < runs.size()) {
        ++k;
        offset = 0;
      }
    }
  }
}

// pwrite(2) of n bytes at `offset`, honouring the test limit.
void put_at(int fd, const char* p, std::size_t n, std::uint64_t offset) {
  while (n > 0) {
    const ssize_t done =
        limited(n, [&](std::size_t m) { return ::pwrite(fd, p, m, static_cast<off_t>(offset)); });
    if (done < 0) {
      if (errno == EINTR) continue;
      throw IoError(errno);
    }
    const auto d = static_cast<std::size_t>(done);
    p += d;
    n -= d;
    offset += d;
  }
}

// The pieces a large file is written in.
constexpr std::size_t piece = std::size_t{4} << 20;

// Asks the system to start putting [offset, offset + n) of the file on the disk now (advice: a
// refusal changes nothing), so that a large file's pieces go to the disk while the next ones are
// made, and the fsync at the end finds little left to do.
void start_writeback([[maybe_unused]] int fd, [[maybe_unused]] std::uint64_t offset,
                     [[maybe_unused]] std::size_t n) {
#ifdef SYNC_FILE_RANGE_WRITE
  ::sync_file_range(fd, static_cast<off_t>(offset), static_cast<off_t>(n), SYNC_FILE_RANGE_WRITE);
#endif
}

// The runs into the file from `offset` on, by pwritev, a piece at a time, the system asked to
// start putting each piece on the disk once it is written. Returns the offset after them.
std::uint64_t write_in_pieces(int fd, std::span<const std::string_view> runs,
                              std::uint64_t offset = 0) {
  std::vector<std::string_view> some;
  std::size_t size = 0;
  auto flush = [&] {
    write_runs(fd, some, offset);
    if (size > 0) start_writeback(fd, offset, size);
    offset += size;
    some.clear();
    size = 0;
  };
  for (std::string_view run : runs) {
    while (!run.empty()) {
      const std::size_t n = std::min(run.size(), piece - size);
      some.push_back(run.substr(0, n));
      size += n;
      run.remove_prefix(n);
      if (size == piece) flush();
    }
  }
  flush();
  return offset;
}

// A TextOut into an open file: one buffer of `piece` bytes, written at its offset whenever it
// fills or a seek moves the text elsewhere. A Ctrl-C waiting stops the text there (the files
// made this way are the user's: EXPORT, PLOT, WRITE; the temporary is removed).
class FileOut final : public TextOut {
 public:
  explicit FileOut(int fd) : fd_(fd), buffer_(std::make_unique_for_overwrite<char[]>(piece)) {
    begin_ = at_ = buffer_.get();
    end_ = begin_ + piece;
  }
  // Writes what is left; IoError when the system refuses.
  void finish() { seek(offset()); }
  // After the buffer, straight from where the runs are.
  void put_runs(std::span<const std::string_view> runs) override {
    seek(offset());
    base_ = write_in_pieces(fd_, runs, base_);
  }

 private:
  void take(std::size_t) override {
    check_interrupt();
    const auto n = static_cast<std::size_t>(at_ - begin_);
    put_at(fd_, begin_, n, base_);
    if (n > 0) start_writeback(fd_, base_, n);
    begin_ = at_ = buffer_.get();
  }
  int fd_;
  std::unique_ptr<char[]> buffer_;
};

// Creates `path` (it must not exist; never through a link), writes by `write(fd)`, fsyncs;
// removes it on failure.
template <class Write>
void create_and_write(const std::filesystem::path& path, const Write& write) {
  Fd fd(::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644));
  if (fd.get() < 0) {
    if (errno == ELOOP) throw IoError(ELOOP, "A SYMBOLIC LINK IS IN THE WAY");
    if (errno == EEXIST) throw IoError(EEXIST, "ANOTHER FILE APPEARED IN THE WAY");
    throw IoError(errno);
  }
  try {
    write(fd.get());
    if (::fdatasync(fd.get()) != 0) throw IoError(errno);
    fd.finish();
  } catch (...) {
    ::unlink(path.c_str());
    throw;
  }
}

void create_and_write(const std::filesystem::path& path, const Writer& bytes) {
  create_and_write(path, [&](int fd) { write_in_pieces(fd, bytes.runs()); });
}

// Clears the way for a temporary: a stale file or link there is removed (never followed), a
// folder is refused.
void clear_temporary(const std::filesystem::path& tmp) {
  struct stat st;
  if (::lstat(tmp.c_str(), &st) != 0) return;
  if (S_ISDIR(st.st_mode)) throw IoError(EISDIR);
  if (::unlink(tmp.c_str()) != 0 && errno != ENOENT) throw IoError(errno);
}

// Writes the temporary of `target` by `write`, then puts it in place (see write_file).
template <class Write>
bool write_in_place(const std::filesystem::path& target, const Write& write, bool replace) {
  auto tmp = temporary_for(target);
  clear_temporary(tmp);
  create_and_write(tmp, write);
  int moved;
  if (replace) {
    moved = ::rename(tmp.c_str(), target.c_str());
  } else {
    moved = ::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE);
    if (moved != 0 && (errno == EINVAL || errno == ENOSYS)) {
      // File systems without RENAME_NOREPLACE: a hard link fails when the name is taken.
      moved = ::link(tmp.c_str(), target.c_str());
      if (moved == 0) ::unlink(tmp.c_str());
    }
  }
  if (moved != 0) {
    int error = errno;
    ::unlink(tmp.c_str());
    if (!replace && error == EEXIST) return false;
    throw IoError(error);
  }
  sync_folder(target.parent_path());
  return true;
}

}  // namespace

long limited_write(int fd, const char* p, std::size_t n) {
  return limited(n, [&](std::size_t m) { return ::write(fd, p, m); });
}

std::string system_reason(int error) {
  std::string s = std::strerror(error);
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

IoError::IoError(int e, std::string_view text)
    : Error("DISK ERROR", text.empty() ? std::string_view(system_reason(e)) : text), error(e) {}

std::filesystem::path temporary_for(const std::filesystem::path& target) {
  auto tmp = target;
  tmp += temporary_suffix;
  return tmp;
}

bool write_file(const std::filesystem::path& target, const Writer& bytes, bool replace) {
  return write_in_place(
      target, [&](int fd) { write_in_pieces(fd, bytes.runs()); }, replace);
}

std::optional<std::uint64_t> write_made(const std::filesystem::path& target, const Make& make,
                                        bool replace) {
  std::uint64_t size = 0;
  const bool written = write_in_place(
      target,
      [&](int fd) {
        FileOut out(fd);
        make(out);
        size = out.size();
        out.finish();
      },
      replace);
  if (!written) return std::nullopt;
  return size;
}

bool write_file(const std::filesystem::path& target, std::string_view bytes, bool replace) {
  Writer w;
  w.borrow(bytes);
  return write_file(target, w, replace);
}

void write_new_file(const std::filesystem::path& target, const Writer& bytes) {
  create_and_write(target, bytes);
}

void sync_folder(const std::filesystem::path& dir) {
  Fd fd(::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) throw IoError(errno);
  if (::fsync(fd.get()) != 0) throw IoError(errno);
  fd.finish();
}

MappedFile::MappedFile(const std::filesystem::path& path, std::size_t max_bytes) {
  // O_NONBLOCK: a FIFO put where a file should be must not hang igds.
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
  if (fd.get() < 0) {
    if (errno == ENOENT) return;
    throw IoError(errno);
  }
  struct stat st;
  if (::fstat(fd.get(), &st) != 0) throw IoError(errno);
  if (S_ISDIR(st.st_mode)) throw IoError(EISDIR);
  if (!S_ISREG(st.st_mode)) throw IoError(EINVAL, "NOT A REGULAR FILE");
  // Checked before a byte is read or mapped: a sparse file of 100 GB costs nothing.
  if (st.st_size < 0 || static_cast<std::uint64_t>(st.st_size) > max_bytes)
    throw IoError(EFBIG, "FILE TOO LARGE");
  exists_ = true;
  size_ = static_cast<std::size_t>(st.st_size);
  if (size_ == 0) return;
  data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd.get(), 0);
  if (data_ == MAP_FAILED) {
    data_ = nullptr;
    size_ = 0;
    throw IoError(errno);
  }
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : exists_(other.exists_),
      data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)) {}

MappedFile::~MappedFile() {
  if (data_) ::munmap(data_, size_);
}

std::vector<std::string> folder_entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (dirent* e = ::readdir(d)) {
      std::string name = e->d_name;
      if (name != "." && name != "..") names.push_back(std::move(name));
    }
    ::closedir(d);
  }
  return names;
}

std::string put_aside(const std::filesystem::path& dir, std::string_view name,
                      std::string_view file) {
  for (int k = 0; k < 100000; ++k) {
    std::string candidate(name);
    if (k > 0) {
      std::string digits = std::to_string(k);
      candidate = candidate.substr(0, 8 - digits.size()) + digits;
    }
    std::string target = fmt::format("{}.IGDSBAD", candidate);
    auto from = dir / file, to = dir / target;
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0)
      return target;
    // File systems without RENAME_NOREPLACE: a hard link fails when the name is taken.
    if (errno == EINVAL || errno == ENOSYS) {
      if (::link(from.c_str(), to.c_str()) == 0) {
        ::unlink(from.c_str());
        return target;
      }
    }
    if (errno != EEXIST) throw IoError(errno);
  }
  throw IoError(EEXIST);
}

bool copy_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  // O_NONBLOCK: a FIFO put at the name must not hang igds; O_NOFOLLOW: nor a link lead it away.
  Fd in(::open(from.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK));
  if (in.get() < 0) {
    if (errno == ENOENT || errno == ELOOP) return false;
    throw IoError(errno);
  }
  struct stat st;
  if (::fstat(in.get(), &st) != 0) throw IoError(errno);
  if (!S_ISREG(st.st_mode)) return false;
  create_and_write(to, [&](int fd) {
    if (!write_limit && ::ioctl(fd, FICLONE, in.get()) == 0) return;
    off_t at = 0;
    bool kernel = !write_limit;  // the test limit counts bytes written by write(2) only
    for (;;) {
      ssize_t n = -1;
      if (kernel) {
        n = ::copy_file_range(in.get(), &at, fd, nullptr, std::size_t{1} << 30, 0);
        if (n < 0 &&
            (errno == EXDEV || errno == ENOSYS || errno == EINVAL || errno == EOPNOTSUPP)) {
          kernel = false;
          continue;
        }
        if (n > 0) bytes_written += static_cast<std::size_t>(n);
      } else {
        char buffer[1 << 16];
        n = ::pread(in.get(), buffer, sizeof buffer, at);
        if (n > 0) {
          put_at(fd, buffer, static_cast<std::size_t>(n), static_cast<std::uint64_t>(at));
          at += n;
        }
      }
      if (n == 0) return;
      if (n < 0 && errno != EINTR) throw IoError(errno);
    }
  });
  return true;
}

std::size_t bytes_written_for_testing() {
  return bytes_written;
}

void set_write_limit_for_testing(std::optional<std::size_t> limit) {
  write_limit = limit;
}

}  // namespace igds::disk
