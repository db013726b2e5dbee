// bccmis: the canonical-state writer of spec/formats.md ("Canonical state"
// and its 3D extension) for a graph of either dimension (Graph, d3::Graph).
// Internal: io/format.cpp and io/d3/format.cpp define write_canonical_state with it.
#pragma once

#include <cstdint>
#include <ostream>

#include "bccmis/d3/point.h"
#include "bccmis/graph.h"
#include "bccmis/text_writer.h"

namespace bccmis::detail {

inline void put_point(TextWriter& w, const Point& p) { w.put_point(p.x, p.y); }
inline void put_point(TextWriter& w, const d3::Point& p) { w.put_point(p.x, p.y, p.z); }
inline void put_size(TextWriter& w, const LatticeSize& s) {
  for (const std::int64_t v : {s.W, s.H, std::int64_t{s.L}}) {
    w.put(' ');
    w.put_int(v);
  }
}
inline void put_size(TextWriter& w, const d3::LatticeSize& s) {
  for (const std::int64_t v : {s.W, s.H, s.D, std::int64_t{s.L}}) {
    w.put(' ');
    w.put_int(v);
  }
}

template <class G>
void write_state_as(std::ostream& out, const G& g) {
  TextWriter w(out);
  w.put("bccmis-state 1\nlattice");
  put_size(w, g.size);
  w.put('\n');
  auto neighbors = [&](const auto& v) {
    w.put(" :");
    for (const auto& b : g.nbr(v)) put_point(w, b);
    w.put('\n');
  };
  // g.level holds the levels of the centers (and, in a graph built by hand,
  // maybe of other points): walked beside g.C, both sorted; a center without
  // a level is written '?', which no parser accepts.
  auto level = g.level.begin();
  for (const auto& c : g.C) {
    w.put('C');
    put_point(w, c);
    w.put(' ');
    while (level != g.level.end() && level->first < c) ++level;
    if (level != g.level.end() && level->first == c) {
      w.put_int(level->second);
    } else {
      w.put('?');
    }
    neighbors(c);
  }
  for (const auto& n : g.N) {
    w.put('N');
    put_point(w, n);
    neighbors(n);
  }
  w.put("end ");
  w.put_int(static_cast<std::int64_t>(g.C.size()));
  w.put(' ');
  w.put_int(static_cast<std::int64_t>(g.N.size()));
  w.put('\n');
  w.flush();
}

}  // namespace bccmis::detail
