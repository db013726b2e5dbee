#include "cli.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "io.h"

namespace bccmis::cli {

namespace {

// ---- Option groups and checks that several subcommands share ----------------

/// Whether all of `text` reads as one number (std::from_chars: no sign for
/// an unsigned type, no leading '+' or white space).
template <class Number>
bool read_whole(const std::string& text, Number& value) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && ptr == text.data() + text.size();
}

/// An integer from `lo` to `hi`; CLI11 prefixes the option's name to the
/// message, which names the value as given: "--max-level: '3.5' is not an
/// integer from 0 to 20".
CLI::Validator integer_in(std::int64_t lo, std::int64_t hi) {
  const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        std::int64_t v = 0;
        return read_whole(text, v) && v >= lo && v <= hi ? std::string()
                                                         : "'" + text + "' is not an integer from " + range;
      },
      "INT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
}

/// A whole number >= 0 (seeds, counts): "--threads: '-1' is not a
/// non-negative integer".
CLI::Validator non_negative_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t v = 0;
        return read_whole(text, v) ? std::string() : "'" + text + "' is not a non-negative integer";
      },
      "NONNEGATIVE");
}

/// A finite number above zero: "--size: '0' is not a positive finite number".
CLI::Validator positive_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0;
        return read_whole(text, v) && std::isfinite(v) && v > 0 ? std::string()
                                                                : "'" + text + "' is not a positive finite number";
      },
      "POSITIVE");
}

/// An option whose value is one of `choices`, its default shown.
CLI::Option* add_choice(CLI::App* cmd, const std::string& name, std::string& value, const std::string& help,
                        const std::vector<std::string>& choices) {
  return cmd->add_option(name, value, help)->check(CLI::IsMember(choices))->capture_default_str();
}

/// --depth: the checker's layers (replay, check, view).
void add_check_depth(CLI::App* cmd, int& depth) {
  cmd->add_option(
         "--depth", depth,
         "Checker layers to run: 1-4, or 5 for the CGAL triangulation layer (3D: the mesh layer and its CGAL check)")
      ->check(integer_in(1, max_check_depth()))
      ->capture_default_str();
}

/// --max-vertices: the bound on a replayed lattice (replay, view).
void add_max_vertices(CLI::App* cmd, std::int64_t& max_vertices, const std::string& help) {
  cmd->add_option("--max-vertices", max_vertices, help)
      ->check(integer_in(1, std::int64_t{1} << 40))
      ->capture_default_str();
}

/// -W, -H, -L: the 2D applications' initial lattice (heightfield, animate).
void add_lattice_size(CLI::App* cmd, std::int64_t& width, std::int64_t& height, int& max_level,
                      const std::string& lattice) {
  cmd->add_option("-W,--width", width, lattice + " width in level-0 cells")->capture_default_str();
  cmd->add_option("-H,--height", height, lattice + " height in level-0 cells")->capture_default_str();
  cmd->add_option("-L,--max-level", max_level, "Maximum refinement level")->capture_default_str();
}

/// --impl: the 2D applications' lattice (heightfield, animate).
void add_lattice_impl(CLI::App* cmd, std::string& impl) {
  add_choice(cmd, "--impl", impl, "Lattice implementation: reference or fast (same output, faster)",
             {"reference", "fast"});
}

/// --state, --stats, --json, --check: what the 2D applications report after
/// each `step` (heightfield: sweep, animate: frame).
void add_run_report(CLI::App* cmd, std::string& state, std::string& stats, bool& json, bool& check,
                    const std::string& statistics, const std::string& step) {
  cmd->add_option("--state", state, "Write the final canonical state");
  cmd->add_option("--stats", stats, "Where the " + statistics + " go ('-' = stdout)")->capture_default_str();
  cmd->add_flag("--json", json, "Statistics as JSON");
  cmd->add_flag("--check", check, "Run the invariant checker after every " + step);
}

// ---- One function per subcommand: its flags, bound to its options struct ----

