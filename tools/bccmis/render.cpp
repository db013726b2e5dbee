// bccmis render STATE -o FILE: a state (or a trace's final state) as SVG;
// a 3D state as the box and one slice; a tetrahedral Medit mesh as its
// boundary (and a cut-away) or its dihedral-angle histogram (spec/cli.md,
// render).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "bccmis/io/medit.h"
#include "bccmis/io/msh.h"
#include "bccmis/io/vtu.h"
#include "bccmis/oracle/oracle.h"
#include "bccmis/stuff/mesh_picture.h"
#include "bccmis/stuff/stuff.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

namespace {

// "--slice AXIS=VALUE" for a 3D lattice of `size`; the middle z plane when empty.
SlicePlane parse_slice(const std::string& text, const d3::LatticeSize& size) {
  if (text.empty()) return middle_slice(size);
  const std::string axes = "xyz";
  const auto bad = [&](const std::string& why) { return InputError("--slice '" + text + "': " + why); };
  if (text.size() < 3 || text[1] != '=' || axes.find(text[0]) == std::string::npos)
    throw bad("expected AXIS=VALUE with AXIS x, y or z, e.g. z=2");
  SlicePlane s{static_cast<int>(axes.find(text[0])), 0};
  const char* first = text.data() + 2;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(first, last, s.value);
  if (ec != std::errc() || end != last) throw bad("the value must be an integer");
  const std::int64_t S = d3::level0_side(size);
  const std::int64_t extent = (s.axis == 0 ? size.W : s.axis == 1 ? size.H : size.D) * S;
  if (s.value < 0 || s.value > extent)
    throw bad("outside the box: " + std::string(1, text[0]) + " in [0, " + std::to_string(extent) + "]");
  return s;
}

// "--slice AXIS=VALUE" for a mesh: a real VALUE within the mesh's extent along AXIS.
stuff::CutPlane parse_cut(const std::string& text, const d3::TetMeshF& mesh) {
  const std::string axes = "xyz";
  const auto bad = [&](const std::string& why) { return InputError("--slice '" + text + "': " + why); };
  if (text.size() < 3 || text[1] != '=' || axes.find(text[0]) == std::string::npos)
    throw bad("expected AXIS=VALUE with AXIS x, y or z, e.g. z=0.5");
  stuff::CutPlane c{static_cast<int>(axes.find(text[0])), 0};
  const char* first = text.data() + 2;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(first, last, c.value);
  if (ec != std::errc() || end != last || !std::isfinite(c.value)) throw bad("the value must be a number");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const d3::Vec3& p : mesh.vertices) {
    lo = std::min(lo, p[static_cast<std::size_t>(c.axis)]);
    hi = std::max(hi, p[static_cast<std::size_t>(c.axis)]);
  }
  if (!(lo <= c.value && c.value <= hi)) {
    char range[96];
    std::snprintf(range, sizeof range, "outside the mesh: %c in [%g, %g]", text[0], lo, hi);
    throw bad(mesh.vertices.empty() ? std::string("the mesh has no vertices") : std::string(range));
  }
  return c;
}

bool ends_with(const std::string& path, std::string_view ext) {
  return path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
}

// A tetrahedral mesh file, read by its extension: Medit, Gmsh or VTK.
bool is_mesh_file(const std::string& path) {
  return ends_with(path, ".mesh") || ends_with(path, ".msh") || ends_with(path, ".vtu");
}

d3::TetMeshF read_mesh_file(const std::string& path, const std::string& name) {
  const std::string text = read_input(path);
  if (ends_with(path, ".msh")) return io::read_msh(text, name, stuff::orientation);
  if (ends_with(path, ".vtu")) return io::read_vtu(text, name, stuff::orientation);
  return io::read_medit(text, name, stuff::orientation);
}

int run_mesh(const RenderOptions& o) {
  const std::string name = display_name(o.state);
  if (o.from_trace) throw InputError(name + ": a mesh file; --from-trace applies to traces");
  if (o.histogram && !o.slice.empty()) throw InputError("--histogram draws no cut-away; drop --slice");
  const d3::TetMeshF mesh = read_mesh_file(o.state, name);
  std::string svg;
  if (o.histogram) {
    svg = stuff::render_histogram_svg(mesh, name);
  } else {
    std::optional<stuff::CutPlane> cut;
    if (!o.slice.empty()) cut = parse_cut(o.slice, mesh);
    svg = stuff::render_mesh_svg(mesh, name, cut);
  }
  write_atomically(o.output, svg);
  return kExitOk;
}

}  // namespace

int run(const RenderOptions& o) {
  if (is_mesh_file(o.state)) return run_mesh(o);
  if (o.histogram) throw InputError(display_name(o.state) + ": --histogram applies to a mesh file (.mesh, .msh, .vtu)");
  const AnyState state = read_any_state_or_trace(o.state, o.from_trace);
  const std::string svg = std::visit(
      [&](const auto& g) {
        if constexpr (std::is_same_v<std::decay_t<decltype(g)>, d3::Graph>) {
          return d3::render_svg(g, display_name(o.state), parse_slice(o.slice, g.size));
        } else {
          if (!o.slice.empty())
            throw InputError(display_name(o.state) + ": a 2D lattice; --slice applies to 3D states");
          return render_svg(g, display_name(o.state));
        }
      },
      state);
  write_atomically(o.output, svg);
  return kExitOk;
}

}  // namespace bccmis::cli
