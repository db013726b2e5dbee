# Property suites (issue 5): RapidCheck properties, the rc::state model test,
# exhaustive exploration of small lattices, and the planted-bug mutants that
# prove the properties can fail. Seeds and budgets are fixed here; a failing
# property prints its reproduce string (RC_PARAMS="reproduce=...").
find_package(rapidcheck REQUIRED CONFIG)  # Debian's package has no version file: no version here

set(BCCMIS_RC_SEED 20090303)  # the paper's publication date

# RapidCheck properties of the reference core.
add_executable(properties_test properties_test.cpp)
target_include_directories(properties_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(properties_test PRIVATE rapidcheck_gtest GTest::gtest_main bccmis::testing
                      bccmis::core bccmis::invariants bccmis::warnings)
target_compile_definitions(properties_test PRIVATE BCCMIS_REGRESSIONS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/regressions")
gtest_discover_tests(properties_test DISCOVERY_MODE PRE_TEST
  PROPERTIES LABELS property ENVIRONMENT "RC_PARAMS=seed=${BCCMIS_RC_SEED} max_success=300")

# Model-based test: the graph against the independent quadtree-leaf model.
add_executable(model_test model_test.cpp)
target_include_directories(model_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(model_test PRIVATE rapidcheck_gtest GTest::gtest_main bccmis::testing
                      bccmis::core bccmis::invariants bccmis::warnings)
gtest_discover_tests(model_test DISCOVERY_MODE PRE_TEST
  PROPERTIES LABELS property ENVIRONMENT "RC_PARAMS=seed=${BCCMIS_RC_SEED} max_success=300")

# Exhaustive exploration: lattices of up to 512 states run with the properties;
# 3 1 2, 2 2 2 and 1 1 3 (4250, 66641, 66642 states) under the `exhaustive`
# label, which the test presets exclude. Run them in the release build:
#   ctest --test-dir build/release -L exhaustive      (about 70 s CPU each for the two large ones)
add_executable(exhaustive_test exhaustive_test.cpp)
target_include_directories(exhaustive_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(exhaustive_test PRIVATE GTest::gtest_main
                      bccmis::explore bccmis::core bccmis::invariants bccmis::warnings)
gtest_discover_tests(exhaustive_test DISCOVERY_MODE PRE_TEST NO_PRETTY_VALUES TEST_FILTER "-*ExhaustiveLarge.*"
  PROPERTIES LABELS property)
gtest_discover_tests(exhaustive_test DISCOVERY_MODE PRE_TEST NO_PRETTY_VALUES TEST_FILTER "*ExhaustiveLarge.*"
  PROPERTIES LABELS exhaustive TIMEOUT 1800)

# Planted-bug mutants: every property suite must be able to fail.
add_executable(mutants_property_test mutants/mutant_ops.cpp mutants/mutants_test.cpp)
target_include_directories(mutants_property_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(mutants_property_test PRIVATE rapidcheck_gtest GTest::gtest_main bccmis::testing
                      bccmis::explore bccmis::core bccmis::invariants bccmis::warnings)
target_compile_definitions(mutants_property_test PRIVATE
                           BCCMIS_REGRESSIONS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/regressions")
gtest_discover_tests(mutants_property_test DISCOVERY_MODE PRE_TEST NO_PRETTY_VALUES TEST_FILTER "-MutantDemo.*"
  PROPERTIES LABELS property ENVIRONMENT "RC_PARAMS=seed=${BCCMIS_RC_SEED}")
