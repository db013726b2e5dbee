# Included by tests/CMakeLists.txt: stuffing split among MPI ranks
# (spec/distributed.md), label mpi. In one process, the pieces of any split
# of the leaves gathered are stuff()'s mesh; under mpirun on 1-4 ranks
# (oversubscribed on small machines), bccmis-mpi stuff against bccmis stuff
# (tests/distributed/mpi_stuff_test.py; --animate: mpi_animate_test.py, D14): --gather byte for byte (with the
# features and --check, D12; their statistics and warnings, D13), the .pvtu's pieces by vertex positions and
# conformity, and the failures.
bccmis_add_gtest(distributed_tests SOURCES stuff_leaves_test.cpp repartition_test.cpp LIBS bccmis::distributed bccmis::stuff PREFIX distributed. NO_PRETTY_VALUES
                 LABELS unit mpi)
# D16: S25's memory estimate split over the ranks, on its line.
bccmis_add_gtest(distributed_rank_memory_tests SOURCES rank_memory_test.cpp LIBS bccmis::distributed bccmis::stuff
                 PREFIX distributed. NO_PRETTY_VALUES LABELS unit mpi)
# D10: a rank's lattice from the leaves it knows, against the whole lattice.
if(TARGET bccmis::stuff_surface)
  bccmis_add_gtest(distributed_local_lattice_tests SOURCES local_lattice_test.cpp
                   LIBS bccmis::distributed bccmis::stuff bccmis::stuff_surface PREFIX distributed. NO_PRETTY_VALUES
                   DEFINITIONS BCCMIS_CGAL_MESHES_DIR="${bccmis_cgal_data}/data/meshes" LABELS unit mpi)
else()
  bccmis_add_gtest(distributed_local_lattice_tests SOURCES local_lattice_test.cpp
                   LIBS bccmis::distributed bccmis::stuff PREFIX distributed. NO_PRETTY_VALUES LABELS unit mpi)
endif()

# D12: the features and --check on the gathered mesh (a CGAL sample mesh with creases).
if(TARGET bccmis::stuff_surface)
  bccmis_add_gtest(distributed_finish_gathered_tests SOURCES finish_gathered_test.cpp
                   LIBS bccmis::distributed bccmis::stuff bccmis::stuff_surface PREFIX distributed. NO_PRETTY_VALUES
                   DEFINITIONS BCCMIS_CGAL_MESHES_DIR="${bccmis_cgal_data}/data/meshes" LABELS unit mpi)
endif()

if(NOT TARGET bccmis_mpi OR NOT BCCMIS_MPIRUN)
  return()
