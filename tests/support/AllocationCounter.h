// SPDX-License-Identifier: MIT
// Counting the allocations of a test program, for the tests that a warm step allocates
// nothing: the global operator new counts while g_counting is set. It replaces operator new
// and delete for the whole program, so include it in exactly one source file of a test
// program (replacement functions cannot be inline).
#pragma once

#include <cstdlib>
#include <new>

inline bool g_counting = false;
inline long g_allocations = 0;

// GCC inlines these next to each other and flags free() of operator new's memory, which is
// this malloc.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t size) {
  if (g_counting) ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
