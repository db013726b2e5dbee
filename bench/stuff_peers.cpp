// The peers of `bccmis stuff` (issue 20, "Against the meshers users would
// pick"): the tetrahedral meshers a user would otherwise run on a closed
// surface, measured the same way as bccmis. One JSON object per run on stdout
// (mesher, input, seconds of meshing, vertices, tetrahedra, min/max dihedral
// angle, fraction of tetrahedra with a dihedral angle below 10 degrees,
// volume and its relative error against the shape's volume, the sampled
// Hausdorff distance both ways, the features found and the largest
// feature-point distance): bccmis::stuff::measure_mesh, the functions that
// measure `bccmis stuff --stats --hausdorff`'s own mesh (spec/stuffing.md
// S13, S33), on the input read as `bccmis stuff` reads it; the features at
// --feature-angle (default 60, as bccmis's). tet_quality.h counts the
// tetrahedra not positively oriented (--verify).
//
//   stuff_peers cgal INPUT.off --cell-size S [--facet-distance D] [--seed N] [--features [--feature-angle A]]
//                   [--verify [--tolerance T] [--max-hausdorff H]]
//       CGAL Mesh_3 on a Polyhedral_mesh_domain_3: make_mesh_3 with
//       facet_angle 25, facet_size S, facet_distance D (default S / 20),
//       cell_radius_edge_ratio 3, cell_size S, then perturb() and exude();
//       the finite cells in the complex. seconds (wall) and cpu_seconds:
//       domain construction and make_mesh_3 (AABB tree, refinement,
//       perturbation, exudation). --features: the same on a
//       Polyhedral_mesh_domain_with_features_3 whose detect_features(A)
//       (default 60 degrees, as bccmis's --feature-angle) finds the creases
//       and corners, which Mesh_3 protects with balls, edge_size S / 2 (the
//       ratio of CGAL's own fandisk example); mesher "cgal-features", and
//       the time includes the detection.
//   stuff_peers tetgen INPUT.off --max-volume V [--feature-angle A] [--verify [--tolerance T] [--max-hausdorff H]]
//       Debian's `tetgen` binary, `-pq1.414 -a<V> -Q` on a copy of INPUT in a
//       temporary directory; reads the .node/.ele it writes. seconds: the
//       tetgen process's wall time, cpu_seconds its user + system time.
//   stuff_peers sphere-off R N OUT.off
//       A closed, outward-oriented sphere: an icosahedron subdivided N times,
//       its vertices on the sphere of radius R.
//   stuff_peers selftest
//       The dihedral-angle function on tetrahedra whose angles are known.
//
// --verify: exit 1 unless the mesh has tetrahedra, every tetrahedron is
// positively oriented (tet_quality.h, orient6 > 0), |volume_rel_error|
// is at most T (default 0.05) and, with --max-hausdorff H, both sampled
// Hausdorff distances are at most H. Numbers: bench/RESULTS.md, sections 14
// and 24.
// GCC's optimizer reports a false "may be used uninitialized" inside
// Boost.Graph's add_edge, which detect_features (CGAL's
// split_graph_into_polylines) instantiates; the state is taken by the line
// of the warning, in a standard header, so it is set before every include.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "bccmis/stuff/measure_mesh.h"
#include "bccmis/stuff/mesh_shape.h"
#include "testing/icosphere.h"
#include "tet_quality.h"

namespace {

using bccmis::bench::Vec3L;
using Clock = std::chrono::steady_clock;
using Tet = std::array<std::size_t, 4>;
using Tri = std::array<std::size_t, 3>;

struct Surface {
  std::vector<Vec3L> points;
  std::vector<Tri> triangles;  // polygons fanned into triangles
};

struct TetMesh {
  std::vector<Vec3L> points;
  std::vector<Tet> tets;
};

// Next line that is not blank and not a comment; false at the end.
bool next_line(std::istream& in, std::string& line) {
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") != std::string::npos) return true;
  }
  return false;
}

