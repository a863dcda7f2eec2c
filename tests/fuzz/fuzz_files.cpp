// libFuzzer target of every reader of files on the disk (docs/disk.md, "What is checked where"):
// the first byte says which file the rest is, written on a scratch disk: a surface (IGDSDATA,
// RESTORE), an image (IGDSIMAG, DISPLAY FILE), a session (BINSAVE.IGDSCONT), or a session and
// one variable file it may name (B0000001.IGDSVARS; the rest cut in two halves). Whatever the
// bytes, the reader returns what the workspace accepts or throws an igds Error; a session read
// is saved again and read back the same; a surface or session that asks for a big surface is
// left at once (fuzz.h, small). The mutator makes the frames' lengths and checksums
// hold again after most mutations, so that they reach the readers behind them. Seeds:
// tests/fuzz/corpus/files.
//   scripts/fuzz 300 files
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string_view>

#include "tests/fuzz/fuzz.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/session.h"
#include "workspace/disk/session_file.h"
#include "workspace/error.h"
#include "workspace/variables.h"

namespace fs = std::filesystem;

namespace igds::fuzz {

namespace {

void put(const fs::path& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<long>(bytes.size()));
}

// The payload of the framed file `bytes` as its frame places it (empty when too short).
std::string_view payload_of(std::string_view bytes) {
  const std::size_t header = disk::frame_header_bytes, trailer = disk::frame_trailer_bytes;
  return bytes.size() < header + trailer ? std::string_view{}
                                         : bytes.substr(header, bytes.size() - header - trailer);
}

// True when the surface file `bytes` (IGDSDATA: NOCUR, NOSTR, INTCU, INTST first) asks for a
// small surface (fuzz.h), or is too short to say.
bool small_surface(std::string_view bytes) {
  const std::string_view p = payload_of(bytes);
  if (p.size() < 16) return true;
  disk::Reader r(p);
  const std::int32_t nocur = r.i32(), nostr = r.i32(), intcu = r.i32(), intst = r.i32();
  return small(nocur, nostr, intcu, intst);
}

}  // namespace

int files(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const fs::path& dir = scratch("files");
  empty(dir);
  Disk disk(dir);
  switch (data[0] % 4) {
    case 0: {
      if (!small_surface(bytes)) return 0;
      put(dir / "F.IGDSDATA", bytes);
      Workspace ws;
      try {
        restore_surface(disk, "F", ws);
      } catch (const Error&) {
        if (!(ws == Workspace{})) std::abort();  // a refused file changes nothing
        return 0;
      }
      if (surface_problem(ws, false)) std::abort();
      for (Variable v : {Variable::patches, Variable::intpn})
        if (finite_problem(v, v == Variable::patches ? ws.patches : ws.intpn)) std::abort();
      return 0;
    }
    case 1: {
      put(dir / "F.IGDSIMAG", bytes);
      try {
        const Image image = load_image(disk, "F");
        if (image_problem(image)) std::abort();
      } catch (const Error&) {
      }
      return 0;
    }
    default: {
      const bool vars = data[0] % 4 == 3;
      if (!small_session(payload_of(vars ? bytes.substr(0, bytes.size() / 2) : bytes))) return 0;
      if (vars) {
        put(dir / "BINSAVE.IGDSCONT", bytes.substr(0, bytes.size() / 2));
        put(dir / "B0000001.IGDSVARS", bytes.substr(bytes.size() / 2));
      } else {
        put(dir / "BINSAVE.IGDSCONT", bytes);
      }
      Workspace ws;
      {
        Session session(disk);
        ws = session.load();  // a damaged session is kept aside: the workspace starts empty
        if (surface_problem(ws, true)) std::abort();
        session.save(ws);
      }
      Session again(disk);
      if (!same_workspace(again.load(), ws)) std::abort();
      return 0;
    }
  }
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(files)

#ifndef IGDS_FUZZ_REPLAY
// libFuzzer's mutation, then the frames made to hold again (seven times in eight: the eighth
// leaves them as mutated, for the frame's own checks).
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned seed) {
  size = LLVMFuzzerMutate(data, size, max_size);
  if (size < 2 || std::minstd_rand(seed)() % 8 == 0) return size;
  const std::size_t file = size - 1;
  if (data[0] % 4 == 3) {
    std::uint8_t* const session = data + 1;
    std::uint8_t* const vars = data + 1 + file / 2;
    const std::size_t session_size = file / 2, vars_size = file - file / 2;
    igds::fuzz::fix_frame(vars, vars_size);
    // The session's references to the variable file say its length and checksum again.
    namespace disk = igds::disk;
    const std::size_t header = disk::frame_header_bytes, trailer = disk::frame_trailer_bytes;
    if (session_size >= header + trailer && vars_size >= header + trailer) {
      const std::string_view payload(reinterpret_cast<const char*>(session) + header,
                                     session_size - header - trailer);
      try {
        disk::SessionTable t = disk::decode_session(payload);
        const disk::FileRef real{1, vars_size,
                                 disk::trailing_checksum(std::string_view(
                                     reinterpret_cast<const char*>(vars), vars_size))};
        auto fix = [&](disk::Blob& b) {
          for (disk::Piece& p : b.pieces)
            if (p.in_file && p.file.number == 1) {
              p.file = real;
              p.size = vars_size - header - trailer;
            }
        };
        for (disk::Record& r : t.records) {
          fix(r.inppn.ravel);
          fix(r.inptg.ravel);
        }
        fix(t.patches.ravel);
        fix(t.intpn.ravel);
        for (disk::ImageEntry& e : t.images) fix(e.data);
        const std::string again = disk::encode_session(t);
        if (again.size() == payload.size()) std::copy(again.begin(), again.end(), session + header);
      } catch (const std::exception&) {
        // Not a session table: its bytes as mutated.
      }
    }
    igds::fuzz::fix_frame(session, session_size);
  } else {
    igds::fuzz::fix_frame(data + 1, file);
  }
  return size;
}
#endif
