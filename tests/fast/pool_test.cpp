// bccmis::fast::Pool (spec/lattice3d.md §9.8, §9.9): growth across the
// switch from heap blocks to mappings keeps every byte, the switch stands at
// exactly 1 MiB, a pool grows 4x below it and by an eighth from it, a failed
// growth (operator new, mmap or mremap) leaves the pool unchanged, copies
// hold the same bytes; a failed mremap inside a refine leaves the lattice
// unchanged; and a block of 4 MiB and more is whole huge pages at a
// huge-page boundary that the kernel was advised to back with them (§9.10,
// read back from /proc/self/smaps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "bccmis/fast/d3/lattice.h"
#include "bccmis/fast/pool.h"

namespace {

using bccmis::fast::Pool;
namespace detail = bccmis::fast::detail;

struct Rec {  // 128 bytes, like a center record
  std::uint64_t w[16];
};

std::uint64_t word(std::size_t i, std::size_t k) { return (i * 0x9E3779B97F4A7C15ull) ^ (k * 0xD6E8FEB86659FD93ull); }

// Every record i holds its own pattern, byte for byte.
::testing::AssertionResult intact(const Pool<Rec>& pool) {
  for (std::size_t i = 0; i < pool.size(); ++i)
    for (std::size_t k = 0; k < 16; ++k)
      if (pool[i].w[k] != word(i, k))
        return ::testing::AssertionFailure() << "record " << i << " word " << k << " of " << pool.size();
  return ::testing::AssertionSuccess();
}

void append(Pool<Rec>& pool, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    Rec& r = pool.emplace_back();
    for (std::size_t k = 0; k < 16; ++k) {
      EXPECT_EQ(r.w[k], 0u);  // value-initialized
      r.w[k] = word(pool.size() - 1, k);
    }
  }
}

// Mapped blocks are whole pages; heap blocks hold exactly what was asked.
constexpr std::size_t kLine = detail::kPoolMapBytes / sizeof(Rec);  // records in 1 MiB

struct Countdown {  // the §9.8 test hook, reset however the test ends
  explicit Countdown(long k) { detail::pool_map_countdown = k; }
  ~Countdown() { detail::pool_map_countdown = -1; }
};

TEST(FastPool, GrowthAcrossTheMapSwitchKeepsEveryByte) {
  // spec/lattice3d.md §9.8: growth by half, from the heap to a mapping at
  // 1 MiB and then by mremap; every record checked after every growth.
  Pool<Rec> pool;
  std::size_t growths = 0, heap_growths = 0, mapped_growths = 0;
  while (pool.size() < 12 * kLine) {  // past 4 MiB too, where the mapping asks for huge pages
    const std::size_t before = pool.capacity();
    append(pool, 1);
    if (pool.capacity() != before) {
      ++growths;
      (pool.capacity() * sizeof(Rec) >= detail::kPoolMapBytes ? mapped_growths : heap_growths) += 1;
      ASSERT_TRUE(intact(pool)) << "after growing to " << pool.capacity();
    }
  }
  EXPECT_GT(heap_growths, 3u);
  EXPECT_GE(mapped_growths, 5u);  // one mmap and a copy, then mremap
  ASSERT_TRUE(intact(pool));
}

TEST(FastPool, TheSwitchStandsAtOneMiB) {
  // spec/lattice3d.md §9.8: below 1 MiB a heap block, at 1 MiB a mapping.
  // With every mapping refused, 1 MiB - 1 record still grows and 1 MiB throws.
  Pool<Rec> below, at;
  append(below, 3);
  append(at, 3);
  const std::size_t capacity = at.capacity();
  const Countdown refuse(0);
  below.reserve(kLine - 1);
  EXPECT_EQ(below.capacity(), kLine - 1);
  EXPECT_THROW(at.reserve(kLine), std::bad_alloc);
  EXPECT_EQ(at.capacity(), capacity);
  EXPECT_TRUE(intact(below));
  EXPECT_TRUE(intact(at));
}

