// libFuzzer target of the conversation on a whole command file (interp/interpreter.h): the line
// parser, the number reader, every command and question, the APL environment after END APL, the
// automatic save. The first byte chooses the terminal mode (none, tek); the rest are the lines.
// Whatever they say, igds answers each with READY or a report and never stops otherwise, and the
// session it saves reads back as the workspace it had. Seeds: tests/fuzz/corpus/session (the
// examples' command files).
//   cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DIGDS_FUZZ=ON
//   cmake --build build-fuzz --target fuzz_session
//   build-fuzz/tests/fuzz_session -max_total_time=300 fuzz-work tests/fuzz/corpus/session
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "interp/interpreter.h"
#include "interp/terminal.h"
#include "tests/support/scripted.h"
#include "workspace/disk/session.h"

namespace fs = std::filesystem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace igds;
  if (size == 0) return 0;
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("igds-fuzz-session-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());

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
  Session again(disk);
  if (!(again.load() == kept)) std::abort();
  return 0;
}
