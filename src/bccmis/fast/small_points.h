// bccmis::fast: a small sorted set of points without heap, one type for every
// dimension (SmallPoints in 2D, d3::fast::SmallPoints in 3D).
#pragma once

#include <array>
#include <cstddef>
#include <set>
#include <type_traits>
#include <utility>

namespace bccmis::fast {

/// Up to N points of type P, sorted by position like the reference's
/// std::set; no heap.
template <class P, std::size_t N>
class BasicSmallPoints {
 public:
  BasicSmallPoints() {}  // the points are not initialized: only [0, size) is ever read
  const P* begin() const { return items_.at; }
  const P* end() const { return items_.at + size_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const P& operator[](std::size_t i) const { return items_.at[i]; }
  bool contains(const P& p) const {
    for (std::size_t i = 0; i < size_; ++i)
      if (items_.at[i] == p) return true;
    return false;
  }
  /// Appends p; the caller keeps the order (or calls sort()).
  void push_back(const P& p) { items_.at[size_++] = p; }
  /// Sorts by position (insertion sort: at most N elements).
  void sort() {
    for (std::size_t i = 1; i < size_; ++i)
      for (std::size_t j = i; j > 0 && items_.at[j] < items_.at[j - 1]; --j) std::swap(items_.at[j], items_.at[j - 1]);
  }
  /// The same points as a std::set (allocates; for comparisons and adapters).
  std::set<P> to_set() const { return std::set<P>(begin(), end()); }

 private:
  // A union, so that a result is not zero-filled before refine or coarsen
  // writes its few points (3D: 18 points of 24 bytes, two sets a result).
  // P is trivially copyable: a copy copies the bytes, read or not.
  union Items {
    Items() {}
    P at[N];
  };
  static_assert(std::is_trivially_copyable_v<P> && std::is_trivially_destructible_v<P>);
  Items items_;
  std::size_t size_ = 0;
};

}  // namespace bccmis::fast
