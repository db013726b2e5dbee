// The Python module `bccmis` (spec/python.md): the stuffing library's entry
// point (stuff::mesh_shape) and the lattices, with numpy arrays in and out.
// One translation unit: pybind11 is slow to compile. The library does the
// work; this file converts arrays, errors and callbacks (P1-P8).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <stdlib.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "bccmis/d3/lattice.h"
#include "bccmis/d3/mesh.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/invariants/d3/invariants.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/io/medit.h"
#include "bccmis/io/msh.h"
#include "bccmis/io/obj.h"
#include "bccmis/io/off.h"
#include "bccmis/io/parse_error.h"
#include "bccmis/io/vtu.h"
#include "bccmis/lattice.h"
#include "bccmis/stuff/animate_shape.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/statistics_json.h"
#include "bccmis/stuff/surface.h"
#include "bccmis/trace.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using bccmis::stuff::Vec3;
using Tri = std::array<std::uint32_t, 3>;

/// Python's ValueError with `message`.
[[noreturn]] void value_error(const std::string& message) { throw py::value_error(message); }

// ---- P1: a triangle mesh from arrays ---------------------------------------

/// (n, 3) float64 vertices, each coordinate finite (P6 names the first that is not).
std::vector<Vec3> vertices_of(const py::handle& object) {
  const auto a = py::array_t<double, py::array::forcecast>::ensure(object);
  if (!a) value_error("vertices: not an array of numbers");
  if (a.ndim() != 2 || a.shape(1) != 3)
    value_error("vertices: expected an array of shape (n, 3), got shape " + std::string(py::str(a.attr("shape"))));
  const auto v = a.unchecked<2>();
  std::vector<Vec3> out(static_cast<std::size_t>(a.shape(0)));
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    for (py::ssize_t k = 0; k < 3; ++k) {
      const double x = v(i, k);
      if (!std::isfinite(x))
        value_error("vertices[" + std::to_string(i) + ", " + std::to_string(k) + "] is " +
                    std::string(py::str(py::float_(x))) + ": every coordinate must be finite");
      out[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = x;
    }
  return out;
}

/// (m, 3) faces of any integer dtype, each index in [0, n).
std::vector<Tri> faces_of(const py::handle& object, std::size_t n) {
  const py::array any = py::array::ensure(object);
  if (!any) value_error("faces: not an array");
  const char kind = any.dtype().kind();
  if (any.size() > 0 && kind != 'i' && kind != 'u')
    value_error("faces: dtype " + std::string(py::str(any.dtype())) + " is not an integer type");
  if (any.ndim() != 2 || any.shape(1) != 3)
    value_error("faces: expected an array of shape (m, 3), got shape " + std::string(py::str(any.attr("shape"))));
  const bool is_unsigned = kind == 'u';
  const auto index = [&](py::ssize_t i, py::ssize_t k, auto value) -> std::uint32_t {
    if (value < 0 || static_cast<std::uint64_t>(value) >= n)
      value_error("faces[" + std::to_string(i) + ", " + std::to_string(k) + "] = " + std::to_string(value) +
                  ": out of range for " + std::to_string(n) + " vertices");
    return static_cast<std::uint32_t>(value);
  };
  std::vector<Tri> out(static_cast<std::size_t>(any.shape(0)));
  const auto fill = [&](const auto& a) {
    const auto f = a.template unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
      for (py::ssize_t k = 0; k < 3; ++k)
        out[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = index(i, k, f(i, k));
  };
  if (is_unsigned)
    fill(py::array_t<std::uint64_t, py::array::forcecast>::ensure(any));
  else
    fill(py::array_t<std::int64_t, py::array::forcecast>::ensure(any));
  return out;
}

// ---- P3: a Python callable as a shape --------------------------------------

/// f(points (k, 3)) -> (k,) signed values, asked one point at a time (the
/// library's Shape interface), with the GIL taken for each call (P7).
class PythonShape final : public bccmis::stuff::Shape {
 public:
  PythonShape(py::function f, const bccmis::stuff::Bounds& box) : f_(std::move(f)), box_(box) {
    name_ = "python function " + std::string(py::str(py::getattr(f_, "__name__", py::str("<callable>"))));
  }
  ~PythonShape() override {
    py::gil_scoped_acquire gil;
    f_ = py::function();
  }
  double signed_distance(const Vec3& p) const override {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    py::array_t<double> points({py::ssize_t{1}, py::ssize_t{3}});
    std::copy(p.begin(), p.end(), points.mutable_data());
    const auto values = py::array_t<double, py::array::forcecast>::ensure(f_(points));
    if (!values || values.size() != 1)
      value_error(name_ + ": expected 1 value for 1 point, got " +
                  (values ? std::to_string(values.size()) : std::string("something that is not an array of numbers")));
    const double f = values.data()[0];
    if (std::isnan(f))
      value_error(name_ + ": the value at (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
                  std::to_string(p[2]) + ") is nan");
    return f;
  }
  double crossing(const Vec3& a, const Vec3& b) const override { return bccmis::stuff::bisect_crossing(*this, a, b); }
  bccmis::stuff::Bounds bounds() const override { return box_; }
  double volume() const override { return std::numeric_limits<double>::quiet_NaN(); }
  std::vector<Vec3> sample_surface(std::size_t, std::uint64_t) const override { return {}; }
  std::string describe() const override { return name_; }

 private:
  py::function f_;
  bccmis::stuff::Bounds box_;
  std::string name_;
};

bccmis::stuff::Bounds bounds_of(const py::handle& object) {
  const auto a = py::array_t<double, py::array::forcecast>::ensure(object);
  if (!a || a.ndim() != 2 || a.shape(0) != 2 || a.shape(1) != 3)
    value_error("bounds: expected ((x0, y0, z0), (x1, y1, z1))");
  bccmis::stuff::Bounds b;
  for (std::size_t k = 0; k < 3; ++k) {
    b.lo[k] = a.at(0, static_cast<py::ssize_t>(k));
    b.hi[k] = a.at(1, static_cast<py::ssize_t>(k));
    if (!std::isfinite(b.lo[k]) || !std::isfinite(b.hi[k]) || !(b.lo[k] < b.hi[k]))
      value_error("bounds: expected finite lo < hi on every axis");
  }
  return b;
}

// ---- P4: the mesh -------------------------------------------------------------

/// What a run made, owned by the Python TetMesh; its arrays are views.
struct TetMesh {
  bccmis::stuff::Meshed meshed;
  std::string shape;
  py::object stats = py::none();
};

/// A read-only view of `count` rows of `T[columns]` at `data`, kept alive by `owner`.
template <class T>
py::array view(const T* data, std::size_t count, std::size_t columns, const py::handle& owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(count)},
      strides{static_cast<py::ssize_t>(columns * sizeof(T))};
  if (columns > 1) shape.push_back(static_cast<py::ssize_t>(columns)), strides.push_back(sizeof(T));
  py::array a(py::dtype::of<T>(), shape, strides, data, owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

/// A property's getter: the read-only view of the vector `get(mesh)` (of
/// numbers, or of rows std::array<T, k>), kept alive by the Python TetMesh.
template <class Get>
auto member_view(Get get) {
  return [get](const py::object& self) {
    const auto& v = get(self.cast<const TetMesh&>());
    using Element = typename std::decay_t<decltype(v)>::value_type;
    if constexpr (std::is_arithmetic_v<Element>)
      return view(v.data(), v.size(), 1, self);
    else
      return view(v.empty() ? nullptr : v[0].data(), v.size(), std::tuple_size_v<Element>, self);
  };
}

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// P4: `path` in the format its extension names, through a temporary file
/// beside it renamed over it when complete.
void write_mesh(const TetMesh& t, const std::string& path, bool binary, bool compress) {
  const auto& mesh = t.meshed.stuffed.mesh;
  const auto& boundary = t.meshed.boundary;
  const auto encoding = compress ? bccmis::io::Encoding::zlib
                        : binary ? bccmis::io::Encoding::binary
                                 : bccmis::io::Encoding::ascii;
  std::function<void(std::ostream&)> writer;
  if (ends_with(path, ".vtu")) writer = [&](std::ostream& out) { bccmis::io::write_vtu(out, mesh, encoding); };
  if (ends_with(path, ".msh")) writer = [&](std::ostream& out) { bccmis::io::write_msh(out, mesh, encoding); };
  if (ends_with(path, ".mesh")) writer = [&](std::ostream& out) { bccmis::io::write_medit(out, mesh); };
  if (ends_with(path, ".off")) writer = [&](std::ostream& out) { bccmis::io::write_off(out, mesh, boundary, false); };
  if (ends_with(path, ".obj")) writer = [&](std::ostream& out) { bccmis::io::write_obj(out, mesh, boundary, false); };
  if (!writer)
    value_error(path +
                ": unknown format; the extension names it: .vtu, .msh, .mesh (tetrahedra), .off, .obj "
                "(boundary surface)");
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  std::string temporary = dir + "." + name + ".tmp-XXXXXX";
  int fd = -1;
  int error = 0;
  {
    py::gil_scoped_release nogil;
    fd = mkstemp(temporary.data());
    if (fd < 0) {
      error = errno;
    } else {
      close(fd);
      std::ofstream out(temporary, std::ios::binary);
      writer(out);
      out.close();
      if (!out) error = errno ? errno : EIO;
      if (error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
      if (error != 0) std::remove(temporary.c_str());
    }
  }
  if (error != 0) {
    errno = error;
    PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
    throw py::error_already_set();
  }
}

py::array dihedral_angles(const TetMesh& t) {
  const auto& mesh = t.meshed.stuffed.mesh;
  py::array_t<double> out({static_cast<py::ssize_t>(mesh.tets.size()), py::ssize_t{6}});
  double* angles = out.mutable_data();
  py::gil_scoped_release nogil;
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
    const auto& tet = mesh.tets[i];
    const auto a = bccmis::d3::dihedral_angles(std::array<Vec3, 4>{mesh.vertices[tet[0]], mesh.vertices[tet[1]],
                                                                   mesh.vertices[tet[2]], mesh.vertices[tet[3]]});
    std::copy(a.begin(), a.end(), angles + 6 * i);
  }
  return out;
}

// ---- P1, P2, P7: a run -------------------------------------------------------

struct RunOptions {
  int max_level = 4, min_level = 0, cells = 4;
  std::optional<double> size;
  std::string impl = "fast";
  bool check = false, strict = false, stats = false;
  std::optional<bool> features;         ///< unset: on for a triangle mesh (spec/stuffing.md S29-S33)
  std::optional<double> feature_angle;  ///< implies features
  py::object progress = py::none();
};

py::object make_run(std::shared_ptr<const bccmis::stuff::Shape> shape, const RunOptions& o, double input_seconds) {
  bccmis::stuff::Settings settings;
  settings.lattice.max_level = o.max_level;
  settings.lattice.min_level = o.min_level;
  settings.lattice.cells = o.cells;
  if (o.size) {
    if (!(std::isfinite(*o.size) && *o.size > 0)) value_error("size: expected a positive finite number");
    if (o.max_level != 4) value_error("size and max_level both choose the finest level: give one");
    settings.lattice.size = o.size;
  }
  if (o.impl != "fast" && o.impl != "reference")
    value_error("impl: expected 'fast' or 'reference', got '" + o.impl + "'");
  settings.impl = o.impl == "fast" ? bccmis::stuff::Impl::fast : bccmis::stuff::Impl::reference;
  settings.check = o.check;
  settings.strict = o.strict;
  settings.statistics = o.stats;
  // P1: features as the CLI's, on for a triangle mesh unless features=False.
  if (o.feature_angle && !(*o.feature_angle >= 0 && *o.feature_angle <= 180))
    value_error("feature_angle: expected degrees from 0 to 180");
  if (o.feature_angle && o.features == false) value_error("feature_angle with features=False: give one");
  settings.features.on = o.features.value_or(o.feature_angle || !shape->surface_triangles().empty());
  if (o.feature_angle) settings.features.angle = *o.feature_angle;
  if (o.stats && dynamic_cast<const PythonShape*>(shape.get()))
    value_error("stats: a Python shape has no volume and no surface samples to compare with (spec/python.md P3)");
  const py::object progress = o.progress;
  // P7: signals are handled at every progress line.
  const bccmis::stuff::Progress on_progress = [&progress](std::string_view line) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!progress.is_none()) progress(py::str(line.data(), line.size()));
  };
  auto mesh = std::make_unique<TetMesh>();
  mesh->shape = shape->describe();
  {
    py::gil_scoped_release nogil;
    mesh->meshed = bccmis::stuff::mesh_shape(*shape, settings, on_progress);
  }
  if (o.stats) {
    bccmis::stuff::PhaseSeconds seconds{{"input", input_seconds}};
    seconds.insert(seconds.end(), mesh->meshed.seconds.begin(), mesh->meshed.seconds.end());
    mesh->stats =
        py::module_::import("json").attr("loads")(bccmis::stuff::statistics_json(mesh->shape, mesh->meshed, seconds));
  }
  return py::cast(std::move(mesh));
}

RunOptions run_options(int max_level, int min_level, int cells, std::optional<double> size, std::string impl,
                       bool check, bool strict, bool stats, std::optional<bool> features,
                       std::optional<double> feature_angle, py::object progress) {
  return {max_level, min_level, cells,    size,          std::move(impl),    check,
          strict,    stats,     features, feature_angle, std::move(progress)};
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// P1, P3: the shape a call names: vertices and faces, a Shape, or a callable with its bounds.
std::shared_ptr<const bccmis::stuff::Shape> shape_of(const py::object& shape, const py::object& faces,
                                                     const py::object& bounds, bool strict) {
  if (py::isinstance<bccmis::stuff::Shape>(shape)) {
    if (!faces.is_none()) value_error("faces: a Shape takes no faces");
    return shape.cast<std::shared_ptr<bccmis::stuff::Shape>>();
  }
  if (!faces.is_none()) {
    const std::vector<Vec3> vertices = vertices_of(shape);
    const std::vector<Tri> triangles = faces_of(faces, vertices.size());
    py::gil_scoped_release nogil;
    if (strict) return bccmis::stuff::make_mesh_shape(vertices, triangles, "<array>");
    return bccmis::stuff::make_soup_shape(vertices, triangles, "<array>");
  }
  if (PyCallable_Check(shape.ptr())) {
    if (bounds.is_none()) value_error("bounds: a Python shape needs bounds=((x0, y0, z0), (x1, y1, z1))");
    return std::make_shared<PythonShape>(shape.cast<py::function>(), bounds_of(bounds));
  }
  value_error("shape: expected vertices and faces, a bccmis Shape or a callable f(points) -> values");
}

py::object stuff_shape(const py::object& shape, const py::object& faces, const py::object& bounds,
                       const RunOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  std::shared_ptr<const bccmis::stuff::Shape> s = shape_of(shape, faces, bounds, o.strict);
  return make_run(std::move(s), o, seconds_since(t0));
}

// ---- P9: a moving shape -------------------------------------------------------

Vec3 vec3_of(const py::handle& object, const char* what) {
  const auto a = py::array_t<double, py::array::forcecast>::ensure(object);
  if (!a || a.ndim() != 1 || a.shape(0) != 3) value_error(std::string(what) + ": expected (dx, dy, dz)");
  const Vec3 v{a.at(0), a.at(1), a.at(2)};
  for (double x : v)
    if (!std::isfinite(x)) value_error(std::string(what) + ": every component must be finite");
  return v;
}

/// S14-S16: the lattice fitted to the box the shape sweeps along `path`,
/// and its mesh, kept up to date by move().
class MovingShape {
 public:
  MovingShape(std::shared_ptr<const bccmis::stuff::Shape> shape, const Vec3& path,
              const bccmis::stuff::StuffOptions& options)
      : shape_(std::move(shape)), path_(path) {
    py::gil_scoped_release nogil;
    const bccmis::stuff::Fit fit = bccmis::stuff::fit_moving(*shape_, path_, options);
    moving_ = std::make_unique<bccmis::stuff::MovingLattice>(shape_, fit, options);
    fit_ = fit;
  }
  ~MovingShape() {
    py::gil_scoped_release nogil;  // a Python shape's destructor takes the GIL itself
    moving_.reset();
    shape_.reset();
  }
  /// The mesh of the current position (S26: an empty one is refused).
  py::object mesh() const {
    auto mesh = std::make_unique<TetMesh>();
    mesh->shape = shape_->describe();
    mesh->meshed.fit = fit_;
    mesh->meshed.leaves = moving_->lattice().cell_count();
    mesh->meshed.stuffed = moving_->stuffed();
    if (mesh->meshed.stuffed.mesh.tets.empty())
      throw bccmis::stuff::ShapeError(mesh->shape +
                                      ": the mesh is empty: " + bccmis::stuff::level_hint(shape_->bounds(), fit_));
    mesh->meshed.boundary = bccmis::stuff::boundary_triangles(mesh->meshed.stuffed.mesh);
    return py::cast(std::move(mesh));
  }
  /// The shape moved to `offset` from its own position (within the box the
  /// path sweeps): the new mesh and what the step did.
  py::tuple move(const py::handle& object) {
    const Vec3 offset = vec3_of(object, "offset");
    for (std::size_t k = 0; k < 3; ++k)
      if (offset[k] < std::min(0.0, path_[k]) || offset[k] > std::max(0.0, path_[k]))
        value_error("offset: outside the box the path sweeps (the lattice is fitted to it, S14)");
    bccmis::stuff::FrameReport r;
    {
      py::gil_scoped_release nogil;
      r = moving_->step(offset);
    }
    py::dict report("refines"_a = r.refines, "coarsens"_a = r.coarsens, "leaves"_a = r.leaves,
                    "restuffed_leaves"_a = r.restuffed_leaves, "restuffed_tetrahedra"_a = r.restuffed_tetrahedra,
                    "lattice_seconds"_a = r.lattice_seconds, "stuff_seconds"_a = r.stuff_seconds);
    return py::make_tuple(mesh(), report);
  }

 private:
  std::shared_ptr<const bccmis::stuff::Shape> shape_;
  Vec3 path_;
  bccmis::stuff::Fit fit_;
  std::unique_ptr<bccmis::stuff::MovingLattice> moving_;
};

py::object stuff_file(const std::string& path, const std::optional<std::string>& format, const RunOptions& o) {
  std::optional<bccmis::io::SurfaceFormat> f;
  if (format) {
    if (*format == "off")
      f = bccmis::io::SurfaceFormat::off;
    else if (*format == "obj")
      f = bccmis::io::SurfaceFormat::obj;
    else if (*format == "ply")
      f = bccmis::io::SurfaceFormat::ply;
    else if (*format == "stl")
      f = bccmis::io::SurfaceFormat::stl;
    else
      value_error("format: expected 'off', 'obj', 'ply' or 'stl', got '" + *format + "'");
  }
  // P6: a file that cannot be opened is an OSError (FileNotFoundError, PermissionError, ...).
  if (path != "-") {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) {
      PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
      throw py::error_already_set();
    }
    std::fclose(file);
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::shared_ptr<const bccmis::stuff::Shape> s;
  {
    py::gil_scoped_release nogil;
    s = bccmis::stuff::load_mesh_file(path, o.strict, f);
  }
  return make_run(std::move(s), o, seconds_since(t0));
}

/// A built-in shape (S1) through make_builtin, so that its checks and its
/// description are the CLI's `--shape` ones.
std::shared_ptr<bccmis::stuff::Shape> builtin(const std::string& name,
                                              const std::vector<std::pair<std::string, double>>& parameters) {
  std::string spec = name;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    char number[32];
    std::snprintf(number, sizeof number, "%.17g", parameters[i].second);
    spec += (i == 0 ? ":" : ",") + parameters[i].first + "=" + number;
  }
  return bccmis::stuff::make_builtin(spec);
}

// ---- P8: the lattices --------------------------------------------------------

template <class P>
P point_of(const py::handle& object) {
  const auto s = py::cast<py::sequence>(object);
  if (static_cast<int>(s.size()) != P::dimension)
    value_error("expected a point of " + std::to_string(P::dimension) + " integers, got " +
                std::string(py::str(object)));
  P p;
  std::array<std::int64_t*, 3> at{&p.x, &p.y, nullptr};
  if constexpr (P::dimension == 3) at[2] = &p.z;
  for (int k = 0; k < P::dimension; ++k) *at[static_cast<std::size_t>(k)] = py::cast<std::int64_t>(s[k]);
  return p;
}

template <class P, class Range>
py::array points_array(const Range& points) {
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(std::ranges::size(points)), py::ssize_t{P::dimension}});
  std::int64_t* o = out.mutable_data();
  for (const P& p : points) {
    *o++ = p.x, *o++ = p.y;
    if constexpr (P::dimension == 3) *o++ = p.z;
  }
  return out;
}

