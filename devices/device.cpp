#include "devices/device.h"

#include <cstring>

namespace igds {

void DeviceBox::add(std::span<const DevicePoint> points) {
  using Pairs = int __attribute__((vector_size(16)));  // x, y, x, y
  Pairs low[2], high[2];
  low[0] = low[1] = Pairs{x0, y0, x0, y0};
  high[0] = high[1] = Pairs{x1, y1, x1, y1};
  const std::size_t n = points.size();
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4)
    for (int c = 0; c < 2; ++c) {
      Pairs p;
      std::memcpy(&p, points.data() + i + 2 * c, sizeof p);
      low[c] = p < low[c] ? p : low[c];
      high[c] = p > high[c] ? p : high[c];
    }
  low[0] = low[1] < low[0] ? low[1] : low[0];
  high[0] = high[1] > high[0] ? high[1] : high[0];
  x0 = std::min(low[0][0], low[0][2]), y0 = std::min(low[0][1], low[0][3]);
  x1 = std::max(high[0][0], high[0][2]), y1 = std::max(high[0][1], high[0][3]);
  for (; i < n; ++i) {
    x0 = std::min(x0, points[i].x), x1 = std::max(x1, points[i].x);
    y0 = std::min(y0, points[i].y), y1 = std::max(y1, points[i].y);
  }
}

}  // namespace igds
