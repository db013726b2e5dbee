# Isosurface stuffing (spec/stuffing.md): the fit and the band, exact
# orientation, and on the built-in shapes the mesh's own checks: closed
# boundary on the surface, enclosed volume equal to the tetrahedra's, every
# interior triangle in two tetrahedra, positive orientation, angle bounds.
add_executable(stuffing_tests stuff/stuffing_test.cpp)
target_link_libraries(stuffing_tests PRIVATE bccmis::stuff bccmis::d3 GTest::gtest_main bccmis::warnings)
gtest_discover_tests(stuffing_tests DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)

# Reading back the Medit files and drawing them (bccmis render MESH.mesh):
# a two-tetrahedron mesh drawn by hand (tests/stuff/two_tets.mesh).
add_executable(stuff_render_tests stuff/render_test.cpp)
target_link_libraries(stuff_render_tests PRIVATE bccmis::stuff bccmis::d3 bccmis::core GTest::gtest_main bccmis::warnings)
target_compile_definitions(stuff_render_tests PRIVATE BCCMIS_TEST_DIR="${CMAKE_CURRENT_SOURCE_DIR}/stuff")
gtest_discover_tests(stuff_render_tests DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)

# A stuffed sphere or torus as a Medit file, for the pictures (tests/cli.cmake).
add_executable(stuffed_example stuff/stuffed_example.cpp)
target_link_libraries(stuffed_example PRIVATE bccmis::stuff bccmis::d3 bccmis::warnings)
