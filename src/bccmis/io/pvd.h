// bccmis::io: ParaView's collection index (.pvd), the file that lists the
// frames of an animation (`bccmis stuff --animate`, spec/stuffing.md S15).
#pragma once

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace bccmis::io {

/// The VTKFile of type "Collection": one DataSet (part 0) per pair of a
/// timestep and a file name, in the order given. File names are written as
/// they are (not escaped).
void write_pvd(std::ostream& out, const std::vector<std::pair<int, std::string>>& timestep_and_file);

}  // namespace bccmis::io
