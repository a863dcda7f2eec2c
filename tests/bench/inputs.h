// The surfaces the benchmarks measure on, made once here: a smooth NOCUR x NOSTR grid with its
// border tangents (INPTG in workspace/state.h order).
#pragma once

#include <cmath>
#include <cstddef>

#include "workspace/kernels/array.h"
#include "workspace/kernels/vec3.h"

namespace igds::bench {

struct Input {
  int nocur, nostr;
  Array inppn, inptg;
};

inline Input wavy(int nocur, int nostr) {
  Input in{nocur, nostr, Array({std::size_t(nocur) * nostr, 3}),
           Array({2 * std::size_t(nocur + nostr), 4})};
  auto pts = as_vec3(in.inppn);
  for (int i = 0; i < nocur; ++i)
    for (int j = 0; j < nostr; ++j)
      pts[i * nostr + j] = {j * 1.0, i * 1.5, 10 * std::sin(0.05 * j) * std::cos(0.03 * i)};
  double* t = in.inptg.data();
  for (int r = 0; r < 2 * (nocur + nostr); ++r) {
    bool along_curve = r < 2 * nocur;
    t[4 * r] = along_curve ? 1 : 0, t[4 * r + 1] = along_curve ? 0 : 1, t[4 * r + 2] = 0;
  }
  return in;
}

}  // namespace igds::bench
