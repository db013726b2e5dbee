// bccmis conformance --impl COMMAND: another implementation against the
// reference, on bundled and random traces of either dimension, with shrinking
// (spec/conformance.md).
#include <algorithm>
#include <filesystem>
#include <iostream>

#include "bccmis/oracle/conformance.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

int run(const ConformanceCommandOptions& o) {
  ConformanceOptions co;
  co.impl = o.impl;
  co.random = o.random;
  co.seed = o.seed;
  co.max_ops = o.max_ops;
  co.timeout_seconds = o.timeout_seconds;
  co.dimension = o.dim == "2" ? TraceDimension::Two : o.dim == "3" ? TraceDimension::Three : TraceDimension::Mixed;
  if (!o.traces.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_directory(o.traces, ec)) throw InputError(o.traces + ": not a directory");
    for (const auto& e : std::filesystem::directory_iterator(o.traces))
      if (e.path().extension() == ".trace") co.trace_files.push_back(e.path().string());
    std::sort(co.trace_files.begin(), co.trace_files.end());
  }
  if (co.trace_files.empty() && co.random == 0)
    throw InputError("conformance: nothing to check: give --traces DIR or --random N with N > 0");
  if (!o.view.empty()) {
    co.write_view = [&](const std::string& html) {
      write_atomically(o.view, html);
      std::cout << "viewer page of the disagreement: " << o.view << "\n";
    };
    // The viewer draws 2D lattices only: a 3D disagreement is written as files.
    co.write_files = [&](const DisagreementFiles& files) {
      OutputSet outputs;
      outputs.add(o.view + ".trace", files.trace);
      outputs.add(o.view + ".reference.state", files.reference_state);
      outputs.add(o.view + ".impl.state", files.impl_state);
      outputs.commit();
      std::cout << "files of the 3D disagreement: " << o.view << ".trace (minimal trace), " << o.view
                << ".reference.state, " << o.view << ".impl.state\n";
    };
  }
  try {
    return run_conformance(co, std::cout);
  } catch (const ImplementationNotRunnable& e) {
    std::cout.flush();
    throw InputError(std::string("conformance: ") + e.what());
  }
}

}  // namespace bccmis::cli
