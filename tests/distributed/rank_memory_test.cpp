// spec/distributed.md D16 in one process: S25's estimate split over the
// ranks, tested on its line (a limit equal to a rank's estimate lets the
// run go on, the next double below refuses it, naming the rank).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "bccmis/distributed/rank_memory.h"
#include "bccmis/stuff/memory_estimate.h"
#include "bccmis/stuff/normalisation.h"

namespace bccmis::distributed {
namespace {

/// The unit sphere in S24's local coordinates at level 2, the options at the
/// fitted level (as fitted() makes them): its estimate is every cube.
struct Sphere {
  std::unique_ptr<stuff::Shape> world = stuff::make_builtin("sphere");
  std::unique_ptr<stuff::Shape> local = world->normalised(stuff::normalisation_of(world->bounds()));
  stuff::StuffOptions options = [this] {
    stuff::StuffOptions o;
    o.max_level = 2;
    o.max_level = stuff::fit_lattice(local->bounds(), o).size.L;
    return o;
  }();
  double leaves() const { return stuff::estimate_memory(*local, options, HUGE_VAL).leaves; }
};

/// The message of the refusal on `role`'s rank at `limit`, or "" when it fits.
std::string refusal(const Sphere& s, double limit, const RankRole& role) {
  try {
    refuse_what_will_not_fit_on_rank(*s.local, s.options, limit, role);
  } catch (const stuff::ShapeError& e) {
    return e.what();
  }
  return "";
}

//= spec/distributed.md D16 type=test
TEST(RankMemory, EachRoleHoldsWhatD16Says) {
  const double E = Sphere().leaves();
  ASSERT_GT(E, 0);
  EXPECT_EQ(rank_bytes(E, {0, 1, false, false}), 3700 * E);
  EXPECT_EQ(rank_bytes(E, {1, 2, false, false}), 3700 * E / 2);
  EXPECT_EQ(rank_bytes(E, {1, 2, true, true}), 3700 * E / 2);  // only rank 0 gathers
  EXPECT_EQ(rank_bytes(E, {0, 2, true, false}), 3700 * E / 2 + 4 * 420 * E);
  EXPECT_EQ(rank_bytes(E, {0, 2, true, true}), 3700 * E / 2 + 4 * 420 * E + 1900 * E);
  EXPECT_EQ(rank_bytes(E, {0, 1, true, false}), 3700 * E + 4 * 420 * E);
}

//= spec/distributed.md D16 type=test
TEST(RankMemory, OnTheLineNamingTheRank) {
  const Sphere s;
  for (const RankRole role : {RankRole{0, 1, false, false}, RankRole{1, 2, false, false}, RankRole{0, 2, true, false},
                              RankRole{0, 3, true, true}}) {
    const double line = rank_bytes(s.leaves(), role);
    EXPECT_EQ(refusal(s, line, role), "");
    const std::string why = refusal(s, std::nextafter(line, 0.0), role);
    const std::string ranks = std::to_string(role.ranks) + (role.ranks == 1 ? " rank" : " ranks");
    EXPECT_NE(why.find("GB on rank " + std::to_string(role.rank) +
                       " by D16's estimate (3700 bytes per estimated leaf over " + ranks),
              std::string::npos)
        << why;
    // Level 2 is the coarsest the 4 cells allow (S25): no coarser level is named.
    EXPECT_NE(why.find("of memory available to a rank; even -L 2, the coarsest max level these options allow, would "
                       "not fit"),
              std::string::npos)
        << why;
    if (role.crease_cuts) {
      EXPECT_NE(why.find("and 1900 for S35.8's candidates"), std::string::npos) << why;
    }
  }
}

}  // namespace
}  // namespace bccmis::distributed
