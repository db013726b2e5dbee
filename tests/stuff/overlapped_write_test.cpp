// spec/stuffing.md S13a: Settings::write, the outputs written while the
// statistics are computed on their own threads. The writer sees the mesh in
// world coordinates (S24's map back done), the statistics are those of a run
// without a writer, bit for bit, and a writer that throws ends the run with
// its error once the statistics' thread has ended.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "bccmis/stuff/mesh_shape.h"

namespace bccmis::stuff {
namespace {

/// A torus away from the origin (S24 translates it, so the map back
/// rounds), meshed with statistics on two threads.
Settings torus_settings() {
  Settings s;
  s.lattice.max_level = 3;
  s.lattice.threads = 2;
  s.statistics = true;
  return s;
}

TEST(StuffOverlappedWrite, TheWriterSeesTheWorldMeshAndTheStatisticsAreUnchanged) {
  const auto shape = make_torus({300.25, -7, 0.5}, 1, 0.4);
  Settings s = torus_settings();
  const Meshed plain = mesh_shape(*shape, s);
  int calls = 0;
  d3::TetMeshF written;
  s.write = [&](const Meshed& r) {
    ++calls;
    written = r.stuffed.mesh;
    EXPECT_FALSE(r.statistics.has_value());
  };
  const Meshed overlapped = mesh_shape(*shape, s);
  EXPECT_EQ(calls, 1);
  ASSERT_GT(written.tets.size(), 1000U);
  EXPECT_EQ(written.vertices, plain.stuffed.mesh.vertices);
  EXPECT_EQ(written.tets, plain.stuffed.mesh.tets);
  EXPECT_EQ(overlapped.stuffed.mesh.vertices, plain.stuffed.mesh.vertices);
  ASSERT_TRUE(plain.statistics && overlapped.statistics);
  EXPECT_TRUE(plain.statistics->quality == overlapped.statistics->quality);
  EXPECT_EQ(plain.statistics->relative_volume_error, overlapped.statistics->relative_volume_error);
  // The phases: "write" after "statistics", only with a writer.
  ASSERT_GE(overlapped.seconds.size(), 2U);
  EXPECT_EQ(overlapped.seconds[overlapped.seconds.size() - 2].first, "statistics");
  EXPECT_EQ(overlapped.seconds.back().first, "write");
  EXPECT_EQ(plain.seconds.back().first, "statistics");
}

TEST(StuffOverlappedWrite, AWriterThatThrowsEndsTheRunWithItsError) {
  const auto shape = make_torus({0, 0, 0}, 1, 0.4);
  Settings s = torus_settings();
  s.write = [](const Meshed&) { throw std::runtime_error("disk full"); };
  try {
    mesh_shape(*shape, s);
    FAIL() << "the writer's error was lost";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "disk full");
  }
}

}  // namespace
}  // namespace bccmis::stuff
