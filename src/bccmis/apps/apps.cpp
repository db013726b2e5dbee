#include "bccmis/apps/apps.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "bccmis/apps/animate.h"
#include "bccmis/apps/balance.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/fast/lattice_interface.h"
#include "bccmis/format.h"
#include "bccmis/apps/heightfield.h"
#include "bccmis/apps/image.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/apps/mesh.h"
#include "bccmis/oracle/oracle.h"

namespace bccmis {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitViolation = 1;
constexpr int kExitInput = 2;
constexpr int kExitInternal = 3;

constexpr std::int64_t kMaxLatticeSide = 1024;  // W and H
constexpr int kMaxLevel = 24;

/// Bad input: the message is complete.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The checker found a violation: the message is complete.
struct CheckFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string fmt(double v, const char* f = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Ordered name/value statistics printed as `name value` lines or one JSON object.
class Record {
 public:
  void add(const std::string& name, const std::string& text, bool quoted) { items_.push_back({name, text, quoted, {}}); }
  void add(const std::string& name, std::int64_t v) { add(name, std::to_string(v), false); }
  void add(const std::string& name, double v) { add(name, std::isfinite(v) ? fmt(v, "%.9g") : "null", false); }
  void add(const std::string& name, const std::string& s) { add(name, s, true); }
  void add_raw_json(const std::string& name, const std::string& json, const std::string& text) {
    items_.push_back({name, text, false, json});
  }
  std::string text() const {
    std::string out;
    for (const auto& it : items_) out += it.name + " " + it.text + "\n";
    return out;
  }
  std::string json() const {
    std::string out = "{";
    for (std::size_t i = 0; i < items_.size(); ++i) {
      const auto& it = items_[i];
      out += (i ? ", " : "") + json_string(it.name) + ": " +
             (!it.json.empty() ? it.json : it.quoted ? json_string(it.text) : it.text);
    }
    return out + "}";
  }

 private:
  struct Item {
    std::string name, text;
    bool quoted = false;
    std::string json;
  };
  std::vector<Item> items_;
};

void write_output(const std::string& path, const std::string& content, std::ostream& out) {
  if (path.empty()) return;
  if (path == "-") {
    out << content << std::flush;
    return;
  }
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw InputError(path + ": cannot open for writing");
  f << content;
  f.close();
  if (!f) throw InputError(path + ": write error");
}

std::string read_input(const std::string& path) {
  std::ostringstream ss;
  if (path == "-") {
    ss << std::cin.rdbuf();
    return ss.str();
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, expected a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open for reading");
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return ss.str();
}

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

void check_lattice_limits(const LatticeSize& s, const std::string& what) {
  require(s.W >= 1 && s.W <= kMaxLatticeSide && s.H >= 1 && s.H <= kMaxLatticeSide,
          what + ": lattice " + std::to_string(s.W) + "x" + std::to_string(s.H) + " is out of range 1.." +
              std::to_string(kMaxLatticeSide) + " per side");
  require(s.L >= 0 && s.L <= kMaxLevel,
          what + ": max level " + std::to_string(s.L) + " is out of range 0.." + std::to_string(kMaxLevel));
}

void check_outputs(const std::vector<const std::string*>& paths) {
  int dashes = 0;
  for (const std::string* p : paths) dashes += *p == "-" ? 1 : 0;
  require(dashes <= 1, "at most one output can be '-' (standard output); the statistics go there by default, "
                       "give them a file with --stats FILE");
}

std::string pos(const Point& p) { return to_string(p); }

// The corner rule's violation as one line, or empty.
std::optional<std::string> corner_violation(const Graph& g) {
  const auto bad = find_corner_imbalance(g);
  if (!bad) return std::nullopt;
  return "corner balance: cell " + pos(bad->first) + " (level " + std::to_string(g.level_of(bad->first)) +
         ") touches cell " + pos(bad->second) + " (level " + std::to_string(g.level_of(bad->second)) + ")";
}

void run_check(const Graph& g, Balance balance, const std::string& when) {
  if (const std::optional<Violation> v = find_violation(g))
    throw CheckFailure("invariant violated " + when + ": " + to_string(*v));
  if (balance == Balance::Corner)
    if (const auto why = corner_violation(g)) throw CheckFailure("invariant violated " + when + ": " + *why);
}

Balance balance_option(const std::string& text) {
  const std::optional<Balance> b = parse_balance(text);
  if (!b) throw InputError("balance '" + text + "' is unknown: use edge or corner");
  return *b;
}

std::string levels_text(const Graph& g, std::string& json) {
  std::map<int, std::size_t> per_level;
  for (const auto& [c, l] : g.level) ++per_level[l];
  std::string text;
  json = "{";
  for (const auto& [l, n] : per_level) {
    if (!text.empty()) text += ' ';
    text += std::to_string(l);
    text += ':';
    text += std::to_string(n);
    if (json.size() > 1) json += ", ";
    json += '"';
    json += std::to_string(l);
    json += "\": ";
    json += std::to_string(n);
  }
  json += "}";
  return text;
}

// Runs `body`, mapping exceptions to exit codes and one-line messages.
template <class Body>
int guarded(const char* tool, std::ostream& err, Body&& body) {
  try {
    return body();
  } catch (const CheckFailure& e) {
    err << tool << ": " << e.what() << "\n";
    return kExitViolation;
  } catch (const InputError& e) {
    err << tool << ": " << e.what() << "\n";
  } catch (const ImageError& e) {
    err << tool << ": " << e.what() << "\n";
  } catch (const ParseError& e) {
    err << tool << ": " << e.what() << "\n";
  } catch (const LatticeError& e) {
    err << tool << ": " << e.what() << "\n";
  } catch (const std::invalid_argument& e) {
    err << tool << ": " << e.what() << "\n";
  } catch (const std::exception& e) {
    err << tool << ": internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitInput;
}

}  // namespace

// ---- bccmis heightfield -----------------------------------------------------------

int run_heightfield(const HeightfieldOptions& o, std::ostream& out, std::ostream& err) {
  static constexpr const char* tool = "bccmis heightfield";
  return guarded(tool, err, [&]() -> int {
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
    check_outputs({&o.obj, &o.ply, &o.vtu, &o.svg, &o.state, &o.stats});
    const std::optional<Impl> impl = parse_impl(o.impl);
    require(impl.has_value(), "impl '" + o.impl + "' is unknown: use reference or fast");

    const std::string input_name = o.input == "-" ? "<stdin>" : o.input;
    const HeightField field = parse_height_field(read_input(o.input), input_name);
    require(field.width >= 2 && field.height >= 2,
            input_name + ": a height field needs at least 2x2 pixels, this one has " + std::to_string(field.width) +
                "x" + std::to_string(field.height));

    Graph g;
    if (!o.from.empty()) {
      const std::string from_name = o.from == "-" ? "<stdin>" : o.from;
      require(o.input != "-" || o.from != "-", "the image and the state cannot both come from standard input");
      g = parse_state(read_input(o.from), from_name);
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
                          (o.progress == "auto" && &err == &std::cerr && ::isatty(STDERR_FILENO) != 0 &&
                           field.width * field.height >= 65536);
    TessellateSettings settings;
    settings.tolerance = o.tolerance;
    settings.error = {*measure, o.samples, o.seed};
    settings.max_sweeps = o.sweeps;
    settings.coarsen = !o.from.empty();
    settings.balance = balance;
    const auto t0 = Clock::now();
    auto after_sweep = [&](int sweep, std::size_t cells, std::size_t ops, const auto& graph_of_now) {
      if (progress)
        err << tool << ": sweep " << sweep << ": " << ops << " operations, " << cells << " cells, "
            << fmt(seconds_since(t0), "%.2f") << " s" << std::endl;
      if (o.check) run_check(graph_of_now(), balance, "after sweep " + std::to_string(sweep));
    };
    TessellateReport report;
    double tessellate_seconds = 0;
    if (*impl == Impl::Reference) {
      report = tessellate(g, sampler, settings, [&](int sweep, const Graph& now, std::size_t ops) {
        after_sweep(sweep, now.C.size(), ops, [&]() -> const Graph& { return now; });
      });
      tessellate_seconds = seconds_since(t0);
    } else {
      fast::Lattice lattice = fast::Lattice::from_graph(g);
      const auto t1 = Clock::now();
      report = tessellate(lattice, sampler, settings, [&](int sweep, const fast::Lattice& now, std::size_t ops) {
        after_sweep(sweep, now.cell_count(), ops, [&] { return now.to_graph(); });
      });
      tessellate_seconds = seconds_since(t1);
      g = lattice.to_graph();
    }
    if (o.check) run_check(g, balance, "at the end");
    const MeshError error = mesh_error(g, sampler);

    // Outputs.
    const std::string title = "heightfield " + input_name + " (tolerance " + fmt(o.tolerance) + ", measure " +
                              o.measure + ")";
    if (!o.obj.empty() || !o.ply.empty() || !o.vtu.empty()) {
      TriangleMesh mesh = triangulate(g, [&](const Point& p) { return sampler.at(p); });
      write_output(o.obj, format_obj(mesh, "bccmis " + title), out);
      write_output(o.ply, format_ply(mesh, "bccmis " + title), out);
      if (!o.vtu.empty()) {
        std::map<Point, double> cell_err;
        for (const Point& c : g.C) cell_err[c] = cell_error(g, c, sampler, {ErrorMeasure::MaxPixel, 0, 0});
        for (const Point& c : mesh.triangle_cell) mesh.triangle_error.push_back(cell_err.at(c));
        write_output(o.vtu, format_vtu(mesh), out);
      }
    }
    if (!o.svg.empty()) write_output(o.svg, render_svg(g, title), out);
    if (!o.state.empty()) write_output(o.state, canonical_state(g), out);

    Record r;
    r.add("input", input_name);
    r.add("image", std::to_string(field.width) + "x" + std::to_string(field.height) + " " + field.format +
                       " maxval " + std::to_string(field.maxval));
    r.add("lattice", std::to_string(g.size.W) + " " + std::to_string(g.size.H) + " " + std::to_string(g.size.L));
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
    r.add("nodes", static_cast<std::int64_t>(g.N.size()));
    r.add("cells", static_cast<std::int64_t>(g.C.size()));
    std::string levels_json;
    const std::string levels = levels_text(g, levels_json);
    r.add_raw_json("cells_per_level", levels_json, levels);
    r.add("max_error", error.max_abs);
    r.add("rms_error", error.rms);
    r.add("within_tolerance", error.max_abs <= o.tolerance + kRoundingSlack * o.vertical_scale ? "true" : "false", false);
    r.add("tessellate_seconds", tessellate_seconds);
    r.add("total_seconds", seconds_since(t_start));
    write_output(o.stats, o.json ? r.json() + "\n" : r.text(), out);

    if (!o.quiet)
      err << tool << ": " << input_name << ": " << g.N.size() << " nodes, " << g.C.size() << " cells, "
          << report.refinements + report.coarsenings << " operations in " << report.sweeps << " sweeps; max error "
          << fmt(error.max_abs) << " (tolerance " << fmt(o.tolerance) << "), " << fmt(tessellate_seconds, "%.3f")
          << " s\n";
    return kExitOk;
  });
}

// ---- bccmis animate ------------------------------------------------------------------

Graph animate(const AnimateOptions& o, const FrameObserver& after_frame, std::vector<FrameReport>* reports) {
  const LatticeSize size{o.width, o.height, o.max_level};
  if (o.width < 1 || o.width > kMaxLatticeSide || o.height < 1 || o.height > kMaxLatticeSide)
    throw std::invalid_argument("lattice " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                                " is out of range 1.." + std::to_string(kMaxLatticeSide) + " per side");
  if (o.max_level < 0 || o.max_level > kMaxLevel)
    throw std::invalid_argument("max level " + std::to_string(o.max_level) + " is out of range 0.." +
                                std::to_string(kMaxLevel));
  if (o.target_level < -1 || o.target_level > o.max_level)
    throw std::invalid_argument("target level " + std::to_string(o.target_level) + " is out of range 0.." +
                                std::to_string(o.max_level) + " (or -1 for the max level)");
  if (!std::isfinite(o.radius) || o.radius < 0) throw std::invalid_argument("radius must be a number >= 0");
  if (o.frames < 1 || o.frames > 100000) throw std::invalid_argument("frames must be in 1..100000");
  const std::optional<Balance> balance = parse_balance(o.balance);
  if (!balance) throw std::invalid_argument("balance '" + o.balance + "' is unknown: use edge or corner");
  const std::vector<std::array<double, 2>> path = parse_path(o.path);
  const int target = o.target_level < 0 ? o.max_level : o.target_level;
  const double S = static_cast<double>(level0_side(size));

  const std::optional<Impl> impl = parse_impl(o.impl);
  if (!impl) throw std::invalid_argument("impl '" + o.impl + "' is unknown: use reference or fast");

  const int total = o.frames + (o.lift ? 1 : 0);
  // The frames on either lattice; `as_graph` gives the observer its view.
  auto run = [&](auto& g, auto cells, auto nodes, auto as_graph) {
    for (int k = 0; k < total; ++k) {
      FrameReport fr;
      fr.frame = k;
      fr.lifted = k >= o.frames;
      const auto t0 = Clock::now();
      AdaptReport a;
      if (fr.lifted) {
        a = adapt_to_disks(g, {}, target, *balance);
      } else {
        const auto p = point_on_path(path, o.frames == 1 ? 0.0 : static_cast<double>(k) / (o.frames - 1));
        fr.x = p[0];
        fr.y = p[1];
        const Disk d{p[0] * S, p[1] * S, o.radius * S};
        a = adapt_to_disks(g, std::span<const Disk>(&d, 1), target, *balance);
      }
      fr.seconds = seconds_since(t0);
      fr.refinements = a.refinements;
      fr.coarsenings = a.coarsenings;
      fr.cells = cells(g);
      fr.nodes = nodes(g);
      if (reports) reports->push_back(fr);
      if (after_frame) after_frame(fr, as_graph(g));
    }
  };
  if (*impl == Impl::Reference) {
    Graph g = make_lattice(size);
    run(
        g, [](const Graph& x) { return x.C.size(); }, [](const Graph& x) { return x.N.size(); },
        [](const Graph& x) -> const Graph& { return x; });
    return g;
  }
  fast::Lattice f(size);
  run(
      f, [](const fast::Lattice& x) { return x.cell_count(); }, [](const fast::Lattice& x) { return x.node_count(); },
      [](const fast::Lattice& x) { return x.to_graph(); });
  return f.to_graph();
}

namespace {

// The feature as an SVG circle in render_svg's coordinates (760 px for the
// longer side, a 20 px margin, y up), inserted before `</svg>`.
std::string frame_svg(const Graph& g, const FrameReport& fr, double radius, const std::string& title) {
  std::string svg = render_svg(g, title);
  if (fr.lifted) return svg;
  const double w = static_cast<double>(g.size.W), h = static_cast<double>(g.size.H);
  const double scale = 760.0 / std::max(w, h), margin = 20.0;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"#e07020\" fill-opacity=\"0.25\" stroke=\"#e07020\" "
                "stroke-width=\"2\"/>\n",
                margin + fr.x * scale, margin + (h - fr.y) * scale, std::max(radius * scale, 3.0));
  const std::size_t end = svg.rfind("</svg>");
  if (end != std::string::npos) svg.insert(end, buf);
  return svg;
}

}  // namespace

int run_animate(const AnimateOptions& o, std::ostream& out, std::ostream& err) {
  static constexpr const char* tool = "bccmis animate";
  return guarded(tool, err, [&]() -> int {
    check_outputs({&o.state, &o.stats});
    if (!o.svg_dir.empty()) {
      std::error_code ec;
      require(std::filesystem::is_directory(o.svg_dir, ec), o.svg_dir + ": not an existing directory");
    }
    // The observer (and with --impl fast its copy of the lattice) only when
    // a frame needs the lattice: the check and the pictures.
    FrameObserver after;
    if (o.check || !o.svg_dir.empty()) after = [&](const FrameReport& fr, const Graph& g) {
      if (o.check) run_check(g, balance_option(o.balance), "after frame " + std::to_string(fr.frame));
      if (!o.svg_dir.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.svg", fr.frame);
        const std::string title = fr.lifted ? "frame " + std::to_string(fr.frame) + " (feature lifted)"
                                            : "frame " + std::to_string(fr.frame) + " at (" + fmt(fr.x, "%.3f") +
                                                  ", " + fmt(fr.y, "%.3f") + ")";
        write_output((std::filesystem::path(o.svg_dir) / name).string(), frame_svg(g, fr, o.radius, title), out);
      }
    };
    std::vector<FrameReport> reports;
    const Graph g = animate(o, after, &reports);
    std::string table;
    std::string frames_json;
    std::size_t refinements = 0, coarsenings = 0;
    double seconds = 0;
    for (const FrameReport& fr : reports) {
      refinements += fr.refinements;
      coarsenings += fr.coarsenings;
      seconds += fr.seconds;
      if (o.json) {
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
    if (!o.state.empty()) write_output(o.state, canonical_state(g), out);
    const std::size_t frames = static_cast<std::size_t>(o.frames) + (o.lift ? 1 : 0);
    std::string stats;
    if (o.json) {
      stats = "{\"lattice\": \"" + std::to_string(g.size.W) + " " + std::to_string(g.size.H) + " " +
              std::to_string(g.size.L) + "\", \"frames\": [\n  " + frames_json + "\n], \"total\": {\"frames\": " +
              std::to_string(frames) + ", \"refinements\": " + std::to_string(refinements) +
              ", \"coarsenings\": " + std::to_string(coarsenings) + ", \"operations\": " +
              std::to_string(refinements + coarsenings) + ", \"cells\": " + std::to_string(g.C.size()) +
              ", \"nodes\": " + std::to_string(g.N.size()) + ", \"seconds\": " + fmt(seconds, "%.9g") + "}}\n";
    } else {
      stats = "# frame         x         y   refine  coarsen    cells    nodes    seconds\n" + table +
              "total frames " + std::to_string(frames) + " refinements " + std::to_string(refinements) +
              " coarsenings " + std::to_string(coarsenings) + " operations " +
              std::to_string(refinements + coarsenings) + " cells " + std::to_string(g.C.size()) + " nodes " +
              std::to_string(g.N.size()) + " seconds " + fmt(seconds, "%.6f") + "\n";
    }
    write_output(o.stats, stats, out);
    if (!o.quiet)
      err << tool << ": " << frames << " frames, " << refinements + coarsenings << " operations (" << refinements
          << " refine, " << coarsenings << " coarsen), final " << g.C.size() << " cells, " << fmt(seconds, "%.3f")
          << " s\n";
    return kExitOk;
  });
}

}  // namespace bccmis