CLI::App* add_replay(CLI::App& app, ReplayOptions& o) {
  CLI::App* cmd = app.add_subcommand("replay", "Replay a trace; print the decision log and the canonical state.");
  cmd->add_option("trace", o.trace, "Trace file ('-' for stdin)")->required();
  cmd->add_option("--log", o.log_file, "Write the decision log to this file (atomically) instead of stdout");
  cmd->add_option("--state", o.state_file, "Write the canonical state to this file (atomically) instead of stdout");
  add_choice(cmd, "--check", o.check, "When to run the invariant checker: every (after each command), end, none",
             {"every", "end", "none"});
  add_check_depth(cmd, o.depth);
  cmd->add_flag("-q,--quiet", o.quiet, "No summary on stderr");
  cmd->add_flag("--json", o.json, "Print one JSON object (decisions, counts, canonical state) instead of the text");
  add_choice(cmd, "--impl", o.impl, "Implementation to replay with: reference (the transcription) or fast",
             {"reference", "fast"});
  add_max_vertices(cmd, o.max_vertices, "Refuse a trace whose lattice grows beyond this many vertices (exit 2)");
  cmd->add_option("--mesh", o.mesh_files,
                  "3D: also write the final state's tetrahedral mesh to this file (.vtu, .msh or .mesh; repeatable)");
  cmd->footer(
      "A trace whose lattice line has four numbers (lattice W H D L) is 3D.\n"
      "Example:\n  bccmis replay spec/examples/fig2.trace\n  bccmis replay run.trace --check=end --log run.log --state "
      "run.state\n  bccmis replay spec/examples/d3/face.trace --depth 5 --mesh face.vtu");
  return cmd;
}

CLI::App* add_check(CLI::App& app, CheckOptions& o) {
  CLI::App* cmd = app.add_subcommand("check", "Check a canonical state against every invariant.");
  cmd->add_option("state", o.state, "State file ('-' for stdin)")->required();
  add_check_depth(cmd, o.depth);
  cmd->add_flag("-q,--quiet", o.quiet, "Print nothing when the state is valid");
  cmd->footer("Example:\n  bccmis replay spec/examples/fig2.trace --state fig2.state && bccmis check fig2.state");
  return cmd;
}

CLI::App* add_diff(CLI::App& app, DiffOptions& o) {
  CLI::App* cmd = app.add_subcommand("diff", "Semantic difference of two canonical states, by position.");
  cmd->add_option("a", o.a, "First state file ('-' for stdin)")->required();
  cmd->add_option("b", o.b, "Second state file")->required();
  cmd->add_flag("-q,--quiet", o.quiet, "Only the exit code: 0 equal, 1 different");
  cmd->footer("Exit codes: 0 equal, 1 different, 2 bad input.\nExample:\n  bccmis diff expected.state actual.state");
  return cmd;
}

CLI::App* add_stats(CLI::App& app, StatsOptions& o) {
  CLI::App* cmd =
      app.add_subcommand("stats", "Counts of a state: cells per level, nodes, junctions, edges, memory estimate.");
  cmd->add_option("state", o.state, "State file ('-' for stdin)")->required();
  cmd->add_flag("--json", o.json, "JSON output");
  cmd->add_flag("--from-trace", o.from_trace, "The input is a trace: replay it first");
  cmd->footer("Example:\n  bccmis stats --from-trace spec/examples/fig2.trace --json");
  return cmd;
}

CLI::App* add_mesh(CLI::App& app, MeshOptions& o) {
  CLI::App* cmd =
      app.add_subcommand("mesh", "Write the graded BCC tetrahedral mesh of a 3D state or trace (spec/mesh3d.md).");
  cmd->add_option("input", o.input, "3D canonical state or trace file ('-' for stdin)")->required();
  cmd->add_option("-o,--output", o.outputs,
                  "Mesh file to write (atomically); the extension names the format: .vtu (VTK, ParaView), .msh "
                  "(Gmsh 4.1), .mesh (Medit); repeatable");
  cmd->add_flag("--stats", o.stats,
                "Print vertices, tetrahedra, boundary triangles, min/max dihedral angle and a histogram");
  cmd->add_flag("--json", o.json, "Statistics as JSON (implies --stats)");
  cmd->add_flag("--check", o.check, "Also run the mesh layer of the checker on the tetrahedra (exit 1 on a violation)");
  cmd->add_flag("--binary", o.binary, "Write .vtu (base64) and .msh (4.1 binary) with binary numbers; ASCII otherwise");
  cmd->add_flag("--compress", o.compress,
                "Binary, and the .vtu's arrays zlib-compressed (vtkZLibDataCompressor); .msh has no compression");
  cmd->add_flag("-q,--quiet", o.quiet, "No summary on stderr");
  cmd->footer("Example:\n  bccmis mesh spec/examples/d3/face_refined.state -o face.vtu -o face.msh --stats");
  return cmd;
}

