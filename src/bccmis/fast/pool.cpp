// bccmis::fast: the pools' blocks (spec/lattice3d.md §9.8).
#include "bccmis/fast/pool.h"

#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace bccmis::fast::detail {

namespace {

constexpr std::align_val_t kAlign{64};
constexpr std::size_t kPage = 4096;

#if defined(__linux__)
// The test hook of pool.h: true when this mmap / mremap is to fail.
bool injected_failure() {
  long left = pool_map_countdown.load(std::memory_order_relaxed);
  while (left >= 0) {
    if (pool_map_countdown.compare_exchange_weak(left, left == 0 ? -1 : left - 1, std::memory_order_relaxed))
      return left == 0;
  }
  return false;
}

// Huge pages for the whole mapping (the lattice's other arrays' rule,
// fast::detail::advise_huge_pages, from 4 MiB up), never for part of it: a
// part would split the mapping, and mremap moves only a range inside one
// mapping (it fails with EFAULT otherwise).
void advise_whole_mapping(void* p, std::size_t bytes) {
#if defined(MADV_HUGEPAGE)
  if (bytes >= (std::size_t{4} << 20)) madvise(p, bytes, MADV_HUGEPAGE);  // advice only: errors ignored
#else
  (void)p;
  (void)bytes;
#endif
}

void* map(std::size_t bytes) {
  if (injected_failure()) throw std::bad_alloc();
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  return p;
}
#endif

}  // namespace

void* pool_grow(void* old, std::size_t old_bytes, std::size_t used, std::size_t& bytes) {
#if defined(__linux__)
  if (pool_block_is_mapped(bytes)) {
    bytes = (bytes + kPage - 1) & ~(kPage - 1);
    void* p = nullptr;
    if (pool_block_is_mapped(old_bytes)) {
      // §9.8: the pages move, not their bytes; on failure the old mapping stays.
      if (injected_failure()) throw std::bad_alloc();
      p = mremap(old, old_bytes, bytes, MREMAP_MAYMOVE);
      if (p == MAP_FAILED) throw std::bad_alloc();
    } else {
      p = map(bytes);
      if (used != 0) std::memcpy(p, old, used);
      pool_free(old, old_bytes);
    }
    advise_whole_mapping(p, bytes);
    return p;
  }
#endif
  void* p = ::operator new(bytes, kAlign);  // may throw: old untouched
  if (used != 0) std::memcpy(p, old, used);
  pool_free(old, old_bytes);
  return p;
}

void pool_free(void* block, std::size_t bytes) noexcept {
  if (block == nullptr) return;
#if defined(__linux__)
  if (pool_block_is_mapped(bytes)) {
    munmap(block, bytes);
    return;
  }
#endif
  ::operator delete(block, kAlign);
}

}  // namespace bccmis::fast::detail
