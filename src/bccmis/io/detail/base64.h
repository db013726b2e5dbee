// bccmis::io::detail: base64 (RFC 4648, with padding), the encoding of the
// binary DataArrays of a .vtu (spec/mesh3d.md M20), both ways.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>

namespace bccmis::io::detail {

inline constexpr char kBase64Digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/// The two digits of each 12-bit value v as one 16-bit word in memory order
/// (little-endian: kBase64Digits[v >> 6] in the low byte, kBase64Digits[v &
/// 63] in the high one).
inline const std::array<std::uint16_t, 4096>& base64_pairs() {
  static_assert(std::endian::native == std::endian::little, "base64_pairs packs two digits little-endian");
  static const std::array<std::uint16_t, 4096> pairs = [] {
    std::array<std::uint16_t, 4096> p{};
    for (std::size_t v = 0; v < p.size(); ++v)
      p[v] = static_cast<std::uint16_t>(static_cast<unsigned char>(kBase64Digits[v >> 6]) |
                                        static_cast<unsigned char>(kBase64Digits[v & 63]) << 8);
    return p;
  }();
  return pairs;
}

/// The 4 digits of each of the `triples` 3-byte groups at `in`, to `out`:
/// two groups at a time as one 48-bit big-endian number, its four 12-bit
/// quarters two digits each (8 bytes written at once); a last odd group
/// alone.
inline char* base64_triples(const unsigned char* in, std::size_t triples, char* out) {
  const auto& pairs = base64_pairs();
  std::size_t t = 0;
  for (; t + 2 <= triples; t += 2, in += 6, out += 8) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < 6; ++i) v = v << 8 | in[i];
    const std::uint64_t digits = std::uint64_t{pairs[v >> 36]} | std::uint64_t{pairs[(v >> 24) & 4095]} << 16 |
                                 std::uint64_t{pairs[(v >> 12) & 4095]} << 32 | std::uint64_t{pairs[v & 4095]} << 48;
    std::memcpy(out, &digits, 8);
  }
  for (; t < triples; ++t, in += 3, out += 4) {
    const unsigned v = unsigned{in[0]} << 16 | unsigned{in[1]} << 8 | unsigned{in[2]};
    const std::uint32_t digits = std::uint32_t{pairs[v >> 12]} | std::uint32_t{pairs[v & 4095]} << 16;
    std::memcpy(out, &digits, 4);
  }
  return out;
}

/// The 4 digits, padded, of the last 1 or 2 bytes (`rest`) at `in`.
inline char* base64_tail(const unsigned char* in, std::size_t rest, char* out) {
  const unsigned v = unsigned{in[0]} << 16 | (rest == 2 ? unsigned{in[1]} << 8 : 0u);
  *out++ = kBase64Digits[(v >> 18) & 63];
  *out++ = kBase64Digits[(v >> 12) & 63];
  *out++ = rest == 2 ? kBase64Digits[(v >> 6) & 63] : '=';
  *out++ = '=';
  return out;
}

/// The base64 text of `bytes`.
inline std::string base64(std::string_view bytes) {
  std::string out((bytes.size() + 2) / 3 * 4, '\0');
  const auto* in = reinterpret_cast<const unsigned char*>(bytes.data());
  char* end = base64_triples(in, bytes.size() / 3, out.data());
  if (const std::size_t rest = bytes.size() % 3; rest > 0) base64_tail(in + bytes.size() - rest, rest, end);
  return out;
}

/// base64 written as the bytes come, in pieces of any length, to a stream:
/// the same text as base64() of all the pieces joined, without holding them.
class Base64Writer {
 public:
  explicit Base64Writer(std::ostream& out) : out_(out) {}
  Base64Writer(const Base64Writer&) = delete;
  Base64Writer& operator=(const Base64Writer&) = delete;

  void put(const void* data, std::size_t n) {
    const auto* in = static_cast<const unsigned char*>(data);
    while (n > 0 && held_ > 0 && held_ < 3) {  // complete a group begun before
      group_[held_++] = *in++;
      --n;
    }
    if (held_ == 3) {
      emit(group_, 1);
      held_ = 0;
    }
    const std::size_t triples = n / 3;
    for (std::size_t done = 0; done < triples;) {
      const std::size_t now = std::min(triples - done, kTriplesPerFlush);
      emit(in + 3 * done, now);
      done += now;
    }
    for (std::size_t i = 3 * triples; i < n; ++i) group_[held_++] = in[i];
  }

  /// The last group, padded, and everything still buffered.
  void finish() {
    if (held_ > 0)
      used_ = static_cast<std::size_t>(base64_tail(group_, held_, buffer_.data() + used_) - buffer_.data());
    held_ = 0;
    flush();
  }

 private:
  static constexpr std::size_t kTriplesPerFlush = 16384;

  void emit(const unsigned char* in, std::size_t triples) {
    if (used_ + 4 * triples > buffer_.size()) flush();
    used_ = static_cast<std::size_t>(base64_triples(in, triples, buffer_.data() + used_) - buffer_.data());
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(used_));
    used_ = 0;
  }

  std::ostream& out_;
  std::array<char, 4 * kTriplesPerFlush + 4> buffer_{};
  std::size_t used_ = 0;
  unsigned char group_[3] = {};
  std::size_t held_ = 0;
};

/// The bytes of the base64 text `text` (white space ignored; padding may
/// end each encoded block); false on a character outside the alphabet.
inline bool from_base64(std::string_view text, std::string& bytes) {
  unsigned v = 0;
  int bits = 0;
  for (const char c : text) {
    int d = -1;
    if (c >= 'A' && c <= 'Z')
      d = c - 'A';
    else if (c >= 'a' && c <= 'z')
      d = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      d = c - '0' + 52;
    else if (c == '+')
      d = 62;
    else if (c == '/')
      d = 63;
    else if (c == '=') {
      bits = 0;
      v = 0;
      continue;
    } else if (c == ' ' || c == '\n' || c == '\r' || c == '\t')
      continue;
    if (d < 0) return false;
    v = (v << 6) | static_cast<unsigned>(d);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes += static_cast<char>((v >> bits) & 0xff);
    }
  }
  return true;
}

}  // namespace bccmis::io::detail
