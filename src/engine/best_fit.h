#pragma once
// Choosing a buffer to reuse: the smallest that holds `size` elements (no new pages, no copy),
// else the largest (the fewest new pages). Shared by the sample cache's spare planes and the
// progressive engine's frame pool.
#include <cstddef>

namespace gloss {

// capacity(element) -> std::size_t. Returns end when [begin, end) is empty.
template <class It, class Capacity>
It best_fit(It begin, It end, std::size_t size, Capacity capacity) {
  It best = end;
  for (It it = begin; it != end; ++it) {
    if (best == end) {
      best = it;
      continue;
    }
    const std::size_t have = capacity(*it), best_have = capacity(*best);
    if (have >= size ? (best_have < size || have < best_have) : have > best_have) best = it;
  }
  return best;
}

}  // namespace gloss
