# The fast implementation against the reference (issue 9), ctest labels
# `unit` and `property`. Seeds and budgets are fixed here; a failing property
# prints its reproducer trace (save it in tests/regressions/).
find_package(rapidcheck REQUIRED CONFIG)  # Debian's package has no version file

set(BCCMIS_FAST_RC_SEED 20090303)

# Unit tests: initial lattices, every project trace replayed through both
# (states compared after every command), queries, conversions, interface.
add_executable(fast_lattice_test fast_lattice_test.cpp)
target_link_libraries(fast_lattice_test PRIVATE bccmis::fast bccmis::invariants GTest::gtest_main bccmis::warnings)
target_compile_definitions(fast_lattice_test PRIVATE BCCMIS_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(fast_lattice_test DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)

# The streamed canonical states and decision lines against the texts built
# line by line (both lattices, random states).
add_executable(output_paths_test output_paths_test.cpp)
target_link_libraries(output_paths_test PRIVATE bccmis::fast GTest::gtest_main bccmis::warnings)
gtest_discover_tests(output_paths_test DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)

# No allocation per operation in steady state; strong guarantee (replaces
# the global operator new, so its own executable).
add_executable(fast_alloc_test fast_alloc_test.cpp)
target_include_directories(fast_alloc_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(fast_alloc_test PRIVATE bccmis::fast GTest::gtest_main bccmis::warnings)
gtest_discover_tests(fast_alloc_test DISCOVERY_MODE PRE_TEST PROPERTIES LABELS unit)

# RapidCheck: the same random sequences through both, compared after every
# operation; and the reference's property bodies run on the fast lattice.
add_executable(fast_differential_test fast_differential_test.cpp)
target_include_directories(fast_differential_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(fast_differential_test PRIVATE rapidcheck_gtest GTest::gtest_main
                      bccmis::testing bccmis::fast bccmis::invariants bccmis::warnings)
gtest_discover_tests(fast_differential_test DISCOVERY_MODE PRE_TEST
  PROPERTIES LABELS property ENVIRONMENT "RC_PARAMS=seed=${BCCMIS_FAST_RC_SEED} max_success=100")

# The conformance harness (src/bccmis/oracle, `bccmis conformance`) against the fast
# implementation: the bundled traces, then random traces with shrinking (2D:
# the fast lattice is 2D).
add_test(NAME fast.conformance
         COMMAND bccmis conformance --impl $<TARGET_FILE:bccmis_fast_replay>
                 --traces ${PROJECT_SOURCE_DIR}/spec/examples --random 300 --seed 20090303 --max-ops 40 --dim 2)
set_tests_properties(fast.conformance PROPERTIES LABELS conformance TIMEOUT 300)
