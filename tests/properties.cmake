# Property suites (issue 5): RapidCheck properties, the rc::state model test,
# exhaustive exploration of small lattices, and the planted-bug mutants that
# prove the properties can fail. Seeds and budgets are fixed here; a failing
# property prints its reproduce string (RC_PARAMS="reproduce=...").
find_package(rapidcheck REQUIRED CONFIG)  # Debian's package has no version file: no version here

set(BCCMIS_RC_SEED 20090303)  # the paper's publication date

# RapidCheck properties of the reference core.
bccmis_add_gtest(properties_test SOURCES properties_test.cpp
  LIBS rapidcheck_gtest bccmis::testing bccmis::core bccmis::invariants
  DEFINITIONS BCCMIS_REGRESSIONS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/regressions"
  LABELS property ENVIRONMENT "RC_PARAMS=seed=${BCCMIS_RC_SEED} max_success=300")

# Model-based test: the graph against the independent quadtree-leaf model.
bccmis_add_gtest(model_test SOURCES model_test.cpp
  LIBS rapidcheck_gtest bccmis::testing bccmis::core bccmis::invariants
  LABELS property ENVIRONMENT "RC_PARAMS=seed=${BCCMIS_RC_SEED} max_success=300")

# Planted-bug mutants: every property suite must be able to fail.
bccmis_add_gtest(mutants_property_test SOURCES mutants/mutant_ops.cpp mutants/mutants_test.cpp
  LIBS rapidcheck_gtest bccmis::testing bccmis::explore bccmis::core bccmis::invariants
  DEFINITIONS BCCMIS_REGRESSIONS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/regressions"
  NO_PRETTY_VALUES FILTER "-MutantDemo.*" LABELS property ENVIRONMENT "RC_PARAMS=seed=${BCCMIS_RC_SEED}")
