# Included by tests/CMakeLists.txt: the p4est bridge (issue 10), label p4est.
# Every test process starts MPI as a singleton (no mpirun needed, ~0.4 s).
# Under AddressSanitizer, LeakSanitizer reports OpenMPI's dlclose'd plugins
# (docs: /work/shared/notes/dependencies.md §7), so leaks are not checked here.
if(NOT TARGET bccmis::p4est)
  return()
endif()

# One variable only: gtest_discover_tests flattens list-valued properties.
set(_bccmis_p4est_env "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1")
# One target per file: tests/p4est/d3/bridge_test.cpp is p4est_d3_bridge_test.
foreach(file bridge_test differential_test d3/bridge_test d3/differential_test)
  string(REPLACE "/" "_" name ${file})
  bccmis_add_gtest(p4est_${name} SOURCES ${file}.cpp OWN_MAIN
    LIBS bccmis::p4est bccmis::apps bccmis::invariants bccmis::invariants_d3 bccmis::core
    PREFIX p4est. LABELS p4est ENVIRONMENT "${_bccmis_p4est_env}")
endforeach()

# The distributed run on two ranks, when mpirun exists; on one rank (a
# singleton, no mpirun) otherwise, which still gathers, imports and checks.
find_program(BCCMIS_MPIRUN NAMES mpirun mpiexec HINTS ${MPIEXEC_EXECUTABLE})
set(_bccmis_p4est_dist LABELS p4est TIMEOUT 120
                       PROPERTIES ENVIRONMENT "${_bccmis_p4est_env}" FAIL_REGULAR_EXPRESSION "FAIL")
if(BCCMIS_MPIRUN)
  bccmis_add_test(p4est.distributed_2_ranks
           COMMAND ${BCCMIS_MPIRUN} -np 2 --allow-run-as-root --oversubscribe $<TARGET_FILE:bccmis_p4est_distributed> --expect-ranks 2
           ${_bccmis_p4est_dist})
  bccmis_add_test(p4est.distributed3_2_ranks
           COMMAND ${BCCMIS_MPIRUN} -np 2 --allow-run-as-root --oversubscribe $<TARGET_FILE:bccmis_p8est_distributed> --expect-ranks 2
           ${_bccmis_p4est_dist})
else()
  message(STATUS "bccmis: mpirun not found, the p4est distributed runs use one rank")
  bccmis_add_test(p4est.distributed_1_rank COMMAND bccmis_p4est_distributed ${_bccmis_p4est_dist})
  bccmis_add_test(p4est.distributed3_1_rank COMMAND bccmis_p8est_distributed ${_bccmis_p4est_dist})
endif()
