#include "bccmis/io/msh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "bccmis/io/regions.h"

namespace bccmis::io {

namespace {

static_assert(std::endian::native == std::endian::little, "the binary .msh is written little-endian");

double coordinate(const d3::Point& p, std::size_t i) { return static_cast<double>(i == 0 ? p.x : i == 1 ? p.y : p.z); }
double coordinate(const d3::Vec3& p, std::size_t i) { return p[i]; }

/// The numbers of an MSH 4.1 section as text (separated by spaces, lines
/// ended by end_line) or binary (int as int32, size_t as uint64, double as
/// float64; end_line writes nothing), gathered in a buffer written out when
/// full and at flush() (so anything written to the stream directly must
/// come after a flush or end_section).
class MshNumbers {
 public:
  MshNumbers(std::ostream& out, Encoding encoding) : out_(out), binary_(encoding != Encoding::ascii) {}
  MshNumbers(const MshNumbers&) = delete;
  MshNumbers& operator=(const MshNumbers&) = delete;
  ~MshNumbers() { flush(); }

  void integer(int v) {
    if (binary_) return raw(static_cast<std::int32_t>(v));
    text(v);
  }
  void size(std::size_t v) {
    if (binary_) return raw(static_cast<std::uint64_t>(v));
    text(v);
  }
  void real(double v) {
    if (binary_) return raw(v);
    text(v);
  }
  void end_line() {
    if (!binary_) put('\n');
    first_ = true;
  }
  /// "$EndNAME", after a newline that ends the binary data.
  void end_section(const char* name) {
    flush();
    if (binary_) out_ << '\n';
    out_ << "$End" << name << '\n';
    first_ = true;
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(used_));
    used_ = 0;
  }

 private:
  static constexpr std::size_t kRoom = 32;  ///< the most one number takes, with its space