endif()
# As tests/p4est: LeakSanitizer reports OpenMPI's plugins.
set(_bccmis_mpi_test ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/mpi_stuff_test.py)
set(_bccmis_mpi_tools ${BCCMIS_MPIRUN} $<TARGET_FILE:bccmis> $<TARGET_FILE:bccmis_mpi>)
# ASan and oversubscribed ranks on a loaded machine: minutes, not seconds.
set(_bccmis_mpi_props LABELS mpi TIMEOUT 300 PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")
# mpi.NAME: one mpi_stuff_test.py MODE run on RANKS ranks, bccmis stuff's
# arguments after them.
function(_bccmis_mpi_stuff_test name mode ranks)
  bccmis_add_test(mpi.${name} COMMAND ${_bccmis_mpi_test} ${mode} ${_bccmis_mpi_tools} ${ranks} -- ${ARGN}
                  ${_bccmis_mpi_props})
endfunction()
foreach(ranks 1 2 3 4)
  # On 2 ranks every format (.vtu binary and ASCII, .msh), else binary .vtu.
  set(_mode gather)
  if(ranks EQUAL 2)
    set(_mode gather-every-format)
  endif()
  bccmis_add_test(mpi.stuff_gather_torus_${ranks}_ranks
                  COMMAND ${_bccmis_mpi_test} ${_mode} ${_bccmis_mpi_tools} ${ranks} -- --shape torus -L 2 --cells 6
                  ${_bccmis_mpi_props})
  bccmis_add_test(mpi.stuff_pvtu_torus_${ranks}_ranks
                  COMMAND ${_bccmis_mpi_test} pvtu ${_bccmis_mpi_tools} ${ranks} -- --shape torus -L 2 --cells 6
                  ${_bccmis_mpi_props})
endforeach()
# Rank 3's leaves all lie outside the torus: it writes no piece (D1).
bccmis_add_test(mpi.stuff_pvtu_torus_empty_piece_4_ranks
                COMMAND ${_bccmis_mpi_test} pvtu ${_bccmis_mpi_tools} 4:3 -- --shape torus -L 3 ${_bccmis_mpi_props})
if(TARGET bccmis::stuff_surface)  # a CGAL sample mesh (tests/stuff/stuff.cmake extracts it)
  foreach(ranks 2 3)
    bccmis_add_test(mpi.stuff_gather_double_torus_${ranks}_ranks
                    COMMAND ${_bccmis_mpi_test} gather ${_bccmis_mpi_tools} ${ranks} --
                            ${bccmis_cgal_data}/data/meshes/double-torus-example.off -L 2 --cells 6
                    ${_bccmis_mpi_props})
  endforeach()
  bccmis_add_test(mpi.stuff_pvtu_double_torus_4_ranks
                  COMMAND ${_bccmis_mpi_test} pvtu ${_bccmis_mpi_tools} 4 --
                          ${bccmis_cgal_data}/data/meshes/double-torus-example.off -L 2 --cells 6
                  ${_bccmis_mpi_props})
endif()
# D12: the features (CGAL's fandisk: creases and corners, S29-S35) and
# --check on the gathered mesh, against bccmis stuff's bytes: on 2 ranks
# --gather, on 3 --gather --check.
if(TARGET bccmis::stuff_surface)
  bccmis_add_test(mpi.stuff_features_fandisk_2_ranks
                  COMMAND ${_bccmis_mpi_test} whole ${_bccmis_mpi_tools} 2 --
                          ${bccmis_cgal_data}/data/meshes/fandisk.off -L 2
                  ${_bccmis_mpi_props})
  bccmis_add_test(mpi.stuff_features_check_fandisk_3_ranks
                  COMMAND ${_bccmis_mpi_test} whole-check ${_bccmis_mpi_tools} 3 --
                          ${bccmis_cgal_data}/data/meshes/fandisk.off -L 2
                  ${_bccmis_mpi_props})
endif()
bccmis_add_test(mpi.stuff_check_torus_2_ranks
                COMMAND ${_bccmis_mpi_test} whole-check ${_bccmis_mpi_tools} 2 -- --shape torus -L 2 --cells 6
                ${_bccmis_mpi_props})
# D13: --stats --json with the features (one run: the bytes, the JSON, the
# warnings), and S26's warning on stderr from the gathered mesh (--check).
if(TARGET bccmis::stuff_surface)
  bccmis_add_test(mpi.stuff_stats_features_fandisk_2_ranks
                  COMMAND ${_bccmis_mpi_test} stats-features ${_bccmis_mpi_tools} 2 --
                          ${bccmis_cgal_data}/data/meshes/fandisk.off -L 2
                  ${_bccmis_mpi_props})
endif()
bccmis_add_test(mpi.stuff_check_warns_coarse_sphere_2_ranks
                COMMAND ${_bccmis_mpi_test} whole-check-warns ${_bccmis_mpi_tools} 2 -- --shape sphere --cells 3 -L 2
                ${_bccmis_mpi_props})
# D11: --stats and --json on 2 and 3 ranks against bccmis stuff's.
foreach(ranks 2 3)
  bccmis_add_test(mpi.stuff_stats_torus_${ranks}_ranks
                  COMMAND ${_bccmis_mpi_test} stats ${_bccmis_mpi_tools} ${ranks} -- --shape torus -L 2 --cells 6
                  ${_bccmis_mpi_props})
endforeach()
# S26's warning, from rank 0 (the unit sphere at h = 1: coarse).
bccmis_add_test(mpi.stuff_stats_coarse_sphere_2_ranks
                COMMAND ${_bccmis_mpi_test} stats ${_bccmis_mpi_tools} 2 -- --shape sphere --cells 3 -L 2
                ${_bccmis_mpi_props})
if(TARGET bccmis::stuff_surface)
  bccmis_add_test(mpi.stuff_stats_double_torus_3_ranks
                  COMMAND ${_bccmis_mpi_test} stats ${_bccmis_mpi_tools} 3 --
                          ${bccmis_cgal_data}/data/meshes/double-torus-example.off -L 2 --cells 6
                  ${_bccmis_mpi_props})
endif()
# D12: --stats --check as bccmis stuff's: passing (the torus), the statistics
# in its order; failing (CGAL's elephant at level 3, S27's extra components),
# exit 1 and no statistics.
_bccmis_mpi_stuff_test(stuff_stats_check_torus_2_ranks stats-check 2 --shape torus -L 2 --cells 6)
if(TARGET bccmis::stuff_surface)
  _bccmis_mpi_stuff_test(stuff_stats_check_fails_elephant_2_ranks stats-check 2
                         --failing ${bccmis_cgal_data}/data/meshes/elephant.off -L 3)
endif()
# D12, D13: --hausdorff on the gathered mesh, as bccmis stuff's (text and JSON).
_bccmis_mpi_stuff_test(stuff_hausdorff_sphere_2_ranks hausdorff 2 --shape sphere -L 2)
# D1: a repaired INPUT's notices, as bccmis stuff prints them (rank 0, once).
if(TARGET bccmis::stuff_surface)
  _bccmis_mpi_stuff_test(stuff_notices_cube_2_ranks notices 2 -L 2)
endif()
# D10: the forest refined by S3's test against G, and each rank's lattice.
add_executable(bccmis_distributed_forest_test ${CMAKE_CURRENT_LIST_DIR}/forest_mpi_test.cpp)
target_link_libraries(bccmis_distributed_forest_test PRIVATE bccmis::distributed_mpi bccmis::stuff bccmis::warnings)
foreach(ranks 2 3)
  bccmis_add_test(mpi.forest_${ranks}_ranks
                  COMMAND ${BCCMIS_MPIRUN} -np ${ranks} --allow-run-as-root --oversubscribe
                          $<TARGET_FILE:bccmis_distributed_forest_test>
                  ${_bccmis_mpi_props} FAIL_REGULAR_EXPRESSION "FAIL")
endforeach()
# D16: --memory-limit per rank on its line, the sphere at level 2 on 2 ranks
# (4,096 leaves, every cube: 3700 x 4096 / 2 bytes a rank; with --gather
# rank 0's 4 x 420 x 4096 more), and --crease-cuts with --gather
# (S35.8 on rank 0: CGAL's P.off at level 2 keeps B with delta 1/4 and C with
# 1/2, 16 curves of 21 against A's 15, each in a second) as bccmis stuff's bytes and statistics.
_bccmis_mpi_stuff_test(stuff_memory_limit_sphere_2_ranks memory 2 0.0075776 0.01445888 --shape sphere -L 2)
if(TARGET bccmis::stuff_surface)
  foreach(delta 0.25 0.5)
    _bccmis_mpi_stuff_test(stuff_crease_cuts_${delta}_p_2_ranks stats-features 2
                           ${bccmis_cgal_data}/data/meshes/P.off -L 2 --crease-cuts ${delta})
  endforeach()
endif()
bccmis_add_test(mpi.stuff_errors_3_ranks COMMAND ${_bccmis_mpi_test} errors ${_bccmis_mpi_tools} 3
                ${_bccmis_mpi_props})
# D14: --animate on ranks, each frame (pieces and gathered) against bccmis
# stuff --animate's, and the options refused with it. D15: the forest kept
# and moved a step a frame, every step coarsening and refining (a partition
# corrected for a split family in each; on 3 ranks a repartition a frame).
set(_bccmis_mpi_animate_test ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/mpi_animate_test.py)
bccmis_add_test(mpi.stuff_animate_sphere_2_ranks
                COMMAND ${_bccmis_mpi_animate_test} frames ${_bccmis_mpi_tools} 2 -- --shape sphere -L 3 --animate 2
                ${_bccmis_mpi_props})
bccmis_add_test(mpi.stuff_animate_steps_sphere_2_ranks
                COMMAND ${_bccmis_mpi_animate_test} steps ${_bccmis_mpi_tools} 2 -- --shape sphere -L 2 --cells 5
                        --animate 3
                ${_bccmis_mpi_props})
bccmis_add_test(mpi.stuff_animate_steps_sphere_3_ranks
                COMMAND ${_bccmis_mpi_animate_test} steps ${_bccmis_mpi_tools} 3 -- --shape sphere -L 2 --cells 6
                        --animate 3 --repartition-threshold 1
                ${_bccmis_mpi_props})
# D14, D17: an empty frame in bccmis stuff's words; the forest check's
# failure, planted by its test hook.
bccmis_add_test(mpi.stuff_animate_faults_2_ranks COMMAND ${_bccmis_mpi_animate_test} faults ${_bccmis_mpi_tools} 2
                ${_bccmis_mpi_props})
# D18: what a signal to the ranks leaves while they stage the frames.
bccmis_add_test(mpi.stuff_animate_signals_2_ranks COMMAND ${_bccmis_mpi_animate_test} signals ${_bccmis_mpi_tools} 2
                ${_bccmis_mpi_props})
bccmis_add_test(mpi.stuff_animate_refusals_2_ranks COMMAND ${_bccmis_mpi_animate_test} refusals ${_bccmis_mpi_tools} 2
                ${_bccmis_mpi_props})
