// The binary files of the disk (IGDSDATA, IGDSIMAG, IGDSCONT and the session's IGDSVARS): a
// frame of magic word, format version and payload length, the payload, and a checksum of all
// that; little-endian throughout. Also the crash-safe whole-file write that every file uses.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "workspace/kernels/array.h"
#include "workspace/state.h"

namespace igds::disk {

inline constexpr std::uint32_t format_version = 1;
inline constexpr std::size_t frame_header_bytes = 24;  // magic 8, version 4, spare 4, length 8
inline constexpr std::size_t frame_trailer_bytes = 8;  // checksum

// Why a file cannot be read, in capitals for the report, e.g. "CHECKSUM" or "TRUNCATED".
struct Damage {
  std::string reason;
};

// A 64-bit checksum that detects every change confined to one 8-byte word (each step is a
// bijection of the running state), and others with probability 1 - 2^-64.
std::uint64_t checksum(std::string_view bytes);

// Appends little-endian values to a byte string.
class Writer {
 public:
  void u8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void u32(std::uint32_t v);
  void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
  void u64(std::uint64_t v);
  void f64(double v);
  void bytes(std::string_view b) { out_.append(b); }
  void array(const Array& a);
  void image(const Image& image);
  std::string& str() { return out_; }

 private:
  std::string out_;
};

// Reads what Writer wrote; throws Damage on anything out of bounds or malformed.
class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  std::uint8_t u8();
  std::uint32_t u32();
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  std::uint64_t u64();
  double f64();
  std::string_view bytes(std::size_t n);
  Array array();
  // `checked`: DESIM[1] must be 0 or 1 and DESIM[2] a projection code of the manual.
  Image image(bool checked = true);
  bool at_end() const { return pos_ == in_.size(); }
  // Throws Damage("FORMAT") unless everything was read.
  void finish() const;

 private:
  std::string_view take(std::size_t n);
  std::string_view in_;
  std::size_t pos_ = 0;
};

// `payload` in its frame: magic (8 characters, e.g. "IGDSDATA"), version, length, checksum.
std::string frame(std::string_view magic, std::string_view payload);
// The payload of a framed file; throws Damage saying why the file is not a good one.
std::string_view unframe(std::string_view magic, std::string_view file);

// Bit-for-bit equality (-0.0 differs from 0.0, a NaN equals the same NaN).
bool same_bits(const Array& a, const Array& b);
bool same_bits(const ImageRef& a, const ImageRef& b);

// The surface variables (NOCUR ... INTPN) and a check that their shapes agree with each other
// (spec igds.md section 4); PATCHES and INTPN may both be empty. "" when they agree.
std::string surface_shape_error(const Workspace& ws);
void write_surface(Writer& w, const Workspace& ws);
void read_surface(Reader& r, Workspace& ws);  // only the surface variables

// A system error as the reports say it: "NO SPACE LEFT ON DEVICE".
std::string system_reason(int error);

// Thrown by the file functions below with the system's reason.
struct IoError {
  explicit IoError(int e, std::string t = {}) : error(e), text(std::move(t)) {}
  int error = 0;
  std::string text;  // overrides the system's words when set
  std::string reason() const { return text.empty() ? system_reason(error) : text; }
};

// Replaces `target` with `bytes` crash-safely: written to NAME.TYPE.IGDSTEMP in the same
// folder, fsync'd, renamed over `target`, folder fsync'd. On failure the temporary is removed,
// `target` is as it was, and IoError is thrown.
void replace_file(const std::filesystem::path& target, std::string_view bytes);
// The temporary that replace_file() uses for `target`.
std::filesystem::path temporary_for(const std::filesystem::path& target);
inline constexpr std::string_view temporary_suffix = ".IGDSTEMP";

// Writes a new file whole and fsyncs it (no rename: the caller makes it reachable later).
void write_new_file(const std::filesystem::path& target, std::string_view bytes);
void sync_folder(const std::filesystem::path& dir);

// The whole content of a file; nullopt when there is no such file; IoError otherwise (a folder
// where the file should be, no permission).
std::optional<std::string> read_whole_file(const std::filesystem::path& path);

// A file mapped read-only into memory: its bytes without copying them (the session's large
// variables are read this way at start). Same refusals as read_whole_file.
class MappedFile {
 public:
  // nullopt-like: exists() is false when there is no such file.
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  bool exists() const { return exists_; }
  std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }

 private:
  bool exists_ = false;
  void* data_ = nullptr;
  std::size_t size_ = 0;
};

// Test hook: the write calls of this process fail with ENOSPC once `limit` more bytes have
// been written (nullopt: no limit). Simulates a full disk where no small file system can be
// mounted.
void set_write_limit_for_testing(std::optional<std::size_t> limit);
// Test hook: the bytes this process's disk writes have written so far (the files only, not the
// terminal: what the limit above counts).
std::size_t bytes_written_for_testing();

}  // namespace igds::disk
