// Helpers shared by the 3D tests: printing, a small trace runner for the 3D
// trace form of spec/formats.md (the real parser comes with the 3D formats),
// and the spec/examples files.
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

namespace bccmis::d3 {

// gtest prints points readably.
inline void PrintTo(const Point3& p, std::ostream* os) { *os << to_string(p); }

namespace test {

/// A vertex set written as {{x, y, z}, ...}.
inline PointSet3 vs(std::initializer_list<Point3> points) { return PointSet3(points); }

/// One line of a 3D trace: `lattice W H D L`, `refine X Y Z`, `coarsen X Y Z`
/// or `check`; `#` starts a comment.
struct Command {
  std::string verb;
  std::vector<std::int64_t> args;
};

inline std::vector<Command> parse(const std::string& text) {
  std::vector<Command> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    Command cmd;
    if (!(words >> cmd.verb)) continue;
    for (std::int64_t v; words >> v;) cmd.args.push_back(v);
    const std::size_t want = cmd.verb == "lattice" ? 4 : cmd.verb == "check" ? 0 : 3;
    if (cmd.args.size() != want) throw std::invalid_argument("bad 3D trace line: " + line);
    out.push_back(cmd);
  }
  if (out.empty() || out.front().verb != "lattice") throw std::invalid_argument("3D trace without lattice");
  return out;
}

/// Replays a 3D trace: the final graph, and the decision log in `log`.
inline Graph3 replay(const std::string& text, std::string* log = nullptr) {
  const std::vector<Command> cmds = parse(text);
  const auto& a = cmds.front().args;
  Graph3 g(LatticeSize3{a[0], a[1], a[2], static_cast<int>(a[3])});
  for (std::size_t i = 1; i < cmds.size(); ++i) {
    const Command& cmd = cmds[i];
    if (cmd.verb == "check") continue;
    const Point3 p{cmd.args[0], cmd.args[1], cmd.args[2]};
    std::string refusal;
    if (cmd.verb == "refine") {
      const RefineResult r = refine(g, p);
      if (r.refused) refusal = code(*r.refused);
    } else if (cmd.verb == "coarsen") {
      const CoarsenResult r = coarsen(g, p);
      if (r.refused) refusal = code(*r.refused);
    } else {
      throw std::invalid_argument("unknown 3D command " + cmd.verb);
    }
    if (log) {
      *log += cmd.verb + ' ' + std::to_string(p.x) + ' ' + std::to_string(p.y) + ' ' + std::to_string(p.z);
      *log += refusal.empty() ? std::string(" ok") : " refused " + refusal;
      *log += '\n';
    }
  }
  return g;
}

/// Replays a trace in which every operation must be applied (for building
/// known states); throws on a refusal.
inline Graph3 build(const std::string& text) {
  std::string log;
  Graph3 g = replay(text, &log);
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
