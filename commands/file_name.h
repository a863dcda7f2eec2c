// The name of a file on the disk, as RESTORE, SAVE, WRITE, STORE FILE, DISPLAY FILE and EXPORT
// take it: from the command line, or asked for.
#pragma once

#include <string>

#include "commands/context.h"

namespace igds {

// The CMS name (in capitals) of the next reply to `prompt`; an empty reply asks again. Throws
// Report(INCORRECT PARAMETER) unless the reply is exactly one valid CMS name.
std::string ask_file_name(Context& ctx, const Prompt& prompt);

}  // namespace igds
