// bccmis mesh INPUT -o FILE...: the graded BCC tetrahedral mesh of a 3D state
// or trace (spec/mesh3d.md), written as .vtu, .msh or .mesh by the
// extension, with --stats for counts and dihedral angles; and the writer
// choice that replay --mesh shares.
#include <array>
#include <cstdio>
#include <iostream>
#include <string>

#include "bccmis/d3/lattice.h"
#include "bccmis/d3/mesh.h"
#include "bccmis/io/medit.h"
#include "bccmis/io/msh.h"
#include "bccmis/io/vtu.h"
#include "bccmis/json_writer.h"
#include "bccmis/trace.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

namespace {

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string stats_text(const d3::MeshQuality& q, bool json) {
  const auto fixed6 = [](double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", x);
    return std::string(buf);
  };
  if (json) {
    JsonWriter w;
    w.begin_object()
        .member("vertices", q.vertices)
        .member("tetrahedra", q.tetrahedra)
        .member("boundary_triangles", q.boundary_triangles);
    w.key("min_dihedral").json_value(fixed6(q.min_dihedral)).key("max_dihedral").json_value(fixed6(q.max_dihedral));
    w.key("dihedral_histogram").begin_object();
    for (std::size_t k = 0; k < q.histogram.size(); ++k) w.member(std::to_string(15 * k), q.histogram[k]);
    w.end_object().end_object();
    return w.str() + "\n";
  }
  std::string out = "vertices " + std::to_string(q.vertices) + "\ntetrahedra " + std::to_string(q.tetrahedra) +
                    "\nboundary_triangles " + std::to_string(q.boundary_triangles) + "\nmin_dihedral " +
                    fixed6(q.min_dihedral) + "\nmax_dihedral " + fixed6(q.max_dihedral) + "\n";
  for (std::size_t k = 0; k < q.histogram.size(); ++k)
    if (q.histogram[k] != 0) out += "dihedral_" + std::to_string(15 * k) + " " + std::to_string(q.histogram[k]) + "\n";
  return out;
}

}  // namespace

void check_mesh_path(const std::string& path) {
  if (path == "-")
    throw InputError(
        "mesh output '-': a mesh is written to a file whose extension names the format (.vtu, .msh, .mesh)");
  if (!ends_with(path, ".vtu") && !ends_with(path, ".msh") && !ends_with(path, ".mesh"))
    throw InputError("mesh output '" + path +
                     "': unknown format; the extension names it: .vtu (VTK XML), .msh (Gmsh 4.1), .mesh (Medit)");
}

void add_mesh_output(OutputSet& outputs, const std::string& path, const d3::TetMesh& mesh, io::Encoding encoding) {
  check_mesh_path(path);
  if (ends_with(path, ".vtu")) outputs.add(path, [&](std::ostream& out) { io::write_vtu(out, mesh, encoding); });
  if (ends_with(path, ".msh")) outputs.add(path, [&](std::ostream& out) { io::write_msh(out, mesh, encoding); });
  if (ends_with(path, ".mesh")) outputs.add(path, [&](std::ostream& out) { io::write_medit(out, mesh); });
}

int run(const MeshOptions& o) {
  for (const std::string& path : o.outputs) check_mesh_path(path);
  if (o.outputs.empty() && !o.stats) throw InputError("nothing to do: give -o FILE (.vtu, .msh, .mesh) or --stats");
  const std::string name = display_name(o.input);
  const std::string text = read_input(o.input);
  // A canonical state, or a trace replayed on the reference.
  const AnyState state = text.starts_with("bccmis-state ") ? parse_any_state(text, name) : [&]() -> AnyState {
    std::string log;
    const AnyTrace trace = parse_any_trace(text, name);
    if (const auto* t3 = std::get_if<d3::Trace>(&trace)) return replay<d3::Graph>(*t3, log);
    return replay<Graph>(std::get<Trace>(trace), log);
  }();
  const auto* g = std::get_if<d3::Graph>(&state);
  if (!g)
    throw InputError(
        name + ": a 2D lattice; bccmis mesh writes the tetrahedra of 3D lattices (2D: bccmis render, heightfield)");
  // The mesh is defined for valid states only (spec/mesh3d.md): layers 1-4
  // always, and with --check the mesh layer on what is written.
  if (auto v = check_message(*g, o.check ? 5 : 4)) throw CheckFailure(name + ": " + *v);
  const std::vector<d3::Tet> tets = d3::tetrahedra(*g);
  const d3::TetMesh mesh = d3::index_mesh(*g, tets);
  OutputSet outputs;
  for (const std::string& path : o.outputs) add_mesh_output(outputs, path, mesh, output_encoding(o.binary, o.compress));
  if (o.stats) outputs.add("-", stats_text(d3::mesh_quality(tets), o.json));
  outputs.commit();
  if (!o.quiet && !o.outputs.empty())
    std::cerr << "bccmis mesh: " << name << ": " << mesh.vertices.size() << " vertices, " << mesh.tets.size()
              << " tetrahedra written to " << o.outputs.size() << " file" << (o.outputs.size() == 1 ? "" : "s") << "\n";
  return kExitOk;
}

}  // namespace bccmis::cli
