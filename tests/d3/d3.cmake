# The 3D lattice's tests (spec/lattice3d.md): equation by equation on the
# hand examples, every refusal code, the spec/examples/d3_* expectations, the
# cardinality facts and the independent structural check in every state of
# random operation sequences, round trips, and state counts by BFS against a
# direct enumeration of balanced leaf sets.
bccmis_add_gtest(d3_tests
  SOURCES lattice_test.cpp refine_test.cpp coarsen_test.cpp refusals_test.cpp examples_test.cpp
  LIBS bccmis::d3 DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS unit)

bccmis_add_gtest(d3_property_tests SOURCES facts_test.cpp counts_test.cpp LIBS bccmis::d3
  DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS property)

# RapidCheck properties (the seed of tests/properties.cmake; a smaller budget,
# each case checks every state against the geometric model).
find_package(rapidcheck REQUIRED CONFIG)
bccmis_add_gtest(d3_rapidcheck_tests SOURCES properties_test.cpp model_test.cpp
  LIBS bccmis::d3 bccmis::invariants_d3 rapidcheck_gtest DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples"
  LABELS property ENVIRONMENT "RC_PARAMS=seed=20090303 max_success=60")

# Strong exception guarantee under injected allocation failures (replaces the
# global operator new, so it is its own executable).
bccmis_add_gtest(d3_exception_safety_test SOURCES exception_safety_test.cpp LIBS bccmis::d3 DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples"
                 LABELS robustness)

# The graded BCC tetrahedral mesh (spec/mesh3d.md): hand counts, shapes and
# angles, the mesh facts in random states, and the writers read back.
bccmis_add_gtest(d3_mesh_tests SOURCES mesh_test.cpp LIBS bccmis::d3 bccmis::io DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS unit)

# The writers against outside readers: meshio (Debian's python3-meshio, for
# the system interpreter /usr/bin/python3) and gmsh must load every file; a
# missing meshio or gmsh fails the test (scripts/setup.sh installs both).
add_executable(d3_mesh_write d3/mesh_write_files.cpp)
target_link_libraries(d3_mesh_write PRIVATE bccmis::d3 bccmis::io bccmis::warnings)
bccmis_add_test(d3.mesh_readers
         COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/d3/mesh_readers_test.py $<TARGET_FILE:d3_mesh_write>
         LABELS unit)

# The independent 3D checker (src/bccmis/invariants/d3/): every code planted,
# random states valid, random mutations caught, the mesh layer on hand-built
# tetrahedra.
bccmis_add_gtest(d3_invariants_tests SOURCES invariants_test.cpp LIBS bccmis::invariants_d3 bccmis::d3
  DEFINITIONS BCCMIS_SOURCE_DIR="${PROJECT_SOURCE_DIR}" BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples"
  LABELS unit)

# Layer 6 of the 3D checker: CGAL as a second referee of the mesh
# (src/bccmis/invariants/cgal/d3/tetrahedralization_check.cpp); built when CGAL
# was found.
if(TARGET bccmis::tetrahedralization_check)
  bccmis_add_gtest(d3_cgal_tests SOURCES tetrahedralization_check_test.cpp
    LIBS bccmis::tetrahedralization_check bccmis::d3 DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS unit)
endif()

# Exhaustive exploration (src/bccmis/explore, 3D): every reachable state of
# small lattices checked with the mesh layer, the state and refine-edge counts
# against a direct enumeration of balanced leaf sets (spec/lattice3d.md §6).
# 1 1 1 1, 1 1 1 2 and 2 2 1 1 run with the properties; 2 2 2 1, and the
# enumeration alone for 2 1 1 2 and 1 1 2 2, under the `exhaustive` label
# (cmake --workflow --preset exhaustive); the exploration of 2 1 1 2 and
# 1 1 2 2 (ExploreLong3, tens of CPU minutes each) is not registered: run
# build/release/tests/d3_explore_tests --gtest_filter='*ExploreLong3*' by hand.
bccmis_add_gtest(d3_explore_tests SOURCES explore_test.cpp LIBS bccmis::explore bccmis::d3
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

# The 3D picture of bccmis render (src/bccmis/oracle d3::render_svg): the leaves
# a slice cuts, by hand and as a tiling of every plane; hand counts.
bccmis_add_gtest(d3_render_tests SOURCES render_test.cpp LIBS bccmis::oracle bccmis::d3 DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS unit)

# The 3D cascade (spec/lattice3d.md §8, bccmis/balance.h): hand cases, and
# random target sets in random orders against the geometric closure of
# tests/d3/cascade_model.h, in edge and corner mode, every state checked.
bccmis_add_gtest(d3_balance_tests SOURCES balance_test.cpp LIBS bccmis::apps bccmis::invariants_d3 bccmis::d3
  DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS property)
