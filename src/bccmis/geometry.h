// bccmis: the few position computations the operations need where the paper's
// sets cannot decide (each use is listed in spec/errata.toml, kind = "position").
#pragma once

#include "bccmis/graph.h"

namespace bccmis {

/// The midpoint of a and b. Callers only pass points whose coordinate
/// differences are even; written to avoid overflow near 2^62.
inline Point midpoint(const Point& a, const Point& b) {
  return {a.x + (b.x - a.x) / 2, a.y + (b.y - a.y) / 2};
}

/// Two corners of one cell are the ends of a side (not a diagonal) iff they
/// share a coordinate.
inline bool are_side_adjacent(const Point& a, const Point& b) {
  return a != b && (a.x == b.x || a.y == b.y);
}

}  // namespace bccmis
