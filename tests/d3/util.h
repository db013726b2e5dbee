// Helpers shared by the 3D tests: printing, replaying a 3D trace through the
// one stepper, and the spec/examples files.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bccmis/d3/lattice.h"
#include "bccmis/io/format.h"
#include "bccmis/trace.h"

namespace bccmis::d3 {

// gtest prints points readably.
inline void PrintTo(const Point& p, std::ostream* os) { *os << to_string(p); }

namespace test {

/// A vertex set written as {{x, y, z}, ...}.
inline PointSet vs(std::initializer_list<Point> points) { return PointSet(points); }

/// The 12 edge midpoints and 6 face centers of the cube [0,8]^3: the
/// nodes refine((4, 4, 4)) adds to a lattice of level-0 side 8.
inline PointSet edge_midpoints_and_face_centers_of_cube_0_8() {
  return vs({{4, 0, 0},
             {4, 0, 8},
             {4, 8, 0},
             {4, 8, 8},
             {0, 4, 0},
             {0, 4, 8},
             {8, 4, 0},
             {8, 4, 8},
             {0, 0, 4},
             {0, 8, 4},
             {8, 0, 4},
             {8, 8, 4},
             {0, 4, 4},
             {8, 4, 4},
             {4, 0, 4},
             {4, 8, 4},
             {4, 4, 0},
             {4, 4, 8}});
}

/// Replays a 3D trace (parse_trace, the one stepper): the final graph, and
/// the decision log in `log`.
inline Graph replay(const std::string& text, std::string* log = nullptr) {
  std::string local;
  return bccmis::replay<Graph>(parse_trace(text, "<test>"), log ? *log : local);
}

/// Replays a trace in which every operation must be applied (for building
/// known states); throws on a refusal.
inline Graph build(const std::string& text) {
  std::string log;
  Graph g = replay(text, &log);
  if (log.find("refused") != std::string::npos) throw std::logic_error("build: a step was refused:\n" + log);
  return g;
}

/// The text of a file under spec/examples/.
inline std::string example(const std::string& name) {
  std::ifstream in(std::string(BCCMIS_SPEC_EXAMPLES_DIR) + "/" + name, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open spec/examples/" + name);
  std::ostringstream s;
  s << in.rdbuf();
  return std::move(s).str();
}

}  // namespace test
}  // namespace bccmis::d3