// An OFF file: header, counts, vertices, then faces (polygons fanned from
// their first vertex; colours after the indices ignored).
Surface read_off(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  if (!next_line(in, line)) throw std::runtime_error(path + ": empty");
  std::istringstream header(line);
  std::string magic;
  header >> magic;
  if (magic.find("OFF") == std::string::npos) throw std::runtime_error(path + ": not an OFF file");
  std::size_t nv = 0, nf = 0;
  if (!(header >> nv >> nf)) {
    if (!next_line(in, line)) throw std::runtime_error(path + ": no counts");
    std::istringstream counts(line);
    if (!(counts >> nv >> nf)) throw std::runtime_error(path + ": bad counts");
  }
  Surface s;
  s.points.reserve(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    if (!next_line(in, line)) throw std::runtime_error(path + ": too few vertices");
    std::istringstream v(line);
    double x = 0, y = 0, z = 0;
    if (!(v >> x >> y >> z)) throw std::runtime_error(path + ": bad vertex");
    s.points.push_back({x, y, z});
  }
  for (std::size_t f = 0; f < nf; ++f) {
    if (!next_line(in, line)) throw std::runtime_error(path + ": too few faces");
    std::istringstream fl(line);
    std::size_t n = 0;
    fl >> n;
    std::vector<std::size_t> idx(n);
    for (auto& i : idx)
      if (!(fl >> i) || i >= nv) throw std::runtime_error(path + ": bad face");
    for (std::size_t k = 1; k + 1 < n; ++k) s.triangles.push_back({idx[0], idx[k], idx[k + 1]});
  }
  return s;
}

// Every directed edge has exactly one opposite and no twin: closed and
// consistently oriented.
bool closed_and_oriented(const Surface& s) {
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for (const Tri& t : s.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
  for (const auto& [e, n] : directed) {
    const auto opposite = directed.find({e.second, e.first});
    if (n != 1 || opposite == directed.end() || opposite->second != 1) return false;
  }
  return true;
}

void write_off(const std::string& path, const Surface& s) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "OFF\n%zu %zu 0\n", s.points.size(), s.triangles.size());
  for (const Vec3L& p : s.points) std::fprintf(f, "%.17Lg %.17Lg %.17Lg\n", p[0], p[1], p[2]);
  for (const Tri& t : s.triangles) std::fprintf(f, "3 %zu %zu %zu\n", t[0], t[1], t[2]);
  if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path);
}

// An icosahedron subdivided `levels` times (each triangle into four), the
// vertices pushed onto the sphere of radius r; faces counter-clockwise seen
// from outside.
Surface icosphere(long double r, int levels) {
  Surface s;
  bccmis::testing::subdivided_icosahedron(
      levels, [](const Vec3L& p) { return p; }, s.points, s.triangles);
  for (Vec3L& p : s.points) {
    const long double scale = r / bccmis::bench::norm(p);
    for (auto& c : p) c *= scale;
  }
  if (bccmis::bench::enclosed_volume(s.points, s.triangles) < 0)
    for (Tri& tri : s.triangles) std::swap(tri[1], tri[2]);
  return s;
}

// ---- CGAL Mesh_3 ----------------------------------------------------------

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Polyhedron_3<K>;
using MeshDomain = CGAL::Polyhedral_mesh_domain_3<Polyhedron, K>;
using FeaturesDomain = CGAL::Polyhedral_mesh_domain_with_features_3<K>;

// The triangulation, complex and criteria of Mesh_3 on Domain.
template <class Domain>
struct Mesh3Types {
  using Tr = typename CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, typename Domain::Corner_index, typename Domain::Curve_index>;
  using Criteria = CGAL::Mesh_criteria_3<Tr>;
};
template <>
struct Mesh3Types<MeshDomain> {
  using Tr = CGAL::Mesh_triangulation_3<MeshDomain, CGAL::Default, CGAL::Sequential_tag>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
  using Criteria = CGAL::Mesh_criteria_3<Tr>;
};

// CPU time of this process (user + system), seconds.
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