TEST(FastPool, GrowthIsFourfoldOnTheHeapAndAnEighthOnceMapped) {
  // spec/lattice3d.md §9.9: a pool short of room grows to max(need, 4 x
  // capacity) while its block is on the heap, max(need, capacity + capacity
  // / 8) once it is mapped. On the line: 1 MiB - 1 record is a heap block,
  // 1 MiB a mapping.
  Pool<Rec> below, at;
  below.reserve(kLine - 1);
  at.reserve(kLine);
  EXPECT_EQ(below.grown_capacity(kLine), 4 * (kLine - 1));
  EXPECT_EQ(at.grown_capacity(kLine + 1), kLine + kLine / 8);
  // need wins when it is larger.
  EXPECT_EQ(below.grown_capacity(5 * kLine), 5 * kLine);
  EXPECT_EQ(at.grown_capacity(2 * kLine), 2 * kLine);
  Pool<Rec> empty;
  EXPECT_EQ(empty.grown_capacity(3), 3u);
}

TEST(FastPool, AFailedGrowthLeavesThePoolUnchanged) {
  // spec/lattice3d.md §9.8: the first mapping (mmap, from a heap block) and a
  // later one (mremap) refused; the pool keeps its block, size and bytes.
  // heap -> mmap, mapped -> mremap onto a huge block, huge -> huge (§9.10)
  for (const std::size_t records : {kLine / 2, kLine + 5, 5 * kLine}) {
    Pool<Rec> pool;
    append(pool, records);
    const Rec* data = pool.data();
    const std::size_t capacity = pool.capacity();
    {
      const Countdown refuse(0);
      EXPECT_THROW(pool.reserve(std::max(4 * kLine, 2 * records)), std::bad_alloc) << records;
    }
    EXPECT_EQ(pool.data(), data);
    EXPECT_EQ(pool.capacity(), capacity);
    EXPECT_EQ(pool.size(), records);
    EXPECT_TRUE(intact(pool));
    pool.reserve(std::max(4 * kLine, 2 * records));  // and it still grows
    EXPECT_GE(pool.capacity(), std::max(4 * kLine, 2 * records));
    EXPECT_TRUE(intact(pool));
  }
}

TEST(FastPool, CopiesHoldTheSameBytes) {
  for (const std::size_t records : {std::size_t{0}, std::size_t{7}, 2 * kLine + 3}) {
    Pool<Rec> pool;
    append(pool, records);
    Pool<Rec> copy(pool);
    EXPECT_EQ(copy.size(), records);
    EXPECT_TRUE(intact(copy));
    if (records != 0) {
      copy[0].w[0] ^= 1;  // its own block
      EXPECT_TRUE(intact(pool));
    }
    Pool<Rec> assigned;
    append(assigned, 2);
    assigned = pool;
    EXPECT_TRUE(intact(assigned));
    Pool<Rec> moved(std::move(assigned));
    EXPECT_EQ(moved.size(), records);
    EXPECT_TRUE(intact(moved));
  }
}

TEST(FastPool, AFailedMremapLeavesTheLatticeUnchanged) {
  // spec/lattice3d.md §9.8, §9.5: refine grows the pools before it writes.
  // Every refine is first tried with the next mapping refused; the center
  // pool passes 1 MiB (8192 centers) on the way to 16 384 cells, so that
  // fails once at the mmap and then at each mremap, and the refused refine
  // must leave the lattice as its twin, which never fails.
  using bccmis::d3::fast::Lattice;
  Lattice g({4, 4, 2, 3}), twin({4, 4, 2, 3});
  int failures = 0;
  for (int level = 0; level < 3; ++level) {
    for (const bccmis::d3::Point& c : g.cells()) {
      try {
        const Countdown refuse(0);
        ASSERT_TRUE(g.refine(c).applied());
      } catch (const std::bad_alloc&) {
        ++failures;
        ASSERT_TRUE(bccmis::d3::fast::canonical_state(g) == bccmis::d3::fast::canonical_state(twin))
            << "failure " << failures << " changed the lattice";
        ASSERT_FALSE(g.audit());
        ASSERT_TRUE(g.refine(c).applied());
      }
      ASSERT_TRUE(twin.refine(c).applied());
    }
  }
  EXPECT_GE(failures, 2);  // the mmap, then at least one mremap
  EXPECT_EQ(g.cell_count(), 16384u);
  EXPECT_TRUE(bccmis::d3::fast::canonical_state(g) == bccmis::d3::fast::canonical_state(twin));
}

