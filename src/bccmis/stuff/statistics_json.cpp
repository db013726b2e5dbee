// S13's report as JSON (spec/cli.md, stuff --json; spec/python.md P5).
#include "bccmis/stuff/statistics_json.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/json_writer.h"

namespace bccmis::stuff {

namespace {

/// The faces of the first few instances of a flaw: [[3,4],[7,9]].
void instances_json(JsonWriter& w, const SoupFlaw& f) {
  w.begin_object().member("count", f.count).key("first").begin_array();
  for (const auto& faces : f.first) {
    w.begin_array();
    for (std::size_t face : faces) w.value(face);
    w.end_array();
  }
  w.end_array().end_object();
}

/// S21's report of a triangle-mesh file: the "soup" member.
void soup_json(JsonWriter& w, const SoupReport& r) {
  w.key("soup").begin_object().member("file", r.file).member("faces", r.faces).member("flaws", r.flaw_count());
  for (std::size_t k = 0; k < SoupReport::kKinds; ++k) {
    w.key(SoupReport::key(static_cast<SoupReport::Kind>(k)));
    instances_json(w, r.flaws[k]);
  }
  w.member("components", r.components)
      .member("inward_components", r.inward_components)
      .member("flipped_faces", r.flipped_faces)
      .member("dropped_faces", r.dropped_faces)
      .member("welded_vertices", r.welded_vertices)
      .key("bad_normals");
  instances_json(w, r.bad_normals);
  w.end_object();
}

}  // namespace

std::vector<std::pair<const char*, std::size_t>> statistics_counts(const Meshed& m) {
  const Statistics& s = *m.statistics;
  std::vector<std::pair<const char*, std::size_t>> counts{{"leaves", m.leaves},
                                                          {"lattice_tetrahedra", m.stuffed.lattice_tetrahedra},
                                                          {"cut_points", m.stuffed.cut_points},
                                                          {"warped", m.stuffed.warped},
                                                          {"vertices", s.vertices},
                                                          {"tetrahedra", s.tetrahedra},
                                                          {"boundary_triangles", s.quality.boundary_triangles},
                                                          {"boundary_components", m.topology.boundary_components},
                                                          {"nonmanifold_edges", m.topology.nonmanifold_edges}};
  if (const auto& f = m.features)  // S33
    counts.insert(counts.end(), {{"feature_edges", f->edges},
                                 {"feature_curves", f->curves},
                                 {"feature_corners", f->corners},
                                 {"feature_corners_conformed", f->corners_conformed},
                                 {"feature_curves_conformed", f->curves_conformed}});
  if (const auto& f = m.features; f && f->crease_cuts)  // S35.8
    counts.insert(counts.end(), {{"crease_cuts_placed", f->placed}, {"crease_cuts_kept", f->placed_kept}});
  return counts;
}

std::string statistics_json(const std::string& shape, const Meshed& m, const PhaseSeconds& seconds) {
  const Statistics& s = *m.statistics;
  const StuffQuality& q = s.quality;
  const Hausdorff& h = s.hausdorff;
  JsonWriter w;
  w.begin_object().member("shape", shape);
  for (const auto& [name, n] : statistics_counts(m))
    if (std::find(m.not_computed.begin(), m.not_computed.end(), name) != m.not_computed.end())
      w.key(name).null();
    else
      w.member(name, n);
  // A volume that overflows a double (S24), and so its relative error, is null.
  const auto finite_or_null = [&](const char* key, double x) {
    w.key(key);
    std::isfinite(x) ? w.value(x) : w.null();
  };
  finite_or_null("volume", q.volume);
  finite_or_null("shape_volume", s.shape_volume);
  finite_or_null("volume_rel_error", s.volume_rel_error());
  if (h.computed) {  // Settings::hausdorff (--hausdorff)
    w.key("hausdorff").begin_object().member("from_boundary", h.from_boundary).key("from_surface");
    if (h.from_surface < 0)
      w.null();
    else
      w.value(h.from_surface);
    w.member("max", h.max())
        .member("sampled", true)
        .member("boundary_points", h.boundary_points)
        .member("surface_samples", h.surface_samples)
        .end_object();
  }
  w.member("min_dihedral", q.min_dihedral).member("max_dihedral", q.max_dihedral).member("below10", s.below10());
  if (m.features) w.member("feature_angle", m.features->angle).member("feature_distance", m.features->distance);
  w.member("boundary_euler", m.topology.boundary_euler).key("warnings").begin_array();
  for (const std::string& warning : m.warnings) w.value(warning);
  w.end_array();
  if (m.soup) soup_json(w, *m.soup);
  w.key("dihedral_histogram").begin_object();
  for (std::size_t k = 0; k < q.histogram.size(); ++k) w.member(std::to_string(15 * k), q.histogram[k]);
  w.end_object().key("seconds").begin_object();
  for (const auto& [phase, t] : seconds) w.member(phase, t);
  w.member("meshing", meshing_seconds(seconds)).member("total", total_seconds(seconds)).end_object().end_object();
  return w.str();
}

}  // namespace bccmis::stuff