/// The reference graph of any lattice, for the checker and the mesh.
template <class Ref, class Fast>
struct Lattice {
  using P = bccmis::point_type_t<Ref>;
  std::variant<Ref, Fast> g;

  template <class F>
  decltype(auto) visit(F&& f) {
    return std::visit(std::forward<F>(f), g);
  }
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit(std::forward<F>(f), g);
  }
  Ref reference() const {
    if (const Ref* r = std::get_if<Ref>(&g)) return *r;
    return std::get<Fast>(g).to_graph();
  }
};

template <class Ref, class Fast>
Lattice<Ref, Fast> make_lattice(const typename Ref::size_type& size, const std::string& impl) {
  if (impl == "reference") return {Ref(size)};
  if (impl == "fast") return {Fast(size)};
  value_error("impl: expected 'reference' or 'fast', got '" + impl + "'");
}

/// A refusal's code as Python gives it: a str, or None when there is none.
template <class Refusal>
py::object code_of(const std::optional<Refusal>& refused) {
  if (!refused) return py::none();
  const std::string_view code = bccmis::code(*refused);
  return py::str(code.data(), code.size());
}

/// `decision(g, p)` (refine, coarsen or their guards) at the point `at`, on whichever lattice l holds.
template <class L, class Decision>
py::object decide(L& l, const py::handle& at, const Decision& decision) {
  const auto p = point_of<typename L::P>(at);
  return l.visit([&](auto& g) { return decision(g, p); });
}

