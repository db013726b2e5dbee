// bccmis::d3: the canonical state of a 3D lattice (spec/formats.md, "3D
// extension"): printing and the strict parser; and the readers that take a
// state of either dimension. The 3D trace and decision-log forms are in
// bccmis/io/format.h beside the 2D ones (Trace, parse_trace, parse_any_trace).
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <variant>

#include "bccmis/d3/graph.h"
#include "bccmis/graph.h"

namespace bccmis::d3 {

/// The canonical text of g: `bccmis-state 1`, `lattice W H D L`, the C lines,
/// the N lines, `end <#C> <#N>`. Two graphs are equal iff their texts are.
std::string canonical_state(const Graph& g);

/// canonical_state(g) written to `out`.
void write_canonical_state(std::ostream& out, const Graph& g);

/// Parses a 3D canonical state, as strictly as the 2D parse_state: it accepts
/// exactly the texts canonical_state prints (up to the validity of the graph,
/// which is the checker's job). Throws bccmis::ParseError (`file:line:col`).
Graph parse_state(std::string_view text, std::string_view file = "<state>");

}  // namespace bccmis::d3

namespace bccmis {

/// A canonical state of either dimension.
using AnyState = std::variant<Graph, d3::Graph>;

/// Parses a canonical state of either dimension: four numbers on its
/// `lattice` line make it 3D, three 2D. Throws ParseError.
AnyState parse_any_state(std::string_view text, std::string_view file = "<state>");

}  // namespace bccmis
