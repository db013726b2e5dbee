// S30-S35: a stuffed mesh made to hold the sharp features (conform_features.h).
#include "bccmis/stuff/conform_features.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <set>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

namespace {

double distance(const Vec3& a, const Vec3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// S30.1: a corner with no candidate within h searched within 2 h.
constexpr double kWideCorner = 2;

/// Items (points, or segments by their boxes) filed in a grid of cubes of
/// side `side` by the cubes their boxes meet, for the queries of a box.
class BoxGrid {
 public:
  explicit BoxGrid(double side) : side_(side) {}
  void insert(std::uint32_t id, const Vec3& lo, const Vec3& hi) {
    const auto a = cell(lo), b = cell(hi);
    for (std::int64_t x = a[0]; x <= b[0]; ++x)
      for (std::int64_t y = a[1]; y <= b[1]; ++y)
        for (std::int64_t z = a[2]; z <= b[2]; ++z) cells_[{x, y, z}].push_back(id);
  }
  /// The item `id` inserted with the box [lo, hi] taken out again.
  void erase(std::uint32_t id, const Vec3& lo, const Vec3& hi) {
    const auto a = cell(lo), b = cell(hi);
    for (std::int64_t x = a[0]; x <= b[0]; ++x)
      for (std::int64_t y = a[1]; y <= b[1]; ++y)
        for (std::int64_t z = a[2]; z <= b[2]; ++z) std::erase(cells_[{x, y, z}], id);
  }
  /// The items filed in the cubes that meet the box [lo, hi], in id order.
  std::vector<std::uint32_t> in_box(const Vec3& lo, const Vec3& hi) const {
    std::vector<std::uint32_t> out;
    const auto a = cell(lo), b = cell(hi);
    for (auto it = cells_.lower_bound(a); it != cells_.end() && it->first[0] <= b[0]; ++it) {
      const auto& c = it->first;
      if (c[1] >= a[1] && c[1] <= b[1] && c[2] >= a[2] && c[2] <= b[2])
        out.insert(out.end(), it->second.begin(), it->second.end());
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

 private:
  std::array<std::int64_t, 3> cell(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p[0] / side_)), static_cast<std::int64_t>(std::floor(p[1] / side_)),
            static_cast<std::int64_t>(std::floor(p[2] / side_))};
  }
  double side_;
  std::map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>> cells_;
};

/// The box [p - r, p + r].
std::pair<Vec3, Vec3> box_around(const Vec3& p, double r) {
  return {{p[0] - r, p[1] - r, p[2] - r}, {p[0] + r, p[1] + r, p[2] + r}};
}

/// The closest points of the segments [p1, q1] and [p2, q2]: their
/// parameters (t1 along the first, t2 along the second, each in [0, 1]) and
/// their distance (Ericson, "Real-Time Collision Detection", 5.1.9).
struct SegmentPair {
  double t1 = 0, t2 = 0, distance = HUGE_VAL;
};
SegmentPair closest_between(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const auto sub = [](const Vec3& a, const Vec3& b) { return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  const auto dot = [](const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const Vec3 d1 = sub(q1, p1), d2 = sub(q2, p2), r = sub(p1, p2);
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a > 0 && e > 0) {
    const double c = dot(d1, r), b = dot(d1, d2), denom = a * e - b * b;
    s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < 0) {
      t = 0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1) {
      t = 1;
      s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  } else if (a > 0) {
    s = std::clamp(-dot(d1, r) / a, 0.0, 1.0);
  } else if (e > 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  }
  const Vec3 x{p1[0] + s * d1[0], p1[1] + s * d1[1], p1[2] + s * d1[2]};
  const Vec3 y{p2[0] + t * d2[0], p2[1] + t * d2[1], p2[2] + t * d2[2]};
  return {s, t, distance(x, y)};
}

/// The point of C at arc length s (0 <= s <= its length).
Vec3 point_at(const FeatureCurve& C, double s) {
  for (std::size_t i = 1; i < C.points.size(); ++i) {
    const Vec3 &a = C.points[i - 1], &b = C.points[i];
    const double len = distance(a, b);
    if (s <= len && len > 0) {
      const double t = s / len;
      return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    }
    s -= len;
  }
  return C.points.back();
}

/// The arc length of each vertex of C's polyline.
std::vector<double> arc_lengths(const FeatureCurve& C) {
  std::vector<double> s{0};
  for (std::size_t i = 1; i < C.points.size(); ++i) s.push_back(s.back() + distance(C.points[i - 1], C.points[i]));
  return s;
}

/// Which flips a move S31 and S34 refuse is tried again after: none,
/// S35.9's, or S35.9's then S35.10's sequences.
enum class Flips { none, single, sequences };

/// The mesh as S30 walks it: the boundary graph, the tetrahedra at each
/// vertex, and the guard of S31.
class Snapper {
 public:
  Snapper(d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& boundary, double h, bool split_edges,
          Flips flips, bool split_chords)
      : mesh_(mesh),
        h_(h),
        split_edges_(split_edges),
        split_chords_(split_chords),
        flips_(flips),
        tets_at_(mesh.vertices.size()),
        neighbours_(mesh.vertices.size()),
        triangles_(boundary),
        triangles_at_(mesh.vertices.size()),
        taken_(mesh.vertices.size(), 0),
        grid_(h) {
    for (std::uint32_t t = 0; t < mesh.tets.size(); ++t)
      for (const std::uint32_t v : mesh.tets[t]) tets_at_[v].push_back(t);
    for (std::uint32_t i = 0; i < triangles_.size(); ++i)
      for (const std::uint32_t v : triangles_[i]) triangles_at_[v].push_back(i);
    for (const auto& f : boundary)
      for (std::size_t i = 0; i < 3; ++i) {
        neighbours_[f[i]].push_back(f[(i + 1) % 3]);
        neighbours_[f[(i + 1) % 3]].push_back(f[i]);
      }
    for (std::uint32_t v = 0; v < neighbours_.size(); ++v) {
      auto& n = neighbours_[v];
      std::sort(n.begin(), n.end());
      n.erase(std::unique(n.begin(), n.end()), n.end());
      if (!n.empty()) grid_.insert(v, mesh.vertices[v], mesh.vertices[v]);
    }
  }

  /// S31: v moved to x when every tetrahedron at it stays positively
  /// oriented (S12) with its dihedral angles in S10's interval; when not,
  /// S34: v moved to x with its interior neighbours moved by w (x - v), for
  /// the first w of kRoomWeights that S31 accepts for every tetrahedron at
  /// a moved vertex; when not, S35.9 and S35.10: v moved to x alone after
  /// flips of the tetrahedra at it that fail.
  bool move(std::uint32_t v, const Vec3& x, FeatureConformity& r) {
    Moves moved{{v, x}};
    if (!accepted(moved)) {
      const Vec3& y = mesh_.vertices[v];
      const Vec3 d{x[0] - y[0], x[1] - y[1], x[2] - y[2]};
      const std::vector<std::uint32_t> ring = interior_neighbours(v);
      bool room = false;
      for (const double w : kRoomWeights) {
        if (ring.empty()) break;
        moved = {{v, x}};
        for (const std::uint32_t a : ring) {
          const Vec3& p = mesh_.vertices[a];
          moved.emplace(a, Vec3{p[0] + w * d[0], p[1] + w * d[1], p[2] + w * d[2]});
        }
        if ((room = accepted(moved))) break;
      }
      if (room) {
        ++r.room_made;
      } else if (flips_ != Flips::none && flipped_into_place(v, x, r)) {
        moved = {{v, x}};
      } else {
        ++r.refused;
        return false;
      }
    }
    ++r.moves;
    for (const auto& [u, p] : moved) {
      const std::uint8_t kind = u == v ? kSnappedVertex : kRoomVertex;
      // S35.4's count: a vertex older than the splits changed (a move onto its own place with its own kind is none).
      if (journal_ && u < journal_->vertices && (p != mesh_.vertices[u] || kind != mesh_.kind[u])) ++journal_->moved;
      keep(mesh_.vertices, u);
      keep(mesh_.kind, u);
      if (!neighbours_[u].empty()) refile(u, mesh_.vertices[u], p);
      mesh_.vertices[u] = p;
      mesh_.kind[u] = kind;
    }
    return true;
  }

  /// S30.1: the nearest free boundary vertex within corner_search_radius
  /// whose move onto c is accepted, taken; none: -1.
  std::int64_t snap_corner(const Vec3& c, FeatureConformity& r) {
    std::vector<std::pair<double, std::uint32_t>> candidates;
    const auto [box_lo, box_hi] = box_around(c, kWideCorner * h_);
    for (const std::uint32_t v : grid_.in_box(box_lo, box_hi))
      if (const double d = distance(mesh_.vertices[v], c); !taken_[v] && d <= kWideCorner * h_)
        candidates.emplace_back(d, v);
    std::sort(candidates.begin(), candidates.end());
    const double radius = corner_search_radius(candidates.empty() ? HUGE_VAL : candidates.front().first, h_);
    std::erase_if(candidates, [radius](const auto& candidate) { return candidate.first > radius; });
    for (const auto& [d, v] : candidates)
      if (move(v, c, r)) {
        taken_[v] = 1;
        return v;
      }
    return -1;
  }

  /// S30.2: the piece C from vertex `from` to vertex `to` (its ends'
  /// vertices, already on them): the cheapest boundary path through free
  /// vertices within h of C, its interior moved onto C; a vertex whose move
  /// is refused (or breaks the order along C) is left out and the path
  /// sought again, up to kAttempts times. When no path is conformed, S35:
  /// the boundary edges crossing C split onto it, and the path sought again;
  /// still not conformed, the splits and everything after them undone
  /// (S35.4), `r` included but for its counts of splits and moves undone;
  /// then S35.5: the same from `to` to `from` along C reversed, without
  /// splits and with them, each undone unless it conforms C. True when
  /// conformed.
  bool snap_piece(const FeatureCurve& C, std::uint32_t from, std::uint32_t to, FeatureConformity& r) {
    if (const auto done = follow(C, from, to, r)) return *done;
    if (!split_edges_) return false;
    std::size_t made = 0;
    if (undone_unless(r, made, [&] {
          made = split_crossings(C, r);
          return made > 0 && follow(C, from, to, r).value_or(false);
        }))
      return true;
    // S35.5: from the other end, without splits and then with them.
    const FeatureCurve reversed{{C.points.rbegin(), C.points.rend()}, false};
    for (const bool with_splits : {false, true}) {
      made = 0;
      if (undone_unless(r, made, [&] {
            if (with_splits && (made = split_crossings(reversed, r)) == 0) return false;
            return follow(reversed, to, from, r).value_or(false);
          })) {
        std::reverse(chain_.begin(), chain_.end());  // along C
        return true;
      }
    }
    return false;
  }

  /// S35.4: `step` run with a journal open; when it returns false, everything
  /// it did is undone, `r` included but for its counts of the `made` splits
  /// and the moves undone.
  template <class Step>
  bool undone_unless(FeatureConformity& r, std::size_t& made, Step step) {
    const FeatureConformity before = r;
    journal_.emplace(Journal{mesh_.vertices.size(), mesh_.tets.size(), triangles_.size(), {}, 0});
    const bool conformed = step();
    if (!conformed) {
      roll_back();
      r = before;
      r.splits_undone += made;
      r.moves_undone += journal_->moved;
    }
    journal_.reset();
    return conformed;
  }

  /// S35.11's record of the piece C just conformed: its path, along it.
  void keep_path(const FeatureCurve& C) { paths_.emplace_back(C, chain_); }

  /// S35.11 on every piece keep_path recorded, in order, after every curve
  /// (no curve's path sees the splits). None without S35 (split_edges).
  void split_chords(FeatureConformity& r) {
    if (!split_edges_ || !split_chords_) return;
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (const auto& [C, chain] : paths_)
      for (std::size_t k = 1; k < chain.size(); ++k)
        if (!seen.insert(std::minmax(chain[k - 1], chain[k])).second)
          shared_.insert(std::minmax(chain[k - 1], chain[k]));
    for (const auto& [C, chain] : paths_) split_chords(C, chain, r);
  }

 private:
  /// S35.11 on the piece C whose path is `chain`, walked in the order of
  /// s; an edge uw farther than kChordTolerance h from an input feature
  /// point strictly between its ends is split at the farthest by S35.2's
  /// guarded split when both halves meet S32's chord condition, its halves
  /// walked next; a refused split leaves uw, as does an edge of two pieces'
  /// paths (two curves between the same two corners' vertices may share
  /// their one edge).
  void split_chords(const FeatureCurve& C, std::vector<std::uint32_t> chain, FeatureConformity& r) {
    const std::vector<double> s_vertex = arc_lengths(C);
    std::vector<double> s{0};
    for (std::size_t k = 1; k < chain.size(); ++k) s.push_back(arc_length(C, chain, k));
    for (std::size_t k = 1; k < chain.size();) {
      const Vec3 &a = mesh_.vertices[chain[k - 1]], &b = mesh_.vertices[chain[k]];
      const std::int64_t i = chord_split_vertex(C, a, b, s[k - 1], s[k], kChordTolerance * h_);
      if (i < 0) {
        ++k;
        continue;
      }
      const Vec3 c = C.points[static_cast<std::size_t>(i)];
      const double s_c = s_vertex[static_cast<std::size_t>(i)];
      if (shared_.contains(std::minmax(chain[k - 1], chain[k])) || !chord_holds(C, s_vertex, a, c, s[k - 1], s_c) ||
          !chord_holds(C, s_vertex, c, b, s_c, s[k]) || !split(chain[k - 1], chain[k], c)) {
        ++r.chord_splits_refused;
        ++k;
        continue;
      }
      const auto p = static_cast<std::uint32_t>(mesh_.vertices.size() - 1);
      taken_[p] = 1;
      ++r.splits, ++r.chord_splits;
      chain.insert(chain.begin() + static_cast<std::ptrdiff_t>(k), p);
      s.insert(s.begin() + static_cast<std::ptrdiff_t>(k), s_c);
    }
  }

  /// S30.2's attempts on the piece C from `from` to `to`: nothing when every
  /// attempt failed (no vertex taken); otherwise whether the path taken
  /// meets S32's chord condition.
  std::optional<bool> follow(const FeatureCurve& C, std::uint32_t from, std::uint32_t to, FeatureConformity& r) {
    std::unordered_map<std::uint32_t, double> near = near_vertices(C, from, to);
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
      const std::optional<std::vector<std::uint32_t>> found = cheapest_path(from, to, near);
      if (!found) return std::nullopt;
      const std::vector<std::uint32_t>& path = *found;
      // The interior onto C, in order, arc lengths strictly increasing.
      double s = 0;
      std::int64_t failed = -1;
      for (const std::uint32_t v : path) {
        // The nearest point of C first, then points h/4 and h/2 along C
        // either side of it.
        const CurvePoint p = nearest_on_curve(C, mesh_.vertices[v]);
        bool moved = false;
        for (const double shift : {0.0, -0.25, 0.25, -0.5, 0.5}) {
          const double target = p.s + shift * h_;
          if (!(target > s && target < C.length())) continue;
          if (move(v, shift == 0 ? p.point : point_at(C, target), r)) {
            moved = true;
            s = target;
            break;
          }
        }
        if (!moved) {
          failed = v;
          break;
        }
        near[v] = 0;
      }
      if (failed < 0) {
        for (const std::uint32_t v : path) keep(taken_, v), taken_[v] = 1;
        chain_ = {from};
        chain_.insert(chain_.end(), path.begin(), path.end());
        chain_.push_back(to);
        return chords_within(C, chain_);
      }
      near.erase(static_cast<std::uint32_t>(failed));
    }
    return std::nullopt;
  }

  /// d(v, C) of the free boundary vertices within h of C (a box around it
  /// first), and of the ends `from` and `to`; with `taken`, of the taken ones too.
  std::unordered_map<std::uint32_t, double> near_vertices(const FeatureCurve& C, std::uint32_t from, std::uint32_t to,
                                                          bool taken = false) const {
    Vec3 lo = C.points.front(), hi = lo;
    for (const Vec3& p : C.points)
      for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    std::unordered_map<std::uint32_t, double> near;
    for (const std::uint32_t v :
         grid_.in_box({lo[0] - h_, lo[1] - h_, lo[2] - h_}, {hi[0] + h_, hi[1] + h_, hi[2] + h_})) {
      const Vec3& x = mesh_.vertices[v];
      bool in_box = true;
      for (std::size_t k = 0; k < 3; ++k) in_box = in_box && x[k] >= lo[k] - h_ && x[k] <= hi[k] + h_;
      if (in_box && (v == from || v == to || taken || !taken_[v]))
        if (const double d = nearest_on_curve(C, x).distance; d <= h_ || v == from || v == to) near[v] = d;
    }
    return near;
  }

  /// S35: the boundary edges uw crossing C (u and w within h of C, not both
  /// taken; the closest points of uw and C at a parameter of uw in [1/4, 3/4]
  /// and within h/2 of each other, at an arc length strictly inside C), split
  /// in the order of that arc length (ties by u, w) at the point c of C, each
  /// split made only when S31's test passes every tetrahedron it changes or
  /// makes. The number of splits made.
  std::size_t split_crossings(const FeatureCurve& C, FeatureConformity& r) {
    struct Crossing {
      double s;
      std::uint32_t u, w;
      Vec3 c;
      bool operator<(const Crossing& o) const { return std::tie(s, u, w) < std::tie(o.s, o.u, o.w); }
    };
    const auto near = near_vertices(C, 0, 0, true);
    std::vector<Crossing> crossings;
    const std::vector<double> s_vertex = arc_lengths(C);
    for (const auto& [u, du] : near) {
      if (du > h_ || neighbours_[u].empty()) continue;
      for (const std::uint32_t w : neighbours_[u]) {
        const auto nw = near.find(w);
        if (w < u || nw == near.end() || nw->second > h_ || (taken_[u] && taken_[w])) continue;
        SegmentPair best;
        std::size_t segment = 0;
        for (std::size_t i = 1; i < C.points.size(); ++i) {
          const SegmentPair p = closest_between(mesh_.vertices[u], mesh_.vertices[w], C.points[i - 1], C.points[i]);
          if (p.distance < best.distance) best = p, segment = i;
        }
        if (!(best.t1 >= 0.25 && best.t1 <= 0.75 && best.distance <= h_ / 2)) continue;
        const Vec3 &a = C.points[segment - 1], &b = C.points[segment];
        const double s = s_vertex[segment - 1] + best.t2 * (s_vertex[segment] - s_vertex[segment - 1]);
        if (!(s > 0 && s < C.length())) continue;
        crossings.push_back(
            {s,
             u,
             w,
             {a[0] + best.t2 * (b[0] - a[0]), a[1] + best.t2 * (b[1] - a[1]), a[2] + best.t2 * (b[2] - a[2])}});
      }
    }
    std::sort(crossings.begin(), crossings.end());
    std::size_t made = 0;
    for (const Crossing& x : crossings)
      if (split(x.u, x.w, x.c)) ++made;
    r.splits += made;
    return made;
  }

  /// S35's split of the boundary edge uw at c: a new vertex p at c (kind
  /// kSnappedVertex, appended); every tetrahedron at uw becomes the two with
  /// u and with w replaced by p (the one without u appended), every boundary
  /// triangle at uw likewise. Made only when S31's test passes all of them;
  /// false (nothing changed) when uw is no longer a boundary edge or the
  /// test fails.
  bool split(std::uint32_t u, std::uint32_t w, const Vec3& c) {
    const auto& nu = neighbours_[u];
    if (!std::binary_search(nu.begin(), nu.end(), w)) return false;
    std::vector<std::uint32_t> at_edge;
    for (const std::uint32_t t : tets_at_[u])
      if (std::find(mesh_.tets[t].begin(), mesh_.tets[t].end(), w) != mesh_.tets[t].end()) at_edge.push_back(t);
    const auto replaced = [](std::array<std::uint32_t, 4> t, std::uint32_t from, std::uint32_t to) {
      for (auto& v : t)
        if (v == from) v = to;
      return t;
    };
    const std::uint32_t p = static_cast<std::uint32_t>(mesh_.vertices.size());
    const auto at = [&](std::uint32_t v) { return v == p ? c : mesh_.vertices[v]; };
    for (const std::uint32_t t : at_edge)
      for (const auto& half : {replaced(mesh_.tets[t], u, p), replaced(mesh_.tets[t], w, p)})
        if (!passes({at(half[0]), at(half[1]), at(half[2]), at(half[3])})) return false;
    // Made: the vertex, the tetrahedra, the boundary triangles, the graph.
    mesh_.vertices.push_back(c);
    mesh_.kind.push_back(kSnappedVertex);
    tets_at_.emplace_back();
    neighbours_.emplace_back();
    triangles_at_.emplace_back();
    taken_.push_back(0);
    for (const std::uint32_t t : at_edge) {
      const auto t_id = static_cast<std::uint32_t>(mesh_.tets.size());
      mesh_.tets.push_back(replaced(mesh_.tets[t], w, p));  // keeps u
      mesh_.level.push_back(mesh_.level[t]);
      keep(mesh_.tets, t);
      mesh_.tets[t] = replaced(mesh_.tets[t], u, p);  // keeps w
      for (const std::uint32_t v : mesh_.tets[t_id])
        if (v != u && v != p) keep(tets_at_, v), tets_at_[v].push_back(t_id);
      keep(tets_at_, u);
      std::replace(tets_at_[u].begin(), tets_at_[u].end(), t, t_id);
      tets_at_[p].push_back(t);
      tets_at_[p].push_back(t_id);
    }
    std::vector<std::uint32_t> opposite;
    for (const std::uint32_t f : std::vector<std::uint32_t>(triangles_at_[u])) {
      if (std::find(triangles_[f].begin(), triangles_[f].end(), w) == triangles_[f].end()) continue;
      keep(triangles_, f);
      auto& tri = triangles_[f];
      auto other = tri;  // keeps w
      for (auto& v : other)
        if (v == u) v = p;
      for (auto& v : tri)  // keeps u
        if (v == w) v = p;
      const auto f_id = static_cast<std::uint32_t>(triangles_.size());
      triangles_.push_back(other);
      for (const std::uint32_t v : other)
        if (v != p && v != w) opposite.push_back(v), keep(triangles_at_, v), triangles_at_[v].push_back(f_id);
      keep(triangles_at_, w);
      std::replace(triangles_at_[w].begin(), triangles_at_[w].end(), f, f_id);
      triangles_at_[p].push_back(f);
      triangles_at_[p].push_back(f_id);
    }
    const auto link = [this](std::uint32_t a, std::uint32_t b) {
      keep(neighbours_, a);
      auto& n = neighbours_[a];
      n.insert(std::upper_bound(n.begin(), n.end(), b), b);
    };
    const auto unlink = [this](std::uint32_t a, std::uint32_t b) {
      keep(neighbours_, a);
      auto& n = neighbours_[a];
      n.erase(std::lower_bound(n.begin(), n.end(), b));
    };
    unlink(u, w);
    unlink(w, u);
    for (const std::uint32_t v : std::vector<std::uint32_t>{u, w}) link(v, p), link(p, v);
    for (const std::uint32_t v : opposite) link(v, p), link(p, v);
    grid_.insert(p, c, c);
    if (journal_) journal_->steps.emplace_back([this, p, c] { grid_.erase(p, c, c); });
    return true;
  }

  /// S35.9: flips of the tetrahedra at v that fail S31's test with v at x,
  /// the first failing one (in the order of v's tetrahedra) each time, until
  /// every tetrahedron at v passes: true, the flips kept (`r.flips`
  /// counts them). A failing tetrahedron with no flip whose pieces all pass,
  /// or more than kFlips flips: every flip undone, then (Flips::sequences)
  /// S35.10's sequences of flips tried; none: false, the mesh as before.
  struct Flip;
  bool flipped_into_place(std::uint32_t v, const Vec3& x, FeatureConformity& r) {
    std::vector<Flip> made;
    for (std::size_t round = 0; round <= kFlips; ++round) {
      const auto failing = std::find_if(tets_at_[v].begin(), tets_at_[v].end(),
                                        [&](std::uint32_t t) { return !passes(placed(mesh_.tets[t], v, x)); });
      if (failing == tets_at_[v].end()) {
        for (const Flip& f : made) journal_flip(f);
        r.flips += made.size();
        return true;
      }
      if (round == kFlips) break;
      std::optional<Flip> f = flip_at(*failing, v, x);
      if (!f) break;
      made.push_back(std::move(*f));
    }
    for (auto f = made.rbegin(); f != made.rend(); ++f) undo_flip(*f);
    if (flips_ != Flips::sequences) return false;
    // S35.10: sequences of up to kSequence flips, the shortest first.
    made.clear();
    std::vector<std::uint32_t> fresh;
    for (std::size_t depth = 1; depth <= kSequence; ++depth)
      if (sequence(v, x, depth, made, fresh)) {
        for (const Flip& f : made) journal_flip(f);
        r.flips += made.size();
        return true;
      }
    return false;
  }

  /// S35.10: a sequence of at most `depth` more flips after `made`, depth
  /// first, each of the first tetrahedron failing S31's test with v at x
  /// (at v, else among `fresh`, those the sequence made), its pieces
  /// positively oriented: true when none fails any longer (the flips kept
  /// in `made`), else false with everything this call made undone.
  bool sequence(std::uint32_t v, const Vec3& x, std::size_t depth, std::vector<Flip>& made,
                std::vector<std::uint32_t>& fresh) {
    const auto fails = [&](std::uint32_t t) { return !passes(placed(mesh_.tets[t], v, x)); };
    auto failing = std::find_if(tets_at_[v].begin(), tets_at_[v].end(), fails);
    std::uint32_t t = 0;
    if (failing != tets_at_[v].end()) {
      t = *failing;
    } else if (const auto f = std::find_if(fresh.begin(), fresh.end(), fails); f != fresh.end()) {
      t = *f;
    } else {
      return true;
    }
    if (depth == 0) return false;
    for (const Candidate& c : candidates(t, v, x, true)) {
      const std::size_t tets = mesh_.tets.size(), fresh_before = fresh.size();
      made.push_back(replace(c.ids, c.pieces));
      fresh.insert(fresh.end(), c.ids.begin(), c.ids.end());
      for (std::size_t id = tets; id < mesh_.tets.size(); ++id) fresh.push_back(static_cast<std::uint32_t>(id));
      if (sequence(v, x, depth - 1, made, fresh)) return true;
      undo_flip(made.back());
      made.pop_back();
      fresh.resize(fresh_before);
    }
    return false;
  }

  /// A flip made: the tetrahedra it replaced (index, old vertices), how many
  /// it appended, and the tetrahedra at each vertex it touched before it.
  struct Flip {
    std::vector<std::pair<std::uint32_t, std::array<std::uint32_t, 4>>> replaced;
    std::size_t appended = 0;
    std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> tets_at;
  };

  /// S35.9's flips of the failing tetrahedron t = (.., v, ..), v at x: the
  /// first of its candidates (S35.9's) whose pieces all pass S31's test
  /// with v at x is made.
  std::optional<Flip> flip_at(std::uint32_t t, std::uint32_t v, const Vec3& x) {
    for (const Candidate& c : candidates(t, v, x, false))
      if (std::all_of(c.pieces.begin(), c.pieces.end(), [&](const auto& q) { return passes(placed(q, v, x)); }))
        return replace(c.ids, c.pieces);
    return std::nullopt;
  }

  /// A flip not yet made: the tetrahedra it replaces and its pieces.
  struct Candidate {
    std::vector<std::uint32_t> ids;
    std::vector<std::array<std::uint32_t, 4>> pieces;
  };

  /// The flips of tetrahedron t whose new edge is no edge of the mesh yet
  /// and whose pieces are positively oriented with v at x, in order: a 2-3
  /// flip across each face of t not on the boundary (in the order of the
  /// vertex it omits), then a 4-4 flip of each edge pq of t with exactly
  /// four tetrahedra around it and a closed ring of four (the new edge each
  /// pair of opposite ring vertices, in index order). The edges: S35.9's
  /// (`wider` false), vu with u not on the boundary (u in t's order, p = v);
  /// S35.10's, every edge of t (pairs in t's order).
  std::vector<Candidate> candidates(std::uint32_t t, std::uint32_t v, const Vec3& x, bool wider) const {
    std::vector<Candidate> out;
    const std::array<std::uint32_t, 4> T = mesh_.tets[t];
    const auto offer = [&](const std::vector<std::uint32_t>& ids, std::vector<std::array<std::uint32_t, 4>> pieces) {
      if (std::all_of(pieces.begin(), pieces.end(), [&](const auto& q) {
            const auto p = placed(q, v, x);
            return orientation(p[0], p[1], p[2], p[3]) > 0;
          }))
        out.push_back({ids, std::move(pieces)});
    };
    // 2-3: t and its neighbour u across the face omitting T[k] (apex T[k],
    // u's other vertex e) become the three with one of the face's vertices
    // replaced by e (each keeps t's orientation of the face it shares with t).
    for (std::size_t k = 0; k < 4; ++k) {
      std::array<std::uint32_t, 3> face;
      for (std::size_t j = 0, n = 0; j < 4; ++j)
        if (j != k) face[n++] = T[j];
      if (is_boundary_triangle(face)) continue;
      const std::optional<std::pair<std::uint32_t, std::uint32_t>> across = neighbour_across(t, face);
      if (!across || has_edge(T[k], across->second)) continue;
      std::vector<std::array<std::uint32_t, 4>> pieces;
      for (std::size_t j = 0; j < 4; ++j)
        if (j != k) pieces.push_back(T), pieces.back()[j] = across->second;
      offer({t, across->first}, std::move(pieces));
    }
    // 4-4: the four tetrahedra around pq (the octahedron p, q and the ring
    // r0..r3) become the four around the diagonal ri rj of the ring: each
    // ring tetrahedron at ri and rm (m neither i nor j) with q, then with p,
    // replaced by rj.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j)
        if (wider) edges.emplace_back(T[i], T[j]);
    if (!wider)
      for (const std::uint32_t u : T)
        if (u != v && neighbours_[u].empty()) edges.emplace_back(v, u);
    for (const auto& [p, q] : edges) {
      std::vector<std::uint32_t> around;
      for (const std::uint32_t w : tets_at_[p])
        if (std::find(mesh_.tets[w].begin(), mesh_.tets[w].end(), q) != mesh_.tets[w].end()) around.push_back(w);
      if (around.size() != 4) continue;
      std::vector<std::uint32_t> ring;
      for (const std::uint32_t w : around)
        for (const std::uint32_t a : mesh_.tets[w])
          if (a != p && a != q) ring.push_back(a);
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      if (ring.size() != 4) continue;
      const auto holding = [&](std::uint32_t a, std::uint32_t b) {
        return std::find_if(around.begin(), around.end(), [&](std::uint32_t w) {
          const auto& W = mesh_.tets[w];
          return std::find(W.begin(), W.end(), a) != W.end() && std::find(W.begin(), W.end(), b) != W.end();
        });
      };
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j) {
          if (holding(ring[i], ring[j]) != around.end() || has_edge(ring[i], ring[j])) continue;  // not opposite
          std::vector<std::array<std::uint32_t, 4>> pieces;
          for (std::size_t m = 0; m < 4; ++m) {
            if (m == i || m == j) continue;
            const auto w = holding(ring[i], ring[m]);
            if (w == around.end()) break;
            for (const std::uint32_t gone : {q, p}) {
              auto piece = mesh_.tets[*w];
              std::replace(piece.begin(), piece.end(), gone, ring[j]);
              pieces.push_back(piece);
            }
          }
          if (pieces.size() == 4) offer(around, std::move(pieces));
        }
    }
    return out;
  }

