// The fast stuffing path against the reference (spec/stuffing.md S3-S9):
// background_fast and background reach the same lattice state, fast::
// tetrahedra and d3::tetrahedra the same graded mesh, and stuff() on either
// lattice the same Stuffed mesh, compared exactly: the same vertices (bit for
// bit) in the same order (S8's key order), the same kinds, the same
// tetrahedra with the same vertex order and levels, the same counts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/fast/d3/mesh.h"
#include "bccmis/io/d3/format.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {
namespace {

/// The first difference between a and b, empty when they are identical.
std::string first_difference(const Stuffed& a, const Stuffed& b) {
  std::ostringstream why;
  why.precision(17);
  if (a.lattice_tetrahedra != b.lattice_tetrahedra) return "lattice_tetrahedra";
  if (a.cut_points != b.cut_points) return "cut_points";
  if (a.warped != b.warped) return "warped";
  const d3::TetMeshF &m = a.mesh, &n = b.mesh;
  if (m.vertices.size() != n.vertices.size()) return "vertex count";
  if (m.kind != n.kind) return "vertex kinds";
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      if (std::memcmp(&m.vertices[i][k], &n.vertices[i][k], sizeof(double)) != 0) {
        why << "vertex " << i << " coordinate " << k << ": " << m.vertices[i][k] << " != " << n.vertices[i][k];
        return why.str();
      }
  if (m.tets.size() != n.tets.size()) return "tetrahedron count";
  for (std::size_t i = 0; i < m.tets.size(); ++i)
    if (m.tets[i] != n.tets[i]) {
      why << "tetrahedron " << i;
      return why.str();
    }
  if (m.level != n.level) return "levels";
  return {};
}

struct Case {
  const char* name;
  std::shared_ptr<const Shape> shape;
  int level;
  int cells;  ///< N: small keeps the reference's Debug run short
};

void expect_same(const Case& c) {
  SCOPED_TRACE(c.name);
  StuffOptions o;
  o.max_level = c.level;
  o.cells = c.cells;
  const Fit fit = fit_lattice(c.shape->bounds(), o);
  const d3::Graph g = background(*c.shape, fit, o);
  const d3::fast::Lattice f = background_fast(*c.shape, fit, o);
  ASSERT_EQ(d3::fast::canonical_state(f), d3::canonical_state(g));  // S3
  ASSERT_EQ(d3::fast::tetrahedra(f), d3::tetrahedra(g));            // spec/mesh3d.md M1-M3
  const Stuffed reference = stuff(*c.shape, fit, g, o);
  const Stuffed flat = stuff(*c.shape, fit, f, o);
  EXPECT_GT(reference.mesh.tets.size(), 0U);
  EXPECT_GT(reference.cut_points + reference.warped, 0U);  // the surface crosses the lattice
  EXPECT_EQ(first_difference(flat, reference), "");
}

// Larger runs (levels 2-5 of the sphere and the torus, in Release):
// bench_stuff, which compares the two meshes wherever the reference runs.
TEST(StuffFast, SphereL2OffCenter) {
  expect_same({"sphere L2 off-center", make_sphere({0.123, -0.071, 0.0317}, 1), 2, 3});
}
TEST(StuffFast, TorusL2OffCenter) {
  expect_same({"torus L2 off-center", make_torus({0.05, -0.021, 0.013}, 1, 0.4), 2, 4});
}
TEST(StuffFast, TwoSpheresL2) {
  expect_same({"two spheres L2", make_spheres({-0.5, 0.03, 0}, {0.5, 0.1, -0.02}, 0.7), 2, 3});
}

TEST(StuffFast, TheSameMeshOnOneTwoAndThreeThreads) {
  // S28a: the renumbering, the cut edges' listing and the stencils run over
  // ranges of the lattice tetrahedra, joined in order; on 1, 2 and 3 threads
  // the mesh is the reference stuffer's, and stuff_part's record of where
  // each lattice tetrahedron's output begins is the one-thread record.
  StuffOptions o;
  o.max_level = 2;
  o.cells = 4;
  const auto torus = make_torus({0.05, -0.021, 0.013}, 1, 0.4);
  const Fit fit = fit_lattice(torus->bounds(), o);
  const d3::Graph g = background(*torus, fit, o);
  const d3::fast::Lattice f = background_fast(*torus, fit, o);
  const Stuffed reference = stuff(*torus, fit, g, o);
  const std::vector<d3::Tet> tets = d3::fast::tetrahedra(f);
  ASSERT_GT(tets.size(), 3U * 256);  // three ranges of at least 256 (S28a)
  o.threads = 1;
  const StuffedPart one = stuff_part(*torus, fit, f, o, tets);
  ASSERT_EQ(one.begin.size(), tets.size() + 1);
  EXPECT_EQ(one.begin.back(), one.stuffed.mesh.tets.size());
  for (const int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    o.threads = threads;
    EXPECT_EQ(first_difference(stuff(*torus, fit, f, o), reference), "");
    const StuffedPart part = stuff_part(*torus, fit, f, o, tets);
    EXPECT_EQ(first_difference(part.stuffed, reference), "");
    EXPECT_EQ(part.begin, one.begin);
    EXPECT_EQ(part.keys, one.keys);
  }
}

TEST(StuffFast, TheSameLatticeOnOneTwoAndThreeThreads) {
  // S28c: each pass's S3 tests run over ranges of its leaves (at least 256
  // a range), the refinements then applied in order; on 1, 2 and 3 threads
  // the lattice is the reference's, built by the serial passes. The passes
  // here hold 18, 144, 1,096 and 6,416 leaves: the third, which refines, is
  // split into two and three ranges.
  StuffOptions o;
  o.max_level = 3;
  o.cells = 3;
  const auto torus = make_torus({0.05, -0.021, 0.013}, 1, 0.4);
  const Fit fit = fit_lattice(torus->bounds(), o);
  const std::string reference = d3::canonical_state(background(*torus, fit, o));
  for (const int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    o.threads = threads;
    const d3::fast::Lattice f = background_fast(*torus, fit, o);
    EXPECT_EQ(f.cell_count(), 6416U);
    EXPECT_TRUE(d3::fast::canonical_state(f) == reference) << "the canonical states differ";
  }
}

TEST(StuffFast, StuffShapeRunsEitherLattice) {
  StuffOptions o;
  o.max_level = 2;
  o.cells = 3;
  const auto sphere = make_sphere({0, 0, 0}, 1);
  PhaseTimes tf, tr;
  const Stuffed flat = stuff_shape(*sphere, o, Impl::fast, &tf);
  const Stuffed reference = stuff_shape(*sphere, o, Impl::reference, &tr);
  EXPECT_GT(flat.mesh.tets.size(), 0U);
  EXPECT_EQ(first_difference(flat, reference), "");
  EXPECT_GT(tf.total(), 0);
  EXPECT_GT(tr.lattice, 0);
}

/// A torus off the lattice's symmetry at level 2, on `threads` threads.
struct TorusRun {
  explicit TorusRun(int threads) {
    o.max_level = 2;
    o.cells = 4;
    o.threads = threads;
    fit = fit_lattice(torus->bounds(), o);
  }
  static std::unique_ptr<Shape> shape() { return make_torus({0.05, -0.021, 0.013}, 1, 0.4); }
  /// b is a, which has tetrahedra and warped vertices.
  static void expect_same(const Stuffed& b, const Stuffed& a) {
    EXPECT_GT(a.mesh.tets.size(), 0U);
    EXPECT_GT(a.warped, 0U);
    EXPECT_EQ(first_difference(b, a), "");
  }
  StuffOptions o;
  std::unique_ptr<Shape> torus = shape();
  Fit fit;
};

TEST(StuffFast, FreeingTheLatticeAfterTheWarpChangesNoByte) {
  // spec/mesh3d.md M26: stuff() on a lattice it may free reads every leaf's
  // level before freeing it after S6, and makes the same mesh as stuff() on
  // a lattice it keeps, on one thread and on two; the lattice is freed.
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(threads);
    const TorusRun r(threads);
    const d3::fast::Lattice kept = background_fast(*r.torus, r.fit, r.o);
    d3::fast::Lattice freed = background_fast(*r.torus, r.fit, r.o);
    ASSERT_GT(freed.memory_bytes(), 0U);
    TorusRun::expect_same(stuff(*r.torus, r.fit, std::move(freed), r.o), stuff(*r.torus, r.fit, kept, r.o));
    EXPECT_EQ(freed.memory_bytes(), 0U);  // NOLINT(bugprone-use-after-move): moved from, its memory freed
  }
}

