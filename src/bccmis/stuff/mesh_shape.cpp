// The stuffing library's entry point (mesh_shape.h): S2-S13 in one call.
#include "bccmis/stuff/mesh_shape.h"

#include "bccmis/fast/d3/lattice.h"
#include "bccmis/invariants/d3/stuffed_mesh.h"
#include "bccmis/json_writer.h"
#include "bccmis/stuff/detail/stuffer.h"
#if BCCMIS_HAVE_STUFF_SURFACE
#include "bccmis/stuff/surface.h"
#endif

namespace bccmis::stuff {

namespace {
using detail::Clock;
using detail::seconds_since;
std::string number(double x) { return JsonWriter::number(x); }
}  // namespace

std::unique_ptr<Shape> load_mesh_file(const std::string& path, bool strict, std::optional<io::SurfaceFormat> format) {
#if BCCMIS_HAVE_STUFF_SURFACE
  return strict ? load_surface(path, format) : load_soup(path, format);
#else
  (void)strict, (void)format;
  throw ShapeError(path + ": this build has no CGAL, so it reads no meshes; use --shape");
#endif
}

std::optional<std::string> find_stuffed_problem(const Shape& shape, const Fit& fit, const d3::TetMeshF& mesh) {
  d3::StuffedMeshClaims claims;
  claims.distance = [&shape](const Vec3& p) { return shape.signed_distance(p); };
  // S11: cut points and warped vertices lie on the surface; 1e-9 of the
  // finest side allows for the crossing's bisection and the distance's rounding.
  claims.tolerance = 1e-9 * fit.h;
  claims.dihedral = d3::kStuffedDihedralBounds;
  if (auto v = d3::check_stuffed_mesh(mesh.vertices, mesh.tets, claims)) return v->message;
  return std::nullopt;
}

Meshed mesh_shape(const Shape& shape, const Settings& settings, const Progress& progress) {
  const auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };
  Meshed r;
  if (const SoupReport* soup = shape.soup_report()) {
    r.soup = *soup;
    if (settings.strict && soup->flaw_count() > 0)
      throw ShapeError(soup->file + ": " + soup->summary() + " (strict: only a clean closed mesh is meshed)");
  }
  StuffOptions options = settings.lattice;
  r.fit = fit_lattice(shape.bounds(), options);
  options.max_level = r.fit.size.L;
  say(shape.describe() + ": lattice " + std::to_string(r.fit.size.W) + " x " + std::to_string(r.fit.size.H) + " x " +
      std::to_string(r.fit.size.D) + ", max level " + std::to_string(r.fit.size.L) + ", finest side " +
      number(r.fit.h));
  // S3-S9 on the fast lattice, or on the reference.
  PhaseTimes times;
  const auto t0 = Clock::now();
  const auto stuff_on = [&](const auto& g, std::size_t leaves) {
    times.lattice = seconds_since(t0);
    r.leaves = leaves;
    say(std::to_string(leaves) + " leaves (" + number(times.lattice) + " s)");
    return stuff(shape, r.fit, g, options, &times);
  };
  if (settings.impl == Impl::reference) {
    const d3::Graph g = background(shape, r.fit, options);
    r.stuffed = stuff_on(g, g.C.size());
  } else {
    const d3::fast::Lattice g = background_fast(shape, r.fit, options);
    r.stuffed = stuff_on(g, g.cell_count());
  }
  r.seconds = {{"lattice", times.lattice},
               {"mesh", times.mesh},
               {"cut", times.cut},
               {"warp", times.warp},
               {"stencils", times.stencils}};
  say(std::to_string(r.stuffed.mesh.tets.size()) + " tetrahedra (" + number(times.total() - times.lattice) + " s)");

  // S21: a soup whose winding number is below 1/2 at every lattice vertex.
  if (r.soup && r.stuffed.mesh.tets.empty())
    throw ShapeError(r.soup->file + ": encloses no volume (the winding number is below 1/2 at every lattice vertex)");
  const auto t1 = Clock::now();
  r.boundary = boundary_triangles(r.stuffed.mesh);
  if (settings.check)
    if (auto why = find_stuffed_problem(shape, r.fit, r.stuffed.mesh)) throw CheckError(shape.describe() + ": " + *why);
  if (settings.statistics) r.statistics = statistics(shape, r.stuffed.mesh, r.boundary);
  r.seconds.emplace_back("statistics", seconds_since(t1));
  return r;
}

}  // namespace bccmis::stuff
