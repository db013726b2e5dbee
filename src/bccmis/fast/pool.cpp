// bccmis::fast: the pools' blocks (spec/lattice3d.md §9.8).
#include "bccmis/fast/pool.h"

#include <cstdint>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace bccmis::fast::detail {

namespace {

constexpr std::align_val_t kAlign{64};

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

// spec/lattice3d.md §9.10: a block of kPoolHugeBytes and more is whole huge
// pages at a huge-page boundary, advised to use them as a whole (advice on a
// part would split the mapping, and mremap moves only a range inside one
// mapping: it fails with EFAULT otherwise).
void advise_whole_mapping(void* p, std::size_t bytes) {
#if defined(MADV_HUGEPAGE)
  if (bytes >= kPoolHugeBytes) madvise(p, bytes, MADV_HUGEPAGE);  // advice only: errors ignored
#else
  (void)p;
  (void)bytes;
#endif
}

// An anonymous mapping of `bytes` (whole pages) starting at a multiple of
// kPoolHugePage when it is a huge block (§9.10): a mapping one huge page
// longer, trimmed at both ends. `prot` PROT_NONE reserves the range only.
void* map_at_boundary(std::size_t bytes, int prot) {
  const std::size_t slack = bytes >= kPoolHugeBytes ? kPoolHugePage : 0;
  const int flags = MAP_PRIVATE | MAP_ANONYMOUS | (prot == PROT_NONE ? MAP_NORESERVE : 0);
  void* p = mmap(nullptr, bytes + slack, prot, flags, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  if (slack == 0) return p;
  const auto start = reinterpret_cast<std::uintptr_t>(p);
  const auto begin = (start + kPoolHugePage - 1) & ~std::uintptr_t{kPoolHugePage - 1};
  if (begin != start) munmap(p, begin - start);
  if (begin != start + slack) munmap(reinterpret_cast<void*>(begin + bytes), start + slack - begin);
  return reinterpret_cast<void*>(begin);
}

void* map(std::size_t bytes) {
  if (injected_failure()) throw std::bad_alloc();
  return map_at_boundary(bytes, PROT_READ | PROT_WRITE);
}

// §9.8, §9.10: the old mapping grown to `bytes`, its pages moved, not their
// bytes; a huge block stays at a huge-page boundary (grown in place when the
// room above it is free, else moved onto a reserved range at a boundary, so
// that its huge pages move whole). On failure the old mapping stays.
void* remap(void* old, std::size_t old_bytes, std::size_t bytes) {
  if (injected_failure()) throw std::bad_alloc();
  const bool huge = bytes >= kPoolHugeBytes;
  if (!huge || reinterpret_cast<std::uintptr_t>(old) % kPoolHugePage == 0) {
    void* p = mremap(old, old_bytes, bytes, huge ? 0 : MREMAP_MAYMOVE);
    if (p != MAP_FAILED) return p;
    if (!huge) throw std::bad_alloc();
  }
  void* target = map_at_boundary(bytes, PROT_NONE);
  void* p = mremap(old, old_bytes, bytes, MREMAP_MAYMOVE | MREMAP_FIXED, target);
  if (p == MAP_FAILED) {
    munmap(target, bytes);
    throw std::bad_alloc();
  }
  return p;
}
#endif

}  // namespace

void* pool_grow(void* old, std::size_t old_bytes, std::size_t used, std::size_t& bytes) {
#if defined(__linux__)
  if (pool_block_is_mapped(bytes)) {
    bytes = pool_mapped_bytes(bytes);
    void* p = nullptr;
    if (pool_block_is_mapped(old_bytes)) {
      p = remap(old, old_bytes, bytes);
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
