# Included by tests/CMakeLists.txt: the fast lattices (src/bccmis/fast) against
# the references.
#
# The fast 2D implementation against the reference (issue 9), ctest labels
# `unit` and `property`. Seeds and budgets are fixed here; a failing property
# prints its reproducer trace (save it in tests/regressions/).
find_package(rapidcheck REQUIRED CONFIG)  # Debian's package has no version file

set(BCCMIS_FAST_RC_SEED 20090303)

# Unit tests: initial lattices, every project trace replayed through both
# (states compared after every command), queries, conversions, interface.
bccmis_add_gtest(fast_lattice_test SOURCES lattice_test.cpp LIBS bccmis::fast bccmis::invariants
                 DEFINITIONS BCCMIS_SOURCE_DIR="${PROJECT_SOURCE_DIR}" LABELS unit)

# The streamed canonical states and decision lines against the texts built
# line by line (both lattices, random states).
bccmis_add_gtest(output_paths_test SOURCES output_paths_test.cpp LIBS bccmis::fast LABELS unit)

# No allocation per operation in steady state; strong guarantee (replaces
# the global operator new: testing/counting_allocator.h, so its own executable).
bccmis_add_gtest(fast_alloc_test SOURCES alloc_test.cpp LIBS bccmis::fast LABELS unit)

# RapidCheck: the same random sequences through both, compared after every
# operation; and the reference's property bodies run on the fast lattice.
bccmis_add_gtest(fast_differential_test SOURCES differential_test.cpp
  LIBS rapidcheck_gtest bccmis::testing bccmis::fast bccmis::invariants
  DEFINITIONS BCCMIS_FAST_RC_SEED=${BCCMIS_FAST_RC_SEED}ULL
  LABELS property ENVIRONMENT "RC_PARAMS=seed=${BCCMIS_FAST_RC_SEED} max_success=100")

# The conformance harness (src/bccmis/oracle, `bccmis conformance`) against the fast
# implementation: the bundled traces, then random traces with shrinking (2D:
# the fast lattice is 2D).
bccmis_add_test(fast.conformance
         COMMAND bccmis conformance --impl $<TARGET_FILE:bccmis_fast_replay>
                 --traces ${PROJECT_SOURCE_DIR}/spec/examples --random 300 --seed 20090303 --max-ops 40 --dim 2
         LABELS conformance TIMEOUT 300)

# The fast 3D lattice (bccmis::d3::fast::Lattice) against the 3D reference
# (issue "3D at scale"): random sequences in lock-step with fixed seeds
# (label property), the spec/examples/d3 traces byte for byte (label unit),
# and no allocation per operation in steady state (label unit).
bccmis_add_gtest(fast_d3_differential_test SOURCES d3/differential_test.cpp LIBS bccmis::fast bccmis::d3
  DEFINITIONS BCCMIS_SPEC_EXAMPLES_DIR="${PROJECT_SOURCE_DIR}/spec/examples"
  FILTER "Fast3Differential.Random*" LABELS property)
bccmis_discover_gtests(fast_d3_differential_test FILTER "-Fast3Differential.Random*" LABELS unit)

# No allocation per operation in steady state; strong guarantee when growth
# fails (replaces the global operator new: testing/counting_allocator.h, so its
# own executable).
bccmis_add_gtest(fast_d3_alloc_test SOURCES d3/alloc_test.cpp LIBS bccmis::fast bccmis::d3 LABELS unit)

# The 3D position table (spec/lattice3d.md §9.4) against a std::map through
# inserts, erases, renames and rehashes.
bccmis_add_gtest(fast_d3_position_table_test SOURCES d3/position_table_test.cpp LIBS bccmis::fast LABELS unit)

# Bulk construction: from_graph of reference states, refine_each /
# coarsen_each against single reference calls.
bccmis_add_gtest(fast_d3_bulk_test SOURCES d3/bulk_test.cpp LIBS bccmis::fast bccmis::d3 LABELS unit)

# The record pools (spec/lattice3d.md §9.8): growth across the switch from
# heap blocks to mappings, every byte kept, a refused growth (operator new,
# mmap, mremap) leaving the pool and a refining lattice unchanged.
bccmis_add_gtest(fast_pool_test SOURCES pool_test.cpp LIBS bccmis::fast LABELS unit)
