// Which surface format a file is in (surface_format.h).
#include "bccmis/io/surface_format.h"

#include <algorithm>
#include <cctype>
#include <cstdint>

#include "bccmis/io/obj.h"
#include "bccmis/io/off.h"
#include "bccmis/io/ply.h"
#include "bccmis/io/read_error.h"
#include "bccmis/io/stl.h"

namespace bccmis::io {

namespace {

/// The first word of the text that is not white space or in a `#` comment.
std::string_view first_word(std::string_view data) {
  std::size_t i = 0;
  for (;;) {
    while (i < data.size() && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
    if (i < data.size() && data[i] == '#') {
      i = data.find('\n', i);
      if (i == std::string_view::npos) return {};
      continue;
    }
    std::size_t end = i;
    while (end < data.size() && !std::isspace(static_cast<unsigned char>(data[end]))) ++end;
    return data.substr(i, end - i);
  }
}

bool binary_stl_size(std::string_view data) {
  if (data.size() < 84) return false;
  const auto u8 = [&](std::size_t i) { return static_cast<std::uint64_t>(static_cast<unsigned char>(data[i])); };
  const std::uint64_t n = u8(80) | u8(81) << 8 | u8(82) << 16 | u8(83) << 24;
  return data.size() == 84 + 50 * n;
}

/// The first line is `ply` (spec/formats.md, "PLY input").
bool ply_magic(std::string_view data) { return data.starts_with("ply\n") || data.starts_with("ply\r\n"); }

bool off_header(std::string_view w) {
  return w.size() >= 3 && w.substr(w.size() - 3) == "OFF" &&
         w.substr(0, w.size() - 3).find_first_not_of("STCN") == std::string_view::npos;
}

bool obj_statement(std::string_view w) {
  for (std::string_view s : {"v", "vt", "vn", "vp", "f", "l", "o", "g", "s", "mtllib", "usemtl"})
    if (w == s) return true;
  return false;
}

}  // namespace

bool is_text(std::string_view data) {
  return std::none_of(data.begin(), data.end(), [](char c) {
    const auto b = static_cast<unsigned char>(c);
    return b < 0x20 && b != '\t' && b != '\n' && b != '\v' && b != '\f' && b != '\r';
  });
}

std::string_view format_name(SurfaceFormat f) {
  switch (f) {
    case SurfaceFormat::off: return "OFF";
    case SurfaceFormat::obj: return "OBJ";
    case SurfaceFormat::ply: return "PLY";
    case SurfaceFormat::stl: return "STL";
  }
  return "?";
}

std::optional<SurfaceFormat> format_of_extension(std::string_view path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return std::nullopt;
  std::string ext(path.substr(dot + 1));
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "off") return SurfaceFormat::off;
  if (ext == "obj") return SurfaceFormat::obj;
  if (ext == "ply") return SurfaceFormat::ply;
  if (ext == "stl") return SurfaceFormat::stl;
  return std::nullopt;
}

std::optional<SurfaceFormat> sniff_format(std::string_view data) {
  if (ply_magic(data)) return SurfaceFormat::ply;
  if (binary_stl_size(data)) return SurfaceFormat::stl;
  if (!is_text(data)) return std::nullopt;
  const std::string_view w = first_word(data);
  if (w == "solid") return SurfaceFormat::stl;
  if (off_header(w)) return SurfaceFormat::off;
  if (obj_statement(w)) return SurfaceFormat::obj;
  return std::nullopt;
}

std::string describe_content(std::string_view data) {
  if (data.empty()) return "empty";
  if (const auto f = sniff_format(data)) {
    if (*f == SurfaceFormat::stl) return binary_stl_size(data) ? "binary STL" : "ASCII STL";
    if (*f == SurfaceFormat::ply) return "PLY";
    return std::string(format_name(*f)) + " text";
  }
  return is_text(data) ? "text" : "binary data";
}

TriangleSoup read_surface(const std::string& file, const std::string& data, std::optional<SurfaceFormat> format) {
  const std::optional<SurfaceFormat> seen = sniff_format(data);
  if (!format && !seen)
    throw ReadError(file + ": cannot tell the format of the content (" + describe_content(data) +
                    "): expected OFF, OBJ, PLY or STL (--format off, obj, ply or stl says which)");
  if (format && seen && *seen != *format) {
    std::string seen_name(format_name(*seen));
    for (char& c : seen_name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    throw ReadError(file + ": the content is " + describe_content(data) + ", not " + std::string(format_name(*format)) +
                    " (to read it as " + std::string(format_name(*seen)) + ": --format " + seen_name + ")");
  }
  switch (format.value_or(*seen)) {
    case SurfaceFormat::off: return read_off(file, data);
    case SurfaceFormat::obj: return read_obj(file, data);
    case SurfaceFormat::ply: return read_ply(file, data);
    case SurfaceFormat::stl: return read_stl(file, data);
  }
  return {};
}

}  // namespace bccmis::io