CLI::App* add_stuff(CLI::App& app, StuffOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "stuff", "Mesh a closed shape with tetrahedra by isosurface stuffing on the graded BCC mesh (spec/stuffing.md).");
  cmd->add_option("input", o.input,
                  "Triangle mesh: .off, .obj, .ply or .stl (PLY and STL ASCII or binary), '-' for stdin; open, "
                  "self-intersecting or "
                  "otherwise flawed meshes are repaired and meshed as the solid where the winding number >= 1/2");
  cmd->add_option("--format", o.format,
                  "Read the input as off, obj, ply or stl whatever its name (default: the extension; for stdin, "
                  "what the content is)")
      ->check(CLI::IsMember({"off", "obj", "ply", "stl"}));
  cmd->add_option("--shape", o.shape,
                  "A built-in shape instead: sphere[:r=R], torus[:R=A,r=B], spheres[:r=R,d=D] (defaults r=1; R=1, "
                  "r=0.4; r=0.7, d=1)");
  cmd->add_option("-o,--output", o.outputs,
                  "File to write (atomically, all or none); the extension names it: .vtu, .msh (Gmsh 4.1), .mesh "
                  "(Medit) for the tetrahedra, .off, .obj for the boundary surface; repeatable");
  cmd->add_option("-L,--max-level", o.max_level, "Finest lattice level, used where the surface is (default 4)")
      ->check(integer_in(0, 20));
  cmd->add_option("--min-level", o.min_level, "Every lattice leaf at least this level (default 0)")
      ->check(integer_in(0, 20));
  cmd->add_option("--cells", o.cells, "Level-0 cubes along the shape's longest side (default 4)")
      ->check(integer_in(1, 1 << 20));
  cmd->add_option("--size", o.size, "Finest edge length at most this (chooses --max-level; not with -L)")
      ->check(positive_finite());
  cmd->add_option("--animate", o.animate,
                  "Move the shape through the lattice in N frames: local refine and coarsen per frame; -o names "
                  "a .pvd (ParaView) and the frames are written beside it as .vtu")
      ->check(integer_in(1, 100000));
  cmd->add_option("--path", o.path,
                  "--animate: the whole motion DX,DY,DZ (default: 1.5 times the shape's x extent along x)");
  cmd->add_flag("--compare", o.compare, "--animate: also build every frame from scratch and report both times");
  cmd->add_option("--impl", o.impl,
                  "The lattice: fast (d3::fast::Lattice, default) or reference (d3::Graph); the same mesh")
      ->check(CLI::IsMember({"fast", "reference"}));
  cmd->add_option("--threads", o.threads,
                  "Threads extracting the lattice's tetrahedra (default 0: every core); the same mesh on any number")
      ->check(integer_in(0, 256));
  cmd->add_flag("--stats", o.stats, "Print counts, volume and its error, dihedral angles and seconds per phase");
  cmd->add_flag("--json", o.json, "Statistics as JSON (implies --stats)");
  cmd->add_flag("--hausdorff", o.hausdorff,
                "Statistics also with the Hausdorff distance between the boundary and the surface, sampled both ways "
                "(implies --stats; not with --animate)");
  cmd->add_flag("--check", o.check,
                "Check the mesh before writing: exact positive orientation, conformity, a closed boundary on the "
                "surface (exit 1 on a violation)");
  cmd->add_flag("--strict", o.strict,
                "Refuse a triangle mesh that is not closed, manifold, consistently oriented and free of "
                "self-intersections, naming its first flaw (exit 2)");
  auto* features = cmd->add_flag(
      "--features", o.features,
      "Keep the sharp features of a triangle mesh (the default for INPUT): creases whose faces turn by more than "
      "the feature angle, and their corners (spec/stuffing.md S29-S33)");
  auto* feature_angle =
      cmd->add_option("--feature-angle", o.feature_angle,
                      "The feature angle in degrees, 0 to 180 (default 60, CGAL's); implies --features")
          ->check(CLI::Range(0.0, 180.0));
  cmd->add_flag("--no-features", o.no_features,
                "Mesh INPUT without features: the mesh of S5-S9 exactly, creases cut by the lattice's chords")
      ->excludes(features)
      ->excludes(feature_angle);
  cmd->add_flag("--binary", o.binary,
                "Write .vtu (base64; also the --animate frames) and .msh (4.1 binary) with binary numbers; ASCII "
                "otherwise");
  cmd->add_flag("--compress", o.compress,
                "Binary, and the .vtu's arrays (also the --animate frames) zlib-compressed "
                "(vtkZLibDataCompressor); .msh has no compression");
  cmd->add_option("--surface-vertices", o.surface_vertices,
                  "The .off/.obj boundary: 'used' (its own vertices, default) or 'all' (every vertex of the "
                  "volume mesh, numbered as in the .vtu/.msh/.mesh)")
      ->check(CLI::IsMember({"used", "all"}));
  cmd->add_option("--memory-limit", o.memory_limit_gb,
                  "Refuse before building when the run's memory estimate exceeds this many GB (10^9 bytes; "
                  "default: the memory available, MemAvailable)")
      ->check(positive_finite());
  cmd->add_flag("-q,--quiet", o.quiet, "No progress or summary on stderr");
  cmd->footer(
      "Examples:\n  bccmis stuff --shape torus -L 4 -o torus.vtu --stats\n"
      "  bccmis stuff elephant.off -L 5 -o elephant.msh -o elephant.off --stats --json\n"
      "  bccmis stuff --shape sphere:r=0.5 -L 4 --animate 20 -o frames/ball.pvd --stats --compare");
  return cmd;
}

