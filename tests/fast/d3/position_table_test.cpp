// bccmis::d3::fast::PositionTable (spec/lattice3d.md §9.4) against a
// std::map: every key found under its reference after inserts, erases,
// renames and rehashes (the homes in a resized table from the stored
// hashes alone), absent keys not found, and keys that share their 32
// stored hash bits told apart by the match.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "bccmis/fast/d3/lattice.h"
#include "bccmis/fast/d3/position_table.h"

namespace {

using bccmis::d3::fast::PositionTable;
using Ref = PositionTable::Ref;

// The keys are 64-bit numbers; a key's hash keeps the key's top 32 bits in a
// third of the cases and changes only the low ones, so that distinct keys
// share their stored bits (and home) and only the match separates them.
std::uint64_t hash_of(std::uint64_t key) {
  std::uint64_t h = key * 0x9E3779B97F4A7C15ull;
  h ^= h >> 29;
  if (key % 3 == 0) return (key / 3 % 64) << 32 | (h & 0xFFFFFFFFu);  // few distinct top halves
  return h;
}

struct Model {
  PositionTable table;
  std::vector<std::uint64_t> key_of;  // by reference
  std::map<std::uint64_t, Ref> ref_of;

  Ref find(std::uint64_t key) const {
    return table.find(hash_of(key), [&](Ref r) { return key_of[r] == key; });
  }
  void check(const char* when) const {
    ASSERT_EQ(table.used(), ref_of.size()) << when;
    for (const auto& [key, ref] : ref_of) ASSERT_EQ(find(key), ref) << when << ": key " << key;
    std::size_t entries = 0;
    table.for_each([&](Ref r) {
      ++entries;
      EXPECT_EQ(ref_of.at(key_of[r]), r) << when;
    });
    EXPECT_EQ(entries, ref_of.size()) << when;
  }
};

TEST(Fast3PositionTable, AgreesWithAMapThroughInsertsErasesRenamesAndRehashes) {
  std::mt19937_64 rng(20261204);
  Model m;
  m.table.reset(32);
  for (int round = 0; round < 6; ++round) {
    // Grow: insert keys, rehashing (doubling) before the load passes 0.6.
    for (int i = 0; i < 400 << round; ++i) {
      const std::uint64_t key = rng() % (std::uint64_t{4000} << round);
      if (m.ref_of.count(key)) continue;
      if ((m.table.used() + 1) * 5 > m.table.slots() * 3) {
        m.table.rehash(m.table.slots() * 2);
        ASSERT_NO_FATAL_FAILURE(m.check("after a rehash"));
      }
      const Ref ref = static_cast<Ref>(m.key_of.size());
      m.key_of.push_back(key);
      m.table.insert(ref, hash_of(key));
      m.ref_of[key] = ref;
    }
    ASSERT_NO_FATAL_FAILURE(m.check("after the inserts"));
    // Erase a third, rename a third (a new reference for the same key).
    std::vector<std::uint64_t> keys;
    for (const auto& entry : m.ref_of) keys.push_back(entry.first);
    for (const std::uint64_t key : keys) {
      const Ref ref = m.ref_of[key];
      if (rng() % 3 == 0) {
        m.table.erase(ref, hash_of(key));
        m.ref_of.erase(key);
        EXPECT_EQ(m.find(key), PositionTable::kNone) << "erased key " << key;
      } else if (rng() % 2 == 0) {
        const Ref by = static_cast<Ref>(m.key_of.size());
        m.key_of.push_back(key);
        m.table.replace(ref, hash_of(key), by);
        m.ref_of[key] = by;
      }
    }
    ASSERT_NO_FATAL_FAILURE(m.check("after the erases and renames"));
    // Absent keys (beyond the range drawn) are not found.
    for (int i = 0; i < 200; ++i) {
      const std::uint64_t key = (std::uint64_t{1} << 40) + rng() % 100000;
      EXPECT_EQ(m.find(key), PositionTable::kNone) << "absent key " << key;
    }
  }
  // A rehash to a table four times as large, and back down to the smallest
  // that keeps the load at most 0.6: every key still found.
  m.table.rehash(m.table.slots() * 4);
  ASSERT_NO_FATAL_FAILURE(m.check("after growing 4x"));
  std::size_t slots = 32;
  while (m.table.used() * 5 > slots * 3) slots *= 2;
  m.table.rehash(slots);
  ASSERT_NO_FATAL_FAILURE(m.check("after shrinking"));
}

TEST(Fast3PositionTable, GrowthStandsOnTheLoadLineAndTheSizeLine) {
  // spec/lattice3d.md §9.9: keys * 5 <= slots * 3 keeps the table; the
  // first key past it multiplies the slots by 4 below 2^17 slots (1 MiB),
  // by 2 from there. 0.6 x 32 = 19.2: 19 keys fit, 20 do not.
  EXPECT_EQ(PositionTable::grown(32, 19), 32u);
  EXPECT_EQ(PositionTable::grown(32, 20), 128u);
  EXPECT_EQ(PositionTable::grown(32, 77), 512u);  // 76.8 fit in 128: two steps
  // The size line: 2^16 slots (512 KiB) still grow 4x, 2^17 (1 MiB) 2x.
  EXPECT_EQ(PositionTable::grown(std::size_t{1} << 16, 39321), std::size_t{1} << 16);  // 0.6 x 2^16 = 39321.6
  EXPECT_EQ(PositionTable::grown(std::size_t{1} << 16, 39322), std::size_t{1} << 18);
  EXPECT_EQ(PositionTable::grown(std::size_t{1} << 17, 78643), std::size_t{1} << 17);  // 0.6 x 2^17 = 78643.2
  EXPECT_EQ(PositionTable::grown(std::size_t{1} << 17, 78644), std::size_t{1} << 18);
}

TEST(Fast3PositionTable, AMappedFreshTableIsEmptyWithoutAWrite) {
  // spec/lattice3d.md §9.9: a table of 1 MiB and more is a fresh mapping
  // whose zero pages are its empty slots; one below is zeroed. Both filled,
  // emptied, refilled after a rehash between the two kinds.
  for (const std::size_t slots : {std::size_t{1} << 16, std::size_t{1} << 17, std::size_t{1} << 18}) {
    Model m;
    m.table.reset(slots);
    ASSERT_EQ(m.table.slots(), slots);
    ASSERT_NO_FATAL_FAILURE(m.check("fresh"));
    for (std::uint64_t i = 0; i < slots / 8; ++i) {  // keys of distinct 32 stored bits, all over the table
      const std::uint64_t key = 3 * i + 1;
      const Ref ref = static_cast<Ref>(m.key_of.size());
      m.key_of.push_back(key);
      m.table.insert(ref, hash_of(key));
      m.ref_of[key] = ref;
    }
    ASSERT_NO_FATAL_FAILURE(m.check("filled"));
    m.table.rehash(slots * 2);
    ASSERT_NO_FATAL_FAILURE(m.check("after a rehash"));
    m.table.reset(slots);  // a fresh table again: nothing of the old one
    m.ref_of.clear();
    ASSERT_NO_FATAL_FAILURE(m.check("reset"));
  }
}

TEST(Fast3PositionTable, ARefineGrowsTheTableAtTheLoadLine) {
  // spec/lattice3d.md §9.9, §9.5: a refine makes room for its 8 new keys
  // first. 3 level-0 cells: 3 -> 11 -> 19 keys, and 19 fit in 32 slots (the
  // refine before the line); 4 cells: 4 -> 12 -> 20, and that second refine
  // grows the table 4x (the refine that crosses it).
  using bccmis::d3::fast::Lattice;
  for (const long long cells : {3, 4}) {
    Lattice g({cells, 1, 1, 2});
    ASSERT_EQ(g.table_slots(), 32u);
    ASSERT_TRUE(g.refine(g.cells()[0]).applied());
    ASSERT_EQ(g.table_slots(), 32u) << cells;
    ASSERT_TRUE(g.refine(g.cells().back()).applied());
    EXPECT_EQ(g.table_keys(), static_cast<std::size_t>(cells) + 16);
    EXPECT_EQ(g.table_slots(), cells == 3 ? 32u : 128u) << cells;
    EXPECT_FALSE(g.audit());
  }
}

}  // namespace
