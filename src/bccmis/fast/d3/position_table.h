// bccmis::d3::fast: the position table of the fast 3D lattice
// (spec/lattice3d.md §9.4): Robin Hood open addressing on 4-byte slots.
//
// A slot holds 0 (empty) or a 27-bit reference (the lattice decides what it
// names) and 1 + the entry's displacement from its home slot in bits 27-31,
// saturated at 31. The table stores no keys: the caller gives the home slot
// of a key, and, when a displacement is saturated, recomputes it through a
// `home_of(ref)` callback. Insertion lets the entry farther from home keep a
// slot; deletion shifts the following entries back by one; a lookup calls
// `match(ref)` only on entries with the probed key's own home.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include "bccmis/fast/lattice.h"  // fast::detail::Array (64-byte aligned, huge pages)

namespace bccmis::d3::fast {

class PositionTable {
 public:
  using Ref = std::uint32_t;
  static constexpr Ref kNone = 0xFFFFFFFFu;
  static constexpr Ref kRefMask = (Ref{1} << 27) - 1;  ///< a slot's reference bits
  static constexpr Ref kMaxRef = kRefMask;             ///< references are below this

  /// An empty table of at least `slots` slots (a power of two, at least 32).
  void reset(std::size_t slots);
  std::size_t slots() const { return slots_.size(); }
  std::size_t used() const { return used_; }
  std::size_t memory_bytes() const { return slots_.capacity() * sizeof(std::uint32_t); }
  /// The home slot of a 64-bit hash: its top bits.
  std::size_t home_of_hash(std::uint64_t hash) const { return static_cast<std::size_t>(hash >> shift_); }
  /// spec/lattice3d.md §9.4: the home of child k (0..7) of a cell whose
  /// hash is `hash`: the top bits of (hash XOR k φ) K, one multiplication a
  /// child, so that the 8 children need one hash of their parent and their
  /// homes spread like independent hashes' (no crowded block).
  std::size_t family_slot(std::uint64_t hash, std::size_t k) const {
    return home_of_hash((hash ^ (k * 0x9E3779B97F4A7C15ull)) * 0xD6E8FEB86659FD93ull);
  }
  void prefetch(std::size_t at) const { __builtin_prefetch(&slots_[at]); }

  /// The reference whose key has home `at` and that `match`es, or kNone.
  template <class Match, class HomeOf>
  Ref find(std::size_t at, Match&& match, HomeOf&& home_of) const;
  /// Inserts ref (its key absent, with home `at`; the caller keeps the load
  /// below 1).
  template <class HomeOf>
  void insert(Ref ref, std::size_t at, HomeOf&& home_of);
  /// Erases ref, whose key has home `at` (it must be present).
  template <class HomeOf>
  void erase(Ref ref, std::size_t at, HomeOf&& home_of);
  /// Names another reference in ref's slot (the key stays the same).
  void replace(Ref ref, std::size_t at, Ref by);
  /// Calls f(ref) for every entry.
  template <class F>
  void for_each(F&& f) const {
    for (const std::uint32_t s : slots_)
      if (s != 0) f(s & kRefMask);
  }

 private:
  static constexpr int kDistShift = 27;
  static constexpr std::uint32_t kDistSaturated = 31;
  static constexpr std::uint32_t encode(Ref ref, std::size_t d) {
    return ref | (static_cast<std::uint32_t>(d < kDistSaturated - 1 ? d + 1 : kDistSaturated) << kDistShift);
  }
  template <class HomeOf>
  std::size_t displacement(std::size_t i, HomeOf& home_of) const {
    const std::uint32_t f = slots_[i] >> kDistShift;
    if (f != kDistSaturated) [[likely]]
      return f - 1u;
    return (i - home_of(slots_[i] & kRefMask)) & (slots_.size() - 1);
  }
  std::size_t slot_of(Ref ref, std::size_t at) const {
    const std::size_t mask = slots_.size() - 1;
    while (slots_[at] == 0 || (slots_[at] & kRefMask) != ref) at = (at + 1) & mask;
    return at;
  }

  bccmis::fast::detail::Array<std::uint32_t> slots_;
  int shift_ = 64;
  std::size_t used_ = 0;
};

// ---- Inline bodies ------------------------------------------------------------

inline void PositionTable::reset(std::size_t slots) {
  int bits = 5;
  while ((std::size_t{1} << bits) < slots) ++bits;
  bccmis::fast::detail::Array<std::uint32_t> fresh(std::size_t{1} << bits, 0);  // may throw: nothing changed
  slots_.swap(fresh);
  shift_ = 64 - bits;
  used_ = 0;
}

template <class Match, class HomeOf>
PositionTable::Ref PositionTable::find(std::size_t i, Match&& match, HomeOf&& home_of) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t d = 0;; ++d, i = (i + 1) & mask) {
    const std::uint32_t s = slots_[i];
    if (s == 0) return kNone;
    const std::size_t e = displacement(i, home_of);
    if (e < d) return kNone;  // the key would have displaced this entry: it is absent
    if (e == d && match(s & kRefMask)) return s & kRefMask;
  }
}

template <class HomeOf>
void PositionTable::insert(Ref ref, std::size_t i, HomeOf&& home_of) {
  const std::size_t mask = slots_.size() - 1;
  ++used_;
  if (slots_[i] == 0) [[likely]] {  // an empty home
    slots_[i] = encode(ref, 0);
    return;
  }
  for (std::size_t d = 0;; ++d, i = (i + 1) & mask) {
    const std::uint32_t s = slots_[i];
    if (s == 0) {
      slots_[i] = encode(ref, d);
      return;
    }
    const std::size_t e = displacement(i, home_of);
    if (e < d) {  // the resident is closer to home: it moves on instead
      slots_[i] = encode(ref, d);
      ref = s & kRefMask;
      d = e;
    }
  }
}

template <class HomeOf>
void PositionTable::erase(Ref ref, std::size_t at, HomeOf&& home_of) {
  const std::size_t mask = slots_.size() - 1;
  if (slots_[at] == encode(ref, 0) && (slots_[(at + 1) & mask] >> kDistShift) <= 1) [[likely]] {
    slots_[at] = 0;  // at its home, nothing displaced behind it
    --used_;
    return;
  }
  std::size_t i = slot_of(ref, at);
  for (std::size_t j = (i + 1) & mask;; i = j, j = (j + 1) & mask) {
    const std::uint32_t s = slots_[j];
    const std::uint32_t f = s >> kDistShift;
    if (f <= 1) break;  // empty, or at its home
    slots_[i] = f != kDistSaturated ? s - (1u << kDistShift) : encode(s & kRefMask, displacement(j, home_of) - 1);
  }
  slots_[i] = 0;
  --used_;
}

inline void PositionTable::replace(Ref ref, std::size_t at, Ref by) {
  const std::size_t i = slot_of(ref, at);
  slots_[i] = (slots_[i] & ~kRefMask) | by;
}

}  // namespace bccmis::d3::fast
