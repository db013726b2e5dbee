// bccmis replay TRACE: replays a trace on the implementation of --impl, with
// the checker when --check asks; prints (or writes) the decision log and the
// canonical state. A 3D trace (`lattice W H D L`) runs on the 3D reference
// (d3::Graph) or the fast 3D lattice (d3::fast::Lattice), with the 3D checker.
// The fast implementations are converted to a Graph (d3::Graph) only for the
// checker and the mesh: with --check=none their log and state are written
// from the lattice itself.
#include <iostream>
#include <map>
#include <string>

#include "bccmis/d3/lattice.h"
#include "bccmis/d3/mesh.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/json_writer.h"
#include "bccmis/trace.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

namespace {

// The decision log, one JSON string per line.

template <class L>
int replay_with(const ReplayOptions& o, const trace_t<L>& trace) {
  const std::string name = display_name(o.trace);
  std::string log;
  std::size_t refines = 0, coarsens = 0, refused = 0, checks = 0;
  std::optional<std::string> failure, limit_error;
  struct Stop {};  // a violation or the vertex limit stops the replay at its command
  auto observe = [&](const trace_command_t<L>& c, const L& now, std::string_view decision) {
    if (c.kind == TraceCommand::Kind::Refine) ++refines;
    if (c.kind == TraceCommand::Kind::Coarsen) ++coarsens;
    if (decision.find(" refused ") != std::string_view::npos) ++refused;
    if (const auto v = static_cast<std::int64_t>(cell_count(now) + node_count(now)); v > o.max_vertices) {
      limit_error = name + ":" + std::to_string(c.line) + ":1: after '" + command_text(c) + "' the lattice has " +
                    std::to_string(v) + " vertices, above the limit of " + std::to_string(o.max_vertices) +
                    " (--max-vertices)";
      throw Stop{};
    }
    if (c.kind == TraceCommand::Kind::Check || o.check == "every") {
      ++checks;
      if (auto v = check_message(now, o.depth)) {
        failure = name + ":" + std::to_string(c.line) + ": invariant violated after '" + command_text(c) + "': " + *v;
        throw Stop{};
      }
    }
  };
  std::optional<L> result;
  try {
    result.emplace(replay<L>(trace, log, observe));
  } catch (const Stop&) {
  }
  if (limit_error) throw InputError(*limit_error);
  if (failure) {
    std::cerr << "bccmis replay: " << *failure << "\n";
    if (!o.log_file.empty()) write_atomically(o.log_file, log);
    return kExitViolation;
  }
  const L& g = *result;
  if (o.check == "end") {
    ++checks;
    if (auto v = check_message(g, o.depth)) {
      std::cerr << "bccmis replay: " << name << ": invariant violated at the end: " << *v << "\n";
      return kExitViolation;
    }
  }
  const Writer state = [&](std::ostream& out) { write_canonical_state(out, g); };
  OutputSet outputs;
  if constexpr (std::is_same_v<L, d3::Graph>) {
    if (!o.mesh_files.empty()) {
      const d3::TetMesh mesh = d3::index_mesh(g, d3::tetrahedra(g));
      for (const std::string& path : o.mesh_files) add_mesh_output(outputs, path, mesh);
    }
  } else if constexpr (std::is_same_v<L, d3::fast::Lattice>) {
    if (!o.mesh_files.empty()) {
      const d3::Graph graph = g.to_graph();
      const d3::TetMesh mesh = d3::index_mesh(graph, d3::tetrahedra(graph));
      for (const std::string& path : o.mesh_files) add_mesh_output(outputs, path, mesh);
    }
  }
  outputs.add(o.log_file, log);
  outputs.add(o.state_file, state);
  if (o.json) {
    // One JSON object on stdout: the decisions, the canonical state and the counts.
    JsonWriter w;
    w.begin_object().member("trace", name).member("impl", o.impl).key("decisions").begin_array();
    for (std::size_t start = 0; start < log.size();) {
      const std::size_t nl = log.find('\n', start);
      w.value(std::string_view(log).substr(start, nl - start));
      start = nl + 1;
    }
    w.end_array()
        .member("refines", refines)
        .member("coarsens", coarsens)
        .member("refused", refused)
        .member("checks", checks)
        .member("cells", cell_count(g))
        .member("nodes", node_count(g))
        .member("state", canonical_text(g))
        .end_object();
    outputs.add("-", w.str() + "\n");
    outputs.commit();
    return kExitOk;
  }
  // What is not written to a file goes to stdout: the log, then the state.
  if (o.log_file.empty()) outputs.add("-", log);
  if (o.state_file.empty()) outputs.add("-", state);
  outputs.commit();
  if (!o.quiet)
    std::cerr << "bccmis replay: " << name << ": " << refines << " refine and " << coarsens << " coarsen commands ("
              << refused << " refused), " << checks << " checks passed (depth " << o.depth
              << "); final state: " << summary(g) << "\n";
  return kExitOk;
}

}  // namespace

int run(const ReplayOptions& o) {
  for (const std::string& path : o.mesh_files) check_mesh_path(path);
  TraceLimits limits;
  limits.max_vertices = o.max_vertices;
  const AnyTrace any = read_any_trace(o.trace, limits);
  if (const auto* trace3 = std::get_if<d3::Trace>(&any)) {
    // implementation() names the 2D lattice of --impl; the 3D one is its counterpart.
    return std::visit(
        [&]<class L>(std::type_identity<L>) {
          if constexpr (std::is_same_v<L, Graph>)
            return replay_with<d3::Graph>(o, *trace3);
          else
            return replay_with<d3::fast::Lattice>(o, *trace3);
        },
        implementation(o.impl));
  }
  if (!o.mesh_files.empty())
    throw InputError(display_name(o.trace) + ": --mesh writes the tetrahedra of 3D lattices; this trace is 2D");
  const Trace& trace = std::get<Trace>(any);
  return std::visit([&]<class L>(std::type_identity<L>) { return replay_with<L>(o, trace); }, implementation(o.impl));
}

}  // namespace bccmis::cli
