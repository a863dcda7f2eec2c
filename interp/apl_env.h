// END APL (manual 4.8 and 7.2; spec igds.md section 6): an APL\360 session (interp/apl) in which
// the IGDS globals are APL variables, read and assigned, and the manual's functions (FIT, COONS,
// ASSON, CONIC, ISOM, ORTHOG, DESCR, LUT, the COMxxx command functions, START) call the code
// that does that work in igds. Assignments are checked for their kind and rank at once and
// against each other at START, which recomputes what depends on changed inputs or refuses with
// the reason and stays in APL (docs/interp.md, "END APL").
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "interp/apl/apl_session.h"
#include "workspace/kernels/array.h"
#include "workspace/state.h"

namespace igds {

inline constexpr std::string_view apl_prompt = "      ";

// A workspace variable by its name (any case): NOCUR NOSTR INTCU INTST INPPN INPTG PATCHES
// INTPN IMAGE DESIM TEMP1 DEST1 TEMP2 DEST2 STATUS. nullopt when there is no such variable or
// it has no value (no current image, no stored copy): VALUE ERROR, as for an unassigned name.
std::optional<Array> workspace_variable(const Workspace& ws, std::string_view name);

// The variables that have a value, in alphabetical order (as )VARS lists them).
std::vector<std::string> defined_variables(const Workspace& ws);

class AplEnvironment final : public apl::Host {
 public:
  // What the environment needs of the conversation around it.
  struct Hooks {
    std::function<void(std::string_view)> say;     // a line of output
    std::function<void(std::string_view)> report;  // an error report (counted for --strict)
    std::function<std::optional<std::string>(std::string_view)> read;  // ⎕ and ⍞ input
    // Runs an IGDS command line (COMDIS 'SURFACE ISOMETRIC 3 30' runs DISPLAY ...).
    std::function<void(const std::vector<std::string>&)> command;
    // )SAVE and )LOAD NAME: SAVE and RESTORE of NAME.IGDSDATA; the line to print.
    std::function<std::string(std::string_view)> save, load;
  };

  AplEnvironment(Workspace& ws, Hooks hooks);

  // One line typed at the six-blank prompt.
  apl::AplSession::Next execute(std::string_view line);
  std::string prompt() const { return session_.prompt(); }
  // START: the workspace made whole again after what APL assigned (PATCHES and INTPN made again
  // from changed inputs), or the reason it cannot be, in which case the environment stays.
  std::optional<std::string> start();
  // Names completion offers: variables, functions, system commands.
  std::vector<std::string> names() const;
  // Ctrl-C while a statement runs.
  void interrupt() { session_.interrupt(); }
  // The workspace may have changed outside APL (commands ran since the last line).
  void forget() { values_.clear(); }

  // apl::Host
  void print(std::string_view line) override;
  std::optional<std::string> read_line(std::string_view prompt) override;
  bool owns(std::string_view name) const override;
  std::optional<apl::Value> get(std::string_view name) override;
  void check(std::string_view name, const apl::Value& value) override;
  void set(std::string_view name, const apl::Value& value) override;
  std::vector<std::string> variable_names() const override;
  std::string save_workspace(std::string_view name) override;
  std::string load_workspace(std::string_view name) override;

 private:
  void define_manual_functions();

  Workspace& ws_;
  Hooks hooks_;
  apl::AplSession session_;
  std::set<std::string> assigned_;  // the IGDS globals assigned since the last START
  // The globals as APL values, made once while APL runs: a statement on INTPN then costs the
  // statement, not a copy of INTPN.
  std::map<std::string, apl::Value, std::less<>> values_;
};

}  // namespace igds
