// libFuzzer target of the session as a whole, structure-aware (docs/disk.md, "The session" and
// "The undo journal"): the input is a disk, a session file and the variable files it may name,
// each framed as igds frames it; the mutator changes a valid session record by record (a count,
// a shape, a piece of a blob, an image's kind or view, STATUS, a field of the undo journal) and
// keeps the frames and, when the input asks, the session's references to its files holding, so
// that every mutation reaches the checks of meaning. The session is loaded, its journal undone
// and redone to its ends with a save after each step, saved and loaded again: whatever the
// files say, igds refuses them or works with what it accepts, never crashes, never keeps a
// number that is not finite. Seeds: tests/fuzz/corpus/records (sessions made by igds).
//   scripts/fuzz 300 records
//
// The input: a byte of flags (1: make the session's references name its files' true lengths and
// checksums), then files, each a kind byte (0 the session's payload, 1 a variable file's payload,
// 2 the copy of an image file's payload), its number (u32, for variable files) and its length
// (u32), then its bytes. A file cut short ends the input.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "tests/fuzz/fuzz.h"
#include "tests/fuzz/records.h"
#include "workspace/disk/session.h"
#include "workspace/disk/session_file.h"
#include "workspace/error.h"
#include "workspace/journal.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/limits.h"
#include "workspace/variables.h"

namespace fs = std::filesystem;

namespace igds::fuzz {

namespace {

// Nothing the workspace holds is other than what it accepts (images that are made only).
void check_accepted(const Workspace& ws) {
  if (surface_problem(ws, true) || status_problem(ws.status) ||
      finite_problem(Variable::patches, ws.patches) || finite_problem(Variable::intpn, ws.intpn))
    std::abort();
  const std::array<const ImageRef*, 3> images{&ws.image, &ws.temp1, &ws.temp2};
  const std::array<Variable, 3> slots{Variable::image, Variable::temp1, Variable::temp2};
  for (std::size_t k = 0; k < 3; ++k)
    if (*images[k] && images[k]->made() && image_problem(**images[k], slots[k])) std::abort();
}

ImageRef& slot(Workspace& ws, Variable v) {
  return v == Variable::image ? ws.image : v == Variable::temp1 ? ws.temp1 : ws.temp2;
}

// A save that must not fail on the scratch disk; the images it kept out are none from then on.
void save(Session& session, Workspace& ws, const Journal* journal) {
  for (const UnsavedImage& u : session.save(ws, journal)) slot(ws, u.slot) = nullptr;
}

}  // namespace

namespace {

// True when the session of `in` has only small surfaces in its records (fuzz.h).
bool small_records(const RecordsInput& in) {
  return std::all_of(in.files.begin(), in.files.end(),
                     [](const RecordsFile& f) { return f.kind != 0 || small_session(f.payload); });
}

}  // namespace

int records(const std::uint8_t* data, std::size_t size) {
  const RecordsInput in = read_records(data, size);
  if (!small_records(in)) return 0;
  const fs::path& dir = scratch("records");
  empty(dir);
  write_records(dir, in);
  Disk disk(dir);
  Workspace ws;
  {
    Session session(disk);
    ws = session.load();
    check_accepted(ws);
    Journal journal = session.take_journal(ws);
    // The journal to its start and to its end, the session saved after every step as igds does.
    for (const bool back : {true, false}) {
      for (int step = 0; step < 300; ++step) {
        // The state the step goes to: made (interpolated) only when small.
        const std::size_t at = journal.position();
        if (back ? at == 0 : at == journal.steps().size()) break;
        const Settings& to = back ? journal.steps()[at - 1].before : journal.steps()[at].after;
        if (!small(to.nocur, to.nostr, to.intcu, to.intst)) break;
        try {
          const auto name = back ? journal.undo(ws) : journal.redo(ws);
          if (!name) break;
        } catch (const DataError&) {
          break;  // a state that does not interpolate: refused, the workspace as it was
        }
        check_accepted(ws);
        try {
          save(session, ws, &journal);
        } catch (const Report&) {
          std::abort();  // the scratch disk takes every save
        }
      }
    }
    save(session, ws, &journal);
  }
  Session again(disk);
  const Workspace back = again.load();
  if (!again.notices().empty()) finding("a saved session read back with: " + again.notices()[0]);
  if (!same_workspace(back, ws)) finding("a saved session read back is not the workspace saved");
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(records)

#ifndef IGDS_FUZZ_REPLAY
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned seed) {
  return igds::fuzz::mutate_records(data, size, max_size, seed);
}
#endif
