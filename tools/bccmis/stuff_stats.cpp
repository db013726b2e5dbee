// S13's report as text (stuff_stats.h).
#include "stuff_stats.h"

#include <algorithm>
#include <cstddef>
#include <string>

#include "bccmis/json_writer.h"
#include "bccmis/stuff/statistics_json.h"

namespace bccmis::cli {

namespace {

std::string number(double x) { return JsonWriter::number(x); }

/// The faces of the first few instances of a flaw: "3+4 7+9".
std::string instances_text(const stuff::SoupFlaw& f) {
  std::string out;
  for (const auto& faces : f.first) {
    out += out.empty() ? "" : " ";
    for (std::size_t i = 0; i < faces.size(); ++i) out += (i == 0 ? "" : "+") + std::to_string(faces[i]);
  }
  return out;
}
std::string soup_text(const stuff::SoupReport& r) {
  std::string out = "soup_faces " + std::to_string(r.faces) + "\nsoup_flaws " + std::to_string(r.flaw_count()) + "\n";
  const auto item = [&](const std::string& key, const stuff::SoupFlaw& f) {
    out += "soup_" + key + " " + std::to_string(f.count) + "\n";
    if (f.count > 0) out += "soup_" + key + "_first " + instances_text(f) + "\n";
  };
  for (std::size_t k = 0; k < stuff::SoupReport::kKinds; ++k)
    item(stuff::SoupReport::key(static_cast<stuff::SoupReport::Kind>(k)), r.flaws[k]);
  out += "soup_components " + std::to_string(r.components) + "\nsoup_inward_components " +
         std::to_string(r.inward_components) + "\nsoup_flipped_faces " + std::to_string(r.flipped_faces) +
         "\nsoup_dropped_faces " + std::to_string(r.dropped_faces) + "\nsoup_welded_vertices " +
         std::to_string(r.welded_vertices) + "\n";
  item("bad_normals", r.bad_normals);
  return out;
}

}  // namespace

/// --stats: S13's report as `name value` lines, or one JSON object.
std::string stats_text(const std::string& shape, const stuff::Meshed& m, const stuff::PhaseSeconds& seconds,
                       bool json) {
  const stuff::Statistics& s = *m.statistics;
  const stuff::StuffQuality& q = s.quality;
  const stuff::Hausdorff& h = s.hausdorff;
  if (json) return stuff::statistics_json(shape, m, seconds) + "\n";
  std::string out = "shape " + shape + "\n";
  for (const auto& [name, n] : stuff::statistics_counts(m)) {
    const bool computed = std::find(m.not_computed.begin(), m.not_computed.end(), name) == m.not_computed.end();
    out += std::string(name) + " " + (computed ? std::to_string(n) : std::string("-")) + "\n";
  }
  out += "volume " + number(q.volume) + "\nshape_volume " + number(s.shape_volume) + "\nvolume_rel_error " +
         number(s.volume_rel_error()) + "\n";
  if (h.computed)  // --hausdorff
    out += "hausdorff_from_boundary " + number(h.from_boundary) + "\nhausdorff_from_surface " +
           (h.from_surface < 0 ? std::string("-") : number(h.from_surface)) + "\nhausdorff " + number(h.max()) +
           "\nhausdorff_boundary_points " + std::to_string(h.boundary_points) + "\nhausdorff_surface_samples " +
           std::to_string(h.surface_samples) + "\n";
  out += "min_dihedral " + number(q.min_dihedral) + "\nmax_dihedral " + number(q.max_dihedral) + "\nbelow10 " +
         number(s.below10()) + "\n";
  for (std::size_t k = 0; k < q.histogram.size(); ++k)
    if (q.histogram[k] != 0) out += "dihedral_" + std::to_string(15 * k) + " " + std::to_string(q.histogram[k]) + "\n";
  out += "boundary_euler " + std::to_string(m.topology.boundary_euler) + "\n";
  for (const std::string& warning : m.warnings) out += "warning " + warning + "\n";
  if (m.features)  // S33
    out += "feature_angle " + number(m.features->angle) + "\nfeature_distance " + number(m.features->distance) + "\n";
  if (m.soup) out += soup_text(*m.soup);
  for (const auto& [phase, t] : seconds) out += "seconds_" + phase + " " + number(t) + "\n";
  return out;
}

}  // namespace bccmis::cli
