// bccmis animate: a disk moves along a path and the lattice adapts around it
// (Erleben 2009, §3, Fig. 6; spec/apps.md). The flags become the apps
// library's AnimationSettings; the frames' pictures, the state and the
// statistics are staged and written only when the whole run has succeeded.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app_support.h"
#include "bccmis/apps/apps.h"
#include "bccmis/apps/moving_disk.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/io/svg.h"
#include "bccmis/oracle/oracle.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

namespace {

constexpr const char* kTool = "bccmis animate";

// The frame's picture with the feature drawn over it as a circle in
// render_svg's coordinates (760 px for the longer side, a 20 px margin, y up).
std::string frame_svg(const Graph& g, const FrameReport& fr, double radius, const std::string& title) {
  if (fr.lifted) return render_svg(g, title);
  const double w = static_cast<double>(g.size.W), h = static_cast<double>(g.size.H);
  const double scale = 760.0 / std::max(w, h), margin = 20.0;
  return render_svg(g, title,
                    io::circle(margin + fr.x * scale, margin + (h - fr.y) * scale, std::max(radius * scale, 3.0),
                               "fill=\"#e07020\" fill-opacity=\"0.25\" stroke=\"#e07020\" stroke-width=\"2\""));
}

std::string frame_title(const FrameReport& fr) {
  return fr.lifted ? "frame " + std::to_string(fr.frame) + " (feature lifted)"
                   : "frame " + std::to_string(fr.frame) + " at (" + fmt(fr.x, "%.3f") + ", " + fmt(fr.y, "%.3f") + ")";
}

/// The sums over the frames.
struct Totals {
  std::size_t refinements = 0, coarsenings = 0;
  double seconds = 0;
};

Totals totals(const std::vector<FrameReport>& reports) {
  Totals t;
  for (const FrameReport& fr : reports) {
    t.refinements += fr.refinements;
    t.coarsenings += fr.coarsenings;
    t.seconds += fr.seconds;
  }
  return t;
}

std::string stats_text(const std::vector<FrameReport>& reports, const LatticeSize& size, std::size_t cells,
                       std::size_t nodes, bool json) {
  std::string table, frames_json;
  const auto [refinements, coarsenings, seconds] = totals(reports);
  for (const FrameReport& fr : reports) {
    if (json) {
      frames_json += std::string(frames_json.empty() ? "" : ",\n  ") + "{\"frame\": " + std::to_string(fr.frame) +
                     ", \"lifted\": " + (fr.lifted ? "true" : "false") + ", \"x\": " + fmt(fr.x, "%.9g") +
                     ", \"y\": " + fmt(fr.y, "%.9g") + ", \"refinements\": " + std::to_string(fr.refinements) +
                     ", \"coarsenings\": " + std::to_string(fr.coarsenings) +
                     ", \"cells\": " + std::to_string(fr.cells) + ", \"nodes\": " + std::to_string(fr.nodes) +
                     ", \"seconds\": " + fmt(fr.seconds, "%.9g") + "}";
    } else {
      char line[200];
      std::snprintf(line, sizeof line, "%5d %9.4f %9.4f %8zu %8zu %8zu %8zu %10.6f%s\n", fr.frame, fr.x, fr.y,
                    fr.refinements, fr.coarsenings, fr.cells, fr.nodes, fr.seconds, fr.lifted ? " lifted" : "");
      table += line;
    }
  }
  const std::size_t frames = reports.size();
  if (json)
    return "{\"lattice\": \"" + std::to_string(size.W) + " " + std::to_string(size.H) + " " + std::to_string(size.L) +
           "\", \"frames\": [\n  " + frames_json + "\n], \"total\": {\"frames\": " + std::to_string(frames) +
           ", \"refinements\": " + std::to_string(refinements) + ", \"coarsenings\": " + std::to_string(coarsenings) +
           ", \"operations\": " + std::to_string(refinements + coarsenings) + ", \"cells\": " + std::to_string(cells) +
           ", \"nodes\": " + std::to_string(nodes) + ", \"seconds\": " + fmt(seconds, "%.9g") + "}}\n";
  return "# frame         x         y   refine  coarsen    cells    nodes    seconds\n" + table + "total frames " +
         std::to_string(frames) + " refinements " + std::to_string(refinements) + " coarsenings " +
         std::to_string(coarsenings) + " operations " + std::to_string(refinements + coarsenings) + " cells " +
         std::to_string(cells) + " nodes " + std::to_string(nodes) + " seconds " + fmt(seconds, "%.6f") + "\n";
}

int run_animate(const AnimateCommandOptions& o) {
  require_one_stdout({&o.state, &o.stats}, kOneStdout);
  if (!o.svg_dir.empty()) {
    std::error_code ec;
    require(std::filesystem::is_directory(o.svg_dir, ec), o.svg_dir + ": not an existing directory");
  }
  const LatticeSize size{o.width, o.height, o.max_level};
  try {
    check_lattice_limits(size, "options");
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()).substr(std::string("options: ").size()));
  }
  AnimationSettings settings;
  settings.target_level = o.target_level;
  settings.radius = o.radius;
  settings.path = parse_path(o.path);
  settings.balance = balance_option(o.balance);
  settings.frames = o.frames;
  settings.lift = o.lift;

  OutputSet outputs;
  std::vector<FrameReport> reports;
  std::size_t cells = 0, nodes = 0;
  std::visit(
      [&]<class L>(std::type_identity<L>) {
        L g(size);
        // The observer (and with --impl fast its Graph copy) only when a
        // frame needs the lattice: the check and the pictures.
        FrameObserver<L> after;
        if (o.check || !o.svg_dir.empty())
          after = [&](const FrameReport& fr, const L& now) {
            Graph copy;
            const Graph& graph = as_graph(now, copy);
            if (o.check) run_check(graph, settings.balance, "after frame " + std::to_string(fr.frame));
            if (!o.svg_dir.empty()) {
              char name[32];
              std::snprintf(name, sizeof name, "frame_%04d.svg", fr.frame);
              outputs.add((std::filesystem::path(o.svg_dir) / name).string(),
                          frame_svg(graph, fr, o.radius, frame_title(fr)));
            }
          };
        reports = animate(g, settings, after);
        cells = cell_count(g);
        nodes = node_count(g);
        outputs.add(o.state, [&](std::ostream& out) { write_canonical_state(out, g); });
      },
      implementation(o.impl));
  outputs.add(o.stats, stats_text(reports, size, cells, nodes, o.json));
  outputs.commit();
  if (!o.quiet) {
    const auto [refinements, coarsenings, seconds] = totals(reports);
    std::cerr << kTool << ": " << reports.size() << " frames, " << refinements + coarsenings << " operations ("
              << refinements << " refine, " << coarsenings << " coarsen), final " << cells << " cells, "
              << fmt(seconds, "%.3f") << " s\n";
  }
  return kExitOk;
}

}  // namespace

int run(const AnimateCommandOptions& o) {
  return guarded(kTool, [&] { return translating_app_errors([&] { return run_animate(o); }); });
}

}  // namespace bccmis::cli