/// A shape whose side() answers 256 times the sign (S5 reads only the sign):
/// a stuffer that kept the answer in a byte as it is would read 0.
class WideSides : public Shape {
 public:
  explicit WideSides(std::unique_ptr<Shape> inner) : inner_(std::move(inner)) {}
  double signed_distance(const Vec3& p) const override { return inner_->signed_distance(p); }
  int side(const Vec3& p) const override { return 256 * inner_->side(p); }
  double crossing(const Vec3& a, const Vec3& b) const override { return inner_->crossing(a, b); }
  Bounds bounds() const override { return inner_->bounds(); }
  double volume() const override { return inner_->volume(); }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    return inner_->sample_surface(n, seed);
  }
  std::string describe() const override { return "wide " + inner_->describe(); }

 private:
  std::unique_ptr<Shape> inner_;
};

TEST(StuffFast, OnlyTheSignOfSideEnters) {
  //= spec/stuffing.md S28d type=test
  // The flat stuffer keeps each vertex's side as a byte, the sign of what
  // side() answers: a side of +-256 makes the mesh of +-1, on one thread and
  // on two.
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(threads);
    const TorusRun r(threads);
    const WideSides wide(TorusRun::shape());
    const d3::fast::Lattice g = background_fast(*r.torus, r.fit, r.o);
    TorusRun::expect_same(stuff(wide, r.fit, g, r.o), stuff(*r.torus, r.fit, g, r.o));
  }
}

TEST(StuffFast, TheComparisonSeesOneChange) {
  // The comparison can fail: one coordinate one ulp off, one kind, one
  // tetrahedron's vertex order, one level.
  StuffOptions o;
  o.max_level = 2;
  o.cells = 3;
  const auto sphere = make_sphere({0, 0, 0}, 1);
  const Stuffed s = stuff_shape(*sphere, o, Impl::fast, nullptr);
  ASSERT_EQ(first_difference(s, s), "");
  Stuffed t = s;
  t.mesh.vertices[7][1] = std::nextafter(t.mesh.vertices[7][1], 2.0);
  EXPECT_EQ(first_difference(t, s).substr(0, 8), "vertex 7");
  t = s;
  t.mesh.kind.back() ^= 1;
  EXPECT_EQ(first_difference(t, s), "vertex kinds");
  t = s;
  std::swap(t.mesh.tets[3][2], t.mesh.tets[3][3]);
  EXPECT_EQ(first_difference(t, s), "tetrahedron 3");
  t = s;
  t.mesh.level[0] += 1;
  EXPECT_EQ(first_difference(t, s), "levels");
}

}  // namespace
}  // namespace bccmis::stuff
