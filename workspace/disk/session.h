// The session on the disk: BINSAVE.IGDSCONT saved after every change, restored at start (the
// manual's AUTONSAVE and INIT), and the lock that keeps one igds per disk. What is stored and why:
// docs/disk.md.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "workspace/disk/disk.h"
#include "workspace/journal.h"
#include "workspace/kernels/data_error.h"
#include "workspace/state.h"
#include "workspace/variables.h"

namespace igds {

// An image a save had to make to keep it and could not (a recipe its surface does not allow,
// which only a forged session or journal holds): kept out of the session, said once; the
// workspace keeps it as it is (whoever looks at it meets the same error).
struct UnsavedImage {
  Variable slot;  // IMAGE, TEMP1 or TEMP2
  DataError error;
};

class Session {
 public:
  // Takes the disk's lock. Throws Report naming the process that holds it when another live
  // igds uses the disk; a lock left by a dead process is taken over (see notices()).
  explicit Session(const Disk& disk);
  ~Session();  // releases the lock
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // INIT: the saved session, or an empty workspace the very first time. A damaged, truncated,
  // foreign, newer or inconsistent session is never half-loaded: it is kept aside under a new
  // name, the workspace starts empty, and notices() says what happened. Variable files without
  // a session are kept aside too. PATCHES and INTPN, when they are igds's interpolation of the
  // inputs, are not in the session: they are made again here.
  Workspace load();
  // The undo journal load() read with the session (checked; one that is not is refused with a
  // notice and the journal starts again), once: later calls give an empty one.
  Journal take_journal(const Workspace& ws);

  // AUTONSAVE: makes `ws` the session on disk, crash-safely (old or new, never torn), writing
  // only what changed since the last save or load (ws.changes says what; it is reset here once
  // the new session is on disk). Throws Report when the disk refuses; the previous session
  // stays on disk and the next save writes everything since it. The undo `journal` is saved with
  // it (none: the session has none). Returns the images it kept out (see UnsavedImage).
  std::vector<UnsavedImage> save(Workspace& ws, const Journal* journal = nullptr);

  // What load() and the lock had to tell the user, in IGDS style, to print before READY.
  const std::vector<std::string>& notices() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace igds