TEST(FastPool, ZeroedPoolsAreZeroOnBothSidesOfTheMapSwitch) {
  // spec/lattice3d.md §9.9: a heap block is zeroed, a fresh mapping's pages
  // are zero unwritten; a dirty heap block freed first, so that a block
  // reused without zeroing would show it.
  for (const std::size_t records : {std::size_t{7}, std::size_t{100}, kLine - 1, kLine, 3 * kLine}) {
    {
      Pool<Rec> dirty;
      append(dirty, records);
    }
    const Pool<Rec> pool = Pool<Rec>::zeroed(records);
    ASSERT_EQ(pool.size(), records);
    for (std::size_t i = 0; i < records; ++i)
      for (std::size_t k = 0; k < 16; ++k) ASSERT_EQ(pool[i].w[k], 0u) << records << " records: " << i << ", " << k;
  }
}

TEST(FastPool, AppendInReservedRoomAssignAndShrink) {
  // spec/lattice3d.md §9.9: append_reserved takes the next record of the
  // room made first, with no growth; assign and shrink_to_fit (the 2D
  // lattice's calls) keep every byte.
  Pool<Rec> pool;
  pool.reserve(10);
  const Rec* data = pool.data();
  const std::size_t capacity = pool.capacity();
  for (std::size_t i = 0; i < 10; ++i) {
    ASSERT_EQ(pool.append_reserved(), i);
    for (std::size_t k = 0; k < 16; ++k) pool[i].w[k] = word(i, k);
  }
  EXPECT_EQ(pool.data(), data);
  EXPECT_EQ(pool.capacity(), capacity);
  EXPECT_TRUE(intact(pool));
  pool.reserve(100);
  pool.shrink_to_fit();
  EXPECT_EQ(pool.capacity(), 10u);
  EXPECT_TRUE(intact(pool));
  Rec one{};
  one.w[3] = 7;
  pool.assign(4, one);
  ASSERT_EQ(pool.size(), 4u);
  for (const Rec& r : pool) EXPECT_EQ(r.w[3], 7u);
  pool.push_back(one);
  EXPECT_EQ(pool.size(), 5u);
}

}  // namespace

// ---- Huge pages (spec/lattice3d.md §9.10) ----------------------------------

// The /proc/self/smaps entry of the mapping holding `p`: its range, whether
// it was advised to use huge pages (VmFlags "hg") and its AnonHugePages.
struct Mapping {
  std::uintptr_t begin = 0, end = 0;
  bool advised = false;
  std::size_t huge_kib = 0;
};
Mapping mapping_of(const void* p) {
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  Mapping m;
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    const std::size_t dash = first.find('-');
    if (dash != std::string::npos && first.find(':') == std::string::npos) {  // "begin-end perms ..."
      if (inside) break;
      const std::uintptr_t begin = std::stoull(first.substr(0, dash), nullptr, 16);
      const std::uintptr_t end = std::stoull(first.substr(dash + 1), nullptr, 16);
      inside = begin <= at && at < end;
      if (inside) m = {begin, end, false, 0};
    } else if (inside && first == "AnonHugePages:") {
      words >> m.huge_kib;
    } else if (inside && first == "VmFlags:") {
      for (std::string flag; words >> flag;) m.advised = m.advised || flag == "hg";
    }
  }
  return m;
}

