# Included by tests/CMakeLists.txt: the exhaustive explorer's tests
# (src/bccmis/explore), 2D and 3D (d3/).
# Exhaustive exploration: lattices of up to 512 states run with the properties;
# 3 1 2, 2 2 2 and 1 1 3 (4250, 66641, 66642 states) under the `exhaustive`
# label, which the test presets exclude. Run them in the release build:
#   ctest --test-dir build/release -L exhaustive      (about 70 s CPU each for the two large ones)
bccmis_add_gtest(exhaustive_test SOURCES exhaustive_test.cpp LIBS bccmis::explore bccmis::core bccmis::invariants
  NO_PRETTY_VALUES FILTER "-*ExhaustiveLarge.*" LABELS property)
bccmis_discover_gtests(exhaustive_test NO_PRETTY_VALUES FILTER "*ExhaustiveLarge.*" LABELS exhaustive TIMEOUT 1800)

# Exhaustive exploration (src/bccmis/explore, 3D): every reachable state of
# small lattices checked with the mesh layer, the state and refine-edge counts
# against a direct enumeration of balanced leaf sets (spec/lattice3d.md §6).
# 1 1 1 1, 1 1 1 2 and 2 2 1 1 run with the properties; 2 2 2 1, and the
# enumeration alone for 2 1 1 2 and 1 1 2 2, under the `exhaustive` label
# (cmake --workflow --preset exhaustive); the exploration of 2 1 1 2 and
# 1 1 2 2 (ExploreLong3, tens of CPU minutes each) is not registered: run
# build/release/tests/d3_explore_tests --gtest_filter='*ExploreLong3*' by hand.
bccmis_add_gtest(d3_explore_tests SOURCES d3/explore_test.cpp LIBS bccmis::explore bccmis::d3
  NO_PRETTY_VALUES FILTER "-*Exhaustive3.*:*ExploreLong3.*" TEST_LIST d3_explore_tests_SMALL LABELS property)
bccmis_discover_gtests(d3_explore_tests NO_PRETTY_VALUES FILTER "*Exhaustive3.*" TEST_LIST d3_explore_tests_EXHAUSTIVE
                       LABELS exhaustive TIMEOUT 600)

# bccmis explore with four numbers: the 3D lattice (tests/cli/cli.cmake's helper).
bccmis_cli_test(explore3_1111 0 ARGS explore 1 1 1 1 --no-progress
                STDOUT_REGEX "^explore 1 1 1 1: 2 states, 1 refine edges, 1 coarsen edges, .* ok")
bccmis_cli_test(explore3_2211_json 0 ARGS explore 2 2 1 1 --json
                STDOUT_REGEX "\"W\": 2, \"H\": 2, \"D\": 1, \"L\": 1, \"states\": 16, \"refine_edges\": 32, .*\"ok\": true")
bccmis_cli_test(explore3_beyond_reach 2 ARGS explore 1 1 1 3
                STDERR_REGEX "explore: lattice 1 1 1 3 has at least 2.64 reachable states .*--max-states")
bccmis_cli_test(explore3_partial 0 ARGS explore 1 1 1 3 --max-states 3 --no-progress --threads 1
                STDOUT_REGEX "^explore 1 1 1 3: 3 states, .* incomplete")
bccmis_cli_test(explore3_bad_lattice 2 ARGS explore 1 0 1 1 STDERR_REGEX "explore: .*H")
bccmis_cli_test(explore3_too_many_numbers 2 ARGS explore 1 1 1 1 1 STDERR_REGEX "lattice")
