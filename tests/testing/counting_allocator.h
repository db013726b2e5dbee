// The counting and failing global allocator of the tests and benchmarks that
// watch the heap: a replaced global operator new and delete (every form:
// plain, array, aligned, nothrow) over malloc, which
//   - counts the live bytes (malloc_usable_size of every live block), always;
//   - counts the allocations while `counting` is set (allocations_during);
//   - fails an allocation on request: with `countdown` = k >= 0, k more
//     allocations succeed and the next one throws std::bad_alloc (the nothrow
//     forms return nullptr), after which the countdown is disarmed (-1).
//
// The header DEFINES the replacement functions: include it from exactly one
// translation unit of an executable, and give that executable to this purpose
// alone (every allocation of the process goes through it). A second
// inclusion in the same executable fails to link (multiple definition).
// Users: tests/fast/alloc_test.cpp, tests/fast/d3/alloc_test.cpp,
// tests/robustness_alloc_test.cpp, tests/testing/fault_injection.h (the
// exception-safety tests), bench/bench_memory.cpp, bench/d3/bench_memory.cpp.
#pragma once

#include <malloc.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace bccmis::testing::alloc {

/// Allocations left before the injected failure; negative: none armed.
inline long countdown = -1;
/// Failures injected so far.
inline long failures = 0;
/// While true, every allocation (failed ones included) adds one to `allocations`.
inline bool counting = false;
inline long allocations = 0;
/// Usable bytes of the blocks allocated and not yet freed.
inline std::atomic<std::size_t> live_bytes{0};

/// Counts the allocations made while f runs.
template <class F>
long allocations_during(F&& f) {
  allocations = 0;
  counting = true;
  f();
  counting = false;
  return allocations;
}

/// Runs op with the k-th allocation from now failing (k = 0: the first);
/// true when op threw std::bad_alloc. The countdown is disarmed afterwards,
/// also when op throws anything else (which propagates).
template <class Op>
bool fails_at(long k, Op&& op) {
  countdown = k;
  try {
    op();
  } catch (const std::bad_alloc&) {
    countdown = -1;
    return true;
  } catch (...) {
    countdown = -1;
    throw;
  }
  countdown = -1;
  return false;
}

namespace detail {

/// Counts, then throws if the countdown reaches the allocation.
inline void before_allocation() {
  if (counting) ++allocations;
  if (countdown == 0) {
    countdown = -1;
    ++failures;
    throw std::bad_alloc();
  }
  if (countdown > 0) --countdown;
}

inline void* allocate(std::size_t n) {
  before_allocation();
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  live_bytes += malloc_usable_size(p);
  return p;
}

inline void* allocate_aligned(std::size_t n, std::align_val_t a) {
  before_allocation();
  std::size_t align = static_cast<std::size_t>(a);
  if (align < sizeof(void*)) align = sizeof(void*);
  const std::size_t size = n ? n : 1;
  void* p = std::aligned_alloc(align, (size + align - 1) / align * align);
  if (!p) throw std::bad_alloc();
  live_bytes += malloc_usable_size(p);
  return p;
}

inline void* allocate_nothrow(std::size_t n) noexcept {
  try {
    return allocate(n);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

inline void* allocate_aligned_nothrow(std::size_t n, std::align_val_t a) noexcept {
  try {
    return allocate_aligned(n, a);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

inline void deallocate(void* p) noexcept {
  if (!p) return;
  live_bytes -= malloc_usable_size(p);
  std::free(p);
}

}  // namespace detail
}  // namespace bccmis::testing::alloc

// clang-format off
void* operator new(std::size_t n) { return bccmis::testing::alloc::detail::allocate(n); }
void* operator new[](std::size_t n) { return bccmis::testing::alloc::detail::allocate(n); }
void* operator new(std::size_t n, std::align_val_t a) { return bccmis::testing::alloc::detail::allocate_aligned(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return bccmis::testing::alloc::detail::allocate_aligned(n, a); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return bccmis::testing::alloc::detail::allocate_nothrow(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return bccmis::testing::alloc::detail::allocate_nothrow(n); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept { return bccmis::testing::alloc::detail::allocate_aligned_nothrow(n, a); }
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept { return bccmis::testing::alloc::detail::allocate_aligned_nothrow(n, a); }
void operator delete(void* p) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete[](void* p) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete(void* p, std::size_t) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete[](void* p, std::size_t) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete(void* p, std::align_val_t) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete[](void* p, std::align_val_t) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { bccmis::testing::alloc::detail::deallocate(p); }
// clang-format on
