# Isosurface stuffing (spec/stuffing.md): the fit and the band, exact
# orientation, and on the built-in shapes the mesh's own checks: closed
# boundary on the surface, enclosed volume equal to the tetrahedra's, every
# interior triangle in two tetrahedra, positive orientation, angle bounds.
# The checker's stuffed-mesh layer on hand-built meshes shares the executable.
bccmis_add_gtest(stuffing_tests SOURCES stuffing_test.cpp stuffed_mesh_check_test.cpp quality_test.cpp
                 LIBS bccmis::stuff bccmis::d3 bccmis::invariants_d3 LABELS unit)

# The CLI's files read by meshio and gmsh, with the boundary's topology and
# enclosed volume checked independently (tests/stuff/stuff_cli_readers.py).
if(TARGET bccmis::stuff_surface)
  set(_stuff_meshes ${bccmis_cgal_data}/data/meshes)
endif()
bccmis_add_test(cli.stuff_readers
         COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/stuff/stuff_cli_readers.py $<TARGET_FILE:bccmis>
                 ${_stuff_meshes}
         LABELS cli TIMEOUT 900)

# S28: the same mesh, byte for byte, on 1, 2 and 3 threads
# (tests/stuff/stuff_threads.py).
bccmis_add_test(cli.stuff_threads
                COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/stuff/stuff_threads.py $<TARGET_FILE:bccmis>
                LABELS cli TIMEOUT 120)

# A triangle mesh moved rigidly (--animate with an input file, S14 and S15):
# the cube [0,2]^3 (tests/stuff/good/cube.off) in 3 steps; the .pvd's frames
# read by meshio, each the cube moved by its share of the path
# (tests/stuff/stuff_cli_animate_mesh.py).
if(TARGET bccmis::stuff_surface)
  bccmis_add_test(cli.stuff_animate_mesh
           COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/stuff/stuff_cli_animate_mesh.py
                   $<TARGET_FILE:bccmis> ${CMAKE_CURRENT_SOURCE_DIR}/stuff/good/cube.off
           LABELS cli)
endif()

# bccmis stuff refusals: exit 2 (spec/cli.md), the message naming what is
# wrong and where.
bccmis_cli_test(stuff_unknown_shape 2 ARGS stuff --shape cube -o x.vtu
                STDERR_REGEX "--shape 'cube': unknown shape 'cube' \\(sphere, torus, spheres\\)")
bccmis_cli_test(stuff_bad_parameter 2 ARGS stuff --shape torus:R=1,q=2 -o x.vtu
                STDERR_REGEX "--shape 'torus:R=1,q=2': unknown parameter 'q' of torus \\(R, r\\)")
bccmis_cli_test(stuff_bad_value 2 ARGS stuff --shape sphere:r=abc -o x.vtu
                STDERR_REGEX "--shape 'sphere:r=abc': 'abc' is not a number")
bccmis_cli_test(stuff_torus_radii 2 ARGS stuff --shape torus:R=1,r=2 -o x.vtu
                STDERR_REGEX "torus: the radii must satisfy 0 < r < R")
bccmis_cli_test(stuff_nothing_to_mesh 2 ARGS stuff -o x.vtu STDERR_REGEX "nothing to mesh")
bccmis_cli_test(stuff_nothing_to_do 2 ARGS stuff --shape sphere STDERR_REGEX "nothing to do")
bccmis_cli_test(stuff_unknown_format 2 ARGS stuff --shape sphere -o x.stl
                STDERR_REGEX "output 'x.stl': unknown format; the extension names it")
bccmis_cli_test(stuff_margin 2 ARGS stuff --shape sphere --cells 5 -L 1 -o x.vtu
                STDERR_REGEX "--cells x 2\\^max-level must exceed 10")
bccmis_cli_test(stuff_bad_path 2 ARGS stuff --shape sphere --animate 2 --path 1,x,0 -o a.pvd
                STDERR_REGEX "--path '1,x,0': 'x' is not a number")
bccmis_cli_test(stuff_animate_not_pvd 2 ARGS stuff --shape sphere --animate 2 -o a.vtu
                STDERR_REGEX "--animate writes one .pvd")
bccmis_cli_test(stuff_animate_too_fine 2 ARGS stuff --shape sphere -L 19 --cells 4 --animate 2 -o a.pvd
                STDERR_REGEX "--animate: the lattice is too fine: 4194304 lattice points along a side")
bccmis_cli_test(stuff_path_without_animate 2 ARGS stuff --shape sphere --path 1,0,0 -o a.vtu
                STDERR_REGEX "--path and --compare apply with --animate")
