// bccmis::d3::fast: the position table of the fast 3D lattice
// (spec/lattice3d.md §9.4): Robin Hood open addressing on 8-byte entries.
//
// An entry holds 1 + a reference (0: empty; the lattice decides what a
// reference names) and the top 32 bits of its key's 64-bit hash. The table
// stores no keys: the caller gives a key's hash, and a key's home in a table
// of 2^b slots is the top b bits of it, so every entry's home and
// displacement follow from the entry (§9.4): a rehash reads no record.
// Insertion lets the entry farther from home keep a slot; deletion shifts
// the following entries back by one; a lookup calls `match(ref)` only on
// entries with the probed key's 32 hash bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "bccmis/fast/pool.h"

namespace bccmis::d3::fast {

class PositionTable {
 public:
  using Ref = std::uint32_t;
  static constexpr Ref kNone = 0xFFFFFFFFu;

  /// An empty table of at least `slots` slots (a power of two, at least 32).
  void reset(std::size_t slots);
  std::size_t slots() const { return slots_.size(); }
  std::size_t used() const { return used_; }
  std::size_t memory_bytes() const { return slots_.capacity() * sizeof(Entry); }
  /// spec/lattice3d.md §9.4: the hash of child k (0..7) of a cell whose hash
  /// is `hash`: (hash XOR k φ) K, one multiplication a child, so that the 8
  /// children need one hash of their parent and their homes spread like
  /// independent hashes' (no crowded block).
  static std::uint64_t family_hash(std::uint64_t hash, std::size_t k) {
    return (hash ^ (k * 0x9E3779B97F4A7C15ull)) * 0xD6E8FEB86659FD93ull;
  }
  void prefetch(std::uint64_t hash) const { __builtin_prefetch(&slots_[home(top(hash))]); }

  /// The reference whose key has this hash and that `match`es, or kNone.
  template <class Match>
  Ref find(std::uint64_t hash, Match&& match) const;
  /// Inserts ref, whose key (absent) has this hash; the caller keeps the
  /// load below 1.
  void insert(Ref ref, std::uint64_t hash) { place({top(hash), ref + 1}); }
  /// Erases ref, whose key has this hash (it must be present).
  void erase(Ref ref, std::uint64_t hash);
  /// Names another reference in ref's entry (the key, and so the hash, stay).
  void replace(Ref ref, std::uint64_t hash, Ref by) { slots_[slot_of(ref, top(hash))].ref1 = by + 1; }
  /// spec/lattice3d.md §9.9: the slots for `keys` keys in a table of
  /// `slots`: unchanged while keys * 5 <= slots * 3 (load at most 0.6);
  /// otherwise multiplied by 4 while below kQuadrupleBelow slots (1 MiB),
  /// by 2 from there, until the load line holds.
  static std::size_t grown(std::size_t slots, std::size_t keys) {
    while (keys * 5 > slots * 3) slots *= slots < kQuadrupleBelow ? 4 : 2;
    return slots;
  }
  static constexpr std::size_t kQuadrupleBelow = std::size_t{1} << 17;
  /// The same entries in a table of `slots` slots (a power of two, at least
  /// 32, above used() / 0.6 for the caller's load): homes from the stored
  /// hashes (§9.4). May throw std::bad_alloc, and then nothing changed.
  void rehash(std::size_t slots);
  /// Calls f(ref) for every entry.
  template <class F>
  void for_each(F&& f) const {
    for (const Entry& e : slots_)
      if (e.ref1 != 0) f(e.ref1 - 1);
  }

 private:
  struct Entry {
    std::uint32_t hash;  ///< the top 32 bits of the key's hash
    std::uint32_t ref1;  ///< 1 + the reference; 0: an empty slot
  };
  static std::uint32_t top(std::uint64_t hash) { return static_cast<std::uint32_t>(hash >> 32); }
  std::size_t home(std::uint32_t hash) const { return static_cast<std::size_t>(hash >> shift_); }
  std::size_t displacement(std::size_t i) const { return (i - home(slots_[i].hash)) & (slots_.size() - 1); }
  std::size_t slot_of(Ref ref, std::uint32_t hash) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t at = home(hash);
    while (slots_[at].ref1 != ref + 1) at = (at + 1) & mask;
    return at;
  }
  void place(Entry entry);

  bccmis::fast::Pool<Entry> slots_;  ///< spec/lattice3d.md §9.8, §9.9
  int shift_ = 32;                   ///< 32 - b for 2^b slots
  std::size_t used_ = 0;
};

// ---- Inline bodies ------------------------------------------------------------

inline void PositionTable::reset(std::size_t slots) {
  int bits = 5;
  while ((std::size_t{1} << bits) < slots) ++bits;
  if (bits > 32) throw std::length_error("d3::fast::PositionTable: more than 2^32 slots");
  // §9.9: a mapped table's zero pages come from the kernel, unwritten.
  auto fresh = bccmis::fast::Pool<Entry>::zeroed(std::size_t{1} << bits);  // may throw: nothing changed
  slots_.swap(fresh);
  shift_ = 32 - bits;
  used_ = 0;
}

template <class Match>
PositionTable::Ref PositionTable::find(std::uint64_t hash, Match&& match) const {
  const std::uint32_t h = top(hash);
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = home(h);
  for (std::size_t d = 0;; ++d, i = (i + 1) & mask) {
    const Entry e = slots_[i];
    if (e.ref1 == 0) return kNone;
    if (displacement(i) < d) return kNone;  // the key would have displaced this entry: it is absent
    if (e.hash == h && match(e.ref1 - 1)) return e.ref1 - 1;
  }
}

inline void PositionTable::place(Entry entry) {
  const std::size_t mask = slots_.size() - 1;
  ++used_;
  std::size_t i = home(entry.hash);
  for (std::size_t d = 0;; ++d, i = (i + 1) & mask) {
    if (slots_[i].ref1 == 0) {
      slots_[i] = entry;
      return;
    }
    const std::size_t e = displacement(i);
    if (e < d) {  // the resident is closer to home: it moves on instead
      std::swap(slots_[i], entry);
      d = e;
    }
  }
}

inline void PositionTable::erase(Ref ref, std::uint64_t hash) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = slot_of(ref, top(hash));
  for (std::size_t j = (i + 1) & mask;; i = j, j = (j + 1) & mask) {
    if (slots_[j].ref1 == 0 || displacement(j) == 0) break;  // empty, or at its home
    slots_[i] = slots_[j];
  }
  slots_[i] = Entry{0, 0};
  --used_;
}

inline void PositionTable::rehash(std::size_t slots) {
  PositionTable fresh;
  fresh.reset(slots);  // may throw: nothing changed yet
  for (const Entry& e : slots_)
    if (e.ref1 != 0) fresh.place(e);
  *this = std::move(fresh);
}

}  // namespace bccmis::d3::fast
