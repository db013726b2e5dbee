# Isosurface stuffing (spec/stuffing.md): the fit and the band, exact
# orientation, and on the built-in shapes the mesh's own checks: closed
# boundary on the surface, enclosed volume equal to the tetrahedra's, every
# interior triangle in two tetrahedra, positive orientation, angle bounds.
add_executable(stuffing_tests stuff/stuffing_test.cpp)
target_link_libraries(stuffing_tests PRIVATE bccmis::stuff bccmis::d3 GTest::gtest_main bccmis::warnings)
gtest_discover_tests(stuffing_tests DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)

# The fast path against the reference: the same lattice, graded mesh and
# stuffed mesh, exactly.
add_executable(stuffing_fast_tests stuff/stuffing_fast_test.cpp)
target_link_libraries(stuffing_fast_tests PRIVATE bccmis::stuff bccmis::d3 bccmis::fast GTest::gtest_main bccmis::warnings)
gtest_discover_tests(stuffing_fast_tests DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)
