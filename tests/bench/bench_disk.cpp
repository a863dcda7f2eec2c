// Speed of the disk: the autosave after a CHANGE GRID and after a STATUS-only change (HELP
// SHORT), the bytes that one writes, and RESTORE, on a surface of 100 x 100 input points with
// INTCU = INTST = 10 (INTPN 1090 x 1090 x 3, 28.5 MB), in a scratch folder of the system's
// temporary disk (fsync included). And WRITE's card text of the same surface, in MB/s.
#include <fmt/core.h>
#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/bench/bench.h"
#include "workspace/disk/cards.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/frame.h"
#include "workspace/disk/session.h"
#include "workspace/disk/session_file.h"
#include "workspace/journal.h"
#include "workspace/kernels/surface.h"

namespace {

using namespace igds;

// Bytes this process has handed to write(2) so far (Linux /proc/self/io).
std::size_t bytes_written_so_far() {
  std::ifstream io("/proc/self/io");
  std::string key;
  std::size_t value = 0;
  while (io >> key >> value)
    if (key == "wchar:") return value;
  return 0;
}

struct Folder {
  std::filesystem::path path;
  Folder() {
    std::string t = (std::filesystem::temp_directory_path() / "igds-bench-XXXXXX").string();
    path = ::mkdtemp(t.data());
  }
  ~Folder() { std::filesystem::remove_all(path); }
};

constexpr int n = 100;  // input curves and stringers

// A wavy n x n input surface with its border tangents, interpolated with INTCU, INTST.
Workspace surface(int intcu, int intst) {
  Workspace ws;
  ws.nocur = ws.nostr = n;
  ws.inppn = Array({std::size_t(n * n), 3});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double* p = ws.inppn.data() + 3 * (i * n + j);
      p[0] = j, p[1] = 1.5 * i, p[2] = std::sin(0.5 * j) * std::cos(0.3 * i);
    }
  ws.inptg = Array({std::size_t(4 * n), 4});
  for (int r = 0; r < 4 * n; ++r) ws.inptg.ravel[4 * r + (r < 2 * n ? 0 : 1)] = 1;
  ws.intcu = intcu;
  ws.intst = intst;
  Surface s = interpolate({n, n, intcu, intst, &ws.inppn, &ws.inptg});
  ws.patches = std::move(s.patches);
  ws.intpn = std::move(s.intpn);
  return ws;
}

// The XY view of INTPN, as DISPLAY SURFACE ORTHOGONAL XY keeps it.
Image view(const Workspace& ws) {
  Image image;
  image.desim.what = 1;
  image.points = Array({ws.intpn.shape[0], ws.intpn.shape[1], 2});
  for (std::size_t k = 0; k < ws.intpn.size() / 3; ++k) {
    image.points.ravel[2 * k] = ws.intpn.ravel[3 * k];
    image.points.ravel[2 * k + 1] = ws.intpn.ravel[3 * k + 1];
  }
  return image;
}

}  // namespace

IGDS_BENCH("disk") {
  Folder folder;
  Disk disk(folder.path);
  Workspace fine = surface(10, 10);  // INTPN 1090 x 1090 x 3
  Workspace coarse = surface(9, 9);
  {
    Session session(disk);
    session.load();
    Workspace ws = coarse;
    session.save(ws);
    // Time only the save: the copies above are the command's work, not the autosave's.
    double change_grid = 1e300;
    for (int r = 0; r < 10; ++r) {
      ws.intcu = ws.intst = 9;
      ws.intpn = coarse.intpn;
      session.save(ws);
      ws.intcu = ws.intst = 10;
      ws.intpn = fine.intpn;
      change_grid = std::min(change_grid, bench::best_seconds(1, [&] { session.save(ws); }));
    }
    fmt::print("autosave_change_grid_100x100_int10_ms {:.3f}\n", change_grid * 1e3);

    // The same surface with the current image and both stored copies.
    ws.image = std::make_shared<const igds::Image>(view(ws));
    ws.temp1 = std::make_shared<const igds::Image>(view(ws));
    ws.temp2 = std::make_shared<const igds::Image>(view(coarse));
    session.save(ws);
    double help_short = 1e300;
    std::size_t bytes = 0;
    for (int r = 0; r < 20; ++r) {
      ws.status[0] = 1 - ws.status[0];  // HELP SHORT / HELP LONG
      std::size_t w0 = bytes_written_so_far();
      help_short = std::min(help_short, bench::best_seconds(1, [&] { session.save(ws); }));
      bytes = bytes_written_so_far() - w0;
    }
    fmt::print("autosave_help_short_ms {:.3f}\n", help_short * 1e3);
    fmt::print("autosave_help_short_bytes_written {}\n", bytes);
    std::size_t w0 = bytes_written_so_far();
    session.save(ws);
    fmt::print("autosave_unchanged_bytes_written {}\n", bytes_written_so_far() - w0);
  }
  {
    double load = bench::best_seconds(10, [&] {
      Session session(disk);
      Workspace ws = session.load();
      if (ws.intpn != fine.intpn) fmt::print("session_load: wrong INTPN\n");
    });
    fmt::print("session_load_100x100_int10_ms {:.3f}\n", load * 1e3);
  }
  save_surface(disk, "HULL", fine);
  Workspace ws;
  double restore = bench::best_seconds(20, [&] { restore_surface(disk, "HULL", ws); });
  fmt::print("restore_100x100_int10_ms {:.3f}\n", restore * 1e3);
  double save = bench::best_seconds(10, [&] { save_surface(disk, "HULL", fine); });
  fmt::print("save_100x100_int10_ms {:.3f}\n", save * 1e3);
}

