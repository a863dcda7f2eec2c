// The session on the disk: BINSAVE.IGDSCONT saved after every change, restored at start (the
// manual's AUTONSAVE and INIT), and the lock that keeps one igds per disk.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "workspace/disk/disk.h"
#include "workspace/state.h"

namespace igds {

class Session {
 public:
  // Takes the disk's lock. Throws Report naming the process that holds it when another live
  // igds uses the disk; a lock left by a dead process is taken over (see notices()).
  explicit Session(const Disk& disk);
  ~Session();  // releases the lock
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // INIT: the saved session, or an empty workspace the very first time. A damaged, truncated,
  // foreign or newer file is never half-loaded: it is kept aside under a new name, the
  // workspace starts empty, and notices() says what happened.
  Workspace load();

  // AUTONSAVE: makes `ws` the session on disk, crash-safely (old or new, never torn), writing
  // only what changed since the last save or load. Throws Report when the disk refuses; the
  // previous session stays on disk.
  void save(const Workspace& ws);

  // What load() and the lock had to tell the user, in IGDS style, to print before READY.
  const std::vector<std::string>& notices() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace igds
