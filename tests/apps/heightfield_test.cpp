// Height-field tessellation (src/bccmis/apps/heightfield.h, mesh.h, apps.h) on
// synthetic fields with known answers, the mesh's watertightness and area,
// the output formats parsed back. The CLI (`bccmis heightfield`) is tested in
// tests/apps/apps.cmake.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "bccmis/apps/heightfield.h"
#include "bccmis/apps/triangulate.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/io/obj.h"
#include "bccmis/io/ply.h"
#include "bccmis/io/vtu.h"

namespace bccmis {
namespace {

/// A w x h field with value f(u, v), u = col/(w-1) to the right, v = j/(h-1)
/// upwards (j counted from the bottom row).
HeightField synthetic(std::int64_t w, std::int64_t h, const std::function<double(double, double)>& f) {
  HeightField field;
  field.width = w;
  field.height = h;
  field.maxval = 65535;
  field.format = "synthetic";
  field.values.resize(static_cast<std::size_t>(w * h));
  for (std::int64_t row = 0; row < h; ++row)
    for (std::int64_t col = 0; col < w; ++col)
      field.values[static_cast<std::size_t>(row * w + col)] =
          f(static_cast<double>(col) / static_cast<double>(w - 1),
            static_cast<double>(h - 1 - row) / static_cast<double>(h - 1));
  return field;
}

struct Tessellation {
  Graph g;
  TessellateReport report;
  MeshError error;
};

Tessellation tessellated(const HeightField& field, const LatticeSize& size, double tolerance,
                         ErrorMeasure measure = ErrorMeasure::MaxPixel) {
  Tessellation r{make_lattice(size), {}, {}};
  const HeightSampler s(field, size, 1.0);
  TessellateSettings t;
  t.tolerance = tolerance;
  t.error.measure = measure;
  r.report = tessellate(
      r.g, s, t, [](int, const Graph& g, std::size_t) { ASSERT_TRUE(is_valid(g)) << to_string(*find_violation(g)); });
  r.error = mesh_error(r.g, s);
  EXPECT_TRUE(is_valid(r.g)) << to_string(*find_violation(r.g));
  EXPECT_TRUE(r.report.converged);
  EXPECT_EQ(r.error.pixels, field.width * field.height) << "every pixel is in exactly one cell";
  // The post-condition of a converged run: a cell above tolerance is at the maximum level.
  for (const Point& c : r.g.C)
    if (r.g.level_of(c) < size.L) {
      EXPECT_LE(cell_error(r.g, c, s, {ErrorMeasure::MaxPixel, 0, 0}), tolerance + 1e-12) << c.x << " " << c.y;
    }
  return r;
}

// The square of cell c in level-0 cell units.
struct Box {
  double x0, x1, y0, y1;
};
Box box(const Graph& g, const Point& c) {
  const double S = static_cast<double>(level0_side(g.size));
  const double h = static_cast<double>(cell_side(g.size, g.level_of(c))) / 2;
  return {(static_cast<double>(c.x) - h) / S, (static_cast<double>(c.x) + h) / S, (static_cast<double>(c.y) - h) / S,
          (static_cast<double>(c.y) + h) / S};
}

TEST(Heightfield, PlaneNeedsNoRefinementAtAnyTolerance) {
  const HeightField plane = synthetic(64, 48, [](double u, double v) { return 0.1 + 0.5 * u + 0.3 * v; });
  for (const double tol : {0.0, 1e-9, 0.01, 0.5})
    for (const ErrorMeasure m : {ErrorMeasure::MaxPixel, ErrorMeasure::RandomSamples}) {
      const Tessellation r = tessellated(plane, {6, 6, 5}, tol, m);
      EXPECT_EQ(r.report.refinements, 0u) << "tolerance " << tol;
      EXPECT_EQ(r.g, make_lattice({6, 6, 5}));
      EXPECT_LT(r.error.max_abs, 1e-12);
    }
}

TEST(Heightfield, SinglePeakRefinesOnlyAroundIt) {
  const double pu = 0.3, pv = 0.6, sigma = 0.03;
  const HeightField peak = synthetic(160, 160, [&](double u, double v) {
    return std::exp(-((u - pu) * (u - pu) + (v - pv) * (v - pv)) / (2 * sigma * sigma));
  });
  const LatticeSize size{8, 8, 6};
  const Tessellation r = tessellated(peak, size, 0.01);
  EXPECT_GT(r.report.refinements, 0u);
  EXPECT_LE(r.error.max_abs, 0.01);
  // Far from the peak (5 sigma, plus two level-0 cells of balance rings) the
  // lattice is untouched; the cell under the peak is refined deeply.
  const double px = pu * 8, py = pv * 8, reach = 5 * sigma * 8 + 2.0;
  int far = 0;
  for (const Point& c : r.g.C) {
    const Box b = box(r.g, c);
    const double dx = std::max({b.x0 - px, px - b.x1, 0.0}), dy = std::max({b.y0 - py, py - b.y1, 0.0});
    if (std::hypot(dx, dy) > reach) {
      EXPECT_EQ(r.g.level_of(c), 0) << c.x << " " << c.y;
      ++far;
    }
    if (dx == 0 && dy == 0) {
      EXPECT_GE(r.g.level_of(c), 3);
    }
  }
  EXPECT_GT(far, 20);
}

TEST(Heightfield, StepRefinesAlongTheStepToMaxLevel) {
  // Columns 0..39 are 0, columns 40..127 are 1: the field ramps between the
  // pixel columns 39 and 40 (x = 39.5/127 of the domain).
  const std::int64_t w = 128;
  const HeightField step = synthetic(w, 96, [&](double u, double) { return u * (w - 1) >= 39.5 ? 1.0 : 0.0; });
  const LatticeSize size{6, 6, 4};
  const Tessellation r = tessellated(step, size, 0.05);
  const double xs = 39.5 / 127.0 * 6;
  // Walking up the step: the cell holding the step is at the max level.
  for (int k = 0; k < 60; ++k) {
    const double y = (k + 0.5) / 60.0 * 6;
    int found = 0;
    for (const Point& c : r.g.C) {
      const Box b = box(r.g, c);
      if (b.x0 <= xs && xs <= b.x1 && b.y0 <= y && y <= b.y1) {
        EXPECT_EQ(r.g.level_of(c), size.L) << "at y = " << y;
        ++found;
      }
    }
    EXPECT_GE(found, 1);
  }
  // Away from the step (more than two level-0 cells) nothing is refined.
  for (const Point& c : r.g.C) {
    const Box b = box(r.g, c);
    if (b.x0 > xs + 2 || b.x1 < xs - 2) {
      EXPECT_EQ(r.g.level_of(c), 0);
    }
  }
}

// ---- The mesh -------------------------------------------------------------------

void expect_watertight_cover(const TriangleMesh& m, double W, double H) {
  double area = 0;
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for (const auto& t : m.triangles) {
    const auto& a = m.vertices[t[0]];
    const auto& b = m.vertices[t[1]];
    const auto& c = m.vertices[t[2]];
    const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    EXPECT_GT(twice, 0) << "a triangle is degenerate or clockwise";
    area += twice / 2;
    for (int k = 0; k < 3; ++k) ++directed[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
  }
  EXPECT_NEAR(area, W * H, 1e-9 * W * H) << "the triangles cover the domain";
  std::size_t edges = 0;
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1) << "a directed edge is used twice: inconsistent orientation or overlap";
    const bool paired = directed.count({e.second, e.first}) != 0;
    if (!paired) {
      // A boundary edge: both ends on the same side of the domain.
      const auto& p = m.vertices[e.first];
      const auto& q = m.vertices[e.second];
      const bool on_side =
          (p[0] == 0 && q[0] == 0) || (p[0] == W && q[0] == W) || (p[1] == 0 && q[1] == 0) || (p[1] == H && q[1] == H);
      EXPECT_TRUE(on_side) << "an unpaired edge inside the domain: a crack";
    }
    edges += paired ? 1 : 2;  // an interior edge is counted from both sides
  }
  edges /= 2;
  // Euler's formula for a disk: V - E + F = 1.
  EXPECT_EQ(static_cast<long>(m.vertices.size()) - static_cast<long>(edges) + static_cast<long>(m.triangles.size()), 1);
}

TEST(Mesh, WatertightAndCoversTheDomain) {
  const HeightField terrain = read_height_field(BCCMIS_APPS_SAMPLES "/terrain128.pgm");
  const LatticeSize size{6, 4, 5};
  const Tessellation r = tessellated(terrain, size, 0.03);
  const HeightSampler s(terrain, size, 2.0);
  const TriangleMesh m = triangulate(r.g, [&](const Point& p) { return s.at(p); });
  EXPECT_EQ(m.vertices.size(), r.g.N.size() + r.g.C.size());
  expect_watertight_cover(m, 6, 4);
  expect_watertight_cover(triangulate(make_lattice({3, 2, 2}), [](const Point&) { return 0.0; }), 3, 2);
}

TEST(Mesh, FanInterpolatesTheVertexHeights) {
  const HeightField bumpy = synthetic(50, 50, [](double u, double v) { return std::sin(7 * u) * std::cos(5 * v); });
  const Tessellation r = tessellated(bumpy, {2, 2, 4}, 0.05);
  const HeightSampler s(bumpy, r.g.size, 1.0);
  for (const Point& c : r.g.C) {
    const CellFan fan = cell_fan(r.g, c, s);
    EXPECT_DOUBLE_EQ(fan.at(static_cast<double>(c.x), static_cast<double>(c.y)), s.at(c));
    for (const Point& b : r.g.nbr(c))
      EXPECT_NEAR(fan.at(static_cast<double>(b.x), static_cast<double>(b.y)), s.at(b), 1e-12);
  }
}

// Minimal readers, written from the formats' documentation, not from mesh.cpp.
struct Parsed {
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<std::size_t, 3>> f;
  std::vector<int> level;
};

Parsed parse_obj(const std::string& text) {
  Parsed p;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      std::array<double, 3> x{};
      ls >> x[0] >> x[1] >> x[2];
      EXPECT_FALSE(ls.fail()) << line;
      p.v.push_back(x);
    } else if (tag == "f") {
      std::array<std::size_t, 3> t{};
      ls >> t[0] >> t[1] >> t[2];
      EXPECT_FALSE(ls.fail()) << line;
      for (auto& i : t) i -= 1;
      p.f.push_back(t);
    } else {
      EXPECT_TRUE(tag.empty() || tag[0] == '#') << line;
    }
  }
  return p;
}

