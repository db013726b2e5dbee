#include "bccmis/io/pvtu.h"

#include <ostream>

namespace bccmis::io {

void write_pvtu(std::ostream& out, const std::vector<std::string>& pieces) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <PUnstructuredGrid GhostLevel=\"0\">\n"
      << "    <PPointData Scalars=\"kind\">\n      <PDataArray type=\"UInt8\" Name=\"kind\"/>\n    </PPointData>\n"
      << "    <PCellData Scalars=\"level\">\n      <PDataArray type=\"Int32\" Name=\"level\"/>\n    </PCellData>\n"
      << "    <PPoints>\n      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
  for (const std::string& piece : pieces) out << "    <Piece Source=\"" << piece << "\"/>\n";
  out << "  </PUnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace bccmis::io
