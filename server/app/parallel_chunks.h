#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace strahler::app {

/// Runs work(first, last) over [begin, end) in chunks of `chunk` on `threads` threads, the
/// calling one among them, and returns when every chunk is done. Chunks are handed out in
/// order; work that writes only its own range gives the same result for any thread count.
template <class Work> void forChunks(int begin, int end, int chunk, int threads, Work&& work) {
  std::atomic<int> next{begin};
  auto run = [&] {
    for (int first = next.fetch_add(chunk); first < end; first = next.fetch_add(chunk))
      work(first, std::min(end, first + chunk));
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back(run);
  run();
  for (std::thread& t : pool)
    t.join();
}

} // namespace strahler::app
