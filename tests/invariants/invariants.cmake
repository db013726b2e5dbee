# Included by tests/CMakeLists.txt: the checker's tests (issue 4, src/bccmis/invariants).
bccmis_add_gtest(invariants_test SOURCES invariants_test.cpp LIBS bccmis::invariants LABELS unit)

if(TARGET bccmis::triangulation_check)
  bccmis_add_gtest(triangulation_check_test SOURCES cgal/triangulation_check_test.cpp LIBS bccmis::triangulation_check
                   LABELS cgal)
endif()

# The independent 3D checker (src/bccmis/invariants/d3/): every code planted,
# random states valid, random mutations caught, the mesh layer on hand-built
# tetrahedra.
bccmis_add_gtest(d3_invariants_tests SOURCES d3/invariants_test.cpp LIBS bccmis::invariants_d3 bccmis::d3
  DEFINITIONS BCCMIS_SOURCE_DIR="${PROJECT_SOURCE_DIR}" BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples"
  LABELS unit)

# Layer 6 of the 3D checker: CGAL as a second referee of the mesh
# (src/bccmis/invariants/cgal/d3/tetrahedralization_check.cpp); built when CGAL
# was found.
if(TARGET bccmis::tetrahedralization_check)
  bccmis_add_gtest(d3_cgal_tests SOURCES cgal/d3/tetrahedralization_check_test.cpp
    LIBS bccmis::tetrahedralization_check bccmis::d3 DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples" LABELS unit)
endif()
