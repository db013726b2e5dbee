# The fast 3D lattice (bccmis::fast::Lattice3) against the 3D reference
# (issue "3D at scale"): random sequences in lock-step with fixed seeds
# (label property), the spec/examples/d3 traces byte for byte (label unit),
# and no allocation per operation in steady state (label unit).
add_executable(fast3_differential_test fast3_differential_test.cpp)
target_include_directories(fast3_differential_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(fast3_differential_test PRIVATE bccmis::fast bccmis::d3 GTest::gtest_main bccmis::warnings)
target_compile_definitions(fast3_differential_test PRIVATE BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples")
gtest_discover_tests(fast3_differential_test DISCOVERY_MODE PRE_TEST TEST_FILTER "Fast3Differential.Random*"
  PROPERTIES LABELS property)
gtest_discover_tests(fast3_differential_test DISCOVERY_MODE PRE_TEST TEST_FILTER "-Fast3Differential.Random*"
  PROPERTIES LABELS unit)

# No allocation per operation in steady state; strong guarantee when growth
# fails (replaces the global operator new, so its own executable).
add_executable(fast3_alloc_test fast3_alloc_test.cpp)
target_include_directories(fast3_alloc_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(fast3_alloc_test PRIVATE bccmis::fast bccmis::d3 GTest::gtest_main bccmis::warnings)
gtest_discover_tests(fast3_alloc_test DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)

# Bulk construction: from_graph of reference states, refine_each /
# coarsen_each against single reference calls.
add_executable(fast3_bulk_test fast3_bulk_test.cpp)
target_link_libraries(fast3_bulk_test PRIVATE bccmis::fast bccmis::d3 GTest::gtest_main bccmis::warnings)
gtest_discover_tests(fast3_bulk_test DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)
