// bccmis::io: how a writer that offers more than text encodes its numbers
// (spec/mesh3d.md M20, M21; spec/cli.md, --binary).
#pragma once

namespace bccmis::io {

/// ascii: decimal text, the default. binary: the numbers as little-endian
/// machine values (.msh: "4.1 1 8"; .vtu: base64 inside the XML). zlib:
/// binary, and compressed where the format allows it (.vtu: VTK's
/// vtkZLibDataCompressor; .msh has no compression and is written binary).
enum class Encoding { ascii, binary, zlib };

}  // namespace bccmis::io
