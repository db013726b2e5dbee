// bccmis invariants: the checker's verdict, one type for every dimension.
#pragma once

#include <string>
#include <vector>

namespace bccmis {

/// The first broken invariant of a lattice with point type P, named
/// precisely: Violation in 2D (invariants.h), d3::Violation in 3D
/// (d3/invariants.h). Each checker names its codes and sections in
/// spec/invariants.md.
template <class P>
struct BasicViolation {
  std::string code;      ///< stable kebab-case code, e.g. "symmetry" (spec/invariants.md)
  std::vector<P> where;  ///< the positions involved, in the order the message names them
  std::string message;   ///< one line naming the positions, starting with the code
  std::string section;   ///< paper or spec anchor, e.g. "§2.1 ¶2", "spec/lattice3d.md §3 F2"
  int layer = 0;         ///< the checker's layer; 0 for the operation contracts of checked.h
  friend bool operator==(const BasicViolation&, const BasicViolation&) = default;
};

}  // namespace bccmis