  char* room() {
    if (used_ + kRoom > buffer_.size()) flush();
    return buffer_.data() + used_;
  }
  void put(char c) { *room() = c, ++used_; }
  template <class T>
  void raw(T v) {
    std::memcpy(room(), &v, sizeof v);
    used_ += sizeof v;
  }
  template <class T>
  void text(T v) {
    char* p = room();
    if (!first_) *p++ = ' ';
    p = std::to_chars(p, buffer_.data() + buffer_.size(), v).ptr;
    used_ = static_cast<std::size_t>(p - buffer_.data());
    first_ = false;
  }
  std::ostream& out_;
  bool binary_;
  bool first_ = true;
  std::array<char, 65536> buffer_{};
  std::size_t used_ = 0;
};

template <class P>
void write_msh_impl(std::ostream& out, const d3::BasicTetMesh<P>& mesh, const Regions& r, Encoding encoding) {
  const std::size_t n = mesh.vertices.size(), m = mesh.tets.size(), b = r.boundary.size();
  const std::size_t components = r.count;
  // Nodes need an entity even without tetrahedra.
  const std::size_t volumes = std::max<std::size_t>(components, n > 0 ? 1 : 0);
  const bool binary = encoding != Encoding::ascii;
  MshNumbers w(out, encoding);

  out << "$MeshFormat\n4.1 " << (binary ? 1 : 0) << " 8\n";
  if (binary) {
    w.integer(1);  // tells the reader the byte order
    w.flush();
    out << '\n';
  }
  out << "$EndMeshFormat\n";

  out << "$PhysicalNames\n" << components + (b > 0 ? 1 : 0) << '\n';
  for (std::size_t k = 1; k <= components; ++k) out << "3 " << k << " \"component_" << k << "\"\n";
  if (b > 0) out << "2 " << components + 1 << " \"boundary\"\n";
  out << "$EndPhysicalNames\n";

  // Each component's bounding box, over the vertices of its tetrahedra.
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 6>> box(volumes, {inf, inf, inf, -inf, -inf, -inf});
  for (std::size_t t = 0; t < m; ++t)
    for (const std::uint32_t v : mesh.tets[t])
      for (std::size_t i = 0; i < 3; ++i) {
        auto& bb = box[r.tet_component[t]];
        bb[i] = std::min(bb[i], coordinate(mesh.vertices[v], i));
        bb[i + 3] = std::max(bb[i + 3], coordinate(mesh.vertices[v], i));
      }
  for (auto& bb : box)
    if (bb[0] > bb[3]) bb = {0, 0, 0, 0, 0, 0};
  std::vector<bool> has_boundary(volumes, false);
  for (const std::uint32_t k : r.boundary_component) has_boundary[k] = true;
  const std::size_t surfaces = static_cast<std::size_t>(std::count(has_boundary.begin(), has_boundary.end(), true));

  out << "$Entities\n";
  w.size(0), w.size(0), w.size(surfaces), w.size(volumes), w.end_line();
  for (std::size_t k = 0; k < volumes; ++k) {  // surface k + 1: the boundary of component k + 1
    if (!has_boundary[k]) continue;
    w.integer(static_cast<int>(k + 1));
    for (const double c : box[k]) w.real(c);
    w.size(1), w.integer(static_cast<int>(components + 1)), w.size(0), w.end_line();
  }
  for (std::size_t k = 0; k < volumes; ++k) {
    w.integer(static_cast<int>(k + 1));
    for (const double c : box[k]) w.real(c);
    if (k < components)
      w.size(1), w.integer(static_cast<int>(k + 1));
    else
      w.size(0);
    if (has_boundary[k])
      w.size(1), w.integer(static_cast<int>(k + 1));
    else
      w.size(0);
    w.end_line();
  }
  w.end_section("Entities");

  // Every node in volume 1.
  out << "$Nodes\n";
  w.size(n > 0 ? 1 : 0), w.size(n), w.size(n > 0 ? 1 : 0), w.size(n), w.end_line();
  if (n > 0) {
    w.integer(3), w.integer(1), w.integer(0), w.size(n), w.end_line();
    for (std::size_t i = 1; i <= n; ++i) w.size(i), w.end_line();
    for (const P& p : mesh.vertices)
      w.real(coordinate(p, 0)), w.real(coordinate(p, 1)), w.real(coordinate(p, 2)), w.end_line();
  }
  w.end_section("Nodes");

  // One block of tetrahedra per component, then one of triangles per boundary surface.
  std::vector<std::vector<std::uint32_t>> tets_of(components);
  for (std::uint32_t t = 0; t < m; ++t) tets_of[r.tet_component[t]].push_back(t);
  out << "$Elements\n";
  w.size(components + surfaces), w.size(m + b), w.size(m + b > 0 ? 1 : 0), w.size(m + b), w.end_line();
  for (std::size_t k = 0; k < components; ++k) {
    w.integer(3), w.integer(static_cast<int>(k + 1)), w.integer(4), w.size(tets_of[k].size()), w.end_line();
    for (const std::uint32_t t : tets_of[k]) {
      w.size(t + 1);
      for (const std::uint32_t v : mesh.tets[t]) w.size(v + 1);
      w.end_line();
    }
  }
  for (std::size_t j = 0; j < b;) {  // boundary triangles are sorted by component
    const std::uint32_t k = r.boundary_component[j];
    std::size_t e = j;
    while (e < b && r.boundary_component[e] == k) ++e;
    w.integer(2), w.integer(static_cast<int>(k + 1)), w.integer(2), w.size(e - j), w.end_line();
    for (; j < e; ++j) {
      w.size(m + j + 1);
      for (const std::uint32_t v : r.boundary[j]) w.size(v + 1);
      w.end_line();
    }
  }
  w.end_section("Elements");
}

}  // namespace

void write_msh(std::ostream& out, const d3::TetMesh& mesh, Encoding encoding) {
  write_msh_impl(out, mesh, regions_of(mesh.tets), encoding);
}
void write_msh(std::ostream& out, const d3::TetMeshF& mesh, Encoding encoding) {
  write_msh_impl(out, mesh, regions_of(mesh.tets), encoding);
}
void write_msh(std::ostream& out, const d3::TetMeshF& mesh, const Regions& regions, Encoding encoding) {
  write_msh_impl(out, mesh, regions, encoding);
}

}  // namespace bccmis::io