  /// The tetrahedra `ids` replaced by `pieces` (those beyond ids' number
  /// appended, at the level of the first), tets_at_ kept up to date.
  Flip replace(const std::vector<std::uint32_t>& ids, const std::vector<std::array<std::uint32_t, 4>>& pieces) {
    Flip f;
    std::vector<std::uint32_t> touched;
    for (const std::uint32_t id : ids) touched.insert(touched.end(), mesh_.tets[id].begin(), mesh_.tets[id].end());
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (const std::uint32_t a : touched) {
      f.tets_at.emplace_back(a, tets_at_[a]);
      for (const std::uint32_t id : ids) std::erase(tets_at_[a], id);
    }
    std::vector<std::uint32_t> made = ids;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (i < ids.size()) {
        f.replaced.emplace_back(ids[i], mesh_.tets[ids[i]]);
        mesh_.tets[ids[i]] = pieces[i];
        continue;
      }
      made.push_back(static_cast<std::uint32_t>(mesh_.tets.size()));
      mesh_.tets.push_back(pieces[i]);
      mesh_.level.push_back(mesh_.level[ids[0]]);
      ++f.appended;
    }
    for (const std::uint32_t id : made)
      for (const std::uint32_t a : mesh_.tets[id]) tets_at_[a].push_back(id);
    return f;
  }

  /// A flip taken back: its tetrahedra and tets_at_ as before it.
  void undo_flip(const Flip& f) {
    for (const auto& [a, before] : f.tets_at) tets_at_[a] = before;
    mesh_.tets.resize(mesh_.tets.size() - f.appended);
    mesh_.level.resize(mesh_.level.size() - f.appended);
    for (const auto& [id, before] : f.replaced) mesh_.tets[id] = before;
  }

  /// A flip kept: S35.4's journal, when open, puts back what it changed
  /// (what it appended is taken off with the rest).
  void journal_flip(const Flip& f) {
    if (!journal_) return;
    for (const auto& [a, before] : f.tets_at)
      journal_->steps.emplace_back([this, a = a, before = before] { tets_at_[a] = before; });
    for (const auto& [id, before] : f.replaced)
      journal_->steps.emplace_back([this, id = id, before = before] { mesh_.tets[id] = before; });
  }

  /// Whether ab is an edge of a tetrahedron.
  bool has_edge(std::uint32_t a, std::uint32_t b) const {
    return std::any_of(tets_at_[a].begin(), tets_at_[a].end(), [&](std::uint32_t t) {
      return std::find(mesh_.tets[t].begin(), mesh_.tets[t].end(), b) != mesh_.tets[t].end();
    });
  }

  /// Whether the triangle is one of the boundary's.
  bool is_boundary_triangle(std::array<std::uint32_t, 3> f) const {
    std::sort(f.begin(), f.end());
    return std::any_of(triangles_at_[f[0]].begin(), triangles_at_[f[0]].end(), [&](std::uint32_t i) {
      auto g = triangles_[i];
      std::sort(g.begin(), g.end());
      return g == f;
    });
  }

  /// The tetrahedron other than t with the face `face`, and its fourth vertex.
  std::optional<std::pair<std::uint32_t, std::uint32_t>> neighbour_across(
      std::uint32_t t, const std::array<std::uint32_t, 3>& face) const {
    for (const std::uint32_t u : tets_at_[face[0]]) {
      if (u == t) continue;
      const auto& U = mesh_.tets[u];
      const auto in_face = [&](std::uint32_t a) { return std::find(face.begin(), face.end(), a) != face.end(); };
      if (std::count_if(U.begin(), U.end(), in_face) == 3)
        return std::pair{u, *std::find_if_not(U.begin(), U.end(), in_face)};
    }
    return std::nullopt;
  }

  /// The corners of the tetrahedron q with v at x.
  std::array<Vec3, 4> placed(const std::array<std::uint32_t, 4>& q, std::uint32_t v, const Vec3& x) const {
    std::array<Vec3, 4> p;
    for (std::size_t i = 0; i < 4; ++i) p[i] = q[i] == v ? x : mesh_.vertices[q[i]];
    return p;
  }

  // S35.9: at most 8 flips for one move.
  static constexpr std::size_t kFlips = 8;
  // S35.10: sequences of at most 3 flips.
  static constexpr std::size_t kSequence = 3;

  /// S30's search: boundary vertex v moved from x to y filed at y, and
  /// back at x when the journal is rolled back.
  void refile(std::uint32_t v, const Vec3& x, const Vec3& y) {
    if (x == y) return;
    grid_.erase(v, x, x);
    grid_.insert(v, y, y);
    if (journal_) journal_->steps.emplace_back([this, v, x, y] { grid_.erase(v, y, y), grid_.insert(v, x, x); });
  }

  /// S35.4's record of a piece's splits and what followed them: the sizes
  /// before (everything appended after them is taken off) and, for every
  /// element changed, a step putting back its value before the change.
  struct Journal {
    std::size_t vertices, tets, triangles;
    std::vector<std::function<void()>> steps;
    std::size_t moved;  ///< vertices older than the splits moved or given a new kind by S30.2 and S34, per move
  };

  /// Element i of `items` about to change: its value now kept in the
  /// journal, when one is open.
  template <class T>
  void keep(std::vector<T>& items, std::size_t i) {
    if (journal_) journal_->steps.emplace_back([&items, i, old = items[i]] { items[i] = old; });
  }

  /// S35.4: the journal's steps in reverse order (each element back to its
  /// value before its first change), then what was appended taken off.
  void roll_back() {
    Journal& j = *journal_;
    for (auto step = j.steps.rbegin(); step != j.steps.rend(); ++step) (*step)();
    for (auto* per_vertex : {&tets_at_, &neighbours_, &triangles_at_}) per_vertex->resize(j.vertices);
    mesh_.vertices.resize(j.vertices);
    mesh_.kind.resize(j.vertices);
    taken_.resize(j.vertices);
    mesh_.tets.resize(j.tets);
    mesh_.level.resize(j.tets);
    triangles_.resize(j.triangles);
  }

  /// S32's chord condition on the path `chain`, whose vertices lie on C in
  /// order from its start's to its end's: every vertex of C between two
  /// consecutive ones within h/4 of the edge joining them.
  bool chords_within(const FeatureCurve& C, const std::vector<std::uint32_t>& chain) const {
    const std::vector<double> s_vertex = arc_lengths(C);
    double s_from = 0;
    for (std::size_t k = 1; k < chain.size(); ++k) {
      const double s_to = arc_length(C, chain, k);
      if (!chord_holds(C, s_vertex, mesh_.vertices[chain[k - 1]], mesh_.vertices[chain[k]], s_from, s_to)) return false;
      s_from = s_to;
    }
    return true;
  }

  /// The arc length along C of the k-th vertex of the path `chain` on C: 0
  /// at its start, C's length at its end, the nearest point's between.
  double arc_length(const FeatureCurve& C, const std::vector<std::uint32_t>& chain, std::size_t k) const {
    return k == 0 ? 0 : k + 1 == chain.size() ? C.length() : nearest_on_curve(C, mesh_.vertices[chain[k]]).s;
  }

  /// S32's chord condition on one edge ab of a path on C, from arc length
  /// s_from to s_to: every vertex of C strictly between within h/4 of ab.
  bool chord_holds(const FeatureCurve& C, const std::vector<double>& s_vertex, const Vec3& a, const Vec3& b,
                   double s_from, double s_to) const {
    for (std::size_t i = 0; i < C.points.size(); ++i)
      if (s_vertex[i] > s_from && s_vertex[i] < s_to && nearest_on_segment(a, b, C.points[i]).distance > h_ / 4)
        return false;
    return true;
  }

  /// New positions of some vertices (the others stay where they are).
  using Moves = std::unordered_map<std::uint32_t, Vec3>;

  /// S31's test of every tetrahedron at a vertex of `moved`, with the
  /// vertices of `moved` at their new positions.
  bool accepted(const Moves& moved) const {
    for (const auto& [v, x] : moved)
      for (const std::uint32_t t : tets_at_[v]) {
        std::array<Vec3, 4> p;
        for (std::size_t i = 0; i < 4; ++i) {
          const auto it = moved.find(mesh_.tets[t][i]);
          p[i] = it == moved.end() ? mesh_.vertices[mesh_.tets[t][i]] : it->second;
        }
        if (!passes(p)) return false;
      }
    return true;
  }

  /// S31's test of one tetrahedron: positively oriented (S12), its six
  /// dihedral angles in S10's interval.
  static bool passes(const std::array<Vec3, 4>& p) {
    if (orientation(p[0], p[1], p[2], p[3]) <= 0) return false;
    for (const double a : d3::dihedral_angles(p))
      if (!(a >= kDihedralBounds[0] && a <= kDihedralBounds[1])) return false;
    return true;
  }

  /// S34: the vertices sharing a tetrahedron with v that are not on the
  /// boundary, in index order.
  std::vector<std::uint32_t> interior_neighbours(std::uint32_t v) const {
    std::vector<std::uint32_t> ring;
    for (const std::uint32_t t : tets_at_[v])
      for (const std::uint32_t a : mesh_.tets[t])
        if (neighbours_[a].empty()) ring.push_back(a);
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    return ring;
  }

  // S34: the fractions of v's move its interior neighbours make, in the order tried.
  static constexpr std::array<double, 7> kRoomWeights{0.5, 1, 0.25, 0.75, 1.5, 2, -0.5};

  // S30.2: paths sought at most 8 times; an edge costs its length plus 4 times its ends' distances to C.
  static constexpr int kAttempts = 8;
  static constexpr double kNear = 4;

  /// Dijkstra from `from` to `to` through vertices with near[v] finite, an
  /// edge uw costing |u - w| + kNear (near[u] + near[w]): the path's
  /// interior vertices in order (none when uw is an edge); nothing when `to`
  /// cannot be reached.
  std::optional<std::vector<std::uint32_t>> cheapest_path(std::uint32_t from, std::uint32_t to,
                                                          const std::unordered_map<std::uint32_t, double>& near) const {
    std::unordered_map<std::uint32_t, double> cost;
    std::unordered_map<std::uint32_t, std::uint32_t> previous;
    const auto cost_of = [&cost](std::uint32_t v) {
      const auto it = cost.find(v);
      return it == cost.end() ? HUGE_VAL : it->second;
    };
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    cost[from] = 0;
    queue.emplace(0, from);
    while (!queue.empty()) {
      const auto [c, u] = queue.top();
      queue.pop();
      if (u == to) break;
      if (c > cost_of(u)) continue;
      for (const std::uint32_t w : neighbours_[u]) {
        const auto nw = near.find(w);
        if (nw == near.end() || w == from) continue;
        const double next = c + distance(mesh_.vertices[u], mesh_.vertices[w]) + kNear * (near.at(u) + nw->second);
        if (next < cost_of(w) || (next == cost_of(w) && u < previous.at(w))) {
          cost[w] = next;
          previous[w] = u;
          queue.emplace(next, w);
        }
      }
    }
    if (cost_of(to) == HUGE_VAL) return std::nullopt;
    std::vector<std::uint32_t> path;
    for (std::uint32_t v = previous.at(to); v != from; v = previous.at(v)) path.push_back(v);
    std::reverse(path.begin(), path.end());
    return path;
  }

 private:
  d3::TetMeshF& mesh_;
  double h_;
  bool split_edges_;   ///< S35 on
  bool split_chords_;  ///< S35.11 on (with S35)
  Flips flips_;        ///< S35.9, and S35.10, on
  std::vector<std::vector<std::uint32_t>> tets_at_;
  std::vector<std::vector<std::uint32_t>> neighbours_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;   ///< the boundary triangles, S35's splits included
  std::vector<std::vector<std::uint32_t>> triangles_at_;  ///< those at each vertex
  std::vector<char> taken_;
  BoxGrid grid_;                      ///< the boundary vertices at their current places, in cubes of side h (S30)
  std::optional<Journal> journal_;    ///< open while a piece's splits may be undone (S35.4)
  std::vector<std::uint32_t> chain_;  ///< the path of the piece S30.2 conformed last, along it (S35.11)
  std::vector<std::pair<FeatureCurve, std::vector<std::uint32_t>>> paths_;  ///< the pieces conformed, with their paths
  std::set<std::pair<std::uint32_t, std::uint32_t>> shared_;  ///< edges of two pieces' paths (u < w), not split
};