Parsed parse_ply(const std::string& text) {
  Parsed p;
  std::istringstream in(text);
  std::string line;
  std::size_t nv = 0, nf = 0;
  std::getline(in, line);
  EXPECT_EQ(line, "ply");
  std::getline(in, line);
  EXPECT_EQ(line, "format ascii 1.0");
  std::vector<std::string> face_props;
  std::string element;
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream ls(line);
    std::string kw;
    ls >> kw;
    if (kw == "element") {
      ls >> element;
      (element == "vertex" ? nv : nf) = 0;
      ls >> (element == "vertex" ? nv : nf);
    } else if (kw == "property" && element == "face") {
      face_props.push_back(line);
    }
  }
  EXPECT_EQ(face_props, (std::vector<std::string>{"property list uchar int vertex_indices", "property int level"}));
  for (std::size_t i = 0; i < nv; ++i) {
    std::array<double, 3> x{};
    in >> x[0] >> x[1] >> x[2];
    p.v.push_back(x);
  }
  for (std::size_t i = 0; i < nf; ++i) {
    int count = 0, level = 0;
    std::array<std::size_t, 3> t{};
    in >> count >> t[0] >> t[1] >> t[2] >> level;
    EXPECT_EQ(count, 3);
    p.f.push_back(t);
    p.level.push_back(level);
  }
  EXPECT_FALSE(in.fail());
  std::string rest;
  in >> rest;
  EXPECT_TRUE(rest.empty()) << "data after the last face";
  return p;
}

