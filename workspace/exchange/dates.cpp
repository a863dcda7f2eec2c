#include "workspace/exchange/dates.h"

#include <fmt/format.h>

namespace igds {

namespace {
constexpr const char* month_names[] = {"JAN", "FEB", "MAR", "APR", "MAY", "JUN",
                                       "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"};
}

std::string duct_date(const Timestamp& t) {
  const char* month = t.month >= 1 && t.month <= 12 ? month_names[t.month - 1] : "???";
  return fmt::format("{:02} {} {:04} {:02}:{:02}:{:02}", t.day, month, t.year, t.hour, t.minute,
                     t.second);
}

std::string iges_date(const Timestamp& t) {
  return fmt::format("{:04}{:02}{:02}.{:02}{:02}{:02}", t.year, t.month, t.day, t.hour, t.minute,
                     t.second);
}

std::string iso_date(const Timestamp& t) {
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}", t.year, t.month, t.day, t.hour,
                     t.minute, t.second);
}

}  // namespace igds
