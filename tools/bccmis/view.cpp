// bccmis view: one HTML page that steps through a trace, or through a
// sequence of states (spec/viewer.md).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <variant>

#include "bccmis/oracle/conformance.h"
#include "bccmis/oracle/view.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

namespace {

// The state files of --states: the files given, or the *.state files of one directory.
std::vector<std::string> state_files(const std::vector<std::string>& given) {
  std::error_code ec;
  if (given.size() != 1 || !std::filesystem::is_directory(given[0], ec)) return given;
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(given[0]))
    if (e.path().extension() == ".state") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(given[0] + ": no *.state files in the directory");
  return files;
}

}  // namespace

int run(const ViewCommandOptions& v) {
  ViewOptions o;
  if (v.check != "none") o.check = [depth = v.depth](const Graph& g) { return check_graph(g, depth); };
  o.check_last_only = v.check == "end";
  if (v.step >= 0) o.open_step = static_cast<std::size_t>(v.step);
  ViewResult r;
  if (!v.states.empty()) {
    if (!v.trace.empty()) throw InputError("view: give a trace or --states, not both");
    if (!v.from_log.empty()) throw InputError("view: --from-log needs a trace, not --states");
    const std::vector<std::string> files = state_files(v.states);
    std::vector<std::pair<std::string, Graph>> states;
    for (const std::string& f : files)
      states.emplace_back(display_name(f), read_state(f, "give a trace as the first argument, not with --states"));
    o.title = v.title.empty() ? "states: " + display_name(files.front()) +
                                    (files.size() > 1 ? " ... " + display_name(files.back()) : "")
                              : v.title;
    try {
      r = view_states(states, o);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("view: ") + e.what());
    }
  } else {
    if (v.trace.empty()) throw InputError("view: give a trace file or --states (see 'bccmis view --help')");
    const std::string name = display_name(v.trace);
    o.title = v.title.empty() ? name : v.title;
    TraceLimits limits;
    limits.max_vertices = v.max_vertices;
    o.max_vertices = v.max_vertices;
    const AnyTrace any = read_any_trace(v.trace, limits, "give canonical states with --states");
    if (const auto* t3 = std::get_if<d3::Trace>(&any))
      throw InputError(name + ":" + std::to_string(t3->lattice_line) +
                       ":1: a 3D trace ('lattice W H D L'): the viewer draws 2D lattices only (replay it with "
                       "'bccmis replay', mesh it with 'bccmis mesh')");
    const Trace& trace = std::get<Trace>(any);
    if (!v.from_log.empty()) {
      // Another implementation's output on the trace (spec/conformance.md).
      ImplRun run;
      run.out = read_input(v.from_log);
      o.side = implementation_side(trace, run, {}, false);
      if (o.side) {
        o.side->title = display_name(v.from_log);
        if (!o.open_step) o.open_step = o.side->step;
      }
    }
    try {
      r = view_trace(trace, o);
    } catch (const ViewLimitError& e) {
      throw InputError(name + ":" + std::to_string(e.line) + ":1: " + e.what());
    } catch (const std::invalid_argument& e) {
      throw InputError(name + ": view: " + e.what());
    }
  }
  write_atomically(v.output, r.html);
  if (o.side) {
    std::cerr << "bccmis view: " << display_name(v.from_log) << " disagrees with the reference at step " << o.side->step
              << " (the page opens there): " << o.side->message << "\n";
    return kExitViolation;
  }
  if (r.first_violation) {
    std::cerr << "bccmis view: invariant violated at step " << *r.first_violation
              << " (the page opens there): " << r.violation << "\n";
    return kExitViolation;
  }
  if (!v.quiet && v.output != "-")
    std::cerr << "bccmis view: " << v.output << ": " << r.steps << " steps, " << r.html.size() << " bytes\n";
  return kExitOk;
}

}  // namespace bccmis::cli