py::object invariant_error;  // bccmis.InvariantError

template <class Ref, class Fast>
py::class_<Lattice<Ref, Fast>> bind_lattice(py::module_& m, const char* name, const char* doc) {
  using L = Lattice<Ref, Fast>;
  using P = typename L::P;
  const auto vertex = [](const L& l, const py::handle& object) {
    const P p = point_of<P>(object);
    if (!l.visit([&](const auto& g) { return is_center(g, p) || is_node(g, p); }))
      value_error(std::string(py::str(object)) + " is not a vertex of the lattice");
    return p;
  };
  return py::class_<L>(m, name, doc)
      .def_property_readonly("impl", [](const L& l) { return l.g.index() == 0 ? "reference" : "fast"; })
      .def(
          "refine",
          [](L& l, const py::handle& c) {
            return decide(l, c, [](auto& g, const P& p) { return code_of(refine(g, p).refused); });
          },
          "c"_a, "Refines cell c; None when applied, else the refusal code. l.refine((4, 4))")
      .def(
          "coarsen",
          [](L& l, const py::handle& n) {
            return decide(l, n, [](auto& g, const P& p) { return code_of(coarsen(g, p).refused); });
          },
          "n"_a, "Coarsens around node n; None when applied, else the refusal code. l.coarsen((4, 4))")
      .def(
          "can_refine",
          [](L& l, const py::handle& c) {
            return decide(l, c, [](auto& g, const P& p) { return code_of(can_refine(g, p)); });
          },
          "c"_a, "The refusal code refine(c) would give, or None. l.can_refine((4, 4))")
      .def(
          "can_coarsen",
          [](L& l, const py::handle& n) {
            return decide(l, n, [](auto& g, const P& p) { return code_of(can_coarsen(g, p)); });
          },
          "n"_a, "The refusal code coarsen(n) would give, or None. l.can_coarsen((4, 4))")
      .def(
          "cells", [](const L& l) { return l.visit([](const auto& g) { return points_array<P>(cells(g)); }); },
          "The cell centers C, sorted by position: int64 (k, dim). l.cells()")
      .def(
          "nodes", [](const L& l) { return l.visit([](const auto& g) { return points_array<P>(nodes(g)); }); },
          "The nodes N, sorted by position: int64 (k, dim). l.nodes()")
      .def(
          "levels",
          [](const L& l) {
            return l.visit([](const auto& g) {
              const auto& c = cells(g);
              py::array_t<std::int32_t> out(static_cast<py::ssize_t>(std::ranges::size(c)));
              std::int32_t* o = out.mutable_data();
              for (const P& p : c) *o++ = level_of(g, p);
              return out;
            });
          },
          "The level of each of cells(): int32 (k,). l.levels()")
      .def(
          "neighbors",
          [vertex](const L& l, const py::handle& v) {
            const P p = vertex(l, v);
            return l.visit([&](const auto& g) { return points_array<P>(neighbors(g, p)); });
          },
          "v"_a, "N(v), sorted by position: int64 (k, dim). l.neighbors((0, 0))")
      .def(
          "canonical_state",
          [](const L& l) { return l.visit([](const auto& g) { return bccmis::canonical_text(g); }); },
          "The canonical state (spec/formats.md). print(l.canonical_state())")
      .def(
          "check",
          [](const L& l) {
            std::optional<bccmis::BasicViolation<P>> v;
            {
              py::gil_scoped_release nogil;
              if constexpr (P::dimension == 2)
                v = bccmis::find_violation(l.reference());
              else
                v = bccmis::d3::find_violation(l.reference());
            }
            if (!v) return;
            py::object e = invariant_error(v->message);
            e.attr("code") = v->code;
            e.attr("positions") = points_array<P>(v->where);
            e.attr("section") = v->section;
            PyErr_SetObject(invariant_error.ptr(), e.ptr());
            throw py::error_already_set();
          },
          "Raises InvariantError (code, positions) when an invariant is violated. l.check()")
      .def("__repr__", [name](const L& l) {
        return std::string("<bccmis.") + name + " impl=" + (l.g.index() == 0 ? "reference" : "fast") + ">";
      });
}

