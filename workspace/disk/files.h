// The file system as igds uses it, inside the disk's folder only: files written whole or not at
// all, never through a link; files read or mapped only after their size was checked; names set
// aside instead of deleted. Every failure is an IoError carrying the system's reason.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/disk/frame.h"
#include "workspace/error.h"
#include "workspace/text_out.h"

namespace igds::disk {

// A system error as the reports say it: "NO SPACE LEFT ON DEVICE".
std::string system_reason(int error);

// The system refused a file operation. reason(): the system's words, or `text` when given.
struct IoError : Error {
  explicit IoError(int e, std::string_view text = {});
  int error = 0;
};

// The temporary beside `target` that the writes below use: NAME.TYPE.IGDSTEMP.
inline constexpr std::string_view temporary_suffix = ".IGDSTEMP";
std::filesystem::path temporary_for(const std::filesystem::path& target);

// Writes `bytes` (the runs of a Writer, or one string) to `target` crash-safely: into the
// temporary (a stale one is removed first; a folder there is refused), created with O_EXCL and
// without following a link, fsync'd, then renamed to `target` and the folder fsync'd. `replace`:
// an existing `target` is replaced; else one there makes the call return false and changes
// nothing. On failure the temporary is removed, `target` is as it was, and IoError is thrown.
bool write_file(const std::filesystem::path& target, const Writer& bytes, bool replace = true);
bool write_file(const std::filesystem::path& target, std::string_view bytes, bool replace = true);

// The same for a text that make(out) puts into `out` as it is written, a few megabytes at a time
// (workspace/text_out.h; skipped bytes are holes filled later, the file being written at
// offsets): a listing of hundreds of megabytes is never held whole. Returns the file's size in
// bytes, or nullopt when `replace` is false and a file is there.
using Make = std::function<void(TextOut& out)>;
std::optional<std::uint64_t> write_made(const std::filesystem::path& target, const Make& make,
                                        bool replace = true);

// Writes a new file whole (O_EXCL: never an existing one, never through a link) and fsyncs it;
// the caller makes it reachable later (and syncs the folder).
void write_new_file(const std::filesystem::path& target, const Writer& bytes);
void sync_folder(const std::filesystem::path& dir);

// A file to read whole: its bytes (mapped, not copied). exists() is false when there is no such
// file. IoError for a folder or anything else that is not a regular file, and — before anything
// is read — "FILE TOO LARGE" for a file above `max_bytes`.
class MappedFile {
 public:
  MappedFile(const std::filesystem::path& path, std::size_t max_bytes);
  ~MappedFile();
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&&) = delete;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  bool exists() const { return exists_; }
  std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }

 private:
  bool exists_ = false;
  void* data_ = nullptr;
  std::size_t size_ = 0;
};

// The names in a folder (nothing when it cannot be read).
std::vector<std::string> folder_entries(const std::filesystem::path& dir);

// Renames `file` in `dir` to a free NAME.IGDSBAD (NAME, then NAME1, NAME2, ... within 8
// characters), never replacing anything; the new name.
std::string put_aside(const std::filesystem::path& dir, std::string_view name,
                      std::string_view file);

// A copy of the file `from` as the new file `to` (created as write_new_file creates, and synced):
// the same blocks shared where the file system can (a reflink, FICLONE), else the bytes copied by
// the system. Never a second name of `from`: a file changed in place later changes no copy.
// False, and nothing made, when `from` is not there, is a link or is not a plain file.
bool copy_file(const std::filesystem::path& from, const std::filesystem::path& to);

// Test hooks. The writes of this process fail with ENOSPC once `limit` more bytes have been
// written (nullopt: no limit): a full disk where no small file system can be mounted.
void set_write_limit_for_testing(std::optional<std::size_t> limit);
// The bytes this process's file writes have written so far (not the terminal's).
std::size_t bytes_written_for_testing();
// write(2) that honours the limit above (the lock file writes through it too).
long limited_write(int fd, const char* p, std::size_t n);

}  // namespace igds::disk