/// The corner of `features` at p, if any (its index), by exact equality.
std::int64_t corner_index(const Features& features, const Vec3& p) {
  const auto it = std::lower_bound(features.corners.begin(), features.corners.end(), p);
  return it != features.corners.end() && *it == p ? it - features.corners.begin() : -1;
}

/// S30-S35.5, with the flips `flips` asks for (S35.9, S35.10).
FeatureConformity conform(d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                          const Features& features, double h, bool split_edges, Flips flips, bool split_chords) {
  FeatureConformity r;
  Snapper snapper(mesh, boundary, h, split_edges, flips, split_chords);
  // S30.1: the corners, in order.
  std::vector<std::int64_t> corner_vertex;
  for (const Vec3& c : features.corners) {
    corner_vertex.push_back(snapper.snap_corner(c, r));
    if (corner_vertex.back() >= 0) {
      r.corners.push_back(c);
      ++r.corners_conformed;
    }
  }
  // S30.2: the curves, in order; a loop in two pieces from its start and its
  // vertex nearest half its length, both snapped as corners.
  for (std::size_t curve = 0; curve < features.curves.size(); ++curve) {
    const FeatureCurve& C = features.curves[curve];
    std::vector<FeatureCurve> pieces;
    std::vector<std::int64_t> ends;
    if (C.closed) {
      const double half = C.length() / 2;
      std::size_t middle = 1;
      double s = 0, best = HUGE_VAL;
      for (std::size_t i = 1; i + 1 < C.points.size(); ++i) {
        s += distance(C.points[i], C.points[i - 1]);
        if (std::abs(s - half) < best) best = std::abs(s - half), middle = i;
      }
      pieces.push_back({{C.points.begin(), C.points.begin() + static_cast<std::ptrdiff_t>(middle) + 1}, false});
      pieces.push_back({{C.points.begin() + static_cast<std::ptrdiff_t>(middle), C.points.end()}, false});
      const std::int64_t start = snapper.snap_corner(C.points.front(), r);
      ends = {start, snapper.snap_corner(C.points[middle], r), start};
    } else {
      pieces.push_back(C);
      const std::int64_t a = corner_index(features, C.points.front()), b = corner_index(features, C.points.back());
      ends = {a < 0 ? -1 : corner_vertex[static_cast<std::size_t>(a)],
              b < 0 ? -1 : corner_vertex[static_cast<std::size_t>(b)]};
    }
    bool conformed = true;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const bool ok = ends[i] >= 0 && ends[i + 1] >= 0 &&
                      snapper.snap_piece(pieces[i], static_cast<std::uint32_t>(ends[i]),
                                         static_cast<std::uint32_t>(ends[i + 1]), r);
      if (ok) r.pieces.push_back(pieces[i]), snapper.keep_path(pieces[i]);
      conformed = conformed && ok;
    }
    if (conformed) ++r.curves_conformed, r.conformed_curves.push_back(curve);
  }
  snapper.split_chords(r);  // S35.11, after every curve
  return r;
}

}  // namespace

