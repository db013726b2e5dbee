// bccmis heightfield IMAGE: adaptive tessellation of a height field
// (Erleben 2009, §3, Fig. 4 and 5; spec/apps.md). The flags become typed
// settings of the apps library (heightfield.h, mesh.h); every output is
// staged and written only when the whole run has succeeded.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>

#include <unistd.h>

#include "app_support.h"
#include "bccmis/apps/balance.h"
#include "bccmis/apps/heightfield.h"
#include "bccmis/apps/image.h"
#include "bccmis/apps/triangulate.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/io/obj.h"
#include "bccmis/io/ply.h"
#include "bccmis/io/vtu.h"
#include "bccmis/oracle/oracle.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

namespace {

constexpr const char* kTool = "bccmis heightfield";

int run_heightfield(const HeightfieldCommandOptions& o) {
  const auto t_start = Clock::now();
  require(!o.input.empty(), "no input image given");
  const std::optional<ErrorMeasure> measure = parse_error_measure(o.measure);
  require(measure.has_value(), "measure '" + o.measure + "' is unknown: use max or samples");
  require(std::isfinite(o.tolerance) && o.tolerance >= 0, "tolerance must be a number >= 0");
  require(std::isfinite(o.vertical_scale) && o.vertical_scale > 0, "vertical scale must be a number > 0");
  require(o.samples >= 1 && o.samples <= 100000, "samples must be in 1..100000");
  require(o.sweeps >= 0, "sweeps must be >= 0 (0: until nothing changes)");
  const Balance balance = balance_option(o.balance);
  require(o.progress == "auto" || o.progress == "always" || o.progress == "never",
          "progress '" + o.progress + "' is unknown: use auto, always or never");
  require_one_stdout({&o.obj, &o.ply, &o.vtu, &o.svg, &o.state, &o.stats}, kOneStdout);
  const Implementation impl = implementation(o.impl);

  const std::string input_name = display_name(o.input);
  const HeightField field = parse_height_field(read_input(o.input), input_name);
  require(field.width >= 2 && field.height >= 2, input_name +
                                                     ": a height field needs at least 2x2 pixels, this one has " +
                                                     std::to_string(field.width) + "x" + std::to_string(field.height));

  Graph g;
  if (!o.from.empty()) {
    const std::string from_name = display_name(o.from);
    require(o.input != "-" || o.from != "-", "the image and the state cannot both come from standard input");
    g = read_state(o.from);
    check_lattice_limits(g.size, from_name);
    if (const std::optional<Violation> v = find_violation(g))
      throw InputError(from_name + ": not a valid lattice state: " + to_string(*v));
    if (balance == Balance::Corner)
      if (const auto why = corner_violation(g))
        throw InputError(from_name + ": not corner-balanced (--balance corner): " + *why);
  } else {
    const LatticeSize size{o.width, o.height, o.max_level};
    check_lattice_limits(size, "options");
    g = make_lattice(size);
  }
  const HeightSampler sampler(field, g.size, o.vertical_scale);

  const bool progress = o.progress == "always" ||
                        (o.progress == "auto" && ::isatty(STDERR_FILENO) != 0 && field.width * field.height >= 65536);
  TessellateSettings settings;
  settings.tolerance = o.tolerance;
  settings.error = {*measure, o.samples, o.seed};
  settings.max_sweeps = o.sweeps;
  settings.coarsen = !o.from.empty();
  settings.balance = balance;
  TessellateReport report;
  double tessellate_seconds = 0;
  MeshError error;
  std::size_t node_total = 0, cell_total = 0;
  std::map<int, std::size_t> per_level;
  OutputSet outputs;
  const std::string title =
      "heightfield " + input_name + " (tolerance " + fmt(o.tolerance) + ", measure " + o.measure + ")";
  const LatticeSize size = g.size;
  // The tessellation and every output run on the chosen lattice; a Graph
  // copy is made only for what only the reference answers (the checker, the
  // SVG picture, the per-cell errors of --vtu).
  std::visit(
      [&]<class L>(std::type_identity<L>) {
        L lattice = [&] {
          if constexpr (std::is_same_v<L, Graph>)
            return std::move(g);
          else
            return L::from_graph(g);
        }();
        const auto t0 = Clock::now();
        report = tessellate(lattice, sampler, settings, [&](int sweep, const L& now, std::size_t ops) {
          if (progress)
            std::cerr << kTool << ": sweep " << sweep << ": " << ops << " operations, " << cell_count(now) << " cells, "
                      << fmt(seconds_since(t0), "%.2f") << " s" << std::endl;
          if (o.check) {
            Graph copy;
            run_check(as_graph(now, copy), balance, "after sweep " + std::to_string(sweep));
          }
        });
        tessellate_seconds = seconds_since(t0);
        Graph copy;
        const bool needs_graph = o.check || !o.svg.empty() || !o.vtu.empty();
        const Graph* graph = needs_graph ? &as_graph(lattice, copy) : nullptr;
        if (o.check) run_check(*graph, balance, "at the end");
        error = mesh_error(lattice, sampler);
        node_total = node_count(lattice);
        cell_total = cell_count(lattice);
        for (const Point& c : cells(lattice)) ++per_level[level_of(lattice, c)];

        // Outputs, all or nothing.
        if (!o.obj.empty() || !o.ply.empty() || !o.vtu.empty()) {
          auto mesh =
              std::make_shared<TriangleMesh>(triangulate(lattice, [&](const Point& p) { return sampler.at(p); }));
          const std::string comment = "bccmis " + title;
          if (!o.obj.empty())
            outputs.add(o.obj, [mesh, comment](std::ostream& out) { io::write_obj(out, *mesh, comment); });
          if (!o.ply.empty())
            outputs.add(o.ply, [mesh, comment](std::ostream& out) { io::write_ply(out, *mesh, comment); });
          if (!o.vtu.empty()) {
            std::map<Point, double> cell_err;
            for (const Point& c : graph->C)
              cell_err[c] = cell_error(*graph, c, sampler, {ErrorMeasure::MaxPixel, 0, 0});
            for (const Point& c : mesh->triangle_cell) mesh->triangle_error.push_back(cell_err.at(c));
            outputs.add(o.vtu, [mesh](std::ostream& out) { io::write_vtu(out, *mesh); });
          }
        }
        if (!o.svg.empty()) outputs.add(o.svg, render_svg(*graph, title));
        if (!o.state.empty()) {
          auto kept = std::make_shared<L>(std::move(lattice));
          outputs.add(o.state, [kept](std::ostream& out) { write_canonical_state(out, *kept); });
        }
      },
      impl);

  Record r;
  r.add("input", input_name);
  r.add("image", std::to_string(field.width) + "x" + std::to_string(field.height) + " " + field.format + " maxval " +
                     std::to_string(field.maxval));
  r.add("lattice", std::to_string(size.W) + " " + std::to_string(size.H) + " " + std::to_string(size.L));
  if (!o.from.empty()) r.add("from", o.from);
  r.add("impl", o.impl);
  r.add("balance", o.balance);
  r.add("measure", o.measure);
  if (*measure == ErrorMeasure::RandomSamples) {
    r.add("samples", std::int64_t{o.samples});
    r.add("seed", std::to_string(o.seed), false);
  }
  r.add("tolerance", o.tolerance);
  r.add("vertical_scale", o.vertical_scale);
  r.add("sweeps", std::int64_t{report.sweeps});
  r.add("converged", report.converged ? "true" : "false", false);
  r.add("operations", static_cast<std::int64_t>(report.refinements + report.coarsenings));
  r.add("refinements", static_cast<std::int64_t>(report.refinements));
  r.add("coarsenings", static_cast<std::int64_t>(report.coarsenings));
  r.add("nodes", static_cast<std::int64_t>(node_total));
  r.add("cells", static_cast<std::int64_t>(cell_total));
  std::string levels_json;
  const std::string levels = levels_text(per_level, levels_json);
  r.add_raw_json("cells_per_level", levels_json, levels);
  r.add("max_error", error.max_abs);
  r.add("rms_error", error.rms);
  r.add("within_tolerance", error.max_abs <= o.tolerance + kRoundingSlack * o.vertical_scale ? "true" : "false", false);
  r.add("tessellate_seconds", tessellate_seconds);
  r.add("total_seconds", seconds_since(t_start));
  outputs.add(o.stats, o.json ? r.json() + "\n" : r.text());
  outputs.commit();

  if (!o.quiet)
    std::cerr << kTool << ": " << input_name << ": " << node_total << " nodes, " << cell_total << " cells, "
              << report.refinements + report.coarsenings << " operations in " << report.sweeps << " sweeps; max error "
              << fmt(error.max_abs) << " (tolerance " << fmt(o.tolerance) << "), " << fmt(tessellate_seconds, "%.3f")
              << " s\n";
  return kExitOk;
}

}  // namespace

int run(const HeightfieldCommandOptions& o) {
  return guarded(kTool, [&] { return translating_app_errors([&] { return run_heightfield(o); }); });
}

}  // namespace bccmis::cli