// CGAL Mesh_3 on a Domain built from the Polyhedron (see the header);
// feature_angle > 0: Domain is FeaturesDomain, its features detected at that
// angle and protected.
template <class Domain, class InputPolyhedron>
TetMesh run_cgal(const Surface& s, double cell_size, double facet_distance, double feature_angle, unsigned seed,
                 double& seconds, double& cpu_seconds) {
  using Tr = typename Mesh3Types<Domain>::Tr;
  using C3t3 = typename Mesh3Types<Domain>::C3t3;
  using Criteria = typename Mesh3Types<Domain>::Criteria;
  std::vector<K::Point_3> points;
  points.reserve(s.points.size());
  for (const Vec3L& p : s.points)
    points.emplace_back(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]));
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(s.triangles.size());
  for (const Tri& t : s.triangles) polygons.push_back({t[0], t[1], t[2]});
  InputPolyhedron polyhedron;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, polyhedron);
  CGAL::get_default_random() = CGAL::Random(seed);

  namespace params = CGAL::parameters;
  const auto start = Clock::now();
  const double cpu_start = process_cpu_seconds();
  Domain domain(polyhedron);
  const auto criteria = [&] {
    if constexpr (std::is_same_v<Domain, FeaturesDomain>) {
      domain.detect_features(feature_angle);
      return Criteria(params::edge_size = cell_size / 2, params::facet_angle = 25, params::facet_size = cell_size,
                      params::facet_distance = facet_distance, params::cell_radius_edge_ratio = 3,
                      params::cell_size = cell_size);
    } else {
      return Criteria(params::facet_angle = 25, params::facet_size = cell_size, params::facet_distance = facet_distance,
                      params::cell_radius_edge_ratio = 3, params::cell_size = cell_size);
    }
  }();
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_lloyd(), params::no_odt(), params::perturb(),
                                      params::exude());
  seconds = std::chrono::duration<double>(Clock::now() - start).count();
  cpu_seconds = process_cpu_seconds() - cpu_start;

  TetMesh m;
  std::unordered_map<typename Tr::Vertex_handle, std::size_t> index;
  const Tr& tr = c3t3.triangulation();
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    Tet t{};
    for (int i = 0; i < 4; ++i) {
      const typename Tr::Vertex_handle v = c->vertex(i);
      auto [it, inserted] = index.emplace(v, m.points.size());
      if (inserted) {
        const K::Point_3 p = tr.geom_traits().construct_point_3_object()(tr.point(c, i));
        m.points.push_back({p.x(), p.y(), p.z()});
      }
      t[static_cast<std::size_t>(i)] = it->second;
    }
    m.tets.push_back(t);
  }
  return m;
}

// ---- TetGen -----------------------------------------------------------------

// Runs argv (no shell) and waits; its stdout goes to /dev/null. Returns the
// exit status, -1 if it could not be started; cpu_seconds: the child's user +
// system time.
int run_process(const std::vector<std::string>& args, double& cpu_seconds) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (!std::freopen("/dev/null", "w", stdout)) _exit(127);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return -1;
  cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The records of a TetGen file: a first line whose first number is n, then
// n lines, each parsed by parse(line, i); `plural` names them in errors.
template <class Record, class Parse>
std::vector<Record> read_records(const std::string& path, const char* plural, Parse parse) {
  std::ifstream in(path);
  std::string line;
  if (!in || !next_line(in, line)) throw std::runtime_error("cannot read " + path);
  std::size_t n = 0;
  std::istringstream(line) >> n;
  std::vector<Record> records;
  records.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!next_line(in, line)) throw std::runtime_error(path + ": too few " + plural);
    std::istringstream l(line);
    records.push_back(parse(l, i));
  }
  return records;
}

// A .node file: "n 3 attributes markers", then "index x y z ...". The first
// index (0 or 1) is the numbering base of the .ele file too.
std::vector<Vec3L> read_node(const std::string& path, std::size_t& base) {
  return read_records<Vec3L>(path, "nodes", [&](std::istringstream& l, std::size_t i) {
    std::size_t index = 0;
    long double x = 0, y = 0, z = 0;
    if (!(l >> index >> x >> y >> z)) throw std::runtime_error(path + ": bad node");
    if (i == 0) base = index;
    return Vec3L{x, y, z};
  });
}

// A .ele file: "n 4 attributes", then "index a b c d ..."; the corners as
// TetGen orders them, which is the positive orientation of tet_quality.h
// (orient6 > 0; --verify checks it).
std::vector<Tet> read_ele(const std::string& path, std::size_t base, std::size_t nodes) {
  return read_records<Tet>(path, "tetrahedra", [&](std::istringstream& l, std::size_t) {
    std::size_t index = 0;
    Tet t{};
    if (!(l >> index >> t[0] >> t[1] >> t[2] >> t[3])) throw std::runtime_error(path + ": bad tetrahedron");
    for (auto& v : t) {
      if (v < base || v - base >= nodes) throw std::runtime_error(path + ": node index out of range");
      v -= base;
    }
    return t;
  });
}