FeatureConformity conform_features(d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                                   const Features& features, double h, bool split_edges, bool flip, bool split_chords) {
  if (!flip) return conform(mesh, boundary, features, h, split_edges, Flips::none, split_chords);
  // S35.9: the run with flips (B) kept only when it gains on the run
  // without (A); S35.10: the run with sequences of flips too (C) kept only
  // when it gains on the one kept.
  d3::TetMeshF original = mesh;
  d3::TetMeshF flipped = original;
  FeatureConformity kept = conform(mesh, boundary, features, h, split_edges, Flips::none, split_chords);
  FeatureConformity with = conform(flipped, boundary, features, h, split_edges, Flips::single, split_chords);
  if (with.flips > 0 && gains_on(with, kept)) mesh = std::move(flipped), kept = std::move(with);
  flipped = {};
  with = conform(original, boundary, features, h, split_edges, Flips::sequences, split_chords);
  if (with.flips > 0 && gains_on(with, kept)) mesh = std::move(original), kept = std::move(with);
  return kept;
}

std::int64_t chord_split_vertex(const FeatureCurve& C, const Vec3& a, const Vec3& b, double s_from, double s_to,
                                double tolerance) {
  const std::vector<double> s_vertex = arc_lengths(C);
  std::int64_t farthest = -1;
  double worst = tolerance;
  for (std::size_t i = 0; i < C.points.size(); ++i)
    if (s_vertex[i] > s_from && s_vertex[i] < s_to)
      if (const double d = nearest_on_segment(a, b, C.points[i]).distance; d > worst)
        worst = d, farthest = static_cast<std::int64_t>(i);
  return farthest;
}

