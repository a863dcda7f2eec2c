// What the fuzz targets of tests/fuzz share. Each target is a function igds::fuzz::<name>(data,
// size), called by libFuzzer (LLVMFuzzerTestOneInput, in a build with -DIGDS_FUZZ=ON, scripts/fuzz)
// and by the ordinary test suite, which feeds it every file of tests/fuzz/corpus/<name>
// (tests/fuzz/replay.cpp). A target aborts on what must never happen; an exception that escapes
// it is a finding too: libFuzzer's entry says which and aborts, the replay test reports it.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "workspace/disk/frame.h"
#include "workspace/disk/session_file.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/limits.h"
#include "workspace/state.h"

namespace igds::fuzz {

// A scratch folder of this process for the disks a target writes (emptied by the target before
// each input), removed when the process ends.
inline const std::filesystem::path& scratch(const std::string& name) {
  struct Folder {
    std::filesystem::path path;
    explicit Folder(std::filesystem::path p) : path(std::move(p)) {
      std::filesystem::create_directories(path);
    }
    ~Folder() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Folder folder(std::filesystem::temp_directory_path() /
                             ("igds-fuzz-" + name + "-" + std::to_string(::getpid())));
  return folder.path;
}

// Empties the scratch folder `dir`.
inline void empty(const std::filesystem::path& dir) {
  for (const auto& e : std::filesystem::directory_iterator(dir))
    std::filesystem::remove_all(e.path());
}

// Makes the frame of the framed file at data[0, size) hold again after a mutation: its length
// (bytes 16 to 23) and its checksum (the last 8 bytes), so that a mutation reaches the reader
// of the payload instead of being refused as CHECKSUM (workspace/disk/frame.h). The magic and
// version are left as they are.
inline void fix_frame(std::uint8_t* data, std::size_t size) {
  if (size < disk::frame_header_bytes + disk::frame_trailer_bytes) return;
  const std::uint64_t length = size - disk::frame_header_bytes - disk::frame_trailer_bytes;
  for (int i = 0; i < 8; ++i) data[16 + i] = static_cast<std::uint8_t>(length >> (8 * i));
  const std::size_t end = size - disk::frame_trailer_bytes;
  const std::uint64_t sum =
      disk::checksum(std::string_view(reinterpret_cast<const char*>(data), end));
  for (int i = 0; i < 8; ++i) data[end + i] = static_cast<std::uint8_t>(sum >> (8 * i));
}

// The inputs run whole are those of surfaces of at most this many points: the checks are the
// same at any size, and a surface of millions of points (a mutated INTCU) takes seconds under the
// sanitizers, each load and each UNDO.
inline constexpr double most_points = 1 << 15;

inline bool small(int nocur, int nostr, int intcu, int intst) {
  return grid_points(nocur, nostr, intcu, intst) <= most_points;
}

// True when the session payload `payload` (when it decodes) has only small surfaces in its
// records; one that does not decode is small (its reader refuses it at once).
inline bool small_session(std::string_view payload) {
  try {
    const disk::SessionTable t = disk::decode_session(payload);
    for (const disk::Record& r : t.records)
      if (!small(r.nocur, r.nostr, r.intcu, r.intst)) return false;
  } catch (const disk::Damage&) {
  }
  return true;
}

// The same image in both, or none in either: an image that cannot be made (a recipe read from
// a forged file: DataError) is none, as the session keeps it (Session::save, UnsavedImage).
inline bool same_made(const ImageRef& a, const ImageRef& b) {
  auto made = [](const ImageRef& r) -> const Image* {
    if (!r) return nullptr;
    try {
      return &*r;
    } catch (const DataError&) {
      return nullptr;
    }
  };
  const Image *x = made(a), *y = made(b);
  return x && y ? *x == *y : !x && !y;
}

// Workspace's operator==, with images compared as same_made does.
inline bool same_workspace(const Workspace& a, const Workspace& b) {
  Workspace x = a, y = b;
  const bool images =
      same_made(a.image, b.image) && same_made(a.temp1, b.temp1) && same_made(a.temp2, b.temp2);
  x.image = x.temp1 = x.temp2 = y.image = y.temp1 = y.temp2 = nullptr;
  return images && x == y;
}

// What must never happen, said, then a crash (libFuzzer keeps the input).
[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz: %s\n", what.c_str());
  std::abort();
}

// libFuzzer's call of a target: an exception that escapes is said and is a crash.
template <class Target>
int guarded(Target target, const std::uint8_t* data, std::size_t size) {
  try {
    return target(data, size);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: an exception escaped: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "fuzz: an exception that is no std::exception escaped\n");
  }
  std::abort();
}

}  // namespace igds::fuzz

// The entry of a target for libFuzzer (not in the replay test, which calls the target itself).
#ifdef IGDS_FUZZ_REPLAY
#define IGDS_FUZZ_ENTRY(target)
#else
#define IGDS_FUZZ_ENTRY(target)                                                       \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    return igds::fuzz::guarded(igds::fuzz::target, data, size);                       \
  }
#endif

// libFuzzer's own mutation, for the custom mutators.
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);
