#include "commands/file_name.h"

#include "workspace/disk/disk.h"
#include "workspace/error.h"

namespace igds {

std::string ask_file_name(Context& ctx, const Prompt& prompt) {
  std::vector<std::string> words;
  while (words.empty()) words = ctx.ask(prompt);
  auto name = words.size() == 1 ? cms_name(words[0]) : std::nullopt;
  if (!name) throw Report(reports::incorrect_parameter);
  return *name;
}

}  // namespace igds
