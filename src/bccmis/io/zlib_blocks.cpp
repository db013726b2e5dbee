// VTK's zlib-compressed DataArrays (detail/zlib_blocks.h, spec/mesh3d.md M20).
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "bccmis/io/detail/base64.h"
#include "bccmis/io/detail/zlib_blocks.h"

namespace bccmis::io::detail {

std::string zlib_base64(std::string_view raw) {
  const std::uint64_t blocks = (raw.size() + kZlibBlockBytes - 1) / kZlibBlockBytes;
  const std::uint64_t last = raw.size() - (blocks == 0 ? 0 : (blocks - 1) * kZlibBlockBytes);
  std::vector<std::uint64_t> header = {blocks, kZlibBlockBytes, last};
  std::string data;
  std::vector<Bytef> block(compressBound(kZlibBlockBytes));
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::size_t from = b * kZlibBlockBytes, size = std::min(kZlibBlockBytes, raw.size() - from);
    uLongf out = static_cast<uLongf>(block.size());
    // compress2 fails only on a lack of memory or room, neither possible
    // with compressBound's room; treat it as an internal error all the same.
    if (compress2(block.data(), &out, reinterpret_cast<const Bytef*>(raw.data() + from), static_cast<uLong>(size),
                  Z_DEFAULT_COMPRESSION) != Z_OK)
      throw std::runtime_error("zlib could not compress a DataArray block");
    header.push_back(out);
    data.append(reinterpret_cast<const char*>(block.data()), out);
  }
  std::string header_bytes(header.size() * sizeof(std::uint64_t), '\0');
  std::memcpy(header_bytes.data(), header.data(), header_bytes.size());
  return base64(header_bytes) + base64(data);
}

std::optional<std::string> zlib_inflate_blocks(std::string_view bytes, std::size_t header_bytes, std::string& why) {
  const auto integer = [&](std::size_t k) {
    std::uint64_t v = 0;
    std::memcpy(&v, bytes.data() + k * header_bytes, header_bytes);
    return v;
  };
  if (bytes.size() < 3 * header_bytes) {
    why = "no compression header";
    return std::nullopt;
  }
  const std::uint64_t blocks = integer(0), block_size = integer(1), last = integer(2);
  if (blocks > (bytes.size() / header_bytes) - 3) {
    why = "the compression header counts more blocks than the data holds";
    return std::nullopt;
  }
  std::size_t at = (3 + blocks) * header_bytes;
  std::string raw;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t compressed = integer(3 + b);
    // A last block of size 0 is a full block (VTK's convention).
    const std::uint64_t size = b + 1 == blocks && last != 0 ? last : block_size;
    if (compressed > bytes.size() - at) {
      why = "compressed block " + std::to_string(b) + " runs past the data";
      return std::nullopt;
    }
    // Deflate's largest expansion is about 1032 to 1 (zlib's technical
    // details): a header promising more is refused before any allocation.
    if (size > 1032 * compressed + 1032) {
      why = "compressed block " + std::to_string(b) + " does not inflate to " + std::to_string(size) + " bytes";
      return std::nullopt;
    }
    const std::size_t from = raw.size();
    raw.resize(from + size);
    uLongf out = static_cast<uLongf>(size);
    if (uncompress(reinterpret_cast<Bytef*>(raw.data() + from), &out, reinterpret_cast<const Bytef*>(bytes.data() + at),
                   static_cast<uLong>(compressed)) != Z_OK ||
        out != size) {
      why = "compressed block " + std::to_string(b) + " does not inflate to " + std::to_string(size) + " bytes";
      return std::nullopt;
    }
    at += compressed;
  }
  return raw;
}

}  // namespace bccmis::io::detail
