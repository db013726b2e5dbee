// base64 (spec/mesh3d.md M20's binary DataArrays): RFC 4648 §10's test
// vectors, written by hand from the RFC, and the streaming writer against
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
