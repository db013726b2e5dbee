# Included by tests/CMakeLists.txt: the checker's tests (issue 4).
add_executable(invariants_test ${CMAKE_CURRENT_LIST_DIR}/invariants_test.cpp)
target_link_libraries(invariants_test PRIVATE bccmis::invariants GTest::gtest_main bccmis::warnings)
gtest_discover_tests(invariants_test DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)

if(TARGET bccmis::triangulation_check)
  add_executable(triangulation_check_test ${CMAKE_CURRENT_LIST_DIR}/triangulation_check_test.cpp)
  target_link_libraries(triangulation_check_test PRIVATE bccmis::triangulation_check GTest::gtest_main bccmis::warnings)
  gtest_discover_tests(triangulation_check_test DISCOVERY_MODE PRE_TEST PROPERTIES LABELS cgal)
endif()
