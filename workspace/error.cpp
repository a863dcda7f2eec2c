#include "workspace/error.h"

namespace igds {

Error::Error(std::string_view words, std::string_view reason)
    : line_(reason.empty() ? std::string(words) : std::string(words) + ": " + std::string(reason)),
      reason_(reason) {}

}  // namespace igds