bool gains_on(const FeatureConformity& x, const FeatureConformity& a) {
  // S30.1 lists the conformed corners in the order of Features::corners
  // (coordinate order), S30.2 the curves by increasing index: both sorted.
  const bool corners = std::includes(x.corners.begin(), x.corners.end(), a.corners.begin(), a.corners.end());
  const bool curves = std::includes(x.conformed_curves.begin(), x.conformed_curves.end(), a.conformed_curves.begin(),
                                    a.conformed_curves.end());
  return corners && curves &&
         (x.corners.size() > a.corners.size() || x.conformed_curves.size() > a.conformed_curves.size());
}

double corner_search_radius(double nearest, double h) { return nearest <= h ? h : kWideCorner * h; }

double feature_distance(const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                        const Features& features, double h) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& f : boundary)
    for (std::size_t i = 0; i < 3; ++i) edges.emplace_back(std::minmax(f[i], f[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  if (edges.empty()) return features.curves.empty() ? 0 : HUGE_VAL;
  // The edges filed by their boxes in a grid of cubes of side h; for each
  // point, boxes of half-side r = h, 2h, 4h, ... around it until the
  // nearest edge found is within r (every edge within r meets the box).
  BoxGrid grid(h);
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    const Vec3 &a = mesh.vertices[edges[e].first], &b = mesh.vertices[edges[e].second];
    grid.insert(e, {std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2])},
                {std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2])});
  }
  double worst = 0;
  for (const FeatureCurve& C : features.curves)
    for (const Vec3& p : C.points) {
      double nearest = HUGE_VAL;
      for (double r = h; nearest > r; r *= 2) {
        const auto [lo, hi] = box_around(p, r);
        for (const std::uint32_t e : grid.in_box(lo, hi))
          nearest = std::min(
              nearest, nearest_on_segment(mesh.vertices[edges[e].first], mesh.vertices[edges[e].second], p).distance);
      }
      worst = std::max(worst, nearest);
    }
  return worst;
}

FeatureReport feature_report(const Features& features, const FeatureConformity& conformity) {
  FeatureReport r;
  r.angle = features.angle;
  r.edges = features.edges;
  r.curves = features.curves.size();
  r.corners = features.corners.size();
  r.corners_conformed = conformity.corners_conformed;
  r.curves_conformed = conformity.curves_conformed;
  r.splits = conformity.splits;
  r.flips = conformity.flips;
  r.splits_undone = conformity.splits_undone;
  r.chord_splits = conformity.chord_splits;
  r.chord_splits_refused = conformity.chord_splits_refused;
  r.moves_undone = conformity.moves_undone;
  return r;
}

}  // namespace bccmis::stuff