TetMesh run_tetgen(const std::string& input, double max_volume, double& seconds, double& cpu_seconds) {
  char dir_template[] = "/tmp/stuff_peers.XXXXXX";
  if (!mkdtemp(dir_template)) throw std::runtime_error("mkdtemp failed");
  const std::filesystem::path dir(dir_template);
  const std::filesystem::path copy = dir / "in.off";
  std::filesystem::copy_file(input, copy);
  char volume[64];
  std::snprintf(volume, sizeof volume, "-a%.17g", max_volume);
  const auto start = Clock::now();
  const int status = run_process({"tetgen", "-pq1.414", volume, "-Q", copy.string()}, cpu_seconds);
  seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (status != 0) {
    std::filesystem::remove_all(dir);
    throw std::runtime_error("tetgen failed (exit status " + std::to_string(status) + ")");
  }
  TetMesh m;
  std::size_t base = 0;
  m.points = read_node((dir / "in.1.node").string(), base);
  m.tets = read_ele((dir / "in.1.ele").string(), base, m.points.size());
  std::filesystem::remove_all(dir);
  return m;
}

// ---- Reporting ---------------------------------------------------------------

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// The peer's mesh as bccmis's meshes are held (double coordinates, 32-bit
// indices), for measure_mesh.
bccmis::d3::TetMeshF to_mesh(const TetMesh& m) {
  bccmis::d3::TetMeshF out;
  out.vertices.reserve(m.points.size());
  for (const Vec3L& p : m.points)
    out.vertices.push_back({static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])});
  out.tets.reserve(m.tets.size());
  for (const Tet& t : m.tets)
    out.tets.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                        static_cast<std::uint32_t>(t[2]), static_cast<std::uint32_t>(t[3])});
  out.kind.assign(out.vertices.size(), 0);
  out.level.assign(out.tets.size(), 0);
  return out;
}

// Prints the JSON object; returns false when --verify fails.
bool report(const std::string& mesher, const std::string& input, const TetMesh& m, double seconds, double cpu_seconds,
            double feature_angle, bool verify, double tolerance, double max_hausdorff) {
  const std::size_t inverted = bccmis::bench::measure(m.points, m.tets).inverted;
  std::vector<char> used(m.points.size(), 0);
  for (const Tet& t : m.tets)
    for (const std::size_t v : t) used[v] = 1;
  std::size_t vertices = 0;
  for (const char u : used) vertices += static_cast<std::size_t>(u);
  const auto shape = bccmis::stuff::load_mesh_file(input);
  const auto measured = bccmis::stuff::measure_mesh(*shape, to_mesh(m), feature_angle);
  const auto& s = measured.statistics;
  const double rel = s.volume_rel_error();
  std::printf(
      "{\"mesher\": %s, \"input\": %s, \"seconds\": %.6f, \"cpu_seconds\": %.6f, \"vertices\": %zu, \"tetrahedra\": "
      "%zu, \"min_dihedral\": %.6f, \"max_dihedral\": %.6f, \"below10\": %.8f, \"volume\": %.12g, "
      "\"input_volume\": %.12g, \"volume_rel_error\": %.8e, \"inverted\": %zu, "
      "\"hausdorff\": {\"from_boundary\": %.6g, \"from_surface\": %.6g}, \"feature_angle\": %g, "
      "\"feature_curves\": %zu, \"feature_corners\": %zu, \"feature_distance\": %.6g}\n",
      json_string(mesher).c_str(), json_string(input).c_str(), seconds, cpu_seconds, vertices, s.tetrahedra,
      s.quality.min_dihedral, s.quality.max_dihedral, s.below10(), s.quality.volume, s.shape_volume, rel, inverted,
      s.hausdorff.from_boundary, s.hausdorff.from_surface, feature_angle, measured.feature_curves,
      measured.feature_corners, measured.feature_distance);
  std::fflush(stdout);
  if (!verify) return true;
  bool ok = true;
  if (s.tetrahedra == 0) {
    std::fprintf(stderr, "stuff_peers: %s: no tetrahedra\n", mesher.c_str());
    ok = false;
  }
  if (inverted != 0) {
    std::fprintf(stderr, "stuff_peers: %s: %zu tetrahedra not positively oriented\n", mesher.c_str(), inverted);
    ok = false;
  }
  if (!(std::fabs(rel) <= tolerance)) {
    std::fprintf(stderr, "stuff_peers: %s: volume error %.3e above the tolerance %.3g\n", mesher.c_str(), rel,
                 tolerance);
    ok = false;
  }
  if (!(s.hausdorff.from_boundary <= max_hausdorff && s.hausdorff.from_surface <= max_hausdorff)) {
    std::fprintf(stderr, "stuff_peers: %s: Hausdorff distance %.3g, %.3g above %.3g\n", mesher.c_str(),
                 s.hausdorff.from_boundary, s.hausdorff.from_surface, max_hausdorff);
    ok = false;
  }
  return ok;
}

