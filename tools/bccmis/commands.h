// bccmis CLI: the subcommands (spec/cli.md). Each has an options struct,
// filled by the command line (cli.cpp, one field per flag, with the defaults
// below), and a run function in its own file (replay.cpp, check.cpp, ...)
// that returns the exit code (io.h) or throws InputError / CheckFailure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/graph.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/encoding.h"
#include "bccmis/io/format.h"

namespace bccmis::fast {
class Lattice;
}  // namespace bccmis::fast
namespace bccmis::d3 {
using Graph = BasicGraph<Point, LatticeSize>;
namespace fast {
class Lattice;
}  // namespace fast
template <class P>
struct BasicTetMesh;
using TetMesh = BasicTetMesh<Point>;
}  // namespace bccmis::d3

namespace bccmis::cli {

class OutputSet;

// ---- Shared by the subcommands (check.cpp) ----------------------------------------

/// The lattice implementations of --impl, chosen once at the edge:
/// std::visit([]<class L>(std::type_identity<L>) { ... }, implementation(name)).
using Implementation = std::variant<std::type_identity<Graph>, std::type_identity<fast::Lattice>>;
/// "reference" (Graph) or "fast" (fast::Lattice); throws InputError otherwise.
Implementation implementation(std::string_view name);

/// The lattice as a Graph, for the checker and the renderers: g itself, or
/// (fast) its conversion, stored in `copy`.
inline const Graph& as_graph(const Graph& g, Graph&) { return g; }
const Graph& as_graph(const fast::Lattice& g, Graph& copy);

/// The checker's deepest layer: 5 (the CGAL triangulation) when built with CGAL.
int max_check_depth();
/// The checker to `depth` (5 adds the CGAL triangulation layer).
std::optional<Violation> check_graph(const Graph& g, int depth);
/// The first violation the checker finds to `depth`, as one line, on a
/// lattice of either dimension: 2D layers 1-4 and 5 (CGAL); 3D layers 1-4,
/// and with depth 5 the tetrahedral mesh layer and its CGAL cross-check
/// (layers 5 and 6 of spec/invariants.md, "3D").
std::optional<std::string> check_message(const Graph& g, int depth);
std::optional<std::string> check_message(const fast::Lattice& g, int depth);
std::optional<std::string> check_message(const d3::Graph& g, int depth);
/// The 3D checker on the fast 3D lattice, converted to a d3::Graph.
std::optional<std::string> check_message(const d3::fast::Lattice& g, int depth);
/// "9 cells (level 0: 1, level 1: 8), 17 nodes", from the cells per level.
std::string summary(const std::map<int, std::size_t>& cells_per_level, std::size_t nodes);
std::string summary(const Graph& g);
std::string summary(const fast::Lattice& g);
std::string summary(const d3::Graph& g);
std::string summary(const d3::fast::Lattice& g);

/// A mesh output path: '.vtu', '.msh' or '.mesh'; throws InputError otherwise.
void check_mesh_path(const std::string& path);
/// Stages `mesh` for `path` in the writer its extension names (mesh.cpp).
void add_mesh_output(OutputSet& outputs, const std::string& path, const d3::TetMesh& mesh,
                     io::Encoding encoding = io::Encoding::ascii);
/// --binary and --compress as the writers' encoding (spec/cli.md).
inline io::Encoding output_encoding(bool binary, bool compress) {
  return compress ? io::Encoding::zlib : binary ? io::Encoding::binary : io::Encoding::ascii;
}

// ---- The subcommands ------------------------------------------------------------------

struct ReplayOptions {
  std::string trace;
  std::string log_file;
  std::string state_file;
  std::string check = "every";  ///< every, end, none
  int depth = 4;
  bool quiet = false;
  std::int64_t max_vertices = TraceLimits{}.max_vertices;
  std::string impl = "reference";  ///< reference, fast
  bool json = false;
  std::vector<std::string> mesh_files;  ///< 3D: the final state's tetrahedral mesh (mesh.cpp)
};
int run(const ReplayOptions& o);

struct CheckOptions {
  std::string state;
  int depth = 4;
  bool quiet = false;
};
int run(const CheckOptions& o);

struct DiffOptions {
  std::string a, b;
  bool quiet = false;
};
int run(const DiffOptions& o);

struct StatsOptions {
  std::string state;
  bool json = false;
  bool from_trace = false;
};
int run(const StatsOptions& o);

struct MeshOptions {
  std::string input;                 ///< a 3D canonical state or trace
  std::vector<std::string> outputs;  ///< -o, repeatable; the extension names the format
  bool stats = false;
  bool json = false;
  bool check = false;     ///< the mesh layer on the mesh before writing it
  bool binary = false;    ///< .vtu and .msh with binary numbers (spec/cli.md)
  bool compress = false;  ///< binary, and .vtu zlib-compressed (spec/cli.md)
  bool quiet = false;
};
int run(const MeshOptions& o);

struct StuffOptions {
  std::string input;                 ///< a triangle mesh (.off, .obj, .ply, .stl); "-" standard input
  std::string format;                ///< "off", "obj", "ply", "stl": the input's format, whatever its name; "": by name
  std::string shape;                 ///< or a built-in shape, NAME[:KEY=VALUE,...]
  std::vector<std::string> outputs;  ///< -o, repeatable; the extension names the format
  int max_level = 4;
  int min_level = 0;
  int cells = 4;
  double size = 0;            ///< > 0: the finest edge length asked for (chooses the max level)
  int animate = 0;            ///< > 0: frames of the shape moving along `path`
  std::string path;           ///< "DX,DY,DZ": the whole motion (default: 1.5 times the shape's x extent along x)
  bool compare = false;       ///< --animate: also build every frame from scratch and time it
  std::string impl = "fast";  ///< fast (d3::fast::Lattice) or reference (d3::Graph)
  int threads = 0;            ///< spec/stuffing.md S28: 0 every core
  bool stats = false;
  bool json = false;
  bool hausdorff = false;  ///< --stats also reports S13's sampled Hausdorff distance
  bool check = false;
  bool strict = false;        ///< refuse a triangle mesh at its first flaw (spec/stuffing.md S21)
  bool features = false;      ///< keep the sharp features (spec/stuffing.md S29-S33)
  double feature_angle = -1;  ///< >= 0: S29's feature angle (and features on)
  bool no_features = false;   ///< the mesh of S5-S9 exactly
  double crease_cuts = 0;     ///< S35.7's delta, of the finest side; 0: none
  bool binary = false;        ///< .vtu (also the --animate frames) and .msh with binary numbers (spec/cli.md)
  bool compress = false;      ///< binary, and .vtu zlib-compressed (spec/cli.md)
  std::string surface_vertices = "used";  ///< .off/.obj: "used" (compact) or "all" (the volume mesh's numbering)
  double memory_limit_gb = 0;             ///< > 0: the memory a run may take (spec/stuffing.md S25), else MemAvailable
  bool quiet = false;
  /// spec/cli.md: the features are on by default for a triangle-mesh INPUT,
  /// and with any feature option (S29-S35), unless --no-features.
  bool features_on() const {
    return (features || feature_angle >= 0 || crease_cuts > 0 || !input.empty()) && !no_features;
  }
};
int run(const StuffOptions& o);

struct RenderOptions {
  std::string state;
  std::string output;
  bool from_trace = false;
  std::string slice;       ///< 3D: "AXIS=VALUE", empty for z at the middle of the box; a .mesh: the cut-away
  bool histogram = false;  ///< a .mesh: the dihedral-angle histogram instead of the picture
};
int run(const RenderOptions& o);

struct ViewCommandOptions {
  std::string trace;
  std::vector<std::string> states;
  std::string output;
  std::string check = "every";  ///< every, end, none
  int depth = 4;
  std::int64_t step = -1;  ///< -1: the first violation, else 0
  std::string from_log;
  std::string title;
  std::int64_t max_vertices = TraceLimits{}.max_vertices;
  bool quiet = false;
};
int run(const ViewCommandOptions& o);

struct ConformanceCommandOptions {
  std::string impl;
  std::string traces;  ///< a directory of *.trace files
  int random = 100;
  std::uint64_t seed = 1;
  int max_ops = 30;
  double timeout_seconds = 10;
  std::string dim = "mixed";  ///< of the random traces: 2, 3 or mixed
  std::string view;           ///< the viewer page of a 2D disagreement; VIEW.* files of a 3D one
};
int run(const ConformanceCommandOptions& o);

struct ExploreCommandOptions {
  /// W H L (2D) or W H D L (3D).
  std::vector<std::int64_t> lattice;
  int depth = 4;
  std::int64_t max_states = 0;  ///< 0: no limit
  int threads = 0;              ///< 0: one per core
  bool json = false;
  bool no_progress = false;
};
int run(const ExploreCommandOptions& o);

struct HeightfieldCommandOptions {
  std::string input;
  std::int64_t width = 6;
  std::int64_t height = 6;
  int max_level = 5;
  double vertical_scale = 1.0;
  double tolerance = 0.02;
  std::string measure = "max";  ///< max, samples
  int samples = 16;
  std::uint64_t seed = 1;
  std::string balance = "edge";  ///< edge, corner
  int sweeps = 0;
  std::string impl = "reference";  ///< reference, fast
  std::string from;
  std::string obj, ply, vtu, svg, state;
  std::string stats = "-";
  bool json = false;
  bool check = false;
  std::string progress = "auto";  ///< auto, always, never
  bool quiet = false;
};
int run(const HeightfieldCommandOptions& o);

struct AnimateCommandOptions {
  std::int64_t width = 8;
  std::int64_t height = 8;
  int max_level = 5;
  int target_level = -1;
  double radius = 0.5;
  std::string path = "1,4;4,7;7,4;4,1;1,4";
  std::string balance = "edge";  ///< edge, corner
  int frames = 40;
  std::string impl = "reference";  ///< reference, fast
  bool lift = false;
  std::string svg_dir;
  std::string state;
  std::string stats = "-";
  bool json = false;
  bool check = false;
  bool quiet = false;
};
int run(const AnimateCommandOptions& o);

}  // namespace bccmis::cli
