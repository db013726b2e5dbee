// base64 (spec/mesh3d.md M20's binary DataArrays): RFC 4648 §10's test
// vectors, written by hand from the RFC, every byte value against the RFC's
// bit-by-bit rule, and the streaming writer against
// the whole-string encoder for every way of cutting an input into pieces.
#include <gtest/gtest.h>

#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/io/detail/base64.h"

namespace bccmis::io::detail {
namespace {

TEST(Base64, Rfc4648TestVectors) {
  // RFC 4648 §10, then the last two digits of the alphabet and a high bit.
  const std::vector<std::pair<std::string, std::string>> vectors{{"", ""},
                                                                 {"f", "Zg=="},
                                                                 {"fo", "Zm8="},
                                                                 {"foo", "Zm9v"},
                                                                 {"foob", "Zm9vYg=="},
                                                                 {"fooba", "Zm9vYmE="},
                                                                 {"foobar", "Zm9vYmFy"},
                                                                 {std::string("\xfb\xff\xbf", 3), "+/+/"}};
  for (const auto& [bytes, text] : vectors) EXPECT_EQ(base64(bytes), text) << bytes;
}

/// RFC 4648 §4 read literally: the bits of `bytes`, most significant first,
/// six at a time (zeros appended), each an index into the alphabet, then
/// '=' to a multiple of 4 digits. Independent of base64_triples' tables.
std::string base64_by_bits(const std::string& bytes) {
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<int> bits;
  for (const char c : bytes)
    for (int b = 7; b >= 0; --b) bits.push_back((static_cast<unsigned char>(c) >> b) & 1);
  while (bits.size() % 6 != 0) bits.push_back(0);
  std::string out;
  for (std::size_t i = 0; i < bits.size(); i += 6) {
    std::size_t index = 0;
    for (std::size_t k = 0; k < 6; ++k) index = 2 * index + static_cast<std::size_t>(bits[i + k]);
    out += alphabet[index];
  }
  while (out.size() % 4 != 0) out += '=';
  return out;
}

TEST(Base64, EveryByteAtEveryPlaceAsTheBitsSay) {
  // Every byte value at each of the 6 places of two groups (the encoder
  // takes two groups at a time), and lengths 0..13 of a mixed string.
  for (int value = 0; value < 256; ++value)
    for (std::size_t place = 0; place < 6; ++place) {
      std::string bytes("\x5a\xa5\x0f\xf0\x33\xcc", 6);
      bytes[place] = static_cast<char>(value);
      ASSERT_EQ(base64(bytes), base64_by_bits(bytes)) << "byte " << value << " at " << place;
    }
  std::string mixed;
  for (int i = 0; i < 13; ++i) mixed += static_cast<char>((i * 97 + 200) & 0xff);
  for (std::size_t n = 0; n <= mixed.size(); ++n)
    EXPECT_EQ(base64(mixed.substr(0, n)), base64_by_bits(mixed.substr(0, n))) << "length " << n;
}

/// The writer's text for `bytes` given in pieces of the lengths `cuts` (then
/// the rest in one piece).
std::string streamed(const std::string& bytes, const std::vector<std::size_t>& cuts) {
  std::ostringstream out;
  Base64Writer w(out);
  std::size_t at = 0;
  for (const std::size_t n : cuts) {
    w.put(bytes.data() + at, n);
    at += n;
  }
  w.put(bytes.data() + at, bytes.size() - at);
  w.finish();
  return out.str();
}

TEST(Base64Writer, AnyCutEqualsTheWholeAndTheRfc) {
  EXPECT_EQ(streamed("foobar", {1, 1, 1, 1, 1}), "Zm9vYmFy");
  EXPECT_EQ(streamed("fooba", {2, 0, 2}), "Zm9vYmE=");
  EXPECT_EQ(streamed("", {}), "");
  std::string bytes;
  for (int i = 0; i < 300; ++i) bytes += static_cast<char>((i * 37 + 11) & 0xff);
  for (std::size_t a = 0; a <= 7; ++a)
    for (std::size_t b = 0; b <= 7; ++b)
      for (std::size_t len : {std::size_t{0}, std::size_t{14}, std::size_t{15}, std::size_t{16}, bytes.size()})
        if (a + b <= len) {
          const std::string part = bytes.substr(0, len);
          EXPECT_EQ(streamed(part, {a, b}), base64(part)) << "cuts " << a << ", " << b << " of " << len;
        }
}

TEST(Base64Writer, LongerThanItsBufferInOnePieceAndByteByByte) {
  // 200,002 bytes: several of the writer's 49,152-byte flushes, and two
  // padding digits at the end (one byte left over).
  std::string bytes(200'002, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 2654435761U) >> 13);
  EXPECT_EQ(streamed(bytes, {}), base64(bytes));
  std::ostringstream out;
  Base64Writer w(out);
  for (const char c : bytes) w.put(&c, 1);
  w.finish();
  EXPECT_EQ(out.str(), base64(bytes));
  EXPECT_EQ(out.str().size(), (bytes.size() + 2) / 3 * 4);
  EXPECT_EQ(out.str().substr(out.str().size() - 2), "==");
}

}  // namespace
}  // namespace bccmis::io::detail