// Transparent huge pages are not off (/sys/kernel/mm/transparent_hugepage/
// enabled reads "[always]" or "[madvise]"), so advised blocks get them.
bool huge_pages_on() {
  std::ifstream enabled("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(enabled, text);
  return text.find("[always]") != std::string::npos || text.find("[madvise]") != std::string::npos;
}

// What §9.10 asks of a block of `bytes` at `p`: from kPoolHugeBytes up, whole
// huge pages at a huge-page boundary, inside one mapping advised as a whole.
::testing::AssertionResult huge_block(const void* p, std::size_t bytes) {
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  if (at % detail::kPoolHugePage != 0) return ::testing::AssertionFailure() << "starts off a 2 MiB boundary";
  if (bytes % detail::kPoolHugePage != 0)
    return ::testing::AssertionFailure() << bytes << " bytes: not whole huge pages";
  const Mapping m = mapping_of(p);
  if (m.begin > at || m.end < at + bytes) return ::testing::AssertionFailure() << "not inside one mapping";
  if (!m.advised) return ::testing::AssertionFailure() << "mapping not advised to use huge pages (no hg in VmFlags)";
  return ::testing::AssertionSuccess();
}

TEST(FastPool, BlocksFromFourMiBAreWholeHugePagesAtABoundaryAndAdvised) {
  // spec/lattice3d.md §9.10: the line at kPoolHugeBytes. A block of 4 MiB
  // is huge; one of 4 MiB - 4 KiB is a plain mapping, not advised.
  constexpr std::size_t kHugeLine = detail::kPoolHugeBytes / sizeof(Rec);
  Pool<Rec> at, below;
  at.reserve(kHugeLine);
  below.reserve(kHugeLine - 4096 / sizeof(Rec));
  EXPECT_EQ(at.capacity(), kHugeLine);
  EXPECT_EQ(below.capacity(), kHugeLine - 4096 / sizeof(Rec));
  EXPECT_TRUE(huge_block(at.data(), at.capacity() * sizeof(Rec)));
  EXPECT_FALSE(mapping_of(below.data()).advised);
  // A block just past the line is rounded up to whole huge pages.
  Pool<Rec> past;
  past.reserve(kHugeLine + 1);
  EXPECT_EQ(past.capacity() * sizeof(Rec), detail::kPoolHugeBytes + detail::kPoolHugePage);
  EXPECT_TRUE(huge_block(past.data(), past.capacity() * sizeof(Rec)));
}

TEST(FastPool, AGrowingPoolKeepsItsHugePages) {
  // spec/lattice3d.md §9.10: a pool grown record by record past 4 MiB stays
  // at a boundary, whole huge pages, advised, after every growth (in place
  // or moved onto a reservation), and its written pages are huge pages
  // (AnonHugePages), which a move to an address off a boundary would split.
  Pool<Rec> pool;
  std::size_t huge_growths = 0;
  while (pool.size() < 24 * kLine) {  // 24 MiB
    const std::size_t before = pool.capacity();
    append(pool, 1);
    if (pool.capacity() != before && pool.capacity() * sizeof(Rec) >= detail::kPoolHugeBytes) {
      ++huge_growths;
      ASSERT_TRUE(huge_block(pool.data(), pool.capacity() * sizeof(Rec))) << "after growing to " << pool.capacity();
    }
  }
  EXPECT_GE(huge_growths, 3u);
  ASSERT_TRUE(intact(pool));
  ASSERT_TRUE(huge_pages_on()) << "transparent huge pages are off: this test needs them";
  // The records written since the block reached 4 MiB: at least 20 MiB of
  // whole huge pages (what was written below 4 MiB may be small pages).
  EXPECT_GE(mapping_of(pool.data()).huge_kib, std::size_t{16} << 10);
}
