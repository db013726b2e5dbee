// The four layers of the checker (internal to invariants/). Each returns the
// first violation of its own layer, assuming the lower layers passed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bccmis/invariants/invariants.h"

namespace bccmis::inv {

std::optional<Violation> check_combinatorial(const Graph& g);  // layer 1, combinatorial.cpp
std::optional<Violation> check_structural(const Graph& g);     // layer 2, structural.cpp
std::optional<Violation> check_grading(const Graph& g);        // layer 3, grading.cpp
std::optional<Violation> check_geometry(const Graph& g);       // layer 4, geometry.cpp

/// A Violation whose message is "<code>: <text>".
inline Violation violation(int layer, std::string code, std::vector<Point> where, const std::string& text,
                           std::string section) {
  Violation v;
  v.message = code + ": " + text;
  v.code = std::move(code);
  v.where = std::move(where);
  v.section = std::move(section);
  v.layer = layer;
  return v;
}

}  // namespace bccmis::inv
