#include "bccmis/io/pvd.h"

#include <ostream>

namespace bccmis::io {

void write_pvd(std::ostream& out, const std::vector<std::pair<int, std::string>>& timestep_and_file) {
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [timestep, file] : timestep_and_file)
    out << "    <DataSet timestep=\"" << timestep << "\" part=\"0\" file=\"" << file << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
}

}  // namespace bccmis::io
