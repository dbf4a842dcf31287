// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <memory>

#include "core/FunctionRef.h"

namespace stroma {

/// The threads a scene's element loops may use (`stroma run --threads N`; default: all cores),
/// a TBB arena of that size. Loops write per index or per element and reduce in a fixed order,
/// so results do not depend on scheduling or on the thread count.
class ThreadPool {
 public:
  /// 0 means all cores.
  explicit ThreadPool(int threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threadCount() const { return m_threads; }

  /// Calls body(begin, end) on disjoint ranges covering [0, n), in parallel when n is large
  /// enough to pay for it (more than `grain` items per task). The body is referenced, not
  /// copied: a loop allocates nothing, whatever its lambda captures.
  void parallelFor(std::size_t n, std::size_t grain,
                   FunctionRef<void(std::size_t, std::size_t)> body) const;

 private:
  struct Arena;
  int m_threads;
  std::unique_ptr<Arena> m_arena;
};

}  // namespace stroma
