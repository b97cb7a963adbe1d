#include "strahler/landscape/depressions.h"

#include <cmath>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace strahler::landscape {

void fillDepressions(LatticeGrid<double>& heights, const LatticeGrid<NodeRole>& roles,
                     double epsilon) {
  const int w = heights.columns, h = heights.rows;
  std::vector<std::uint8_t> closed(heights.size(), 0);
  using Entry = std::pair<double, std::size_t>; // (height, index): ties broken by index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto isFixed = [&](std::size_t i) { return roles.values[i] != NodeRole::kFree; };
  // Seed with the fixed nodes that touch free land (the others never matter), and close every
  // fixed node.
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const std::size_t i = heights.at(c, r);
      if (!isFixed(i))
        continue;
      closed[i] = 1;
      bool touches = false;
      for (int dr = -1; dr <= 1 && !touches; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int cc = c + dc, rr = r + dr;
          if (cc >= 0 && rr >= 0 && cc < w && rr < h && !isFixed(heights.at(cc, rr))) {
            touches = true;
            break;
          }
        }
      if (touches)
        open.push({heights.values[i], i});
    }
  while (!open.empty()) {
    const auto [z, i] = open.top();
    open.pop();
    const int c = static_cast<int>(i % static_cast<std::size_t>(w));
    const int r = static_cast<int>(i / static_cast<std::size_t>(w));
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int cc = c + dc, rr = r + dr;
        if ((dc != 0) == (dr != 0) || cc < 0 || rr < 0 || cc >= w || rr >= h)
          continue; // the four edge neighbours only (see the header)
        const std::size_t n = heights.at(cc, rr);
        if (closed[n])
          continue;
        closed[n] = 1;
        if (heights.values[n] < z + epsilon)
          heights.values[n] = z + epsilon;
        open.push({heights.values[n], n});
      }
  }
}

} // namespace strahler::landscape
