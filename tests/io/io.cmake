# The readers and writers of bccmis::io (src/bccmis/io/), format by format.
add_executable(io_tests io/ply_read_test.cpp io/pvd_test.cpp io/surface_format_test.cpp)
target_link_libraries(io_tests PRIVATE bccmis::io GTest::gtest_main bccmis::warnings)
gtest_discover_tests(io_tests DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)
