// libFuzzer target of the conversation on a whole command file (interp/interpreter.h): the line
// parser, the number reader, every command and question, the APL environment after END APL, the
// automatic save. The first byte chooses the terminal mode (none, tek); the rest are the lines.
// Whatever they say, igds answers each with READY or a report and never stops otherwise, and the
// session it saves reads back as the workspace it had. Seeds: tests/fuzz/corpus/session (the
// examples' command files).
//   scripts/fuzz 300 session
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "interp/interpreter.h"
#include "interp/terminal.h"
#include "tests/fuzz/fuzz.h"
#include "tests/support/scripted.h"
#include "workspace/disk/session.h"
#include "workspace/variables.h"

namespace fs = std::filesystem;

namespace igds::fuzz {

int session(const std::uint8_t* data, std::size_t size) {
  using namespace igds;
  if (size == 0) return 0;
  const fs::path& dir = scratch("session");
  empty(dir);

  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  test::ScriptedSource lines(false, true);
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.add_line(std::string(text.substr(at, end - at)));
    at = end + 1;
  }
  test::StringOutput out;
  Options options;
  options.disk = dir;
  options.term = data[0] % 2 ? TermMode::tek : TermMode::none;
  Disk disk(dir);
  Workspace kept;
  {
    Session session(disk);
    Terminal terminal(options.term, options.tek, out);
    Interpreter interpreter(options, disk, session, session.load(), terminal);
    terminal.use_input(&lines);
    terminal.begin();
    interpreter.converse();
    interpreter.save();
    kept = interpreter.workspace();
    if (!interpreter.saved()) std::abort();  // the scratch disk has room
  }
  // Whatever was typed, nothing that is not a finite number entered the workspace.
  if (surface_problem(kept) || finite_problem(Variable::patches, kept.patches) ||
      finite_problem(Variable::intpn, kept.intpn))
    std::abort();
  const Variable slots[] = {Variable::image, Variable::temp1, Variable::temp2};
  const ImageRef* images[] = {&kept.image, &kept.temp1, &kept.temp2};
  for (int k = 0; k < 3; ++k)
    if (*images[k] && images[k]->made() && image_problem(**images[k], slots[k])) std::abort();
  Session again(disk);
  if (!same_workspace(again.load(), kept)) std::abort();
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(session)