if(TARGET bccmis::stuff_surface)
  # --strict refuses at the first flaw with §1's message; by default the
  # open cube is meshed (S21) with one line on stderr, and --json has the report.
  bccmis_cli_test(stuff_open_mesh_strict 2 ARGS stuff ${CMAKE_CURRENT_SOURCE_DIR}/stuff/bad/open.off --strict -o x.vtu
                  STDERR_REGEX "open.off: open mesh: 3 border edges, one from vertex 3 to vertex 0")
  bccmis_cli_test(stuff_open_mesh 0 ARGS stuff ${CMAKE_CURRENT_SOURCE_DIR}/stuff/bad/open.off -L 2 -o x.vtu
                  STDERR_REGEX "open.off: 3 border edges: meshed as the solid where the winding number >= 1/2; --strict refuses")
  bccmis_cli_test(stuff_open_mesh_json 0 ARGS stuff ${CMAKE_CURRENT_SOURCE_DIR}/stuff/bad/open.off -L 2 --stats --json -q
                  STDOUT_REGEX "\"soup\": {.*\"border_edges\": {\"count\": 3, \"first\": \\[\\[0\\], \\[3\\], \\[9\\]\\]}")
  bccmis_cli_test(stuff_self_intersecting_strict 2 ARGS stuff ${CMAKE_CURRENT_SOURCE_DIR}/stuff/bad/self_intersecting.off
                  --strict -o x.vtu STDERR_REGEX "self_intersecting.off: self-intersecting \\(face 3 and face 4\\)")
  bccmis_cli_test(stuff_self_intersecting_stats 0 ARGS stuff ${CMAKE_CURRENT_SOURCE_DIR}/stuff/bad/self_intersecting.off
                  -L 2 --stats -q STDOUT_REGEX "soup_self_intersecting_pairs 3.soup_self_intersecting_pairs_first 3\\+4 3\\+5 3\\+6")
  # One open triangle: the winding number stays below 1/2 (S21).
  bccmis_cli_test(stuff_patch 2 ARGS stuff ${CMAKE_CURRENT_SOURCE_DIR}/stuff/bad/patch.off -L 2 -o x.vtu
                  STDERR_REGEX "patch.off: encloses no volume \\(the winding number is below 1/2 at every lattice vertex\\)")
  bccmis_cli_test(stuff_syntax 2 ARGS stuff ${CMAKE_CURRENT_SOURCE_DIR}/stuff/bad/syntax.obj -o x.vtu
                  STDERR_REGEX "syntax.obj:3:7: ")
endif()

# Reading back the Medit files and drawing them (bccmis render MESH.mesh):
# a two-tetrahedron mesh drawn by hand (tests/stuff/two_tets.mesh).
bccmis_add_gtest(stuff_mesh_picture_tests SOURCES mesh_picture_test.cpp LIBS bccmis::stuff bccmis::d3 bccmis::core
                 DEFINITIONS BCCMIS_TEST_DIR="${CMAKE_CURRENT_LIST_DIR}" LABELS unit)

# The fast path against the reference: the same lattice, graded mesh and
# stuffed mesh, exactly.
bccmis_add_gtest(stuffing_fast_tests SOURCES stuffing_fast_test.cpp position_order_test.cpp LIBS bccmis::stuff bccmis::d3 bccmis::fast
                 LABELS unit)

# Sharp features (spec/stuffing.md S29-S33, spec/cli.md): the cube's 12
# creases and 8 corners found and conformed, checked by the feature layer;
# the options' refusals.
if(TARGET bccmis::stuff_surface)
  bccmis_cli_test(stuff_features_cube 0
                  ARGS stuff ${CMAKE_CURRENT_SOURCE_DIR}/stuff/good/cube.off -L 2 --features --check --stats -q
                  STDOUT_REGEX "feature_edges 12\nfeature_curves 12\nfeature_corners 8\nfeature_corners_conformed 8\nfeature_curves_conformed 12\n.*feature_angle 60\nfeature_distance 0\n")
endif()
bccmis_cli_test(stuff_features_and_no_features 2 ARGS stuff --shape sphere --features --no-features --stats
                STDERR_REGEX "--features excludes --no-features")
bccmis_cli_test(stuff_feature_angle_range 2 ARGS stuff --shape sphere --feature-angle 181 --stats
                STDERR_REGEX "--feature-angle: Value 181 not in range")
bccmis_cli_test(stuff_features_animate 2 ARGS stuff --shape sphere --features --animate 2 -o a.pvd
                STDERR_REGEX "--features, --feature-angle and --crease-cuts apply without --animate")
# spec/cli.md: with --animate the options a moving shape does not take are refused, not ignored.
bccmis_cli_test(stuff_crease_cuts_animate 2 ARGS stuff --shape sphere --crease-cuts 0.25 --animate 2 -o a.pvd
                STDERR_REGEX "--features, --feature-angle and --crease-cuts apply without --animate")
bccmis_cli_test(stuff_memory_limit_animate 2 ARGS stuff --shape sphere --memory-limit 8 --animate 2 -o a.pvd
                STDERR_REGEX "--memory-limit applies without --animate \\(spec/stuffing.md S25")
bccmis_cli_test(stuff_impl_reference_animate 2 ARGS stuff --shape sphere --impl reference --animate 2 -o a.pvd
                STDERR_REGEX "--impl reference applies without --animate")