/// replay(trace_text): the trace's final lattice and its decision log (P8).
template <class Ref, class Fast, class Trace>
py::tuple replay_as(const Trace& trace, const std::string& impl) {
  using L = Lattice<Ref, Fast>;
  std::string log;
  std::optional<L> out;
  {
    py::gil_scoped_release nogil;
    if (impl == "reference")
      out = L{bccmis::replay<Ref>(trace, log)};
    else if (impl == "fast")
      out = L{bccmis::replay<Fast>(trace, log)};
  }
  if (!out) value_error("impl: expected 'reference' or 'fast', got '" + impl + "'");
  return py::make_tuple(py::cast(std::move(*out)), log);
}

}  // namespace

PYBIND11_MODULE(bccmis, m) {
  m.doc() = "bccmis: adaptive BCC lattices and tetrahedral meshes by isosurface stuffing (spec/python.md).";

  // P6: errors.
  py::register_exception<bccmis::stuff::CheckError>(m, "CheckError", PyExc_RuntimeError);
  invariant_error =
      py::reinterpret_borrow<py::object>(PyErr_NewException("bccmis.InvariantError", PyExc_RuntimeError, nullptr));
  m.attr("InvariantError") = invariant_error;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const bccmis::stuff::ShapeError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const bccmis::ParseError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const bccmis::LatticeError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  // P1-P3: shapes and runs.
  py::class_<bccmis::stuff::Shape, std::shared_ptr<bccmis::stuff::Shape>>(m, "Shape",
                                                                          "A closed shape the mesher can mesh.")
      .def("__repr__", [](const bccmis::stuff::Shape& s) { return "<bccmis.Shape " + s.describe() + ">"; })
      .def_property_readonly("description", &bccmis::stuff::Shape::describe)
      .def_property_readonly("volume", &bccmis::stuff::Shape::volume)
      .def_property_readonly("bounds", [](const bccmis::stuff::Shape& s) {
        const auto b = s.bounds();
        return py::make_tuple(py::make_tuple(b.lo[0], b.lo[1], b.lo[2]), py::make_tuple(b.hi[0], b.hi[1], b.hi[2]));
      });
  py::module_ shapes = m.def_submodule("shapes", "The built-in shapes (spec/stuffing.md S1).");
  shapes.def(
      "sphere",
      [](double r) {
        return builtin("sphere", {{"r", r}});
      },
      "r"_a = 1.0, "A sphere of radius r at the origin. bccmis.shapes.sphere(r=2)");
  shapes.def(
      "torus",
      [](double R, double r) {
        return builtin("torus", {{"R", R}, {"r", r}});
      },
      "R"_a = 1.0, "r"_a = 0.4,
      "A torus around the z axis: ring radius R, tube radius r. bccmis.shapes.torus(R=1, r=0.3)");
  shapes.def(
      "spheres",
      [](double r, double d) {
        return builtin("spheres", {{"r", r}, {"d", d}});
      },
      "r"_a = 0.7, "d"_a = 1.0,
      "Two spheres of radius r at x = -d/2 and d/2, united. bccmis.shapes.spheres(r=0.7, d=1)");
  shapes.def(
      "builtin",
      [](const std::string& spec) { return std::shared_ptr<bccmis::stuff::Shape>(bccmis::stuff::make_builtin(spec)); },
      "spec"_a, "A built-in shape by the CLI's --shape text. bccmis.shapes.builtin('torus:R=1,r=0.4')");

  py::class_<TetMesh>(m, "TetMesh", "A tetrahedral mesh made by bccmis.stuff (spec/python.md P4).")
      .def_property_readonly(
          "points", member_view([](const TetMesh& t) -> const auto& { return t.meshed.stuffed.mesh.vertices; }),
          "float64 (n, 3), a read-only view. mesh.points[:3]")
      .def_property_readonly("tets",
                             member_view([](const TetMesh& t) -> const auto& { return t.meshed.stuffed.mesh.tets; }),
                             "uint32 (m, 4), positively oriented, a read-only view. mesh.tets.shape")
      .def_property_readonly("levels",
                             member_view([](const TetMesh& t) -> const auto& { return t.meshed.stuffed.mesh.level; }),
                             "int32 (m,): each tetrahedron's lattice level. mesh.levels.max()")
      .def_property_readonly("kinds",
                             member_view([](const TetMesh& t) -> const auto& { return t.meshed.stuffed.mesh.kind; }),
                             "uint8 (n,): 0 lattice vertex, 1 warped, 2 cut point. (mesh.kinds == 2).sum()")
      .def_property_readonly("boundary_faces",
                             member_view([](const TetMesh& t) -> const auto& { return t.meshed.boundary; }),
                             "uint32 (b, 3): the boundary triangles, outward. mesh.boundary_faces.shape")
      .def_readonly("stats", &TetMesh::stats, "With stats=True: bccmis stuff --json's object. mesh.stats['tetrahedra']")
      .def_readonly("shape", &TetMesh::shape, "The shape's description. mesh.shape")
      .def("dihedral_angles", &dihedral_angles, "float64 (m, 6), degrees. mesh.dihedral_angles().min()")
      .def("write", &write_mesh, "path"_a, "binary"_a = false, "compress"_a = false,
           "Writes .vtu, .msh, .mesh (tetrahedra), .off or .obj (boundary); compress: a zlib-compressed .vtu. "
           "mesh.write('out.vtu', compress=True)")
      .def(
          "to_meshio",
          [](const py::object& self) {
            const py::module_ meshio = py::module_::import("meshio");
            py::list cells;
            cells.append(py::make_tuple("tetra", self.attr("tets")));
            py::dict point_data, cell_data;
            point_data["kind"] = self.attr("kinds");
            py::list levels;
            levels.append(self.attr("levels"));
            cell_data["level"] = levels;
            return meshio.attr("Mesh")(self.attr("points"), cells, "point_data"_a = point_data,
                                       "cell_data"_a = cell_data);
          },
          "A meshio.Mesh: tetra cells, point data kind, cell data level. mesh.to_meshio().write('out.vtk')")
      .def("__len__", [](const TetMesh& t) { return t.meshed.stuffed.mesh.tets.size(); })
      .def("__repr__", [](const TetMesh& t) {
        return "<bccmis.TetMesh " + t.shape + ": " + std::to_string(t.meshed.stuffed.mesh.vertices.size()) +
               " points, " + std::to_string(t.meshed.stuffed.mesh.tets.size()) + " tetrahedra>";
      });

  m.def(
      "stuff",
      [](const py::object& shape, const py::object& faces, int max_level, int min_level, int cells,
         std::optional<double> size, std::string impl, bool check, bool strict, bool stats,
         std::optional<bool> features, std::optional<double> feature_angle, const py::object& bounds,
         py::object progress) {
        return stuff_shape(shape, faces, bounds,
                           run_options(max_level, min_level, cells, size, std::move(impl), check, strict, stats,
                                       features, feature_angle, std::move(progress)));
      },
      "shape"_a, "faces"_a = py::none(), py::kw_only(), "max_level"_a = 4, "min_level"_a = 0, "cells"_a = 4,
      "size"_a = py::none(), "impl"_a = "fast", "check"_a = false, "strict"_a = false, "stats"_a = false,
      "features"_a = py::none(), "feature_angle"_a = py::none(), "bounds"_a = py::none(), "progress"_a = py::none(),
      "A tetrahedral mesh of a triangle mesh (vertices, faces), a Shape or a callable (spec/python.md P1).\n"
      "mesh = bccmis.stuff(bccmis.shapes.torus(), max_level=3)");
  m.def(
      "stuff_file",
      [](const std::string& path, std::optional<std::string> format, int max_level, int min_level, int cells,
         std::optional<double> size, std::string impl, bool check, bool strict, bool stats,
         std::optional<bool> features, std::optional<double> feature_angle, py::object progress) {
        return stuff_file(path, format,
                          run_options(max_level, min_level, cells, size, std::move(impl), check, strict, stats,
                                      features, feature_angle, std::move(progress)));
      },
      "path"_a, py::kw_only(), "format"_a = py::none(), "max_level"_a = 4, "min_level"_a = 0, "cells"_a = 4,
      "size"_a = py::none(), "impl"_a = "fast", "check"_a = false, "strict"_a = false, "stats"_a = false,
      "features"_a = py::none(), "feature_angle"_a = py::none(), "progress"_a = py::none(),
      "A tetrahedral mesh of a triangle mesh file (.off, .obj, .ply, .stl; spec/python.md P2).\n"
      "mesh = bccmis.stuff_file('bunny.off', max_level=5)");

  // P9: a moving shape.
  py::class_<MovingShape>(m, "MovingShape",
                          "A shape moving through one lattice, its mesh updated locally (spec/python.md P9).")
      .def(py::init([](const py::object& shape, const py::object& path, const py::object& faces, int max_level,
                       int min_level, int cells, const py::object& bounds) {
             std::shared_ptr<const bccmis::stuff::Shape> s = shape_of(shape, faces, bounds, false);
             bccmis::stuff::StuffOptions options;
             options.max_level = max_level, options.min_level = min_level, options.cells = cells;
             const Vec3 p = path.is_none() ? bccmis::stuff::default_path(*s) : vec3_of(path, "path");
             return std::make_unique<MovingShape>(std::move(s), p, options);
           }),
           "shape"_a, "path"_a = py::none(), "faces"_a = py::none(), py::kw_only(), "max_level"_a = 4,
           "min_level"_a = 0, "cells"_a = 4, "bounds"_a = py::none(),
           "The lattice fitted to the box the shape sweeps along path. m = bccmis.MovingShape(bccmis.shapes.sphere(), "
           "(1, 0, 0))")
      .def_property_readonly("mesh", &MovingShape::mesh, "The mesh where the shape is now. m.mesh")
      .def("move", &MovingShape::move, "offset"_a,
           "Moves the shape to offset: (the new TetMesh, what changed). mesh, report = m.move((0.5, 0, 0))");

  // P8: the lattices.
  using L3 = Lattice<bccmis::d3::Graph, bccmis::d3::fast::Lattice>;
  bind_lattice<bccmis::Graph, bccmis::fast::Lattice>(m, "Lattice", "A 2D adaptive BCC lattice (spec/formats.md).")
      .def(py::init([](std::int64_t W, std::int64_t H, int L, const std::string& impl) {
             return make_lattice<bccmis::Graph, bccmis::fast::Lattice>({W, H, L}, impl);
           }),
           "W"_a, "H"_a, "L"_a, "impl"_a = "reference", "W x H level-0 cells, L levels. bccmis.Lattice(2, 2, 3)");
  bind_lattice<bccmis::d3::Graph, bccmis::d3::fast::Lattice>(m, "Lattice3",
                                                             "A 3D adaptive BCC lattice (spec/lattice3d.md).")
      .def(py::init([](std::int64_t W, std::int64_t H, std::int64_t D, int L, const std::string& impl) {
             return make_lattice<bccmis::d3::Graph, bccmis::d3::fast::Lattice>({W, H, D, L}, impl);
           }),
           "W"_a, "H"_a, "D"_a, "L"_a, "impl"_a = "reference",
           "W x H x D level-0 cubes, L levels. bccmis.Lattice3(1, 1, 1, 2)")
      .def(
          "tetrahedra",
          [](const L3& l) {
            const auto tets = bccmis::d3::tetrahedra(l.reference());
            py::array_t<std::int64_t> out({static_cast<py::ssize_t>(tets.size()), py::ssize_t{4}, py::ssize_t{3}});
            std::int64_t* o = out.mutable_data();
            for (const auto& t : tets)
              for (const auto& p : t) *o++ = p.x, *o++ = p.y, *o++ = p.z;
            return out;
          },
          "The graded mesh's tetrahedra by vertex position: int64 (t, 4, 3). l.tetrahedra().shape");
  m.def(
      "replay",
      [](const std::string& text, const std::string& impl) {
        const bccmis::AnyTrace trace = bccmis::parse_any_trace(text);
        if (const auto* t2 = std::get_if<bccmis::Trace>(&trace))
          return replay_as<bccmis::Graph, bccmis::fast::Lattice>(*t2, impl);
        return replay_as<bccmis::d3::Graph, bccmis::d3::fast::Lattice>(std::get<bccmis::d3::Trace>(trace), impl);
      },
      "trace"_a, "impl"_a = "reference",
      "Replays a trace: (the final lattice, the decision log). g, log = bccmis.replay(open('fig2.trace').read())");
  m.def(
      "parse_state",
      [](const std::string& text) -> py::object {
        bccmis::AnyState state = bccmis::parse_any_state(text);
        if (auto* g2 = std::get_if<bccmis::Graph>(&state))
          return py::cast(Lattice<bccmis::Graph, bccmis::fast::Lattice>{std::move(*g2)});
        return py::cast(
            Lattice<bccmis::d3::Graph, bccmis::d3::fast::Lattice>{std::move(std::get<bccmis::d3::Graph>(state))});
      },
      "text"_a,
      "A canonical state as a reference lattice, unchecked. g = bccmis.parse_state(open('run.state').read())");
}
