// The sizes igds accepts for a surface, wherever it comes from (BUILD, CHANGE, RESTORE, the
// session, the APL environment, the importers): limits that keep a typing slip or a crafted file
// from asking for gigabytes.
#pragma once

#include <cstddef>

namespace igds {

// Input points (NOCUR x NOSTR) and points of INTPN.
inline constexpr std::size_t max_input_points = 1'000'000;
inline constexpr std::size_t max_grid_points = 4'000'000;

// The points of INTPN for a grid of NOCUR x NOSTR input points and INTCU, INTST (as a double, so
// that no size overflows).
inline double grid_points(double nocur, double nostr, double intcu, double intst) {
  return (nocur + intcu * (nocur - 1)) * (nostr + intst * (nostr - 1));
}

}  // namespace igds
