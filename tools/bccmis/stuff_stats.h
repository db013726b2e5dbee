// bccmis stuff --stats, --json: S13's report of a run as `name value` lines
// or one JSON object (spec/cli.md, stuff; spec/stuffing.md S13), the words
// of every tool that stuffs (bccmis stuff; bccmis-mpi stuff, spec/distributed.md D11).
#pragma once

#include <string>

#include "bccmis/stuff/mesh_shape.h"

namespace bccmis::cli {

/// --stats: S13's report of `m` (made with statistics) as `name value`
/// lines, or with `json` one JSON object and a newline.
std::string stats_text(const std::string& shape, const stuff::Meshed& m, const stuff::PhaseSeconds& seconds, bool json);

}  // namespace bccmis::cli
