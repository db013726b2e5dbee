// The generalized winding number of a triangle soup (spec/stuffing.md
// S17-S18): the time per query of WindingNumber::side() and estimate() at
// several distances from the surface of a subdivided icosphere (unit
// sphere; 5120 and 81920 triangles) and inside and around a random soup,
// and the fraction of side() queries that fell to the sum with no far node
// left (WindingNumber::full_sums()). Distances are in units of the mean
// edge length h, negative inside. A plain program; CPU time of the thread
// (CLOCK_THREAD_CPUTIME_ID). With --verify every side() is checked against
// the exact sum (direct_bounded) wherever that sum decides (exit 1 if not).
//
//   bench_winding_number [--smoke] [--verify] [--queries N]
//
// Numbers and the command that produced them: bench/RESULTS.md, "Winding
// number".
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/soup/winding_number.h"
#include "testing/icosphere.h"

namespace {

using bccmis::soup::Triangle;
using bccmis::soup::Vec3;
using bccmis::soup::WindingNumber;

double thread_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}

struct Soup {
  std::vector<Vec3> v;
  std::vector<Triangle> t;
};

Vec3 unit(Vec3 x) {
  const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  return {x[0] / n, x[1] / n, x[2] / n};
}

// The icosahedron subdivided `levels` times, on the unit sphere, outward.
Soup icosphere(int levels) {
  Soup s;
  bccmis::testing::subdivided_icosahedron(levels, unit, s.v, s.t);
  return s;
}

double mean_edge(const Soup& s) {
  double sum = 0;
  for (const Triangle& t : s.t)
    for (int j = 0; j < 3; ++j) {
      const Vec3& a = s.v[t[j]];
      const Vec3& b = s.v[t[(j + 1) % 3]];
      sum += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
  return sum / (3.0 * static_cast<double>(s.t.size()));
}

// n triangles of edges up to about 0.2 with centres uniform in the unit cube.
Soup random_soup(std::uint32_t n) {
  std::mt19937_64 rng(1207);
  std::uniform_real_distribution<double> u(0, 1), small(-0.08, 0.08);
  Soup s;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec3 c{u(rng), u(rng), u(rng)};
    for (int k = 0; k < 3; ++k) s.v.push_back({c[0] + small(rng), c[1] + small(rng), c[2] + small(rng)});
    s.t.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return s;
}

bool verify = false;
int failures = 0;

// One row: side() and estimate() over the points, ns per query.
void row(const WindingNumber& w, const char* shape, const std::string& where, const std::vector<Vec3>& points) {
  const std::uint64_t full0 = w.full_sums();
  // The best of three runs (the machine may be shared).
  int sum_sides = 0;
  double side_ns = 1e300, estimate_ns = 1e300;
  std::uint64_t full = 0;
  double sum_error = 0, max_error = 0;
  for (int run = 0; run < 3; ++run) {
    sum_sides = 0;
    const double t0 = thread_ns();
    for (const Vec3& p : points) sum_sides += w.side(p);
    const double t1 = thread_ns();
    if (run == 0) full = w.full_sums() - full0;
    sum_error = 0;
    const double t2 = thread_ns();
    for (const Vec3& p : points) {
      const auto e = w.estimate(p);
      sum_error += e.error;
      max_error = std::max(max_error, e.error);
    }
    const double t3 = thread_ns();
    side_ns = std::min(side_ns, t1 - t0);
    estimate_ns = std::min(estimate_ns, t3 - t2);
  }
  const double n = static_cast<double>(points.size());
  std::printf("%-14s %8zu  %-18s %10.2f %12.2f %10.4f %10.2g %10.2g  (%d)\n", shape, w.size(), where.c_str(),
              side_ns / n / 1e3, estimate_ns / n / 1e3, static_cast<double>(full) / n, sum_error / n, max_error,
              sum_sides);
  if (verify)
    for (const Vec3& p : points) {
      const auto e = w.direct_bounded(p);
      if (std::abs(e.value - 0.5) <= e.error) continue;
      const int expected = e.value >= 0.5 ? -1 : 1;
      if (w.side(p) != expected) {
        ++failures;
        std::printf("  wrong side at (%.17g, %.17g, %.17g): w = %.17g\n", p[0], p[1], p[2], e.value);
      }
    }
}

void sphere(int levels, int queries) {
  const Soup s = icosphere(levels);
  const double h = mean_edge(s);
  const WindingNumber w(s.v, s.t);
  std::mt19937_64 rng(27);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> band(0.9, 1.1);
  auto points_at = [&](auto radius) {
    std::vector<Vec3> points;
    for (int i = 0; i < queries; ++i) {
      const Vec3 d = unit({g(rng), g(rng), g(rng)});
      const double r = radius();
      points.push_back({d[0] * r, d[1] * r, d[2] * r});
    }
    return points;
  };
  const std::string name = "icosphere(" + std::to_string(levels) + ")";
  for (const double k : {-4.0, -1.0, -0.25, 0.25, 1.0, 4.0, 16.0}) {
    char where[64];
    std::snprintf(where, sizeof where, "%+gh (r %.4f)", k, 1 + k * h);
    row(w, name.c_str(), where, points_at([&] { return 1 + k * h; }));
  }
  row(w, name.c_str(), "r in [0.9, 1.1]", points_at([&] { return band(rng); }));
  row(w, name.c_str(), "r in [0, 3]", points_at([&] { return 3 * std::cbrt(band(rng) * 5 - 4.5 + 0.5); }));
}

void soup(std::uint32_t n, int queries) {
  const Soup s = random_soup(n);
  const WindingNumber w(s.v, s.t);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> inside(0, 1), around(-2, 3);
  std::vector<Vec3> in, out;
  for (int i = 0; i < queries; ++i) {
    in.push_back({inside(rng), inside(rng), inside(rng)});
    out.push_back({around(rng), around(rng), around(rng)});
  }
  row(w, "random soup", "in [0,1]^3", in);
  row(w, "random soup", "in [-2,3]^3", out);
}

}  // namespace

int main(int argc, char** argv) {
  bool smoke = false;
  int queries = 2000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--smoke")) {
      smoke = true;
    } else if (!std::strcmp(argv[i], "--verify")) {
      verify = true;
    } else if (!std::strcmp(argv[i], "--queries") && i + 1 < argc) {
      queries = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: bench_winding_number [--smoke] [--verify] [--queries N]\n");
      return 2;
    }
  }
  if (smoke) queries = std::min(queries, 20);
  std::printf("%-14s %8s  %-18s %10s %12s %10s %10s %10s\n", "shape", "tris", "where", "side us", "estimate us",
              "full sums", "mean err", "max err");
  sphere(smoke ? 2 : 4, queries);
  if (!smoke) sphere(6, queries);
  soup(smoke ? 300 : 5000, queries);
  if (failures > 0) std::printf("%d wrong sides\n", failures);
  return failures > 0 ? 1 : 0;
}
