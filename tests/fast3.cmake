# The fast 3D lattice (bccmis::fast::Lattice3) against the 3D reference
# (issue "3D at scale"): random sequences in lock-step with fixed seeds
# (label property), the spec/examples/d3 traces byte for byte (label unit),
# and no allocation per operation in steady state (label unit).
bccmis_add_gtest(fast3_differential_test SOURCES fast3_differential_test.cpp LIBS bccmis::fast bccmis::d3
  DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples"
  FILTER "Fast3Differential.Random*" LABELS property)
bccmis_discover_gtests(fast3_differential_test FILTER "-Fast3Differential.Random*" LABELS unit)

# No allocation per operation in steady state; strong guarantee when growth
# fails (replaces the global operator new, so its own executable).
bccmis_add_gtest(fast3_alloc_test SOURCES fast3_alloc_test.cpp LIBS bccmis::fast bccmis::d3 LABELS unit)

# Bulk construction: from_graph of reference states, refine_each /
# coarsen_each against single reference calls.
bccmis_add_gtest(fast3_bulk_test SOURCES fast3_bulk_test.cpp LIBS bccmis::fast bccmis::d3 LABELS unit)
