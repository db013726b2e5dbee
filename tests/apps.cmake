# Included by tests/CMakeLists.txt: the apps' tests (issue 8).
find_package(GTest REQUIRED)
include(GoogleTest)

add_executable(apps_tests
  ${CMAKE_CURRENT_LIST_DIR}/apps_balance_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/apps_image_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/apps_heightfield_test.cpp)
target_link_libraries(apps_tests PRIVATE bccmis::apps bccmis::core bccmis::invariants bccmis::oracle
                      GTest::gtest_main bccmis::warnings)
target_compile_definitions(apps_tests PRIVATE BCCMIS_APPS_SAMPLES="${PROJECT_SOURCE_DIR}/apps/samples")
gtest_discover_tests(apps_tests DISCOVERY_MODE PRE_TEST PROPERTIES LABELS "unit;apps")