// ---- Self-test of the dihedral angles ---------------------------------------

bool near(long double a, long double b) { return std::fabs(a - b) < 1e-9L; }

bool selftest() {
  using bccmis::bench::dihedral_angles;
  bool ok = true;
  auto expect = [&](const char* name, const std::array<Vec3L, 4>& p, const std::array<long double, 6>& want) {
    const auto got = dihedral_angles(p);
    for (std::size_t e = 0; e < 6; ++e)
      if (!near(got[e], want[e])) {
        std::fprintf(stderr, "selftest %s: edge %zu: %.12Lf, expected %.12Lf\n", name, e, got[e], want[e]);
        ok = false;
      }
    // Reordering the corners permutes the edges but keeps the set of angles:
    // the mirrored order gives the same six angles.
    const auto mirrored = dihedral_angles({p[1], p[0], p[2], p[3]});
    long double sum = 0, msum = 0;
    for (std::size_t e = 0; e < 6; ++e) sum += got[e], msum += mirrored[e];
    if (!near(sum, msum)) {
      std::fprintf(stderr, "selftest %s: angle sum changes with the corner order\n", name);
      ok = false;
    }
  };
  // Regular tetrahedron (alternate corners of a cube): acos(1/3) at every edge.
  const long double regular = std::acos(1.0L / 3) * 180 / 3.141592653589793238462643383279502884L;
  expect("regular", {Vec3L{1, 1, 1}, Vec3L{1, -1, -1}, Vec3L{-1, 1, -1}, Vec3L{-1, -1, 1}},
         {regular, regular, regular, regular, regular, regular});
  if (!near(regular, 70.528779365509308630L)) ok = false;
  // The BCC lattice's tetrahedron: two opposite edges of length 2 (one along
  // x, one along z), four of length sqrt(3). 90 degrees at the two long
  // edges: the faces through the x edge project onto the yz plane as the
  // directions (1, 1) and (1, -1). 60 degrees at each short edge: at
  // (0,0,0)-(1,1,1) the other corners projected orthogonally to (1,1,1) are
  // (4,-2,-2)/3 and (2,2,-4)/3, of dot product 12/9 and squared lengths 24/9,
  // so the cosine is 1/2.
  expect("bcc", {Vec3L{0, 0, 0}, Vec3L{2, 0, 0}, Vec3L{1, 1, 1}, Vec3L{1, 1, -1}}, {90, 60, 60, 60, 60, 90});
  // Corner of a cube: 90 degrees at the three edges through the origin,
  // acos(1/sqrt(3)) = 54.7356... at the three edges of the slanted face.
  const long double slanted = std::acos(1 / std::sqrt(3.0L)) * 180 / 3.141592653589793238462643383279502884L;
  expect("corner", {Vec3L{0, 0, 0}, Vec3L{1, 0, 0}, Vec3L{0, 1, 0}, Vec3L{0, 0, 1}},
         {90, 90, 90, slanted, slanted, slanted});
  // A sliver: four nearly coplanar corners of a square, the two diagonals as
  // edges; angles near 0 at the four sides and near 180 at the diagonals.
  const auto sliver = dihedral_angles({Vec3L{0, 0, 0}, Vec3L{1, 1, 0}, Vec3L{1, 0, 1e-6L}, Vec3L{0, 1, 1e-6L}});
  if (!(sliver[0] > 179.99L && sliver[5] > 179.99L && sliver[1] < 0.01L && sliver[4] < 0.01L)) {
    std::fprintf(stderr, "selftest sliver: %.6Lf %.6Lf %.6Lf %.6Lf %.6Lf %.6Lf\n", sliver[0], sliver[1], sliver[2],
                 sliver[3], sliver[4], sliver[5]);
    ok = false;
  }
  // Orientation and volume: the corner tetrahedron is positive, volume 1/6.
  const std::vector<Vec3L> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const auto q = bccmis::bench::measure(pts, {Tet{0, 1, 2, 3}, Tet{1, 0, 2, 3}});
  if (q.inverted != 1 || !near(q.volume, 0)) ok = false;
  // The icosphere encloses a volume a little below the ball's and is closed.
  const Surface s = icosphere(1, 3);
  const long double v = bccmis::bench::enclosed_volume(s.points, s.triangles);
  if (!(v > 0.97L * 4 / 3 * 3.14159265358979L && v < 4.0L / 3 * 3.14159265358979L) || !closed_and_oriented(s)) {
    std::fprintf(stderr, "selftest icosphere: volume %.9Lf\n", v);
    ok = false;
  }
  std::printf("selftest: %s (regular %.6Lf, corner slanted %.6Lf)\n", ok ? "ok" : "FAILED", regular, slanted);
  return ok;
}

