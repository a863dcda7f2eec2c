// Golden files (tests/golden/): a stream compared byte for byte with its file. When they differ
// the message shows the first record that differs, expected and actual, with control bytes
// written as \xNN (records: lines of a text; HP-GL instructions; the runs of a Tek stream
// between its mode bytes). IGDS_UPDATE_GOLDEN=1 rewrites the file and says what changed.
#pragma once

#include <string>
#include <string_view>

namespace igds::test {

// The first record where `expected` and `actual` differ, both shown; "" when they are equal.
std::string first_difference(std::string_view expected, std::string_view actual);

// Checks `bytes` against tests/golden/`name` (or rewrites it, see above).
void check_golden(const std::string& name, const std::string& bytes);

}  // namespace igds::test
