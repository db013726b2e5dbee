// bccmis::fast: the record pools of the fast lattices, 2D and 3D
// (spec/lattice3d.md §9.8): one contiguous block of trivially copyable
// records named by index, grown by one byte copy of the used records (below
// 1 MiB, from the heap) or by mremap with no copy at all (from 1 MiB up, an
// anonymous mapping whose pages arrive zero-filled when first touched; from
// 4 MiB up whole huge pages at a huge-page boundary, advised to use them,
// §9.10). Growth succeeds whole or throws std::bad_alloc with the pool unchanged.
#pragma once

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cstddef>
#include <cstring>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace bccmis::fast {

namespace detail {
/// spec/lattice3d.md §9.8: blocks of this many bytes and more are mapped.
inline constexpr std::size_t kPoolMapBytes = std::size_t{1} << 20;
/// spec/lattice3d.md §9.10: mapped blocks of this many bytes and more are
/// whole huge pages of kPoolHugePage bytes, start at a multiple of it and are
/// advised to use transparent huge pages.
inline constexpr std::size_t kPoolHugeBytes = std::size_t{4} << 20;
inline constexpr std::size_t kPoolHugePage = std::size_t{2} << 20;

/// The size of a mapped block that holds `bytes`: whole pages, and whole
/// huge pages from kPoolHugeBytes up (§9.10).
constexpr std::size_t pool_mapped_bytes(std::size_t bytes) {
  const std::size_t unit = bytes >= kPoolHugeBytes ? kPoolHugePage : std::size_t{4096};
  return (bytes + unit - 1) & ~(unit - 1);
}

/// A block of at least `bytes` bytes holding the first `used` bytes of `old`
/// (a block of `old_bytes` bytes from this function, or null with 0), which
/// is freed. Returns the new block and sets `bytes` to its size (mapped
/// blocks are whole pages, and whole huge pages from 4 MiB, §9.10). On
/// failure throws std::bad_alloc and `old` is untouched (§9.8).
void* pool_grow(void* old, std::size_t old_bytes, std::size_t used, std::size_t& bytes);
/// Frees a block of `bytes` bytes from pool_grow (null with 0: nothing).
void pool_free(void* block, std::size_t bytes) noexcept;

/// Whether a block of this many bytes is a mapping (§9.8; Linux only).
constexpr bool pool_block_is_mapped(std::size_t bytes) {
#if defined(__linux__)
  return bytes >= kPoolMapBytes;
#else
  (void)bytes;
  return false;
#endif
}

/// For tests: when not negative, the number of mmap / mremap calls that
/// succeed before one fails as if the kernel refused (then -1 again). The
/// heap blocks fail through operator new.
inline std::atomic<long> pool_map_countdown{-1};
}  // namespace detail

/// A pool of trivially copyable records (spec/lattice3d.md §9.8): the
/// std::vector calls the lattices use, with growth by a byte copy or by
/// remapping. Copyable (the copy holds exactly the used records) and movable.
template <class T>
class Pool {
  static_assert(std::is_trivially_copyable_v<T>, "a pool moves its records as bytes (spec/lattice3d.md §9.8)");
  static_assert(alignof(T) <= 64);

 public:
  Pool() = default;
  Pool(const Pool& other) {
    if (other.size_ == 0) return;
    std::size_t bytes = other.size_ * sizeof(T);
    data_ = static_cast<T*>(detail::pool_grow(nullptr, 0, 0, bytes));
    bytes_ = bytes;
    std::memcpy(static_cast<void*>(data_), other.data_, other.size_ * sizeof(T));
    size_ = other.size_;
  }
  Pool(Pool&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)),
        size_(std::exchange(other.size_, 0)),
        bytes_(std::exchange(other.bytes_, 0)) {}
  Pool& operator=(const Pool& other) {
    if (this != &other) {
      Pool copy(other);  // may throw: *this unchanged
      swap(copy);
    }
    return *this;
  }
  Pool& operator=(Pool&& other) noexcept {
    Pool moved(std::move(other));
    swap(moved);
    return *this;
  }
  ~Pool() { detail::pool_free(data_, bytes_); }
  void swap(Pool& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(bytes_, other.bytes_);
  }

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return bytes_ / sizeof(T); }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

  /// Room for n records (no change when there is); throws std::bad_alloc
  /// with the pool unchanged.
  void reserve(std::size_t n) {
    if (n <= capacity()) return;
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    std::size_t bytes = n * sizeof(T);
    data_ = static_cast<T*>(detail::pool_grow(data_, bytes_, size_ * sizeof(T), bytes));
    bytes_ = bytes;
  }
  /// spec/lattice3d.md §9.9: the capacity this pool grows to when it must
  /// hold `need` records: max(need, 4 x capacity) while its block is below
  /// kPoolMapBytes (a heap block: growth is a copy, so few large steps),
  /// max(need, capacity + capacity / 8) from there (a mapping: growth is an
  /// mremap that copies nothing, so small steps and little unused capacity).
  std::size_t grown_capacity(std::size_t need) const {
    const std::size_t c = capacity();
    return std::max(need, bytes_ >= detail::kPoolMapBytes ? c + c / 8 : 4 * c);
  }
  /// Appends a value-initialized record (grows by half when full).
  T& emplace_back() {
    if (size_ == capacity()) reserve(size_ + size_ / 2 + 1);
    return *::new (static_cast<void*>(data_ + size_++)) T();
  }
  void push_back(const T& value) { emplace_back() = value; }
  /// The index of a record appended in room already reserved (size() <
  /// capacity()), its bytes not written: the caller writes every field it
  /// will read (spec/lattice3d.md §9.9).
  std::size_t append_reserved() {
    assert(size_ < capacity());
    return size_++;
  }
  /// A pool of n records whose bytes are all zero. A mapped block's pages
  /// are zero already (the kernel fills them when first touched), so from
  /// 1 MiB up nothing is written here (spec/lattice3d.md §9.9); a heap
  /// block is zeroed. Throws std::bad_alloc.
  static Pool zeroed(std::size_t n) {
    Pool pool;
    pool.reserve(n);
    if (!detail::pool_block_is_mapped(pool.bytes_) && n != 0)
      std::memset(static_cast<void*>(pool.data_), 0, n * sizeof(T));
    pool.size_ = n;
    return pool;
  }
  /// n copies of value.
  void assign(std::size_t n, const T& value) {
    reserve(n);
    for (std::size_t i = 0; i < n; ++i) ::new (static_cast<void*>(data_ + i)) T(value);
    size_ = n;
  }
  /// A block of exactly the used records (rounded up to whole pages when
  /// mapped, to whole huge pages from 4 MiB, §9.10); may throw
  /// std::bad_alloc, and then nothing changed.
  void shrink_to_fit() {
    Pool exact(*this);
    swap(exact);
  }
  /// n records; the new ones value-initialized.
  void resize(std::size_t n) {
    reserve(n);
    for (std::size_t i = size_; i < n; ++i) ::new (static_cast<void*>(data_ + i)) T();
    size_ = n;
  }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t bytes_ = 0;  ///< the block's size: heap below kPoolMapBytes, mapped from it up
};

}  // namespace bccmis::fast
