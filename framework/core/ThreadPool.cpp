// SPDX-License-Identifier: MIT
#include "core/ThreadPool.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace stroma {

struct ThreadPool::Arena {
  explicit Arena(int threads) : arena(threads) {}
  tbb::task_arena arena;
};

ThreadPool::ThreadPool(int threads)
    : m_threads(threads > 0 ? threads : tbb::info::default_concurrency()),
      m_arena(std::make_unique<Arena>(m_threads)) {}

ThreadPool::~ThreadPool() = default;

void ThreadPool::parallelFor(std::size_t n, std::size_t grain,
                             FunctionRef<void(std::size_t, std::size_t)> body) const {
  if (n == 0) return;
  if (m_threads <= 1 || n <= grain) {
    body(0, n);
    return;
  }
  m_arena->arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); },
                      tbb::simple_partitioner());
  });
}

}  // namespace stroma
