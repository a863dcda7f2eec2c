// The frame of igds's binary files (IGDSDATA, IGDSIMAG, IGDSCONT, IGDSVARS; docs/disk.md):
// magic word, format version and payload length, the payload, and a checksum of all that;
// little-endian throughout. Writing builds a file as a list of byte runs that borrows the large
// arrays instead of copying them; reading checks every length against what is there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/error.h"
#include "workspace/kernels/array.h"
#include "workspace/state.h"

namespace igds::disk {

inline constexpr std::size_t frame_header_bytes = 24;  // magic 8, version 4, spare 4, length 8
inline constexpr std::size_t frame_trailer_bytes = 8;  // checksum

// A file that is not what it should be. The reason, in capitals, is what the reports show:
// "CHECKSUM", "TRUNCATED", "SHAPES: INPPN IS 8 BY 3, NOT 1600 BY 3".
struct Damage : Error {
  explicit Damage(std::string_view reason) : Error("FILE DAMAGED", reason) {}
};

// A 64-bit checksum that detects every change confined to one 8-byte word (each step is a
// bijection of the running state), and others with probability 1 - 2^-64.
std::uint64_t checksum(std::string_view bytes);

// The same checksum of bytes given in runs: add() the runs in order, then value().
class Checksum {
 public:
  Checksum();
  void add(std::string_view bytes);
  std::uint64_t value() const;

 private:
  std::uint64_t lane_[4];
  char block_[32];
  std::size_t held_ = 0;   // bytes in block_
  std::size_t total_ = 0;  // bytes added
};

// A file's bytes as runs: small values are appended to runs it owns, large arrays are borrowed
// (they must outlive the Writer and stay unchanged until it is written).
class Writer {
 public:
  void u8(std::uint8_t v);
  void u32(std::uint32_t v);
  void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
  void u64(std::uint64_t v);
  void f64(double v);
  void bytes(std::string_view b);   // copied
  void borrow(std::string_view b);  // referred to
  // Rank (u32), shape (u64 each), element count (u64), the doubles (borrowed).
  void array(const Array& a);
  // DESIM[1] DESIM[2] (i32), DESIM[3 4 5] (f64), the points, the arrows; a picture
  // (DESIM[1] = 2) then its name and its DUCT text, each a length (u64) and the bytes.
  // DESIM[1] DESIM[2] (i32), DESIM[3 4 5] (f64).
  void description(const Description& d);
  void image(const Image& image);
  // Another writer's runs, after these.
  void append(const Writer& other);

  const std::vector<std::string_view>& runs() const { return runs_; }
  std::size_t size() const { return size_; }
  // The runs joined (small files, tests).
  std::string str() const;

 private:
  std::string& tail();
  std::deque<std::string> owned_;
  std::vector<std::string_view> runs_;
  bool tail_owned_ = false;
  std::size_t size_ = 0;
};

// Reads what Writer wrote; throws Damage("FORMAT") on anything out of bounds or malformed.
// Given a Checksum, it also adds to it every byte of `in`, in order, as it is read (read_framed).
class Reader {
 public:
  explicit Reader(std::string_view in, Checksum* sum = nullptr) : in_(in), sum_(sum) {}
  std::uint8_t u8();
  std::uint32_t u32();
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  std::uint64_t u64();
  double f64();
  Description description();
  std::string_view bytes(std::size_t n);
  // At most `max_elements` elements (more: Damage "FORMAT").
  Array array(std::size_t max_elements = std::size_t(1) << 60);
  // The image of IGDSIMAG and the session; its points and arrows within `max_elements`. A
  // picture is drawn again from its text (Damage "PICTURE LINE n: ..." when it does not read).
  Image image(std::size_t max_elements = std::size_t(1) << 60);
  std::size_t left() const { return in_.size() - pos_; }
  bool at_end() const { return pos_ == in_.size(); }
  // Throws Damage("FORMAT") unless everything was read.
  void finish() const;
  // The checksum given, with every byte of `in` added, read or not.
  std::uint64_t sum();

 private:
  std::string_view take(std::size_t n);
  void add_read();  // adds to the checksum what was read since it last did
  std::string_view in_;
  std::size_t pos_ = 0;
  Checksum* sum_ = nullptr;
  std::size_t summed_ = 0;  // the bytes of in_ added to sum_
};

// `payload` in its frame: magic (8 characters, e.g. "IGDSDATA"), `version`, length, checksum.
Writer frame(std::string_view magic, const Writer& payload, std::uint32_t version = 1);
std::string frame(std::string_view magic, std::string_view payload, std::uint32_t version = 1);
// The newest format version of each kind of file, the one igds writes (docs/disk.md): 2 for the
// session file of records and recipes (IGDSCONT) and for IGDSDATA that stores PATCHES and INTPN
// only when they are not the interpolation of its inputs, 1 for every other kind.
std::uint32_t newest_version(std::string_view magic);
// A framed file's payload, its version, and the checksum the file ends with.
struct Frame {
  std::string_view payload;
  std::uint32_t version = 1;
  std::uint64_t sum = 0;
};
// The frame of a good file; throws Damage saying why the file is not a good one (EMPTY FILE, NOT
// AN x FILE, TRUNCATED, LENGTH, FORMAT VERSION n OF A NEWER IGDS, CHECKSUM).
Frame unframe(std::string_view magic, std::string_view file);
// The same, all but the checksum.
Frame open_frame(std::string_view magic, std::string_view file);
// Reads a framed file's payload with read(Reader&, version) in one pass: the checksum is found
// as the bytes are read, a large array's from its copy while it is in the cache, instead of in a
// pass of its own before. The reports are unframe's and read's; a file whose checksum does not
// hold is CHECKSUM, whatever read found or threw on the way.
template <class Read>
auto read_framed(std::string_view magic, std::string_view file, const Read& read) {
  const Frame frame = open_frame(magic, file);
  Checksum sum;
  sum.add(file.substr(0, frame_header_bytes));
  Reader r(frame.payload, &sum);
  try {
    auto value = read(r, frame.version);
    if (r.sum() != frame.sum) throw Damage("CHECKSUM");
    return value;
  } catch (...) {
    if (checksum(file.substr(0, frame_header_bytes + frame.payload.size())) != frame.sum)
      throw Damage("CHECKSUM");
    throw;
  }
}
// The checksum a framed file ends with (its last 8 bytes; 0 for a file shorter than that).
std::uint64_t trailing_checksum(std::string_view file);

}  // namespace igds::disk
