# bccmis stuff at the edges (spec/stuffing.md S24-S26): any finite input at
# any scale, the limits refused as bad input (exit 2) with a message naming
# them, empty meshes refused, the sampled Hausdorff figure labelled.
# tests/stuff/extreme/: the octahedron |x|+|y|+|z| <= 1 scaled or moved, and
# a slab 2 x 2 x 0.002. A run on a power-of-two-free scale keeps the unit
# octahedron's 456 tetrahedra at -L 2 (S24: the scale is a power of two near
# the box's extent, the same lattice in local coordinates) and a relative
# volume error below 0.1 in magnitude.
set(_extreme ${CMAKE_CURRENT_SOURCE_DIR}/stuff/extreme)
set(_small_error "tetrahedra 456\n.*volume_rel_error -?0\\.0[0-9]*\n")
bccmis_cli_test(stuff_sphere_r1e300 0 ARGS stuff --shape sphere:r=1e300 -L 2 --stats -q
                STDOUT_REGEX "volume_rel_error -?0\\.0[0-9]*\n")
bccmis_cli_test(stuff_sphere_r1e-300 0 ARGS stuff --shape sphere:r=1e-300 -L 2 --stats -q
                STDOUT_REGEX "volume_rel_error -?0\\.0[0-9]*\n")
# A volume beyond a double is null in --json (the relative error stays finite).
bccmis_cli_test(stuff_sphere_r1e150_json 0 ARGS stuff --shape sphere:r=1e150 -L 2 --stats --json -q
                STDOUT_REGEX "\"volume\": null, \"shape_volume\": null, \"volume_rel_error\": -?0\\.0")
bccmis_cli_test(stuff_sphere_r1e308 2 ARGS stuff --shape sphere:r=1e308 -L 2 -o x.vtu
                STDERR_REGEX "the shape's extent along axis 0 overflows a double \\(from -1e\\+308 to 1e\\+308\\)")
bccmis_cli_test(stuff_cells_2_31 2 ARGS stuff --shape sphere --cells 1048576 -o x.vtu
                STDERR_REGEX "the initial lattice of 1048576 x 1048576 x 1048576 level-0 cubes has 2\\^31 or more")
# S25: refused by the estimate within a second (it ran out of memory after 39 s).
bccmis_cli_test(stuff_level_20 2 ARGS stuff --shape sphere -L 20 -o x.vtu RUN_TIMEOUT 5
                STDERR_REGEX "max level 20 needs about [0-9.e+]+ leaves, .* -L [0-9]+ would fit")
# --memory-limit (S25) on both sides of the sphere's estimate at -L 3
# (about 1.21e4 leaves, 0.023 GB at 1,900 bytes each): 0.0225 refuses naming
# the level that fits (a quarter, 0.0058 GB: -L 2), 0.0235 meshes; 0 is refused.
bccmis_cli_test(stuff_memory_limit_below 2 ARGS stuff --shape sphere -L 3 --memory-limit 0.0225 -o x.vtu
                STDERR_REGEX "max level 3 needs about 1\\.21e\\+04 leaves, 0\\.023 GB by S25.s estimate \\(1900 bytes per estimated leaf\\), more than the 0\\.0225 GB of memory available; -L 2 would fit")
bccmis_cli_test(stuff_memory_limit_above 0 ARGS stuff --shape sphere -L 3 --memory-limit 0.0235 -q -o x.vtu)
bccmis_cli_test(stuff_memory_limit_zero 2 ARGS stuff --shape sphere -L 3 --memory-limit 0 -o x.vtu
                STDERR_REGEX "--memory-limit: '0' is not a positive finite number")
# S26: nothing left of the shape at this level.
bccmis_cli_test(stuff_animate_far 2 ARGS stuff --shape sphere -L 3 --animate 3 --path 1e9,0,0 -o a.pvd
                STDERR_REGEX "sphere r=1: frame 0: the mesh is empty: bad input for this level")
bccmis_cli_test(stuff_animate_notice 0 ARGS stuff --shape sphere -L 2 --animate 1 --stats
                STDERR_REGEX "--animate fits the lattice to the swept box: finest side 0\\.833333333 against 0\\.333333333")
# S26: a mesh on cells coarser than a quarter of the shape's thinnest extent
# is made with a warning. The unit sphere (extent 2): --cells 3 -L 2 gives
# h = 1 (24 tetrahedra, 36 % short), --cells 13 -L 0 gives h = 2/3, both
# warned (under --check too, and still exit 0: a warning, not an error);
# --cells 7 -L 1 gives h = 0.5 = e/4 exactly, no warning.
bccmis_cli_test(stuff_coarse_warning 0 ARGS stuff --shape sphere --cells 3 -L 2 --stats
                STDERR_REGEX "warning: the mesh is coarse \\(the finest cell side 1 against the thinnest extent of the shape's box 2\\); -L 3 would resolve it\n"
                STDOUT_REGEX "\nwarning the mesh is coarse \\(the finest cell side 1 against")
bccmis_cli_test(stuff_coarse_warning_above 0 ARGS stuff --shape sphere --cells 13 -L 0 --check -o x.vtu
                STDERR_REGEX "warning: the mesh is coarse \\(the finest cell side 0\\.666666667 against the thinnest extent of the shape's box 2\\); -L 1 would resolve it\n")
bccmis_cli_test(stuff_coarse_line 0 ARGS stuff --shape sphere --cells 7 -L 1 -o x.vtu
                STDERR_REGEX "^bccmis stuff: sphere r=1: lattice 7 x 7 x 7, max level 1, finest side 0\\.5\n[^\n]* leaves [^\n]*\n[^\n]* tetrahedra [^\n]*\n[^\n]* written to 1 file\n$")
