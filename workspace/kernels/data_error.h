// Data a kernel cannot work with. what() is a report in IGDS style, in capitals, naming the
// point, e.g. "INCORRECT ENTRY: POINT 5 IS NOT A FINITE NUMBER".
#pragma once

#include <stdexcept>

namespace igds {

struct DataError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace igds