CLI::App* add_render(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd =
      app.add_subcommand("render",
                         "Draw a state as SVG (2D: cells, edges, junctions; 3D: the box and one slice), or a "
                         "tetrahedral mesh (.mesh: its boundary, a cut-away, its dihedral angles).");
  cmd->add_option("state", o.state, "State file ('-' for stdin), or a Medit .mesh file of tetrahedra")->required();
  cmd->add_option("-o,--output", o.output, "SVG file to write (atomically); '-' for stdout")->required();
  cmd->add_flag("--from-trace", o.from_trace, "The input is a trace: replay it first");
  cmd->add_option("--slice", o.slice,
                  "3D only: the slice panel's plane, AXIS=VALUE with AXIS x, y or z (default: z at the middle of the "
                  "box); for a .mesh, a cut-away beside the boundary at a real VALUE");
  cmd->add_flag("--histogram", o.histogram, "A .mesh only: draw its dihedral-angle histogram instead");
  cmd->footer(
      "Examples:\n  bccmis render --from-trace spec/examples/fig2.trace -o fig2.svg\n"
      "  bccmis render spec/examples/d3/face_refined.state --slice z=2 -o face.svg\n"
      "  bccmis render sphere.mesh --slice z=0 -o sphere.svg\n"
      "  bccmis render sphere.mesh --histogram -o angles.svg");
  return cmd;
}

