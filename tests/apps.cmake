# Included by tests/CMakeLists.txt: the apps' tests (issue 8).
add_executable(apps_tests
  ${CMAKE_CURRENT_LIST_DIR}/apps_balance_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/apps_image_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/apps_heightfield_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/apps_animate_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/apps_fast_test.cpp)
target_link_libraries(apps_tests PRIVATE bccmis::apps bccmis::fast bccmis::core bccmis::invariants bccmis::oracle
                      GTest::gtest_main bccmis::warnings)
target_compile_definitions(apps_tests PRIVATE BCCMIS_APPS_SAMPLES="${PROJECT_SOURCE_DIR}/apps/samples")
# The 66k-state corner-balance counts run under `exhaustive` (release build,
# excluded from the default test presets), like tests/exhaustive_test.cpp.
gtest_discover_tests(apps_tests DISCOVERY_MODE PRE_TEST TEST_FILTER "-*Exhaustive.*"
  TEST_LIST apps_tests_UNIT PROPERTIES LABELS unit)
gtest_discover_tests(apps_tests DISCOVERY_MODE PRE_TEST TEST_FILTER "*Exhaustive.*"
  TEST_LIST apps_tests_EXHAUSTIVE PROPERTIES LABELS exhaustive TIMEOUT 1800)
# gtest_discover_tests flattens a list-valued LABELS ("unit;apps" becomes the
# label "unit" and a stray property "apps"), so the `apps` label is added by a
# test include file that runs after the discovered tests are defined.
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/apps_tests_labels.cmake
     "if(apps_tests_UNIT)\n  set_tests_properties(\${apps_tests_UNIT} PROPERTIES LABELS \"unit;apps\")\nendif()\n"
     "if(apps_tests_EXHAUSTIVE)\n  set_tests_properties(\${apps_tests_EXHAUSTIVE} PROPERTIES LABELS \"exhaustive;apps\")\nendif()\n")
set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${CMAKE_CURRENT_BINARY_DIR}/apps_tests_labels.cmake)

# The committed sample is what its generator script writes.
find_package(Python3 COMPONENTS Interpreter QUIET)
if(Python3_FOUND)
  add_test(NAME apps.sample_terrain_reproducible
           COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/apps/samples/make_terrain.py terrain --size 128 --bits 16
                   --check ${PROJECT_SOURCE_DIR}/apps/samples/terrain128.pgm)
  add_test(NAME apps.sample_terrain256_reproducible
           COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/apps/samples/make_terrain.py terrain --size 256 --bits 16
                   --check ${PROJECT_SOURCE_DIR}/apps/samples/terrain256.pgm)
  set_tests_properties(apps.sample_terrain_reproducible apps.sample_terrain256_reproducible
                       PROPERTIES LABELS "unit;apps")
endif()

# The height field's streamed writers and fast-lattice mesh paths against the
# texts and values they replace.
add_executable(apps_output_test ${CMAKE_CURRENT_LIST_DIR}/apps_output_test.cpp)
target_link_libraries(apps_output_test PRIVATE bccmis::apps bccmis::fast bccmis::core GTest::gtest_main bccmis::warnings)
gtest_discover_tests(apps_output_test DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)
