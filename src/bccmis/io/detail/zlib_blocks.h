// bccmis::io::detail: the zlib-compressed DataArray of VTK's XML formats
// (vtkZLibDataCompressor; spec/mesh3d.md M20), both ways.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace bccmis::io::detail {

/// The raw bytes of a DataArray cut into blocks of this many bytes, each
/// compressed on its own (VTK's default block size).
inline constexpr std::size_t kZlibBlockBytes = 32768;

/// The text of a compressed inline DataArray holding `raw`: the base64 of
/// the UInt64 header (number of blocks, block size, size of the last block,
/// then each block's compressed size), followed by the base64 of the
/// compressed blocks, the two encoded separately as VTK writes them.
std::string zlib_base64(std::string_view raw);

/// The raw bytes of the decoded body `bytes` of a compressed DataArray with
/// a header of `header_bytes`-byte integers (4: UInt32, 8: UInt64): the
/// header, then the compressed blocks. nullopt, with `why` set, when the
/// header does not fit the data or a block does not inflate to its size.
std::optional<std::string> zlib_inflate_blocks(std::string_view bytes, std::size_t header_bytes, std::string& why);

}  // namespace bccmis::io::detail