CLI::App* add_view(CLI::App& app, ViewCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "view", "Write one self-contained HTML page that steps through a trace (or a sequence of states).");
  cmd->add_option("trace", o.trace, "Trace file ('-' for stdin)");
  cmd->add_option("--states", o.states,
                  "Instead of a trace: canonical state files, one per step, or one directory of *.state files "
                  "(taken in name order)");
  cmd->add_option("-o,--output", o.output, "HTML file to write (atomically); '-' for stdout")->required();
  add_choice(cmd, "--check", o.check,
             "When to run the invariant checker: every (each state; the page opens at the first violation), end, none",
             {"every", "end", "none"});
  add_check_depth(cmd, o.depth);
  cmd->add_option("--step", o.step, "Open the page at this step (default: the first violation, else step 0)")
      ->check(integer_in(0, std::int64_t{1} << 40));
  cmd->add_option("--from-log", o.from_log,
                  "Another implementation's output on the trace (decision log, optionally followed by its "
                  "canonical state, spec/conformance.md): mark the first disagreement with the reference");
  cmd->add_option("--title", o.title, "Title of the page (default: the input's name)");
  add_max_vertices(cmd, o.max_vertices,
                   "Refuse a trace whose lattice grows beyond this many vertices (exit 2), as replay does");
  cmd->add_flag("-q,--quiet", o.quiet, "No summary on stderr");
  cmd->footer(
      "Step k shows the state after the k-th command (step 0: the initial lattice) and what the command\n"
      "touched: the refined cell c, its children Y and new junctions J+; for coarsening the removed Y and\n"
      "J-; or the refusal code. With --states, step k is the k-th state file and the page marks what\n"
      "changed. Every state is checked; the page opens at the first violation with the offending\n"
      "vertices marked. Controls: slider, buttons, arrow keys; the URL fragment #step=K opens step K.\n"
      "With --from-log, the page opens at the first decision that differs from the log (or, when they\n"
      "all agree, at the last step with the log's final state beside the reference's, differences marked).\n"
      "Exit codes: 0 page written, 1 page written and a state violates an invariant or the log\n"
      "disagrees, 2 bad input.\n"
      "The embedded model is specified in spec/viewer.md.\n"
      "Example:\n  bccmis view spec/examples/fig2.trace -o fig2.html\n"
      "  bccmis view --states my-impl-states/ -o states.html   # 0000.state, 0001.state, ...\n"
      "  ./my-lattice run.trace > run.out; bccmis view run.trace --from-log run.out -o run.html");
  return cmd;
}

CLI::App* add_conformance(CLI::App& app, ConformanceCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "conformance", "Check another implementation against the reference: decisions and final states, with shrinking.");
  cmd->add_option("--impl", o.impl, "Command to run; the trace file path is appended (spec/conformance.md)")
      ->required();
  cmd->add_option("--traces", o.traces, "Directory of bundled *.trace files to run first");
  cmd->add_option("--random", o.random, "Number of random traces")
      ->check(integer_in(0, 1000000))
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of the random traces")->check(non_negative_integer())->capture_default_str();
  cmd->add_option("--max-ops", o.max_ops, "Operations per random trace")
      ->check(integer_in(1, 100000))
      ->capture_default_str();
  cmd->add_option("--timeout", o.timeout_seconds, "Seconds per run of the implementation")
      ->check(CLI::Range(0.01, 86400.0))
      ->capture_default_str();
  add_choice(cmd, "--dim", o.dim, "Dimension of the random traces: 2, 3, or mixed (2D and 3D alternately)",
             {"2", "3", "mixed"});
  cmd->add_option("--view", o.view,
                  "On a 2D disagreement, write a viewer page (bccmis view) for the minimal trace: the reference "
                  "and the implementation's state side by side at the first disagreement; on a 3D one, write "
                  "FILE.trace (the minimal trace), FILE.reference.state and FILE.impl.state");
  cmd->footer(
      "Exit codes: 0 all agree, 1 disagreement (the minimal trace is printed), 2 harness error (bad options,\n"
      "unreadable trace, an implementation that cannot be run: exit status 126 or 127).\n"
      "Example:\n  bccmis conformance --impl 'bccmis replay --quiet --check=none' --traces spec/examples --random 200 "
      "--seed 7\n"
      "  bccmis conformance --impl './my-lattice replay' --random 200 --view disagreement.html\n"
      "  bccmis conformance --impl './my-lattice replay' --traces spec/examples/d3 --random 200 --dim 3");
  return cmd;
}

CLI::App* add_explore(CLI::App& app, ExploreCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "explore", "Breadth-first search over every state reachable from a lattice: check each, try every operation.");
  cmd->add_option("lattice", o.lattice,
                  "W H L (2D) or W H D L (3D): level-0 cells across, up (and deep), and the maximum level")
      ->expected(3, 4)
      ->required();
  cmd->add_option("--depth", o.depth, "Checker layers on every state (0-4; in 3D, 4 adds the mesh layer)")
      ->check(integer_in(0, 4))
      ->capture_default_str();
  cmd->add_option("--max-states", o.max_states,
                  "Stop after this many states (0: no limit); the result is then incomplete")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "Worker threads (0: one per core)")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_flag("--json", o.json, "One line of JSON instead of the summary");
  cmd->add_flag("--no-progress", o.no_progress, "No progress line on stderr");
  cmd->footer(
      "Exit codes: 0 every state processed is valid and every inverse exact (a run stopped by --max-states\n"
      "says 'incomplete'), 1 a failure (a reproducing trace is printed), 2 bad input (a lattice whose\n"
      "state space is beyond reach is refused with its estimate; give --max-states for a partial run).\n"
      "Example:\n  bccmis explore 1 1 2        # 17 states\n  bccmis explore 2 2 1 --json  # 16 states\n"
      "  bccmis explore 1 1 1 2      # 257 states (3D)");
  return cmd;
}

