// Dates as the exchange files write them, from a moment the caller gives: the writers never read
// the clock themselves, so that their files can be compared byte for byte.
#pragma once

#include <string>

namespace igds {

struct Timestamp {
  int year = 1975, month = 1, day = 1, hour = 0, minute = 0, second = 0;
};
// "22 SEP 1987 09:55:50", the form of DUCT's header line.
std::string duct_date(const Timestamp& t);
// "19870922.095550", IGES's global section.
std::string iges_date(const Timestamp& t);
// "1987-09-22T09:55:50", STEP's FILE_NAME.
std::string iso_date(const Timestamp& t);

}  // namespace igds
