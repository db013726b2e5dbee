#include "bccmis/d3/format.h"

#include <string>

#include "bccmis/d3/lattice.h"  // static_assert(AdaptiveLattice<Graph3>)

namespace bccmis::d3 {

namespace {

void append_point(std::string& out, const Point3& p) {
  out += std::to_string(p.x);
  out += ' ';
  out += std::to_string(p.y);
  out += ' ';
  out += std::to_string(p.z);
}

// " : x1 y1 z1 x2 y2 z2 ...\n"; the set is sorted by (x, y, z) already.
void append_neighbors(std::string& out, const PointSet3& vs) {
  out += " :";
  for (const Point3& v : vs) {
    out += ' ';
    append_point(out, v);
  }
  out += '\n';
}

}  // namespace

std::string canonical_state(const Graph3& g) {
  std::string out = "bccmis-state 1\nlattice ";
  out += std::to_string(g.size.W);
  out += ' ';
  out += std::to_string(g.size.H);
  out += ' ';
  out += std::to_string(g.size.D);
  out += ' ';
  out += std::to_string(g.size.L);
  out += '\n';
  for (const Point3& c : g.C) {
    out += "C ";
    append_point(out, c);
    out += ' ';
    out += std::to_string(g.level_of(c));
    append_neighbors(out, g.nbr(c));
  }
  for (const Point3& n : g.N) {
    out += "N ";
    append_point(out, n);
    append_neighbors(out, g.nbr(n));
  }
  out += "end ";
  out += std::to_string(g.C.size());
  out += ' ';
  out += std::to_string(g.N.size());
  out += '\n';
  return out;
}

void write_canonical_state(std::ostream& out, const Graph3& g) { out << canonical_state(g); }

}  // namespace bccmis::d3