# S13: the sampled Hausdorff distance only with --hausdorff (which implies
# --stats); without it the statistics have no hausdorff line; not with --animate.
bccmis_cli_test(stuff_hausdorff_sampled 0 ARGS stuff --shape sphere -L 2 --hausdorff -q
                STDOUT_REGEX "volume_rel_error [^\n]*\nhausdorff_from_boundary [^\n]*\nhausdorff_from_surface [^\n]*\nhausdorff [^\n]*\nhausdorff_boundary_points [1-9][0-9]*\nhausdorff_surface_samples 20000\nmin_dihedral ")
bccmis_cli_test(stuff_stats_without_hausdorff 0 ARGS stuff --shape sphere -L 2 --stats -q
                STDOUT_REGEX "volume_rel_error [^\n]*\nmin_dihedral ")
bccmis_cli_test(stuff_json_without_hausdorff 0 ARGS stuff --shape sphere -L 2 --json -q
                STDOUT_REGEX "\"volume_rel_error\": [^,]*, \"min_dihedral\"")
bccmis_cli_test(stuff_hausdorff_animate 2 ARGS stuff --shape sphere -L 2 --animate 1 --hausdorff
                STDERR_REGEX "--hausdorff applies without --animate")
if(TARGET bccmis::stuff_surface)
  bccmis_cli_test(stuff_octahedron_x1e150 0 ARGS stuff ${_extreme}/octahedron_x1e150.off -L 2 --stats -q --no-features
                  STDOUT_REGEX "${_small_error}")
  bccmis_cli_test(stuff_octahedron_x1e20 0 ARGS stuff ${_extreme}/octahedron_x1e20.off -L 2 --stats -q --no-features RUN_TIMEOUT 20
                  STDOUT_REGEX "${_small_error}")
  bccmis_cli_test(stuff_octahedron_x1e-300 0 ARGS stuff ${_extreme}/octahedron_x1e-300.off -L 2 --stats -q --no-features
                  STDOUT_REGEX "${_small_error}")
  # S24: at 1e15 coordinates are 0.125 apart; -L 3's finest side is 0.091.
  bccmis_cli_test(stuff_octahedron_at_1e15 2 ARGS stuff ${_extreme}/octahedron_at_1e15.off -L 3 -o x.vtu
                  STDERR_REGEX "is flat once written: coordinates of magnitude 1e\\+15 are spaced 0\\.125 apart, too coarse for the finest side 0\\.0909090909")
  bccmis_cli_test(stuff_slab_empty 2 ARGS stuff ${_extreme}/slab.off -L 3 -o x.vtu
                  STDERR_REGEX "slab.off: 12 triangles: the mesh is empty: bad input for this level \\(the finest cell side [0-9.]+ against the thinnest extent of the shape's box 0\\.002\\); -L [0-9]+ would resolve it")
endif()
if(TARGET bccmis::stuff_surface)
  # S27: a lost component is an error; a changed topology a warning (an error
  # under --check). CGAL's elephant (one closed surface) gives 3 boundary
  # components at -L 3.
  bccmis_cli_test(stuff_lost_component 2 ARGS stuff ${_extreme}/two_octahedra.off -L 3 -o x.vtu
                  STDERR_REGEX "two_octahedra.off: 16 triangles: a component is lost: the mesh's boundary has 1 component where the shape's surface has 2: bad input for this level \\(the finest cell side 0\\.184090909 against the thinnest extent of the thinnest component's box 0\\.1\\); -L 6 would resolve it")
  bccmis_cli_test(stuff_changed_topology 0 ARGS stuff ${bccmis_cgal_data}/data/meshes/elephant.off -L 3 --stats
                  STDERR_REGEX "warning: the mesh's boundary has 3 components where the shape's surface has 1"
                  STDOUT_REGEX "boundary_components 3\n.*warning the mesh's boundary has 3 components where the shape's surface has 1\n")
  bccmis_cli_test(stuff_changed_topology_check 1 ARGS stuff ${bccmis_cgal_data}/data/meshes/elephant.off -L 3 --check -o x.vtu
                  STDERR_REGEX "the mesh's boundary has 3 components where the shape's surface has 1")
  # A clean input whose mesh changes only by non-manifold edges (CGAL's
  # 3torus.off at -L 3: one, and as many components as the surface): a
  # warning, and under --check an error.
  bccmis_cli_test(stuff_nonmanifold_warning 0 ARGS stuff ${bccmis_cgal_data}/data/meshes/3torus.off -L 3 -o x.vtu
                  STDERR_REGEX "warning: the mesh's boundary has 1 non-manifold edges")
  bccmis_cli_test(stuff_nonmanifold_check 1 ARGS stuff ${bccmis_cgal_data}/data/meshes/3torus.off -L 3 --check -q -o x.vtu
                  STDERR_REGEX "^bccmis: mesh 3torus.off: 46 triangles: the mesh's boundary has 1 non-manifold edges \\(parts meeting along a lattice edge; a finer level separates them\\)\n$")
endif()

# S24's map: exactness of the translation, the scale, and a tiny sphere as
# the unit sphere scaled, coordinate for coordinate.
bccmis_add_gtest(stuff_normalisation_tests SOURCES normalisation_test.cpp LIBS bccmis::stuffing LABELS unit)

# S13a: the outputs written while the statistics are computed.
bccmis_add_gtest(stuff_overlapped_write_tests SOURCES overlapped_write_test.cpp LIBS bccmis::stuffing LABELS unit)