CLI::App* add_heightfield(CLI::App& app, HeightfieldCommandOptions& o) {
  CLI::App* cmd =
      app.add_subcommand("heightfield", "Tessellate a height-field image adaptively (the paper's §3, Fig. 4-5).");
  cmd->add_option("input", o.input, "PGM (P2/P5, 8/16-bit) or PNG image; '-' for stdin")->required();
  add_lattice_size(cmd, o.width, o.height, o.max_level, "Initial lattice");
  cmd->add_option("--vertical-scale", o.vertical_scale, "Height of a full-scale pixel")->capture_default_str();
  cmd->add_option("-t,--tolerance", o.tolerance, "Refine cells whose error is above this")->capture_default_str();
  add_choice(cmd, "--measure", o.measure, "Cell error: max (every pixel, exact) or samples (the paper's)",
             {"max", "samples"});
  cmd->add_option("--samples", o.samples, "Random points per cell for --measure=samples")->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of --measure=samples")->check(non_negative_integer())->capture_default_str();
  add_choice(cmd, "--balance", o.balance, "2:1 rule: edge (the core's) or corner", {"edge", "corner"});
  add_lattice_impl(cmd, o.impl);
  cmd->add_option("--sweeps", o.sweeps, "Number of sweeps; 0 = until nothing changes")->capture_default_str();
  cmd->add_option("--from", o.from, "Start from this canonical state (incremental re-tessellation)");
  cmd->add_option("--obj", o.obj, "Write a Wavefront OBJ mesh");
  cmd->add_option("--ply", o.ply, "Write an ASCII PLY mesh");
  cmd->add_option("--vtu", o.vtu, "Write a VTK .vtu (level and error as cell data)");
  cmd->add_option("--svg", o.svg, "Write an SVG top view");
  add_run_report(cmd, o.state, o.stats, o.json, o.check, "statistics", "sweep");
  add_choice(cmd, "--progress", o.progress, "Progress lines on stderr: auto, always, never",
             {"auto", "always", "never"});
  cmd->add_flag("-q,--quiet", o.quiet, "No summary line on stderr");
  cmd->footer(
      "Example:\n  bccmis heightfield apps/samples/terrain128.pgm --tolerance 0.02 --obj terrain.obj --svg "
      "terrain.svg");
  return cmd;
}

CLI::App* add_animate(CLI::App& app, AnimateCommandOptions& o) {
  CLI::App* cmd =
      app.add_subcommand("animate", "A disk moves along a path; the lattice adapts around it (the paper's Fig. 6).");
  add_lattice_size(cmd, o.width, o.height, o.max_level, "Lattice");
  cmd->add_option("--target-level", o.target_level, "Level of the cells the feature meets; -1 = L")
      ->capture_default_str();
  cmd->add_option("--radius", o.radius, "Feature radius in level-0 cell units")->capture_default_str();
  cmd->add_option("--path", o.path, "Path 'x,y;x,y;...' in level-0 cell units")->capture_default_str();
  add_choice(cmd, "--balance", o.balance, "2:1 rule: edge or corner", {"edge", "corner"});
  cmd->add_option("--frames", o.frames, "Number of frames")->capture_default_str();
  add_lattice_impl(cmd, o.impl);
  cmd->add_flag("--lift", o.lift, "One more frame without the feature at the end");
  cmd->add_option("--svg-dir", o.svg_dir, "Write frame_NNNN.svg into this existing directory");
  add_run_report(cmd, o.state, o.stats, o.json, o.check, "per-frame statistics", "frame");
  cmd->add_flag("-q,--quiet", o.quiet, "No summary line on stderr");
  cmd->footer("Example:\n  mkdir frames && bccmis animate --frames 60 --svg-dir frames --check");
  return cmd;
}