// The text of <DataArray ... Name="name" ...> ... </DataArray> (or the first
// DataArray inside <Points>).
std::vector<double> vtu_array(const std::string& text, const std::string& opener) {
  std::size_t at = text.find(opener);
  EXPECT_NE(at, std::string::npos) << opener;
  if (at != std::string::npos && opener == "<Points>") at = text.find("<DataArray", at);
  if (at == std::string::npos) return {};
  const std::size_t start = text.find('>', at) + 1;
  const std::size_t end = text.find("</DataArray>", start);
  std::istringstream in(text.substr(start, end - start));
  std::vector<double> out;
  double x = 0;
  while (in >> x) out.push_back(x);
  return out;
}

TEST(Mesh, ObjPlyVtuParseBack) {
  const HeightField terrain = read_height_field(BCCMIS_APPS_SAMPLES "/crater64.pgm");
  const Tessellation r = tessellated(terrain, {3, 3, 4}, 0.04);
  const HeightSampler s(terrain, r.g.size, 1.5);
  TriangleMesh m = triangulate(r.g, [&](const Point& p) { return s.at(p); });
  for (const Point& c : m.triangle_cell) m.triangle_error.push_back(cell_error(r.g, c, s, {}));

  for (const Parsed& p : {parse_obj(io::format_obj(m, "test\nwith a newline")), parse_ply(io::format_ply(m, "test"))}) {
    ASSERT_EQ(p.v.size(), m.vertices.size());
    ASSERT_EQ(p.f.size(), m.triangles.size());
    for (std::size_t i = 0; i < p.v.size(); ++i) EXPECT_EQ(p.v[i], m.vertices[i]) << "exact round trip";
    EXPECT_EQ(p.f, m.triangles);
    if (!p.level.empty()) {
      EXPECT_EQ(p.level, m.triangle_level);
    }
  }

  const std::string vtu = io::format_vtu(m);
  EXPECT_EQ(vtu.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"", 0), 0u);
  EXPECT_NE(vtu.find("NumberOfPoints=\"" + std::to_string(m.vertices.size()) + "\" NumberOfCells=\"" +
                     std::to_string(m.triangles.size()) + "\""),
            std::string::npos);
  const std::vector<double> points = vtu_array(vtu, "<Points>");
  ASSERT_EQ(points.size(), 3 * m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(points[3 * i + k], m.vertices[i][k]);
  const std::vector<double> conn = vtu_array(vtu, "Name=\"connectivity\"");
  const std::vector<double> offsets = vtu_array(vtu, "Name=\"offsets\"");
  const std::vector<double> types = vtu_array(vtu, "Name=\"types\"");
  const std::vector<double> levels = vtu_array(vtu, "Name=\"level\"");
  const std::vector<double> errors = vtu_array(vtu, "Name=\"error\"");
  const std::vector<double> heights = vtu_array(vtu, "Name=\"height\"");
  ASSERT_EQ(conn.size(), 3 * m.triangles.size());
  ASSERT_EQ(offsets.size(), m.triangles.size());
  ASSERT_EQ(levels.size(), m.triangles.size());
  ASSERT_EQ(errors.size(), m.triangles.size());
  ASSERT_EQ(heights.size(), m.vertices.size());
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    EXPECT_EQ(types[i], 5);
    EXPECT_EQ(offsets[i], static_cast<double>(3 * (i + 1)));
    EXPECT_EQ(levels[i], m.triangle_level[i]);
    EXPECT_EQ(errors[i], m.triangle_error[i]);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(conn[3 * i + k], static_cast<double>(m.triangles[i][k]));
  }
}

