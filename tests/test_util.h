// Helpers shared by the core's unit tests.
#pragma once

#include <initializer_list>
#include <ostream>
#include <string>

#include "bccmis/graph.h"
#include "bccmis/io/format.h"
#include "bccmis/ops.h"

namespace bccmis {

// gtest prints points and sets readably.
inline void PrintTo(const Point& p, std::ostream* os) { *os << "(" << p.x << ", " << p.y << ")"; }

namespace test {

/// A vertex set written as {{x, y}, ...}.
inline PointSet vs(std::initializer_list<Point> points) { return PointSet(points); }

/// Replays a trace text and fails the test (via exception) if any refine or
/// coarsen in it is refused: the helper is for building known states.
Graph build(const std::string& trace_text);

/// The decision log of a trace text.
std::string decisions(const std::string& trace_text);

}  // namespace test
}  // namespace bccmis