// ---- Messages for common slips --------------------------------------------------

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "unknown subcommand 'replya': did you mean 'replay'?" (the nearest name
// within a third of its length, at least 2 edits), or the list of names.
std::string unknown_subcommand(std::string_view given, const std::vector<std::string>& names) {
  std::string best;
  std::size_t best_distance = 0;
  for (const std::string& n : names) {
    const std::size_t d = edit_distance(given, n);
    if (best.empty() || d < best_distance) {
      best = n;
      best_distance = d;
    }
  }
  std::string message = "unknown subcommand '" + std::string(given) + "'";
  if (!best.empty() && best_distance <= std::max<std::size_t>(2, best.size() / 3))
    return message + ": did you mean '" + best + "'?";
  message += " (subcommands:";
  for (const std::string& n : names) message += " " + n;
  return message + ")";
}

/// Where a usage error points: the subcommand's help when argv[1] names one
/// (parse_command_line has refused any other word there), else the tool's.
std::string help_command(int argc, char** argv) {
  if (argc > 1 && argv[1][0] != '-') return std::string("bccmis ") + argv[1] + " --help";
  return "bccmis --help";
}

}  // namespace

std::variant<int, Command> parse_command_line(int argc, char** argv) {
  CLI::App app{
      "bccmis: adaptive BCC lattices in 2D and 3D (Erleben's 2009 MIS graph representation, checked against "
      "every invariant), their meshes, and tetrahedral meshes of shapes by isosurface stuffing."};
  app.set_version_flag("--version", std::string("bccmis ") + BCCMIS_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 invariant violated, 2 bad input (usage, parse error, file), 3 internal error.\n"
      "Formats: spec/formats.md. Run 'bccmis SUBCOMMAND --help' for examples.");

  ReplayOptions replay;
  CheckOptions check;
  DiffOptions diff;
  StatsOptions stats;
  MeshOptions mesh;
  StuffOptions stuff;
  RenderOptions render;
  ViewCommandOptions view;
  ConformanceCommandOptions conformance;
  ExploreCommandOptions explore;
  HeightfieldCommandOptions heightfield;
  AnimateCommandOptions animate;
  CLI::App* stuff_cmd = nullptr;
  // In the order --help lists them (a braced list is evaluated in order).
  const std::vector<std::pair<CLI::App*, std::function<Command()>>> commands = {
      {add_replay(app, replay), [&] { return Command(replay); }},
      {add_check(app, check), [&] { return Command(check); }},
      {add_diff(app, diff), [&] { return Command(diff); }},
      {add_stats(app, stats), [&] { return Command(stats); }},
      {add_mesh(app, mesh), [&] { return Command(mesh); }},
      {stuff_cmd = add_stuff(app, stuff), [&] { return Command(stuff); }},
      {add_render(app, render), [&] { return Command(render); }},
      {add_view(app, view), [&] { return Command(view); }},
      {add_conformance(app, conformance), [&] { return Command(conformance); }},
      {add_explore(app, explore), [&] { return Command(explore); }},
      {add_heightfield(app, heightfield), [&] { return Command(heightfield); }},
      {add_animate(app, animate), [&] { return Command(animate); }},
  };

  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const auto& [cmd, options] : commands) names.push_back(cmd->get_name());
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      std::cerr << "bccmis: " << unknown_subcommand(argv[1], names) << "\nRun 'bccmis --help' for usage.\n";
      return kExitInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "bccmis: " << e.what() << "\nRun '" << help_command(argc, argv) << "' for usage.\n";
    return kExitInput;
  }
  // spec/cli.md, stuff: --size chooses the max level, so it and -L exclude
  // each other; --json implies --stats (stuff, mesh), and so does --hausdorff (stuff).
  if (*stuff_cmd && stuff_cmd->count("--size") > 0 && stuff_cmd->count("--max-level") > 0) {
    std::cerr << "bccmis: --size and -L,--max-level both choose the finest level: give one\n"
              << "Run 'bccmis stuff --help' for usage.\n";
    return kExitInput;
  }
  stuff.stats = stuff.stats || stuff.json || stuff.hausdorff;
  mesh.stats = mesh.stats || mesh.json;
  for (const auto& [cmd, options] : commands)
    if (*cmd) return options();
  return kExitInternal;
}

}  // namespace bccmis::cli