int usage() {
  std::fprintf(stderr,
               "usage: stuff_peers cgal INPUT.off --cell-size S [--facet-distance D] [--seed N] [--features "
               "[--feature-angle A]] [--verify [--tolerance T] [--max-hausdorff H]]\n"
               "       stuff_peers tetgen INPUT.off --max-volume V [--feature-angle A] [--verify [--tolerance T] "
               "[--max-hausdorff H]]\n"
               "       stuff_peers sphere-off R N OUT.off\n"
               "       stuff_peers selftest\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string command = argv[1];
  try {
    if (command == "selftest") return selftest() ? 0 : 1;
    if (command == "sphere-off") {
      if (argc != 5) return usage();
      write_off(argv[4], icosphere(std::strtold(argv[2], nullptr), std::atoi(argv[3])));
      return 0;
    }
    if ((command != "cgal" && command != "tetgen") || argc < 3) return usage();
    const std::string input = argv[2];
    double cell_size = 0, facet_distance = 0, max_volume = 0, tolerance = 0.05, feature_angle = 60,
           max_hausdorff = HUGE_VAL;
    unsigned seed = 0;
    bool verify = false, features = false;
    for (int i = 3; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> double {
        if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
        return std::strtod(argv[++i], nullptr);
      };
      if (a == "--cell-size")
        cell_size = value();
      else if (a == "--facet-distance")
        facet_distance = value();
      else if (a == "--max-volume")
        max_volume = value();
      else if (a == "--tolerance")
        tolerance = value();
      else if (a == "--max-hausdorff")
        max_hausdorff = value();
      else if (a == "--seed")
        seed = static_cast<unsigned>(value());
      else if (a == "--verify")
        verify = true;
      else if (a == "--features" && command == "cgal")
        features = true;
      else if (a == "--feature-angle")
        feature_angle = value();
      else
        return usage();
    }
    const Surface s = read_off(input);
    if (!closed_and_oriented(s))
      std::fprintf(stderr, "stuff_peers: warning: %s is not a closed, consistently oriented surface\n", input.c_str());
    double seconds = 0, cpu_seconds = 0;
    TetMesh m;
    if (command == "cgal") {
      if (!(cell_size > 0)) return usage();
      if (!(facet_distance > 0)) facet_distance = cell_size / 20;
      if (!(feature_angle > 0 && feature_angle < 180)) return usage();
      m = features ? run_cgal<FeaturesDomain, FeaturesDomain::Polyhedron>(s, cell_size, facet_distance, feature_angle,
                                                                          seed, seconds, cpu_seconds)
                   : run_cgal<MeshDomain, Polyhedron>(s, cell_size, facet_distance, 0, seed, seconds, cpu_seconds);
    } else {
      if (!(max_volume > 0)) return usage();
      m = run_tetgen(input, max_volume, seconds, cpu_seconds);
    }
    if (!(feature_angle > 0 && feature_angle < 180)) return usage();
    return report(features ? "cgal-features" : command, input, m, seconds, cpu_seconds, feature_angle, verify,
                  tolerance, max_hausdorff)
               ? 0
               : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stuff_peers: %s\n", e.what());
    return 1;
  }
}
