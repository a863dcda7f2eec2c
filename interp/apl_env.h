// END APL (manual 4.8 and section 7; docs/interp.md, "END APL"): an APL\360 session
// (interp/apl) in which the IGDS globals are APL variables, read and assigned, and the functions
// of the manual's workspace IGDS4013 (section 7) call the code that does that work in igds.
// Assignments to the globals are checked for their kind at once and against each other at
// START, which makes again what depends on changed inputs or refuses with the reason and stays
// in APL.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "interp/apl/apl_session.h"
#include "workspace/drawing/drawing.h"
#include "workspace/kernels/array.h"
#include "workspace/state.h"

namespace igds {

class Disk;
struct Command;
namespace disk {
struct AplWorkspace;
}

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
    std::function<void(std::string_view)> say;       // a line of output
    std::function<void(std::string_view)> report;    // an error report (counted for --strict)
    std::function<void(std::string_view)> document;  // a long text (paged)
    std::function<std::optional<std::string>(std::string_view)> read;  // ⎕, ⍞, ALFINP input
    // Runs an IGDS command line (COMDIS 'SURFACE ISOMETRIC 3 30' runs DISPLAY ...); false when
    // the command reported an error.
    std::function<bool(const std::vector<std::string>&)> command;
    // The session on the disk (AUTOMSAVE): saved now; the report, or empty.
    std::function<std::string()> save_session;
    // The workspace the session on the disk holds (RESTORE); nullopt, said, when it cannot be.
    std::function<std::optional<Workspace>()> load_session;
    // IMAGE on the screen, as DISPLAY shows it (DISPLA).
    std::function<void(const ImageRef&)> show;
    // A picture on the screen (TEKG, TEKP, TEKV, TEKC), with its one-line description.
    std::function<void(const Picture&, std::string_view)> draw;
    // A picture on the plotter, as PLOT sends one (PLOTG, PLOTP, PLOTV).
    std::function<void(const Picture&)> plot;
    // The disk (STATE, WRT, )SAVE, )LOAD, )COPY); null: none.
    const Disk* disk = nullptr;
  };

  AplEnvironment(Workspace& ws, Hooks hooks);

  // One line typed at the six-blank prompt.
  apl::AplSession::Next execute(std::string_view line);
  std::string prompt() const { return session_.prompt(); }
  // START: the workspace made whole again after what APL assigned (what depends on a changed
  // variable made again from it: PATCHES from the inputs, INTPN from PATCHES), or the reason it
  // cannot be, in which case the environment stays.
  std::optional<std::string> start();
  // No IGDS variable assigned since the last START: the workspace is whole, and may be saved.
  bool settled() const { return assigned_.empty(); }
  // Names completion offers: variables, functions, system commands.
  std::vector<std::string> names() const;
  // The workspace may have changed outside APL (commands ran since the last line).
  void forget() { values_.clear(); }
  // The explanation of the APL environment (HELP at END APL's question, )HELP).
  static std::string help(bool long_text);

  // apl::Host
  void print(std::string_view line) override;
  std::optional<std::string> read_line(std::string_view prompt) override;
  bool owns(std::string_view name) const override;
  std::optional<apl::Value> get(std::string_view name) override;
  void check(std::string_view name, const apl::Value& value) override;
  void set(std::string_view name, const apl::Value& value) override;
  std::vector<std::string> variable_names() const override;
  std::string heading() const override { return "IGDS"; }
  std::vector<std::string> save_workspace(std::string_view name) override;
  std::vector<std::string> load_workspace(std::string_view name) override;
  std::vector<std::string> copy_workspace(std::string_view name,
                                          const std::vector<std::string>& names) override;

 private:
  using Args = const apl::Value*;
  void define_manual_functions();
  void define_line_functions();
  void define_disk_functions();
  void define_device_functions();
  void define_dialogue_functions();
  // Runs an IGDS command from APL, the workspace made whole first; DOMAIN ERROR with the
  // command's report when it fails.
  void run_command(std::vector<std::string> words);
  // The workspace as APL values again, and nothing pending for START (the surface was replaced).
  void surface_replaced();
  // The user's variables into the workspace (Workspace::apl_variables), when they changed.
  void keep_variables();
  // )LOAD and )COPY: the functions and variables of `from` (those `wanted`, all when empty) into
  // the session, replacing those of the same names; `found` gets the names taken. Returns the
  // names that could not be taken.
  std::vector<std::string> take(const disk::AplWorkspace& from, const std::set<std::string>& wanted,
                                std::set<std::string>& found);
  // A line read for ALFINP and NUMINP: HELP there is answered (EXPL) and the line read again.
  std::string read_answer(int code);
  // The codes of a command's words (PARxx, GETCOM), its option asked when it is missing.
  std::vector<double> codes_of(const Command& command, std::vector<std::string> words);
  void explain(int code, bool long_text);

  Workspace& ws_;
  Hooks hooks_;
  apl::AplSession session_;
  std::set<std::string> assigned_;  // the IGDS globals assigned since the last START
  // The surface's modes (STATUS[3] twists, STATUS[4] AUTO mark) before the first assignment of
  // STATUS since the last START: a change of them is a change of the surface.
  std::optional<std::pair<bool, bool>> modes_before_;
  // The globals as APL values, made once while APL runs: a statement on INTPN then costs the
  // statement, not a copy of INTPN.
  std::map<std::string, apl::Value, std::less<>> values_;
  std::uint64_t kept_version_ = 0;  // of the variables in ws_.apl_variables
  std::size_t kept_bytes_ = 0;      // what they take in the session file
  std::set<std::string> not_kept_;  // too large for the session, said once
};

}  // namespace igds
