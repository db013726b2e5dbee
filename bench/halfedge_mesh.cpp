// The only translation unit of bench/ that includes CGAL.
#include "halfedge_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace bccmis::bench {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

template <class P, class Make>
HalfedgeMeshStats build(const Triangulation& t, Make make_point, bool reserve,
                        const std::function<std::size_t()>& live_bytes) {
  HalfedgeMeshStats s;
  const std::size_t before = live_bytes();
  {
    CGAL::Surface_mesh<P> mesh;
    // Euler: E = V + F - 1 for a triangulated disk.
    if (reserve)
      mesh.reserve(static_cast<typename CGAL::Surface_mesh<P>::size_type>(t.points.size()),
                   static_cast<typename CGAL::Surface_mesh<P>::size_type>(t.points.size() + t.triangles.size()),
                   static_cast<typename CGAL::Surface_mesh<P>::size_type>(t.triangles.size()));
    std::vector<typename CGAL::Surface_mesh<P>::Vertex_index> v;
    v.reserve(t.points.size());
    for (const auto& p : t.points) v.push_back(mesh.add_vertex(make_point(p)));
    std::size_t added = 0;
    for (const auto& f : t.triangles)
      added += mesh.add_face(v[f[0]], v[f[1]], v[f[2]]) != CGAL::Surface_mesh<P>::null_face();
    v.clear();
    v.shrink_to_fit();
    s.vertices = mesh.number_of_vertices();
    s.edges = mesh.number_of_edges();
    s.faces = mesh.number_of_faces();
    s.ok = added == t.triangles.size();
    s.bytes = live_bytes() - before;
  }
  return s;
}

}  // namespace

HalfedgeMeshStats surface_mesh_of(const Triangulation& t, bool point3, bool reserve,
                                  const std::function<std::size_t()>& live_bytes) {
  if (point3)
    return build<K::Point_3>(
        t, [](const std::array<double, 2>& p) { return K::Point_3(p[0], p[1], 0); }, reserve, live_bytes);
  return build<K::Point_2>(
      t, [](const std::array<double, 2>& p) { return K::Point_2(p[0], p[1]); }, reserve, live_bytes);
}

}  // namespace bccmis::bench
