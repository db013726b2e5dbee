// ParaView's collection index (bccmis/io/pvd.h): the exact text of the
// index that `bccmis stuff --animate` writes beside its frames.
#include "bccmis/io/pvd.h"

#include <gtest/gtest.h>

#include <sstream>

namespace bccmis::io {
namespace {

std::string pvd(const std::vector<std::pair<int, std::string>>& frames) {
  std::ostringstream out;
  write_pvd(out, frames);
  return out.str();
}

TEST(Pvd, ListsTheFramesInOrder) {
  EXPECT_EQ(pvd({{0, "ball_0000.vtu"}, {1, "ball_0001.vtu"}, {2, "ball_0002.vtu"}}),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0\" part=\"0\" file=\"ball_0000.vtu\"/>\n"
            "    <DataSet timestep=\"1\" part=\"0\" file=\"ball_0001.vtu\"/>\n"
            "    <DataSet timestep=\"2\" part=\"0\" file=\"ball_0002.vtu\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
}

TEST(Pvd, EmptyCollection) {
  EXPECT_EQ(pvd({}),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\">\n"
            "  <Collection>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
}

}  // namespace
}  // namespace bccmis::io
