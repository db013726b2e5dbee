// bccmis::io: which surface format a file is in (spec/stuffing.md,
// "Formats"): by its extension, by its content, and one reader for all
// four.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "bccmis/io/triangle_soup.h"

namespace bccmis::io {

enum class SurfaceFormat { off, obj, ply, stl };

/// "OFF", "OBJ", "PLY", "STL".
std::string_view format_name(SurfaceFormat f);

/// The format a file name's extension names (.off, .obj, .ply, .stl,
/// case-insensitive), or none.
std::optional<SurfaceFormat> format_of_extension(std::string_view path);

/// No control byte but tab, line feed, vertical tab, form feed and carriage
/// return: text, not a binary file.
bool is_text(std::string_view data);

/// What the bytes are, when that is plain: PLY (its first line `ply`), OFF
/// text (its first word an OFF
/// header), OBJ text (its first statement v, vt, vn, vp, f, l, o, g, s,
/// mtllib or usemtl), ASCII STL (`solid` first), binary STL (exactly
/// 84 + 50 n bytes, n the count at byte 80); none otherwise.
std::optional<SurfaceFormat> sniff_format(std::string_view data);

/// The content in words, for messages: "OFF text", "OBJ text", "PLY",
/// "ASCII STL", "binary STL", "empty", "text" or "binary data".
std::string describe_content(std::string_view data);

/// The soup of `data` (named `file` in messages) read as `format`, or when
/// none is given as its content says (sniff_format). Throws ReadError when
/// the content is in none of the four formats, or when it plainly is in
/// another format than `format` ("file: the content is OFF text, not STL
/// (to read it as OFF: --format off)"), or as the format's reader does.
TriangleSoup read_surface(const std::string& file, const std::string& data, std::optional<SurfaceFormat> format);

}  // namespace bccmis::io
