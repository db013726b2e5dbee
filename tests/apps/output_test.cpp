// The height field's output paths against the texts and values they replace:
// format_obj, format_ply and format_vtu (streamed through TextWriter) equal
// the texts built with std::string and std::to_string as spec/apps.md
// describes them; triangulate and mesh_error of the fast lattice (read from
// its pools) equal those of the reference Graph, on random states.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "bccmis/apps/heightfield.h"
#include "bccmis/apps/image.h"
#include "bccmis/apps/triangulate.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/io/obj.h"
#include "bccmis/io/ply.h"
#include "bccmis/io/vtu.h"
#include "bccmis/ops.h"

namespace bccmis {
namespace {

std::string num(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}
std::string num(std::size_t v) { return std::to_string(v); }
std::string xyz(const std::array<double, 3>& v) { return num(v[0]) + " " + num(v[1]) + " " + num(v[2]); }
std::string abc(const std::array<std::size_t, 3>& t, std::size_t base) {
  return num(t[0] + base) + " " + num(t[1] + base) + " " + num(t[2] + base);
}

std::string spec_obj(const TriangleMesh& m, const std::string& comment) {
  std::string out =
      "# " + comment + "\n# " + num(m.vertices.size()) + " vertices, " + num(m.triangles.size()) + " triangles\n";
  for (const auto& v : m.vertices) out += "v " + xyz(v) + "\n";
  for (const auto& t : m.triangles) out += "f " + abc(t, 1) + "\n";
  return out;
}

std::string spec_ply(const TriangleMesh& m, const std::string& comment) {
  std::string out = "ply\nformat ascii 1.0\ncomment " + comment + "\nelement vertex " + num(m.vertices.size()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                    num(m.triangles.size()) +
                    "\nproperty list uchar int vertex_indices\nproperty int level\nend_header\n";
  for (const auto& v : m.vertices) out += xyz(v) + "\n";
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    out += "3 " + abc(m.triangles[i], 0) + " " + std::to_string(m.triangle_level[i]) + "\n";
  return out;
}

std::string spec_vtu(const TriangleMesh& m) {
  const std::string in = "          ";
  std::string out =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
      "byte_order=\"LittleEndian\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" +
      num(m.vertices.size()) + "\" NumberOfCells=\"" + num(m.triangles.size()) + "\">\n";
  out +=
      "      <PointData Scalars=\"height\">\n        <DataArray type=\"Float64\" Name=\"height\" format=\"ascii\">\n";
  for (const auto& v : m.vertices) out += in + num(v[2]) + "\n";
  out += "        </DataArray>\n      </PointData>\n";
  out += "      <CellData Scalars=\"level\">\n        <DataArray type=\"Int32\" Name=\"level\" format=\"ascii\">\n";
  for (const int l : m.triangle_level) out += in + std::to_string(l) + "\n";
  out += "        </DataArray>\n";
  if (!m.triangle_error.empty()) {
    out += "        <DataArray type=\"Float64\" Name=\"error\" format=\"ascii\">\n";
    for (const double e : m.triangle_error) out += in + num(e) + "\n";
    out += "        </DataArray>\n";
  }
  out += "      </CellData>\n";
  out += "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& v : m.vertices) out += in + xyz(v) + "\n";
  out += "        </DataArray>\n      </Points>\n";
  out += "      <Cells>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& t : m.triangles) out += in + abc(t, 0) + "\n";
  out += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < m.triangles.size(); ++i) out += in + num(3 * (i + 1)) + "\n";
  out += "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < m.triangles.size(); ++i) out += in + "5\n";
  out += "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

// A smooth field with steep spots, `w` x `h` pixels.
HeightField field(std::int64_t w, std::int64_t h) {
  HeightField f;
  f.width = w;
  f.height = h;
  f.maxval = 65535;
  f.format = "P5";
  for (std::int64_t r = 0; r < h; ++r)
    for (std::int64_t c = 0; c < w; ++c)
      f.values.push_back(0.5 + 0.3 * std::sin(0.37 * static_cast<double>(c)) * std::cos(0.23 * static_cast<double>(r)) +
                         (c * 7 + r * 3) % 11 * 0.01);
  return f;
}

void expect_same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.vertex_position, b.vertex_position);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangle_cell, b.triangle_cell);
  EXPECT_EQ(a.triangle_level, b.triangle_level);
}

