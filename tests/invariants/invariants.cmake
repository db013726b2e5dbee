# Included by tests/CMakeLists.txt: the checker's tests (issue 4, src/bccmis/invariants).
bccmis_add_gtest(invariants_test SOURCES invariants_test.cpp LIBS bccmis::invariants LABELS unit)

if(TARGET bccmis::triangulation_check)
  bccmis_add_gtest(triangulation_check_test SOURCES cgal/triangulation_check_test.cpp LIBS bccmis::triangulation_check
                   LABELS cgal)
endif()
