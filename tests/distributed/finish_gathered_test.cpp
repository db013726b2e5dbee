// spec/distributed.md D12 in one process: the pieces of a split in two
// runs (as p8est partitions), kept in S24's local coordinates and gathered, then the feature
// step and --check's layers (finish_gathered), are mesh_shape()'s mesh with
// the features, bit for bit, and their report (D13: S13's statistics, S27's
// topology and warnings, S33's feature report) is mesh_shape()'s; a gathered
// mesh with a boundary vertex moved off the surface fails --check's
// stuffed-mesh layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

#include "bccmis/distributed/gathered.h"
#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/stuff/conform_features.h"
#include "bccmis/stuff/mesh_shape.h"

namespace bccmis::distributed {
namespace {

constexpr const char* kFandisk = BCCMIS_CGAL_MESHES_DIR "/fandisk.off";  // creases and corners

stuff::StuffOptions level2() {
  stuff::StuffOptions options;
  options.max_level = 2;
  return options;
}

/// fandisk as read (load_mesh_file, as bccmis stuff reads it), read once.
const stuff::Shape& fandisk() {
  static const std::unique_ptr<stuff::Shape> world = stuff::load_mesh_file(kFandisk);
  return *world;
}

/// Its lattice at level 2 (S24, S2, S3 as every rank makes them), made once.
const Replicated& lattice() {
  static const Replicated r = replicate(fandisk(), level2(), 18);
  return r;
}

/// fandisk at level 2 in two pieces, the first and the second half of the
/// leaves, gathered in local coordinates (D3-D5, no world map).
d3::TetMeshF gathered(const Replicated& r) {
  const std::vector<d3::Point> leaves = r.lattice->cells();
  const auto half = leaves.begin() + static_cast<std::ptrdiff_t>(leaves.size() / 2);
  const std::vector<d3::Point> own[] = {{leaves.begin(), half}, {half, leaves.end()}};
  std::vector<LeafPiece> pieces;
  for (const auto& o : own) pieces.push_back(stuff_leaves(*r.shape, r.fit, *r.lattice, r.options, o));
  return gather_pieces(pieces);
}

TEST(FinishGathered, FeaturesOnTheGatheredMeshAreTheSerialOnes) {
  const stuff::Shape* world = &fandisk();
  stuff::Settings settings;
  settings.lattice = level2();
  settings.features.on = true;
  settings.statistics = true;
  const stuff::Meshed serial = stuff::mesh_shape(*world, settings);
  // The features changed the mesh: some vertex snapped (S30).
  ASSERT_TRUE(std::count(serial.stuffed.mesh.kind.begin(), serial.stuffed.mesh.kind.end(), stuff::kSnappedVertex) > 0);
  const Replicated& r = lattice();
  d3::TetMeshF mesh = gathered(r);
  const Finished f = finish_gathered(*world, r, mesh, settings.features, true, true);  // --check passes
  const io::Regions& regions = f.regions;
  EXPECT_TRUE(mesh.vertices == serial.stuffed.mesh.vertices);  // bit for bit, world coordinates
  EXPECT_TRUE(mesh.kind == serial.stuffed.mesh.kind);
  EXPECT_TRUE(mesh.tets == serial.stuffed.mesh.tets);
  EXPECT_TRUE(mesh.level == serial.stuffed.mesh.level);
  EXPECT_TRUE(regions.tet_component == serial.regions.tet_component);  // the writers' regions (M23)
  EXPECT_TRUE(regions.boundary == serial.regions.boundary);
  // D13: the report of the conformed mesh, as mesh_shape()'s, bit for bit.
  ASSERT_TRUE(serial.features && serial.features->edges > 0 && serial.features->distance >= 0);
  ASSERT_TRUE(f.statistics && f.features);
  const stuff::Statistics& s = *f.statistics;
  const stuff::Statistics& w = *serial.statistics;
  EXPECT_EQ(s.vertices, w.vertices);
  EXPECT_EQ(s.tetrahedra, w.tetrahedra);
  EXPECT_EQ(s.quality.volume, w.quality.volume);
  EXPECT_EQ(s.quality.min_dihedral, w.quality.min_dihedral);
  EXPECT_EQ(s.quality.max_dihedral, w.quality.max_dihedral);
  EXPECT_EQ(s.quality.below10, w.quality.below10);
  EXPECT_TRUE(s.quality.histogram == w.quality.histogram);
  EXPECT_EQ(s.quality.boundary_triangles, w.quality.boundary_triangles);
  EXPECT_EQ(s.shape_volume, w.shape_volume);
  EXPECT_EQ(s.relative_volume_error, w.relative_volume_error);
  EXPECT_EQ(f.topology.boundary_components, serial.topology.boundary_components);
  EXPECT_EQ(f.topology.boundary_euler, serial.topology.boundary_euler);
  EXPECT_EQ(f.topology.nonmanifold_edges, serial.topology.nonmanifold_edges);
  EXPECT_TRUE(f.warnings == serial.warnings);
  const stuff::FeatureReport& a = *f.features;
  const stuff::FeatureReport& b = *serial.features;
  EXPECT_EQ(a.angle, b.angle);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.curves, b.curves);
  EXPECT_EQ(a.corners, b.corners);
  EXPECT_EQ(a.corners_conformed, b.corners_conformed);
  EXPECT_EQ(a.curves_conformed, b.curves_conformed);
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.splits, b.splits);
  EXPECT_EQ(a.splits_undone, b.splits_undone);
  EXPECT_EQ(a.moves_undone, b.moves_undone);
}

TEST(FinishGathered, CheckCatchesAVertexOffTheSurface) {
  const stuff::Shape* world = &fandisk();
  const Replicated& r = lattice();
  d3::TetMeshF mesh = gathered(r);
  stuff::FeatureSettings off;  // S11's layer alone: nothing moves the vertex back
  d3::TetMeshF good = mesh;
  EXPECT_NO_THROW(finish_gathered(*world, r, good, off, true));
  const std::uint32_t v = stuff::boundary_triangles(mesh)[0][0];
  mesh.vertices[v][0] += 0.1 * r.fit.h;  // a tenth of the finest side off the surface
  EXPECT_THROW(finish_gathered(*world, r, mesh, off, true), stuff::CheckError);
}

}  // namespace
}  // namespace bccmis::distributed
