#include "stuff_input.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "bccmis/io/medit.h"
#include "bccmis/io/msh.h"
#include "bccmis/io/obj.h"
#include "bccmis/io/off.h"
#include "bccmis/io/surface_format.h"
#include "bccmis/io/vtu.h"
#include "bccmis/stuff/animate_shape.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/soup_report.h"
#include "io.h"

namespace bccmis::cli {

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

io::Encoding encoding(const StuffOptions& o) { return output_encoding(o.binary, o.compress); }

void add_tetrahedra_output(OutputSet& outputs, const std::string& path, const d3::TetMeshF& mesh,
                           const io::Regions& regions, io::Encoding encoding) {
  if (ends_with(path, ".vtu")) outputs.add(path, [&](std::ostream& out) { io::write_vtu(out, mesh, encoding); });
  if (ends_with(path, ".msh"))
    outputs.add(path, [&](std::ostream& out) { io::write_msh(out, mesh, regions, encoding); });
  if (ends_with(path, ".mesh")) outputs.add(path, [&](std::ostream& out) { io::write_medit(out, mesh, regions); });
}

void add_mesh_outputs(OutputSet& outputs, const StuffOptions& o, const d3::TetMeshF& mesh, const io::Regions& regions,
                      const std::vector<std::array<std::uint32_t, 3>>& boundary) {
  const bool all = o.surface_vertices == "all";
  for (const std::string& path : o.outputs) {
    add_tetrahedra_output(outputs, path, mesh, regions, encoding(o));
    if (ends_with(path, ".off"))
      outputs.add(path, [&, all](std::ostream& out) { io::write_off(out, mesh, boundary, all); });
    if (ends_with(path, ".obj"))
      outputs.add(path, [&, all](std::ostream& out) { io::write_obj(out, mesh, boundary, all); });
  }
}

std::shared_ptr<const stuff::Shape> load_shape(const StuffOptions& o) {
  if (!o.shape.empty() && !o.input.empty()) throw InputError("give either an input mesh or --shape, not both");
  if (o.shape.empty() && o.input.empty())
    throw InputError("nothing to mesh: give an input mesh (.off, .obj, .ply, .stl) or --shape NAME");
  if (!o.shape.empty()) return stuff::make_builtin(o.shape);
  std::optional<io::SurfaceFormat> format;
  if (o.format == "off") format = io::SurfaceFormat::off;
  if (o.format == "obj") format = io::SurfaceFormat::obj;
  if (o.format == "ply") format = io::SurfaceFormat::ply;
  if (o.format == "stl") format = io::SurfaceFormat::stl;
  return stuff::load_mesh_file(o.input, o.strict, format);
}

std::string soup_notices(const std::string& tool, const stuff::Shape& shape) {
  const stuff::SoupReport* r = shape.soup_report();
  if (!r) return "";
  std::string out;
  if (r->flaw_count() > 0)
    out += tool + ": " + r->file + ": " + r->summary() +
           ": meshed as the solid where the winding number >= 1/2; --strict refuses\n";
  if (r->welded_vertices > 0)
    out += tool + ": " + r->file + ": " + std::to_string(r->welded_vertices) +
           " repeated vertices welded (the coordinates of an earlier vertex)\n";
  return out;
}

stuff::Vec3 parse_path(const std::string& text, const stuff::Shape& shape) {
  if (text.empty()) return stuff::default_path(shape);
  stuff::Vec3 d{};
  std::size_t at = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t end = i < 2 ? text.find(',', at) : text.size();
    if (end == std::string::npos) throw InputError("--path '" + text + "': expected DX,DY,DZ");
    const std::string item = text.substr(at, end - at);
    const auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), d[i]);
    if (item.empty() || ec != std::errc() || ptr != item.data() + item.size() || !std::isfinite(d[i]))
      throw InputError("--path '" + text + "': '" + item + "' is not a number");
    at = end + 1;
  }
  return d;
}

std::string numbered(const std::string& stem, int k, std::string_view extension) {
  char digits[16];
  std::snprintf(digits, sizeof digits, "_%04d", k);
  return stem + digits + std::string(extension);
}

stuff::StuffOptions lattice_options(const StuffOptions& o) {
  stuff::StuffOptions lattice;
  lattice.max_level = o.max_level;
  lattice.min_level = o.min_level;
  lattice.cells = o.cells;
  if (o.size > 0) lattice.size = o.size;
  lattice.threads = o.threads;
  return lattice;
}

}  // namespace bccmis::cli
