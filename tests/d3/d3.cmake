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

# The 3D cascade (spec/lattice3d.md §8, bccmis/balance.h): hand cases, and
# random target sets in random orders against the geometric closure of
# tests/d3/cascade_model.h, in edge and corner mode, every state checked.
bccmis_add_gtest(d3_balance_tests SOURCES balance_test.cpp LIBS bccmis::invariants_d3 bccmis::d3
  DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS property)
