#include "bccmis/apps/heightfield.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "bccmis/apps/detail/generic.h"

namespace bccmis {

namespace {

std::int64_t floor_div(std::int64_t a, std::int64_t b) {  // b > 0
  const std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
std::int64_t ceil_div(std::int64_t a, std::int64_t b) {  // b > 0
  const std::int64_t q = a / b;
  return (a % b != 0 && a > 0) ? q + 1 : q;
}

// Indices i in [0, n-1] with i * side / (n-1) in [lo, hi] (or [lo, hi) when
// half_open and hi < side). Exact integer arithmetic.
std::pair<std::int64_t, std::int64_t> pixel_range(std::int64_t lo, std::int64_t hi, std::int64_t side, std::int64_t n,
                                                  bool half_open) {
  const std::int64_t m = n - 1;
  std::int64_t first = ceil_div(lo * m, side);
  std::int64_t last = (half_open && hi < side) ? ceil_div(hi * m, side) - 1 : floor_div(hi * m, side);
  first = std::max<std::int64_t>(first, 0);
  last = std::min<std::int64_t>(last, m);
  return {first, last};
}

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// SplitMix64: the per-cell random stream of the sample measure.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

}  // namespace

// ---- HeightSampler -----------------------------------------------------------

HeightSampler::HeightSampler(const HeightField& field, const LatticeSize& size, double vertical_scale)
    : field_(&field), size_(size), scale_(vertical_scale) {
  if (field.width < 2 || field.height < 2)
    throw std::invalid_argument("a height field needs at least 2x2 pixels, this one has " +
                                std::to_string(field.width) + "x" + std::to_string(field.height));
  if (field.values.size() != static_cast<std::size_t>(field.width * field.height))
    throw std::invalid_argument("height field: " + std::to_string(field.values.size()) + " values for " +
                                std::to_string(field.width) + "x" + std::to_string(field.height) + " pixels");
  validate_lattice_size(size);
  const std::int64_t S = level0_side(size);
  domain_w_ = size.W * S;
  domain_h_ = size.H * S;
  const std::int64_t limit = std::numeric_limits<std::int64_t>::max() / 4;
  if (domain_w_ > limit / field.width || domain_h_ > limit / field.height)
    throw std::invalid_argument("lattice " + std::to_string(size.W) + " " + std::to_string(size.H) + " " +
                                std::to_string(size.L) + " is too fine for exact pixel arithmetic on a " +
                                std::to_string(field.width) + "x" + std::to_string(field.height) + " image");
}

double HeightSampler::at(double x, double y) const {
  const std::int64_t w = field_->width, h = field_->height;
  const double u =
      std::clamp(x * static_cast<double>(w - 1) / static_cast<double>(domain_w_), 0.0, static_cast<double>(w - 1));
  const double v =
      std::clamp(y * static_cast<double>(h - 1) / static_cast<double>(domain_h_), 0.0, static_cast<double>(h - 1));
  const auto i0 = std::min(static_cast<std::int64_t>(u), w - 2);
  const auto j0 = std::min(static_cast<std::int64_t>(v), h - 2);
  const double fu = u - static_cast<double>(i0), fv = v - static_cast<double>(j0);
  const double a = pixel(i0, j0), b = pixel(i0 + 1, j0), c = pixel(i0, j0 + 1), d = pixel(i0 + 1, j0 + 1);
  return (a * (1 - fu) + b * fu) * (1 - fv) + (c * (1 - fu) + d * fu) * fv;
}

std::pair<std::int64_t, std::int64_t> HeightSampler::columns(std::int64_t x0, std::int64_t x1, bool half_open) const {
  return pixel_range(x0, x1, domain_w_, field_->width, half_open);
}

std::pair<std::int64_t, std::int64_t> HeightSampler::rows(std::int64_t y0, std::int64_t y1, bool half_open) const {
  return pixel_range(y0, y1, domain_h_, field_->height, half_open);
}

double HeightSampler::column_x(std::int64_t col) const {
  return static_cast<double>(col) * static_cast<double>(domain_w_) / static_cast<double>(field_->width - 1);
}

double HeightSampler::row_y(std::int64_t j) const {
  return static_cast<double>(j) * static_cast<double>(domain_h_) / static_cast<double>(field_->height - 1);
}

double HeightSampler::pixel(std::int64_t col, std::int64_t j) const {
  return field_->at(col, field_->height - 1 - j) * scale_;
}

// ---- error measures ------------------------------------------------------------

std::optional<ErrorMeasure> parse_error_measure(std::string_view text) {
  if (text == "max") return ErrorMeasure::MaxPixel;
  if (text == "samples") return ErrorMeasure::RandomSamples;
  return std::nullopt;
}

std::string_view name(ErrorMeasure m) { return m == ErrorMeasure::MaxPixel ? "max" : "samples"; }

CellFan::CellFan(const Point& center, int level, std::vector<Point> boundary_ccw, const HeightSampler& s)
    : center_(center),
      level_(level),
      half_(cell_side(s.size(), level) / 2),
      zc_(s.at(center)),
      ring_(std::move(boundary_ccw)) {
  z_.reserve(ring_.size());
  for (const Point& b : ring_) z_.push_back(s.at(b));
}

double CellFan::at(double x, double y) const {
  const double dx = x - static_cast<double>(center_.x), dy = y - static_cast<double>(center_.y);
  if (dx == 0 && dy == 0) return zc_;
  // The sector (c, b_i, b_i+1) that holds the direction (dx, dy); on a ray
  // between two sectors either gives the same value. Sectors span at most
  // 90 degrees, so the best "least negative" test is robust to rounding.
  std::size_t best = 0;
  double best_score = -std::numeric_limits<double>::infinity();
  const std::size_t k = ring_.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Point& a = ring_[i];
    const Point& b = ring_[(i + 1) % k];
    const double ax = static_cast<double>(a.x - center_.x), ay = static_cast<double>(a.y - center_.y);
    const double bx = static_cast<double>(b.x - center_.x), by = static_cast<double>(b.y - center_.y);
    const double score = std::min(cross(ax, ay, dx, dy), cross(dx, dy, bx, by));
    if (score > best_score) {
      best_score = score;
      best = i;
    }
    if (score >= 0) break;
  }
  const Point& a = ring_[best];
  const Point& b = ring_[(best + 1) % k];
  const double ax = static_cast<double>(a.x - center_.x), ay = static_cast<double>(a.y - center_.y);
  const double bx = static_cast<double>(b.x - center_.x), by = static_cast<double>(b.y - center_.y);
  const double det = cross(ax, ay, bx, by);
  const double sa = cross(dx, dy, bx, by) / det, sb = cross(ax, ay, dx, dy) / det;
  return zc_ + sa * (z_[best] - zc_) + sb * (z_[(best + 1) % k] - zc_);
}

CellFan cell_fan(const Graph& g, const Point& c, const HeightSampler& s) { return detail::cell_fan(g, c, s); }

double cell_error(const CellFan& fan, const HeightSampler& s, const ErrorSettings& e) {
  const Point c = fan.center();
  const std::int64_t h = fan.half_side();
  double worst = 0;
  if (e.measure == ErrorMeasure::MaxPixel) {
    const auto [i0, i1] = s.columns(c.x - h, c.x + h, false);
    const auto [j0, j1] = s.rows(c.y - h, c.y + h, false);
    for (std::int64_t j = j0; j <= j1; ++j) {
      const double y = s.row_y(j);
      for (std::int64_t i = i0; i <= i1; ++i)
        worst = std::max(worst, std::abs(fan.at(s.column_x(i), y) - s.pixel(i, j)));
    }
    return worst;
  }
  // The cell's own stream: a function of (seed, center) only, so the measure
  // does not depend on the order in which cells are visited.
  SplitMix64 rng{e.seed ^ (static_cast<std::uint64_t>(c.x) * 0x9e3779b97f4a7c15ULL) ^
                 (static_cast<std::uint64_t>(c.y) * 0xc2b2ae3d27d4eb4fULL)};
  rng.next();
  const double side = static_cast<double>(2 * h);
  for (int k = 0; k < e.samples; ++k) {
    const double x = static_cast<double>(c.x - h) + rng.uniform() * side;
    const double y = static_cast<double>(c.y - h) + rng.uniform() * side;
    worst = std::max(worst, std::abs(fan.at(x, y) - s.at(x, y)));
  }
  return worst;
}

double cell_error(const Graph& g, const Point& c, const HeightSampler& s, const ErrorSettings& e) {
  return cell_error(cell_fan(g, c, s), s, e);
}

namespace {

// mesh_error over the cells in sorted order (the order fixes which cell is
// named worst and how the squares are summed); fan_of(cell) is its fan.
template <class Cells, class Fan>
MeshError mesh_error_of(const Cells& cells, const HeightSampler& s, const Fan& fan_of) {
  MeshError m;
  double sum = 0;
  for (const auto& cell : cells) {
    const CellFan fan = fan_of(cell);
    const Point c = fan.center();
    const std::int64_t h = fan.half_side();
    const auto [i0, i1] = s.columns(c.x - h, c.x + h, true);
    const auto [j0, j1] = s.rows(c.y - h, c.y + h, true);
    for (std::int64_t j = j0; j <= j1; ++j) {
      const double y = s.row_y(j);
      for (std::int64_t i = i0; i <= i1; ++i) {
        const double err = std::abs(fan.at(s.column_x(i), y) - s.pixel(i, j));
        sum += err * err;
        ++m.pixels;
        if (err > m.max_abs || m.pixels == 1) {
          m.max_abs = err;
          m.worst_cell = c;
        }
      }
    }
  }
  m.rms = m.pixels > 0 ? std::sqrt(sum / static_cast<double>(m.pixels)) : 0.0;
  return m;
}

}  // namespace

MeshError mesh_error(const Graph& g, const HeightSampler& s) {
  return mesh_error_of(g.C, s, [&](const Point& c) { return cell_fan(g, c, s); });
}

MeshError mesh_error(const fast::Lattice& g, const HeightSampler& s) {
  // The fans of detail::cell_fan, read from the pools: the same ring (the
  // angular order), so the same values.
  const std::vector<fast::Lattice::Index> slots = g.sorted_center_slots();
  return mesh_error_of(slots, s, [&](fast::Lattice::Index c) {
    std::vector<Point> ring;
    ring.reserve(8);
    g.for_each_boundary_node(c, [&](fast::Lattice::Index, const Point& p) { ring.push_back(p); });
    return CellFan(g.center_pool()[c].position(), g.level(c), std::move(ring), s);
  });
}

// ---- tessellation --------------------------------------------------------------

TessellateReport tessellate(Graph& g, const HeightSampler& s, const TessellateSettings& t,
                            const SweepObserver& observer) {
  return detail::tessellate(g, s, t, observer);
}

TessellateReport tessellate(fast::Lattice& g, const HeightSampler& s, const TessellateSettings& t,
                            const FastSweepObserver& observer) {
  return detail::tessellate(g, s, t, observer);
}

}  // namespace bccmis
