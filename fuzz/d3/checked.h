// The 3D checked operations of the fuzz targets: refine and coarsen on a
// d3::Graph followed by the independent 3D checker (layers 1-4, and the mesh
// layer 5 on a schedule) and the exact changes of C and N that the 3D
// equations imply (spec/lattice3d.md §4-§5): refine(c) removes c from C and
// adds the 8 children Y; N gains c and J+ (at most 12 edge midpoints and 6
// face centers) and loses nothing. coarsen(n) removes the 8 cells Y around n
// from C and adds n; N loses n and J- and gains nothing. A refused operation
// must leave the canonical state byte-identical. Failures throw
// fuzz::InvariantFailure.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "../op_run.h"
#include "bccmis/d3/lattice.h"
#include "bccmis/d3/mesh.h"
#include "bccmis/invariants/d3/invariants.h"

namespace bccmis::d3::fuzz {

using bccmis::fuzz::InvariantFailure;

/// The first problem the 3D checker finds in g, as one line: layers 1-4
/// (find_violation(g, 4)) and, with `mesh`, layer 5 on tetrahedra(g).
inline std::optional<std::string> problem(const d3::Graph& g, bool mesh) {
  if (auto v = d3::find_violation(g, 4)) return to_string(*v);
  if (!mesh) return std::nullopt;
  std::vector<d3::Tet> tets;
  try {
    tets = d3::tetrahedra(g);
  } catch (const std::exception& e) {
    return std::string("tetrahedra(g) threw on a state layers 1-4 accept: ") + e.what();
  }
  if (auto v = d3::check_mesh(g, tets)) return to_string(*v);
  return std::nullopt;
}

/// refine and coarsen with the checks above. The mesh layer runs after an
/// applied operation while the lattice has at most `mesh_cells` cells, and
/// after every `mesh_every`-th applied operation beyond (never if 0).
struct Checked {
  std::size_t mesh_cells = 64;
  std::size_t mesh_every = 8;
  std::size_t applied = 0;

  d3::RefineResult refine(d3::Graph& g, const d3::Point& c) {
    const std::string op = "refine " + d3::to_string(c);
    const d3::Graph before = g;
    d3::RefineResult r = d3::refine(g, c);
    if (!refused_unchanged_or_valid(r, before, g, op)) return r;
    if (r.Y.size() != 8 || r.J_plus.size() > 18)
      throw InvariantFailure(op + " returned |Y| = " + std::to_string(r.Y.size()) + " and |J+| = " +
                             std::to_string(r.J_plus.size()) + "; spec/lattice3d.md §4 gives 8 and 0..18");
    expect_change(before.C, g.C, r.Y, {c}, "C", op);
    d3::PointSet gained = r.J_plus;
    gained.insert(c);
    expect_change(before.N, g.N, gained, {}, "N", op);
    return r;
  }

  d3::CoarsenResult coarsen(d3::Graph& g, const d3::Point& n) {
    const std::string op = "coarsen " + d3::to_string(n);
    const d3::Graph before = g;
    d3::CoarsenResult r = d3::coarsen(g, n);
    if (!refused_unchanged_or_valid(r, before, g, op)) return r;
    if (r.Y.size() != 8)
      throw InvariantFailure(op + " returned |Y| = " + std::to_string(r.Y.size()) + "; spec/lattice3d.md §5 gives 8");
    expect_change(before.C, g.C, {n}, r.Y, "C", op);
    d3::PointSet lost = r.J_minus;
    lost.insert(n);
    expect_change(before.N, g.N, {}, lost, "N", op);
    return r;
  }

 private:
  // A refused operation must have left the state unchanged (false); an
  // applied one must have left it valid (true).
  template <class Result>
  bool refused_unchanged_or_valid(const Result& r, const d3::Graph& before, const d3::Graph& g, const std::string& op) {
    if (!r.applied()) {
      unchanged(before, g, op + " was refused (" + std::string(code(*r.refused)) + ")");
      return false;
    }
    validate(g, op);
    return true;
  }

  void validate(const d3::Graph& g, const std::string& op) {
    ++applied;
    const bool mesh = g.C.size() <= mesh_cells || (mesh_every != 0 && applied % mesh_every == 0);
    if (auto p = problem(g, mesh)) throw InvariantFailure("after " + op + ": " + *p);
  }

  static void unchanged(const d3::Graph& before, const d3::Graph& g, const std::string& what) {
    if (d3::canonical_state(before) != d3::canonical_state(g) || !(before == g))
      throw InvariantFailure(what + " but changed the state");
  }

  static std::string list(const d3::PointSet& s) {
    std::string out = "{";
    for (const d3::Point& p : s) out += (out.size() > 1 ? ", " : "") + d3::to_string(p);
    return out + "}";
  }

  // The exact change of one vertex set: `gained` and `lost` as expected.
  static void expect_change(const d3::PointSet& before, const d3::PointSet& after, const d3::PointSet& gained,
                            const d3::PointSet& lost, const char* set_name, const std::string& op) {
    d3::PointSet plus, minus;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::inserter(plus, plus.end()));
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::inserter(minus, minus.end()));
    if (plus == gained && minus == lost) return;
    throw InvariantFailure(op + " changed " + set_name + " by +" + list(plus) + " -" + list(minus) +
                           "; the equations give +" + list(gained) + " -" + list(lost));
  }
};

}  // namespace bccmis::d3::fuzz
