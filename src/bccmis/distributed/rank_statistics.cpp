// spec/distributed.md D11: S13's statistics of the mesh the ranks' pieces
// make, each rank's part over what it owns, reduced on rank 0.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "bccmis/distributed/ranks.h"
#include "bccmis/stuff/topology.h"

namespace bccmis::distributed {

namespace {

using Face = std::array<std::int64_t, 3>;

/// D11: the faces in exactly one tetrahedron of the piece, as sorted triples
/// of global ids: S11's boundary faces of its tetrahedra and the faces it
/// shares with another piece.
std::vector<Face> piece_faces(const LeafPiece& piece, std::span<const std::int64_t> ids) {
  std::vector<Face> faces;
  for (const auto& t : stuff::boundary_triangles(piece.mesh)) {
    Face f{ids[t[0]], ids[t[1]], ids[t[2]]};
    std::sort(f.begin(), f.end());
    faces.push_back(f);
  }
  return faces;
}

/// D11, on rank 0: the faces sent once (a face lies in at most two
/// tetrahedra of the mesh: one between two pieces is sent twice), their
/// vertices renumbered 0 .. m-1, and m.
std::vector<std::array<std::uint32_t, 3>> boundary_of(std::vector<Face> faces, std::size_t& vertices) {
  std::sort(faces.begin(), faces.end());
  std::vector<Face> once;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i == 1) once.push_back(faces[i]);
    i = j;
  }
  std::vector<std::int64_t> used;
  for (const Face& f : once) used.insert(used.end(), f.begin(), f.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  vertices = used.size();
  std::vector<std::array<std::uint32_t, 3>> boundary;
  for (const Face& f : once) {
    std::array<std::uint32_t, 3> t{};
    for (std::size_t i = 0; i < 3; ++i)
      t[i] = static_cast<std::uint32_t>(std::lower_bound(used.begin(), used.end(), f[i]) - used.begin());
    boundary.push_back(t);
  }
  return boundary;
}

}  // namespace

stuff::Meshed rank_statistics(const stuff::Shape& world, const Replicated& r, const LeafPiece& piece,
                              const stuff::StuffQuality& quality, std::span<const std::int64_t> ids,
                              std::span<const std::uint8_t> owned, std::int64_t leaves, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // D11: counts of what this rank owns, summed on rank 0 (exact).
  enum : std::size_t { kTets, kLatticeTets, kVertices, kCut, kBelow10, kHistogram };
  std::array<std::uint64_t, kHistogram + 13> counts{};
  counts[kTets] = piece.mesh.tets.size();
  counts[kLatticeTets] = piece.lattice_tetrahedra;
  for (std::size_t v = 0; v < owned.size(); ++v) {
    if (!owned[v]) continue;
    ++counts[kVertices];
    counts[kCut] += piece.mesh.kind[v] == static_cast<std::uint8_t>(stuff::StuffVertex::cut) ? 1 : 0;
  }
  counts[kBelow10] = quality.below10;
  for (std::size_t k = 0; k < 13; ++k) counts[kHistogram + k] = quality.histogram[k];
  std::array<std::uint64_t, kHistogram + 13> sums{};
  MPI_Reduce(counts.data(), sums.data(), static_cast<int>(counts.size()), MPI_UINT64_T, MPI_SUM, 0, comm);
  // The extremes by min and max (exact: each the angle of an extreme cosine);
  // a rank without tetrahedra has none.
  const bool none = piece.mesh.tets.empty();
  double extremes[2] = {none ? std::numeric_limits<double>::infinity() : quality.min_dihedral,
                        none ? std::numeric_limits<double>::infinity() : -quality.max_dihedral};
  double reduced[2] = {0, 0};
  MPI_Reduce(extremes, reduced, 2, MPI_DOUBLE, MPI_MIN, 0, comm);
  // The volume: the ranks' sums added in rank order (rounded, D11).
  int size = 0;
  MPI_Comm_size(comm, &size);
  std::vector<double> volumes(rank == 0 ? static_cast<std::size_t>(size) : 0);
  MPI_Gather(&quality.volume, 1, MPI_DOUBLE, volumes.data(), 1, MPI_DOUBLE, 0, comm);
  // S11's boundary from the faces sent once.
  const std::vector<Face> faces = piece_faces(piece, ids);
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(faces.data()), faces.size() * sizeof(Face));
  const std::vector<std::vector<std::byte>> all = gather_bytes(bytes, 0, comm);
  if (rank != 0) return {};

  std::vector<Face> every;
  for (const auto& b : all) {
    const std::size_t at = every.size();
    every.resize(at + b.size() / sizeof(Face));
    if (!b.empty()) std::memcpy(every.data() + at, b.data(), b.size());
  }
  std::size_t boundary_vertices = 0;
  const std::vector<std::array<std::uint32_t, 3>> boundary = boundary_of(std::move(every), boundary_vertices);
  d3::TetMeshF vertices_only;  // S27's topology reads the boundary and the vertex count only
  vertices_only.vertices.resize(boundary_vertices);

  stuff::Meshed m;
  const stuff::Normalisation& n = r.normalisation;
  m.fit = r.fit;
  m.fit.origin = n.to_world(r.fit.origin);
  m.fit.scale = std::ldexp(r.fit.scale, n.exponent);
  m.fit.h = std::ldexp(r.fit.h, n.exponent);
  m.leaves = static_cast<std::size_t>(leaves);
  m.stuffed.lattice_tetrahedra = sums[kLatticeTets];
  m.stuffed.cut_points = sums[kCut];
  m.not_computed = {"warped"};  // D11: S6's warped vertices are not all in the pieces
  stuff::Statistics s;
  s.quality.below10 = sums[kBelow10];
  for (std::size_t k = 0; k < 13; ++k) s.quality.histogram[k] = sums[kHistogram + k];
  s.tetrahedra = sums[kTets];
  s.vertices = sums[kVertices];
  s.quality.min_dihedral = s.tetrahedra ? reduced[0] : 0;
  s.quality.max_dihedral = s.tetrahedra ? -reduced[1] : 0;
  for (const double v : volumes) s.quality.volume += v;
  s.quality.boundary_triangles = boundary.size();
  s.shape_volume = r.shape->volume();
  s.relative_volume_error = (s.quality.volume - s.shape_volume) / s.shape_volume;
  m.statistics = stuff::to_world(s, n);
  if (const stuff::SoupReport* soup = world.soup_report()) m.soup = *soup;
  m.topology = stuff::topology(vertices_only, boundary);
  m.warnings = stuff::mesh_warnings(world, m.topology, m.fit);  // S26, S27; throws when a component is lost
  return m;
}

}  // namespace bccmis::distributed
