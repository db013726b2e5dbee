// bccmis: text written to a stream through one fixed buffer.
//
// The output paths (canonical states, decision logs, meshes) write millions
// of short numbers. TextWriter formats them with std::to_chars into a 64 KiB
// buffer and hands the buffer to the stream when it is full, so a writer
// holds 64 KiB however long the text is, and no number costs an allocation.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <ostream>
#include <string_view>

namespace bccmis {

class TextWriter {
 public:
  static constexpr std::size_t kBufferBytes = 64 * 1024;

  explicit TextWriter(std::ostream& out) : out_(out), buffer_(new char[kBufferBytes]) {}
  TextWriter(const TextWriter&) = delete;
  TextWriter& operator=(const TextWriter&) = delete;
  /// Does not write: what is still buffered is lost unless flush() was called
  /// (a writer abandoned by an exception leaves no partial last chunk).
  ~TextWriter() = default;

  /// Room for `n` <= kBufferBytes more bytes: a pointer to write them at,
  /// then commit(end) with the end of what was written.
  char* room(std::size_t n) {
    if (kBufferBytes - used_ < n) drain();
    return buffer_.get() + used_;
  }
  void commit(const char* end) { used_ = static_cast<std::size_t>(end - buffer_.get()); }

  void put(char c) {
    *room(1) = c;
    ++used_;
  }
  void put(std::string_view s) {
    if (s.size() > kBufferBytes) {
      drain();
      out_.write(s.data(), static_cast<std::streamsize>(s.size()));
      return;
    }
    char* p = room(s.size());
    std::memcpy(p, s.data(), s.size());
    used_ += s.size();
  }
  void put_int(std::int64_t v) { commit(write_int(room(kIntBytes), v)); }
  /// " x y": a point as the formats write it after a keyword or a colon.
  void put_point(std::int64_t x, std::int64_t y) { commit(write_point(room(kPointBytes), x, y)); }
  /// " x y z": a 3D point, likewise.
  void put_point(std::int64_t x, std::int64_t y, std::int64_t z) { commit(write_point(room(kPoint3Bytes), x, y, z)); }

  /// The most bytes write_int and write_point write.
  static constexpr std::size_t kIntBytes = 20;
  static constexpr std::size_t kPointBytes = 2 + 2 * kIntBytes;
  static constexpr std::size_t kPoint3Bytes = 3 + 3 * kIntBytes;
  /// The decimal text of v at p; returns its end. Numbers below 10^8 (all
  /// coordinates of a lattice below 10^8 units on a side) take the digit-pair
  /// path, the others std::to_chars.
  static char* write_int(char* p, std::int64_t v) {
    if (v < 0) {
      *p++ = '-';
      return write_uint(p, 0 - static_cast<std::uint64_t>(v));
    }
    return write_uint(p, static_cast<std::uint64_t>(v));
  }
  static char* write_uint(char* p, std::uint64_t v) {
    if (v < 10000) return write_small(p, static_cast<std::uint32_t>(v));
    if (v < 100000000) {
      const auto hi = static_cast<std::uint32_t>(v / 10000), lo = static_cast<std::uint32_t>(v % 10000);
      p = write_small(p, hi);
      write_pair(p, lo / 100);
      write_pair(p + 2, lo % 100);
      return p + 4;
    }
    return std::to_chars(p, p + kIntBytes, v).ptr;
  }
  /// " x y" at p; returns its end.
  static char* write_point(char* p, std::int64_t x, std::int64_t y) {
    *p++ = ' ';
    p = write_int(p, x);
    *p++ = ' ';
    return write_int(p, y);
  }
  /// " x y z" at p; returns its end.
  static char* write_point(char* p, std::int64_t x, std::int64_t y, std::int64_t z) {
    p = write_point(p, x, y);
    *p++ = ' ';
    return write_int(p, z);
  }

  /// The decimal text of a number formatted once, to be copied often:
  /// copy_to writes all of `text` (kIntBytes + 4 bytes, so the copy is a
  /// fixed-size one) and returns the end of the number.
  struct Decimal {
    explicit Decimal(std::int64_t v) : size(static_cast<std::size_t>(write_int(text, v) - text)) {}
    char* copy_to(char* p) const {
      std::memcpy(p, text, sizeof text);
      return p + size;
    }
    char text[kIntBytes + 4] = {};
    std::size_t size;
  };

  /// Writes what is buffered to the stream and flushes nothing else.
  void flush() { drain(); }

 private:
  // "00" "01" ... "99".
  static void write_pair(char* p, std::uint32_t v) {
    static constexpr char kPairs[] =
        "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
        "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
        "8081828384858687888990919293949596979899";
    std::memcpy(p, kPairs + 2 * v, 2);
  }
  // v < 10000, without leading zeros.
  static char* write_small(char* p, std::uint32_t v) {
    if (v < 100) {
      if (v < 10) {
        *p = static_cast<char>('0' + v);
        return p + 1;
      }
      write_pair(p, v);
      return p + 2;
    }
    const std::uint32_t hi = v / 100;
    if (hi < 10) {
      *p = static_cast<char>('0' + hi);
      write_pair(p + 1, v % 100);
      return p + 3;
    }
    write_pair(p, hi);
    write_pair(p + 2, v % 100);
    return p + 4;
  }

  void drain() {
    if (used_ != 0) out_.write(buffer_.get(), static_cast<std::streamsize>(used_));
    used_ = 0;
  }

  std::ostream& out_;
  std::unique_ptr<char[]> buffer_;
  std::size_t used_ = 0;
};

}  // namespace bccmis