// ---- The paper's measure -----------------------------------------------------------

TEST(Heightfield, RandomSampleMeasureIsDeterministicAndOrderFree) {
  const HeightField terrain = read_height_field(BCCMIS_APPS_SAMPLES "/terrain128.pgm");
  const LatticeSize size{6, 6, 5};
  const HeightSampler s(terrain, size, 1.0);
  TessellateSettings t;
  t.tolerance = 0.02;
  t.error = {ErrorMeasure::RandomSamples, 16, 42};
  Graph a = make_lattice(size), b = make_lattice(size);
  tessellate(a, s, t);
  tessellate(b, s, t);
  EXPECT_EQ(canonical_state(a), canonical_state(b));
  // A cell's samples depend on (seed, cell) only: measuring in another order
  // or in another lattice gives the same value.
  for (const Point& c : a.C)
    if (b.is_center(c)) {
      EXPECT_EQ(cell_error(a, c, s, t.error), cell_error(b, c, s, t.error));
    }
  // The sampled error never exceeds the error over a dense set of points; it
  // is an under-estimate, so the exact measure is what guarantees tolerance.
  const MeshError exact = mesh_error(a, s);
  EXPECT_GT(exact.max_abs, 0.0);
}

TEST(Heightfield, CornerBalanceKeepsItsRuleAndTheTolerance) {
  const HeightField terrain = read_height_field(BCCMIS_APPS_SAMPLES "/terrain128.pgm");
  const LatticeSize size{6, 6, 5};
  const HeightSampler s(terrain, size, 1.0);
  TessellateSettings t;
  t.tolerance = 0.03;
  Graph edge = make_lattice(size);
  tessellate(edge, s, t);
  t.balance = Balance::Corner;
  Graph corner = make_lattice(size);
  tessellate(corner, s, t, [](int, const Graph& g, std::size_t) {
    ASSERT_TRUE(is_valid(g));
    ASSERT_FALSE(find_corner_imbalance(g));
  });
  EXPECT_TRUE(find_corner_imbalance(edge).has_value()) << "this field needs the corner rule somewhere";
  EXPECT_GT(corner.C.size(), edge.C.size());
  for (const Point& c : corner.C)
    if (corner.level_of(c) < size.L) {
      EXPECT_LE(cell_error(corner, c, s, {}), 0.03 + 1e-12);
    }
  // Coarsening from it keeps the corner rule too.
  t.tolerance = 0.1;
  t.coarsen = true;
  const TessellateReport r = tessellate(corner, s, t);
  EXPECT_GT(r.coarsenings, 0u);
  EXPECT_TRUE(is_valid(corner));
  EXPECT_FALSE(find_corner_imbalance(corner));
}

TEST(Heightfield, MaxSweepsStopsEarly) {
  const HeightField terrain = read_height_field(BCCMIS_APPS_SAMPLES "/terrain128.pgm");
  const LatticeSize size{6, 6, 5};
  const HeightSampler s(terrain, size, 1.0);
  TessellateSettings t;
  t.max_sweeps = 2;
  Graph g = make_lattice(size);
  const TessellateReport r = tessellate(g, s, t);
  EXPECT_EQ(r.sweeps, 2);
  EXPECT_FALSE(r.converged);
}

}  // namespace
}  // namespace bccmis
