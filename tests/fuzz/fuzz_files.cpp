// libFuzzer target of every reader of files on the disk (docs/disk.md, "What is checked where"):
// the first byte says which file the rest is, written on a scratch disk: a surface (IGDSDATA,
// RESTORE), an image (IGDSIMAG, DISPLAY FILE), a session (BINSAVE.IGDSCONT), or a session and
// one variable file it may name (B0000001.IGDSVARS). Whatever the bytes, the reader returns
// what the workspace accepts or throws an igds Error; a session read is saved again and read
// back the same. Seeds: tests/fuzz/corpus/files.
//   cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DIGDS_FUZZ=ON
//   cmake --build build-fuzz --target fuzz_files
//   build-fuzz/tests/fuzz_files -max_total_time=300 fuzz-work tests/fuzz/corpus/files
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "workspace/disk/disk.h"
#include "workspace/disk/session.h"
#include "workspace/error.h"
#include "workspace/variables.h"

namespace fs = std::filesystem;

namespace {

const fs::path& scratch() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("igds-fuzz-files-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

void put(const fs::path& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<long>(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace igds;
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const fs::path& dir = scratch();
  for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
  Disk disk(dir);
  switch (data[0] % 4) {
    case 0: {
      put(dir / "F.IGDSDATA", bytes);
      Workspace ws;
      try {
        restore_surface(disk, "F", ws);
      } catch (const Error&) {
        if (!(ws == Workspace{})) std::abort();  // a refused file changes nothing
        return 0;
      }
      if (surface_problem(ws, false)) std::abort();
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
      if (data[0] % 4 == 3) {
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
      if (!(again.load() == ws)) std::abort();
      return 0;
    }
  }
}
