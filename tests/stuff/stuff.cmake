# Closed triangle meshes as shapes (spec/stuffing.md §1,
# src/bccmis/stuff/surface.cpp): a cube by hand, the readers on small files,
# one file per refusal with its exact message, and two of CGAL's sample
# meshes. Built when CGAL was found.
if(TARGET bccmis::stuff_surface)
  # CGAL's sample meshes come in libcgal-demo's data.tar.gz (scripts/setup.sh);
  # the few the tests read are extracted into the build tree.
  set(BCCMIS_CGAL_DATA_TAR /usr/share/doc/libcgal-dev/data.tar.gz CACHE FILEPATH
      "data.tar.gz of libcgal-demo, CGAL's sample meshes")
  set(bccmis_cgal_meshes elephant.off double-torus-example.off icosahedron.off corner_poly.off prim.off 3torus.off
                         fandisk.off anchor.off turbine.off joint.off # sharp features (features_test.cpp, crease_cuts_test.cpp)
                         P.off # S35.8 keeps B at level 2 (mpi.stuff_crease_cuts_p_2_ranks, spec/distributed.md D16)
                         # flawed files for cli.stuff_wild_files (below)
                         bones.off blob.off mpi.off cube4-shuffled.off colored_tetra.ply)
  set(bccmis_cgal_data ${CMAKE_CURRENT_BINARY_DIR}/cgal_data)
  set(bccmis_cgal_missing "")
  foreach(m ${bccmis_cgal_meshes})
    if(NOT EXISTS ${bccmis_cgal_data}/data/meshes/${m})
      set(bccmis_cgal_missing ${m})
    endif()
  endforeach()
  if(bccmis_cgal_missing)
    if(NOT EXISTS ${BCCMIS_CGAL_DATA_TAR})
      message(FATAL_ERROR "${BCCMIS_CGAL_DATA_TAR} not found: the surface tests (tests/stuff) read CGAL's sample "
                          "meshes from it. Install the Debian package libcgal-demo (scripts/setup.sh does), or set "
                          "BCCMIS_CGAL_DATA_TAR.")
    endif()
    list(TRANSFORM bccmis_cgal_meshes PREPEND data/meshes/ OUTPUT_VARIABLE bccmis_cgal_members)
    file(MAKE_DIRECTORY ${bccmis_cgal_data})
    execute_process(COMMAND ${CMAKE_COMMAND} -E tar xzf ${BCCMIS_CGAL_DATA_TAR} ${bccmis_cgal_members}
                    WORKING_DIRECTORY ${bccmis_cgal_data} RESULT_VARIABLE bccmis_tar_rc)
    foreach(m ${bccmis_cgal_meshes})
      if(NOT bccmis_tar_rc EQUAL 0 OR NOT EXISTS ${bccmis_cgal_data}/data/meshes/${m})
        message(FATAL_ERROR "could not extract data/meshes/${m} from ${BCCMIS_CGAL_DATA_TAR} (tests/stuff)")
      endif()
    endforeach()
  endif()

  # Flawed real files meshed by the default path (issue 27, "Meshes in the
  # wild"): self-intersecting, open, with zero-area faces, inconsistently
  # oriented, and one clean; checked by --check and against the volume of the
  # winding number's solid estimated independently in numpy
  # (tests/stuff/wild_files_test.py; by hand: wild_files_test.py BCCMIS).
  bccmis_add_test(cli.stuff_wild_files
           COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/stuff/wild_files_test.py $<TARGET_FILE:bccmis>
                   ${bccmis_cgal_data}/data/meshes
           LABELS cgal stuff TIMEOUT 600)

  bccmis_add_gtest(stuff_surface_tests SOURCES surface_test.cpp LIBS bccmis::stuff_surface
                   DEFINITIONS BCCMIS_STUFF_TEST_DIR="${CMAKE_CURRENT_LIST_DIR}"
                               BCCMIS_CGAL_MESHES_DIR="${bccmis_cgal_data}/data/meshes"
                   LABELS unit)
  # Triangle soups (spec/stuffing.md S20-S23): the inspection, flawed cubes
  # meshed, the soup's shape against the clean shape on CGAL's meshes.
  bccmis_add_gtest(stuff_soup_tests SOURCES soup_test.cpp
                   LIBS bccmis::stuffing bccmis::stuff_surface bccmis::io bccmis::soup
                   DEFINITIONS BCCMIS_STUFF_TEST_DIR="${CMAKE_CURRENT_LIST_DIR}"
                               BCCMIS_CGAL_MESHES_DIR="${bccmis_cgal_data}/data/meshes"
                   LABELS unit)
endif()

# Sharp features (spec/stuffing.md S29-S35): detection on hand-built
# surfaces, conformity on a turned cube and on fandisk at level 3 with S10's
# bound and the feature checker, the checker's planted failures; S35.9's
# flips on hand-made two-tetrahedron meshes (flips_test.cpp: a flip whose
# pieces pass is made, one whose piece without the moved vertex leaves
# S10's interval is not) and S35.10's sequence of two flips on a piece of
# CGAL's anchor at level 4 (flips/).
if(TARGET bccmis::stuff_surface)
  bccmis_add_gtest(stuff_features_tests SOURCES features_test.cpp flips_test.cpp
                   LIBS bccmis::stuffing bccmis::stuff_surface bccmis::invariants_d3
                   DEFINITIONS BCCMIS_CGAL_MESHES_DIR="${bccmis_cgal_data}/data/meshes"
                               BCCMIS_STUFF_TEST_DIR="${CMAKE_CURRENT_LIST_DIR}"
                   LABELS unit)
endif()

# S25: the memory estimate on its line, with and without S35.8's second
# mesh (--crease-cuts), on CGAL's fandisk at level 2.
if(TARGET bccmis::stuff_surface)
  bccmis_add_gtest(stuff_memory_estimate_tests SOURCES memory_estimate_test.cpp
                   LIBS bccmis::stuffing bccmis::stuff_surface
                   DEFINITIONS BCCMIS_CGAL_MESHES_DIR="${bccmis_cgal_data}/data/meshes"
                   LABELS unit)
endif()

# S35.7: cut points placed on the creases before warping, on CGAL's joint
# and fandisk at level 3, with S10's bound and the feature checker; S35.8:
# on CGAL's anchor at level 2 nothing the run without it conforms is lost.
if(TARGET bccmis::stuff_surface)
  bccmis_add_gtest(stuff_crease_cuts_tests SOURCES crease_cuts_test.cpp
                   LIBS bccmis::stuffing bccmis::stuff_surface bccmis::io
                   DEFINITIONS BCCMIS_CGAL_MESHES_DIR="${bccmis_cgal_data}/data/meshes"
                   LABELS unit)
endif()
