#include "stuff_command_line.h"

#include <CLI/CLI.hpp>

#include "validators.h"

namespace bccmis::cli {

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
  cmd->add_option(
         "--threads", o.threads,
         "Threads testing the lattice's leaves and stuffing it (default 0: every core); the same mesh on any number")
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
  auto* crease_cuts =
      cmd->add_option("--crease-cuts", o.crease_cuts,
                      "Place the cut points within this fraction of the finest side of a feature curve on it before "
                      "warping (spec/stuffing.md S35.7; default 0: none); implies --features")
          ->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("--no-features", o.no_features,
                "Mesh INPUT without features: the mesh of S5-S9 exactly, creases cut by the lattice's chords")
      ->excludes(features)
      ->excludes(feature_angle)
      ->excludes(crease_cuts);
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

std::string finish_stuff_options(const CLI::App& cmd, StuffOptions& o) {
  // spec/cli.md, stuff: --size chooses the max level, so it and -L exclude
  // each other; --json and --hausdorff imply --stats.
  if (cmd.count("--size") > 0 && cmd.count("--max-level") > 0)
    return "--size and -L,--max-level both choose the finest level: give one";
  o.stats = o.stats || o.json || o.hausdorff;
  return {};
}

}  // namespace bccmis::cli