// The undo journal (workspace/journal.h): 200 CHANGE POINTS of one point each on the 100 x 100
// surface with INTCU = INTST = 10, each recorded and autosaved as the interpreter does; the bytes
// the journal keeps, in memory and in the session file, the cost of a step, UNDO, and the start.
IGDS_BENCH("journal") {
  Folder folder;
  Disk disk(folder.path);
  Workspace ws = surface(10, 10);
  double record = 1e300, save = 1e300, save_without = 1e300;
  {
    Session session(disk);
    session.load();
    Journal journal(ws);
    session.save(ws, &journal);
    for (int c = 0; c < 200; ++c) {
      const std::size_t k = std::size_t(c * 37) % std::size_t(n * n);
      ws.inppn.ravel[3 * k + 2] = c;
      Edits points = Edits::none();
      points.part(3 * k, 3 * k + 3);
      ws.changes.edited(points, Edits::none());
      Surface s = interpolate({n, n, ws.intcu, ws.intst, &ws.inppn, &ws.inptg});
      ws.patches = std::move(s.patches);
      ws.intpn = std::move(s.intpn);
      record =
          std::min(record, bench::best_seconds(1, [&] { journal.record(ws, "CHANGE POINTS"); }));
      save = std::min(save, bench::best_seconds(1, [&] { session.save(ws, &journal); }));
    }
    fmt::print("journal_200_change_points_100x100_steps {}\n", journal.undo_count());
    fmt::print("journal_200_change_points_100x100_memory_bytes {}\n", journal.bytes());
    fmt::print("journal_record_change_point_us {:.1f}\n", record * 1e6);
    fmt::print("autosave_change_point_with_journal_ms {:.3f}\n", save * 1e3);
    double undo = 1e300;
    for (int r = 0; r < 5; ++r) {
      undo = std::min(undo, bench::best_seconds(1, [&] { journal.undo(ws); }));
      session.save(ws, &journal);
    }
    fmt::print("undo_change_point_100x100_int10_ms {:.3f}\n", undo * 1e3);
  }
  std::ifstream in(folder.path / "BINSAVE.IGDSCONT", std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto table = disk::decode_session(disk::unframe("IGDSCONT", file).payload);
  fmt::print("journal_200_change_points_100x100_disk_bytes {}\n", table.journal.size());
  fmt::print("session_file_with_journal_bytes {}\n", file.size());
  double load = bench::best_seconds(5, [&] {
    Session session(disk);
    Workspace loaded = session.load();
    if (session.take_journal(loaded).undo_count() != 195) fmt::print("journal: wrong steps\n");
  });
  fmt::print("session_load_with_journal_100x100_int10_ms {:.3f}\n", load * 1e3);
  // The same autosave without a journal, for comparison.
  {
    Session session(disk);
    Workspace loaded = session.load();
    session.save(loaded);
    for (int c = 0; c < 20; ++c) {
      loaded.inppn.ravel[2] = c;
      Edits points = Edits::none();
      points.part(0, 3);
      loaded.changes.edited(points, Edits::none());
      save_without = std::min(save_without, bench::best_seconds(1, [&] { session.save(loaded); }));
    }
  }
  fmt::print("autosave_change_point_without_journal_ms {:.3f}\n", save_without * 1e3);
}

IGDS_BENCH("cards") {
  const Workspace fine = surface(10, 10);  // INTPN 1090 x 1090 x 3
  std::size_t overflow = 0, bytes = 0;
  double s = bench::best_seconds(5, [&] { bytes = disk::char_cards(fine, &overflow).size(); });
  fmt::print("cards_100x100_int10_bytes {}\n", bytes);
  fmt::print("cards_100x100_int10_ms {:.1f}\n", s * 1e3);
  fmt::print("cards_100x100_int10_mb_per_s {:.0f}\n", double(bytes) / s / 1e6);
}