TEST(AppsOutput, RandomStatesBothLatticesEveryFormat) {
  const HeightField f = field(37, 29);
  for (const LatticeSize size : {LatticeSize{1, 1, 4}, LatticeSize{3, 2, 5}, LatticeSize{2, 3, 12}}) {
    const HeightSampler s(f, size, 2.5);
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
      SCOPED_TRACE("lattice " + std::to_string(size.W) + " " + std::to_string(size.H) + " " + std::to_string(size.L) +
                   ", seed " + std::to_string(seed));
      fast::Lattice lattice(size);
      std::mt19937 rng(seed);
      for (int k = 0; k < 80; ++k) {
        const std::vector<Point> cs = lattice.cells();
        const std::vector<Point> ns = lattice.nodes();
        if (rng() % 4 != 0)
          lattice.refine(cs[rng() % cs.size()]);
        else
          lattice.coarsen(ns[rng() % ns.size()]);
      }
      const Graph g = lattice.to_graph();
      const auto height = [&](const Point& p) { return s.at(p); };
      TriangleMesh mesh = triangulate(g, height);
      expect_same_mesh(triangulate(lattice, height), mesh);

      const MeshError a = mesh_error(g, s), b = mesh_error(lattice, s);
      EXPECT_EQ(a.max_abs, b.max_abs);
      EXPECT_EQ(a.rms, b.rms);
      EXPECT_EQ(a.pixels, b.pixels);
      EXPECT_EQ(a.worst_cell, b.worst_cell);
      EXPECT_EQ(a.pixels, f.width * f.height);

      EXPECT_EQ(io::format_obj(mesh, "a\ncomment"), spec_obj(mesh, "a comment"));
      EXPECT_EQ(io::format_ply(mesh, "c"), spec_ply(mesh, "c"));
      EXPECT_EQ(io::format_vtu(mesh), spec_vtu(mesh));
      for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        mesh.triangle_error.push_back(std::ldexp(static_cast<double>(i % 97), -static_cast<int>(i % 40)) / 3.0);
      EXPECT_EQ(io::format_vtu(mesh), spec_vtu(mesh));
    }
  }
}

// More distinct x values (8193: a 2048 x 1 lattice refined once) than the
// formatter's table of recent texts has entries (2^12), in a text of several
// 64 KiB chunks.
TEST(AppsOutput, ManyDistinctCoordinates) {
  const LatticeSize size{2048, 1, 1};
  const HeightField f = field(65, 65);  // the sampler keeps a pointer to it
  const HeightSampler s(f, size, 1.0);
  fast::Lattice lattice(size);
  for (const Point& c : lattice.cells()) lattice.refine(c);
  const Graph g = lattice.to_graph();
  const TriangleMesh mesh = triangulate(lattice, [&](const Point& p) { return s.at(p); });
  expect_same_mesh(mesh, triangulate(g, [&](const Point& p) { return s.at(p); }));
  std::vector<double> xs;
  for (const auto& v : mesh.vertices) xs.push_back(v[0]);
  std::sort(xs.begin(), xs.end());
  EXPECT_EQ(std::unique(xs.begin(), xs.end()) - xs.begin(), 8193);
  EXPECT_EQ(io::format_obj(mesh, "x"), spec_obj(mesh, "x"));
  EXPECT_EQ(io::format_ply(mesh, "x"), spec_ply(mesh, "x"));
}

}  // namespace
}  // namespace bccmis
