# CLI tests: golden traces (spec/examples, hand-derived expected output),
# exit codes and error messages. Each runs tests/cli/run_cli.cmake.
set(_run ${CMAKE_CURRENT_SOURCE_DIR}/cli/run_cli.cmake)
set(_cli ${CMAKE_CURRENT_SOURCE_DIR}/cli)
set(_examples ${PROJECT_SOURCE_DIR}/spec/examples)

function(bccmis_cli_test name exit)
  cmake_parse_arguments(T "" "STDOUT_FILE;STDOUT_REGEX;STDERR_REGEX;STDIN_FILE;LABEL;RUN_TIMEOUT" "ARGS" ${ARGN})
  set(defs -DEXPECT_EXIT=${exit} -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/cli_work/${name})
  if(T_STDOUT_FILE)
    list(APPEND defs -DEXPECT_STDOUT_FILE=${T_STDOUT_FILE})
  endif()
  if(DEFINED T_STDOUT_REGEX)
    list(APPEND defs "-DEXPECT_STDOUT_REGEX=${T_STDOUT_REGEX}")
  endif()
  if(DEFINED T_STDERR_REGEX)
    list(APPEND defs "-DEXPECT_STDERR_REGEX=${T_STDERR_REGEX}")
  endif()
  if(T_STDIN_FILE)
    list(APPEND defs -DSTDIN_FILE=${T_STDIN_FILE})
  endif()
  if(T_RUN_TIMEOUT)
    list(APPEND defs -DRUN_TIMEOUT=${T_RUN_TIMEOUT})
  endif()
  string(REPLACE ";" "|" cmd "$<TARGET_FILE:bccmis>;${T_ARGS}")
  if(NOT T_LABEL)
    set(T_LABEL cli)
  endif()
  bccmis_add_test(cli.${name} COMMAND ${CMAKE_COMMAND} "-DCMD=${cmd}" ${defs} -P ${_run} LABELS ${T_LABEL})
endfunction()

# One test per case "name|counts|arg;arg;...": cli.<prefix>_<name> runs
# tests/cli/d3/check_svg.py on `bccmis render <args>` and compares the SVG's
# element counts by class. The cases are taken by index: a list would split
# their arguments.
function(bccmis_svg_count_tests prefix)
  math(EXPR last "${ARGC} - 1")
  foreach(i RANGE 1 ${last})
    string(REPLACE "|" ";" parts "${ARGV${i}}")
    list(GET parts 0 name)
    list(GET parts 1 counts)
    list(SUBLIST parts 2 -1 args)
    bccmis_add_test(cli.${prefix}_${name}
             COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${_cli}/d3/check_svg.py $<TARGET_FILE:bccmis> ${counts} ${args}
             LABELS cli)
  endforeach()
endfunction()

# Golden traces: every spec/examples/*.trace against its .expected.
file(GLOB _traces ${_examples}/*.trace)
foreach(trace ${_traces})
  get_filename_component(stem ${trace} NAME_WE)
  bccmis_cli_test(golden.${stem} 0 ARGS replay --check=every --quiet ${trace}
                  STDOUT_FILE ${_examples}/${stem}.expected LABEL golden)
  bccmis_cli_test(golden.fast.${stem} 0 ARGS replay --impl=fast --check=every --quiet ${trace}
                  STDOUT_FILE ${_examples}/${stem}.expected LABEL golden)
endforeach()
bccmis_cli_test(golden.fig2_stdin 0 ARGS replay --quiet - STDIN_FILE ${_examples}/fig2.trace
                STDOUT_FILE ${_examples}/fig2.expected LABEL golden)

# Conventional behaviour.
bccmis_cli_test(help 0 ARGS --help STDOUT_REGEX "replay.*check.*Exit codes")
bccmis_cli_test(replay_help 0 ARGS replay --help STDOUT_REGEX "Example:.*bccmis replay")
bccmis_cli_test(version 0 ARGS --version STDOUT_REGEX "^bccmis ${PROJECT_VERSION}")
bccmis_cli_test(no_subcommand 2 ARGS STDERR_REGEX "subcommand")
bccmis_cli_test(unknown_option 2 ARGS replay --frobnicate x STDERR_REGEX "frobnicate")
bccmis_cli_test(bad_check_mode 2 ARGS replay --check=sometimes ${_examples}/fig2.trace STDERR_REGEX "sometimes")
bccmis_cli_test(summary 0 ARGS replay ${_examples}/fig2.trace
                STDERR_REGEX "2 refine and 0 coarsen commands \\(0 refused\\), 4 checks passed.*9 cells \\(level 0: 1, level 1: 8\\), 17 nodes")

# The top-level help says what the tool does (spec/cli.md); a usage error
# points to the help of the subcommand it was in (spec/cli.md, "Inputs,
# outputs and messages").
bccmis_cli_test(help_describes_tool 0 ARGS --help
                STDOUT_REGEX "^bccmis: adaptive BCC lattices in 2D and 3D [^\n]*tetrahedral meshes of shapes by isosurface stuffing")
bccmis_cli_test(unknown_option_subcommand_help 2 ARGS stuff --frobnicate
                STDERR_REGEX "argument was not expected: --frobnicate\nRun 'bccmis stuff --help' for usage")
bccmis_cli_test(unknown_option_tool_help 2 ARGS --frobnicate STDERR_REGEX "Run 'bccmis --help' for usage")
# Values out of range are named as given (spec/cli.md, "Inputs, outputs and
# messages"): an integer option given 3.5, a size of 0 or inf.
bccmis_cli_test(stuff_level_not_integer 2 ARGS stuff --shape sphere -L 3.5 --stats
                STDERR_REGEX "^bccmis: --max-level: '3\\.5' is not an integer from 0 to 20\nRun 'bccmis stuff --help'")
bccmis_cli_test(replay_depth_out_of_range 2 ARGS replay --depth 9 ${_examples}/fig2.trace
                STDERR_REGEX "^bccmis: --depth: '9' is not an integer from 1 to 5\n")
bccmis_cli_test(explore_threads_negative 2 ARGS explore 1 1 2 --threads -1
                STDERR_REGEX "^bccmis: --threads: '-1' is not a non-negative integer\nRun 'bccmis explore --help'")
bccmis_cli_test(stuff_size_zero 2 ARGS stuff --shape sphere --size 0 --stats
                STDERR_REGEX "^bccmis: --size: '0' is not a positive finite number\nRun 'bccmis stuff --help'")
bccmis_cli_test(stuff_size_infinite 2 ARGS stuff --shape sphere --size inf --stats
                STDERR_REGEX "^bccmis: --size: 'inf' is not a positive finite number\n")
# spec/cli.md, stuff: --size and -L both choose the finest level; --json
# implies --stats and prints with -o too (stuff and mesh).
bccmis_cli_test(stuff_size_and_level 2 ARGS stuff --shape sphere --size 0.1 -L 3 --stats
                STDERR_REGEX "^bccmis: --size and -L,--max-level both choose the finest level: give one\n")
bccmis_cli_test(stuff_json_alone 0 ARGS stuff --shape sphere -L 2 --cells 3 --json -o sphere.mesh -q
                STDOUT_REGEX "^{\"shape\": \"sphere r=1\", \"leaves\": [0-9]+,.*\"tetrahedra\": [1-9][0-9]*,")
bccmis_cli_test(mesh_json_alone 0 ARGS mesh ${_examples}/d3/face_refined.state --json
                STDOUT_REGEX "\"tetrahedra\": 168")
# Triangle-mesh inputs (spec/cli.md, stuff; spec/stuffing.md, "Formats"):
# standard input ('-', the format sniffed or given), --format over the
# extension, a directory, OFF text named .stl, text that is no STL.
if(TARGET bccmis::stuff_surface)
  bccmis_cli_test(stuff_stdin_sniffed 0 ARGS stuff - -L 1 --cells 6 -o cube.mesh
                  STDIN_FILE ${PROJECT_SOURCE_DIR}/tests/stuff/good/cube.off
                  STDERR_REGEX "^bccmis stuff: mesh stdin: 12 triangles: .* tetrahedra written to 1 file\n$")
  bccmis_cli_test(stuff_stdin_format 0 ARGS stuff - --format obj -L 1 --cells 6 -o cube.mesh
                  STDIN_FILE ${PROJECT_SOURCE_DIR}/tests/stuff/good/cube_quads.obj
                  STDERR_REGEX "^bccmis stuff: mesh stdin: 12 triangles: .* tetrahedra written to 1 file\n$")
  bccmis_cli_test(stuff_stdin_unknown 2 ARGS stuff - --stats STDIN_FILE ${_cli}/words.stl
                  STDERR_REGEX "^bccmis: stdin: cannot tell the format of the content \\(text\\): expected OFF, OBJ, PLY or STL")
  bccmis_cli_test(stuff_stdin_wrong_format 2 ARGS stuff - --format stl --stats
                  STDIN_FILE ${_cli}/tetrahedron_off_text.stl
                  STDERR_REGEX "^bccmis: stdin: the content is OFF text, not STL \\(to read it as OFF: --format off\\)\n")
  bccmis_cli_test(stuff_off_named_stl 2 ARGS stuff ${_cli}/tetrahedron_off_text.stl --stats
                  STDERR_REGEX "tetrahedron_off_text.stl: the content is OFF text, not STL \\(to read it as OFF: --format off\\)\n")
  bccmis_cli_test(stuff_format_over_extension 0 ARGS stuff ${_cli}/tetrahedron_off_text.stl --format off -L 2 -o tet.mesh
                  STDERR_REGEX "^bccmis stuff: mesh [^\n]*tetrahedron_off_text.stl: 4 triangles: .* tetrahedra written to 1 file\n$")
  bccmis_cli_test(stuff_text_stl 2 ARGS stuff ${_cli}/words.stl --stats
                  STDERR_REGEX "words.stl:1:1: expected 'solid', found 'a'\n")
  bccmis_cli_test(stuff_directory 2 ARGS stuff ${_cli} --stats STDERR_REGEX "cli: is a directory, expected a file\n")

  # PLY (spec/formats.md, "PLY input"): cube.off's vertices and triangles as
  # ASCII PLY (6 quads whose fans are cube.off's triangles, normals and colours
  # skipped) and as binary big-endian PLY give cube.off's mesh, byte for byte;
  # binary PLY on standard input is told by its first line.
  set(_good ${PROJECT_SOURCE_DIR}/tests/stuff/good)
  foreach(_in cube.off cube.ply cube_big_endian.ply)
    bccmis_cli_test(stuff_ply_same_mesh.${_in} 0 ARGS stuff ${_good}/${_in} -L 2 --cells 4 -q -o cube.vtu)
    set_tests_properties(cli.stuff_ply_same_mesh.${_in} PROPERTIES FIXTURES_SETUP cli_stuff_ply_same_mesh)
  endforeach()
  foreach(_in cube.ply cube_big_endian.ply)
    bccmis_add_test(cli.stuff_ply_same_mesh_as_off.${_in}
             COMMAND ${CMAKE_COMMAND} -E compare_files ${CMAKE_CURRENT_BINARY_DIR}/cli_work/stuff_ply_same_mesh.cube.off/cube.vtu
                     ${CMAKE_CURRENT_BINARY_DIR}/cli_work/stuff_ply_same_mesh.${_in}/cube.vtu
             LABELS cli PROPERTIES FIXTURES_REQUIRED cli_stuff_ply_same_mesh)
  endforeach()
  # spec/stuffing.md S22: cube.off written one triangle at a time is welded
  # (28 of its 36 vertices repeat an earlier one) and meshed as cube.off.
  bccmis_cli_test(stuff_unwelded 0 ARGS stuff ${_good}/cube_unwelded.off -L 2 --cells 4 -o cube.vtu
                  STDERR_REGEX "^bccmis stuff: [^\n]*cube_unwelded.off: 28 repeated vertices welded \\(the coordinates of an earlier vertex\\)\n")
  bccmis_add_test(cli.stuff_unwelded_same_mesh_as_off
           COMMAND ${CMAKE_COMMAND} -E compare_files ${CMAKE_CURRENT_BINARY_DIR}/cli_work/stuff_ply_same_mesh.cube.off/cube.vtu
                   ${CMAKE_CURRENT_BINARY_DIR}/cli_work/stuff_unwelded/cube.vtu
           LABELS cli PROPERTIES FIXTURES_REQUIRED "cli_stuff_ply_same_mesh;cli_stuff_unwelded")
  set_tests_properties(cli.stuff_unwelded PROPERTIES FIXTURES_SETUP cli_stuff_unwelded)
  bccmis_cli_test(stuff_ply_point_cloud 2 ARGS stuff ${_cli}/point_cloud.ply --stats
                  STDERR_REGEX "point_cloud.ply:8:1: no element 'face' in the header \\(a point cloud is no surface\\)\n$")
  bccmis_cli_test(stuff_ply_stdin_sniffed 0 ARGS stuff - -L 1 --cells 6 -o cube.mesh STDIN_FILE ${_good}/cube_big_endian.ply
                  STDERR_REGEX "^bccmis stuff: mesh stdin: 12 triangles: .* tetrahedra written to 1 file\n$")
  # spec/cli.md, --crease-cuts (stuffing.md S35.7-S35.8): not with
  # --no-features, for any DELTA; DELTA in [0, 1], both ends accepted, the
  # doubles just outside refused; with DELTA above 0 --stats counts the
  # vertices placed and kept.
  foreach(_delta 0.25 0)
    bccmis_cli_test(stuff_crease_cuts_no_features.${_delta} 2 ARGS stuff ${_good}/cube.off --crease-cuts ${_delta}
                    --no-features --stats STDERR_REGEX "^bccmis: --crease-cuts excludes --no-features\nRun 'bccmis stuff --help'")
  endforeach()
  foreach(_delta -0.01 -4.9e-324 1.0000000000000002 2)
    bccmis_cli_test(stuff_crease_cuts_out_of_range.${_delta} 2 ARGS stuff ${_good}/cube.off -L 1 --stats
                    --crease-cuts ${_delta}
                    STDERR_REGEX "^bccmis: --crease-cuts: Value ${_delta} not in range 0\\.000000 to 1\\.000000\nRun 'bccmis stuff --help'")
  endforeach()
  bccmis_cli_test(stuff_crease_cuts_one 0 ARGS stuff ${_good}/cube.off -L 2 --cells 4 --stats -q --crease-cuts 1
                  STDOUT_REGEX "\nfeature_curves_conformed [0-9]+\ncrease_cuts_placed [0-9]+\ncrease_cuts_kept [0-9]+\n")
  bccmis_cli_test(stuff_crease_cuts_zero 0 ARGS stuff ${_good}/cube.off -L 2 --cells 4 --stats -q --crease-cuts 0
                  STDOUT_REGEX "\nfeature_curves_conformed [0-9]+\nvolume ")
endif()

# Bad input: exit 2 with file:line:column.
bccmis_cli_test(bad_lattice 2 ARGS replay ${_cli}/bad_lattice.trace
                STDERR_REGEX "bad_lattice.trace:2:9: lattice width W must be >= 1, got 0")
bccmis_cli_test(bad_command 2 ARGS replay ${_cli}/bad_command.trace
                STDERR_REGEX "bad_command.trace:3:1: unknown command 'split'")
bccmis_cli_test(missing_file 2 ARGS replay ${_cli}/no-such-file.trace STDERR_REGEX "no-such-file.trace: cannot open")
bccmis_cli_test(directory 2 ARGS replay ${_cli} STDERR_REGEX "is a directory")
bccmis_cli_test(check_parse_error 2 ARGS check ${_examples}/fig2.trace STDERR_REGEX "fig2.trace:1:1: expected 'bccmis-state 1'")

# check: valid, violated.
bccmis_cli_test(check_valid 0 ARGS check ${_cli}/../../spec/examples/initial_1_1_0.state STDOUT_REGEX "valid")
bccmis_cli_test(check_violation 1 ARGS check ${_cli}/broken.state STDERR_REGEX "broken.state: .*\\(2, 2\\)")

# Output files are written (atomically: no temporary left behind).
bccmis_cli_test(output_files 0 ARGS replay --quiet --log out.log --state out.state ${_examples}/fig2.trace)
bccmis_add_test(cli.output_files_content
         COMMAND ${CMAKE_COMMAND} -E compare_files ${CMAKE_CURRENT_BINARY_DIR}/cli_work/output_files/out.log
                 ${_cli}/fig2.log
         LABELS cli PROPERTIES FIXTURES_REQUIRED cli_output_files)
set_tests_properties(cli.output_files PROPERTIES FIXTURES_SETUP cli_output_files)

# Conformance harness: the reference against itself agrees; each deliberately
# wrong implementation (tests/conformance/*.sh) is caught and shrunk to <= 5
# operations.
set(_conf ${CMAKE_CURRENT_SOURCE_DIR}/conformance)
bccmis_cli_test(conformance.self 0
  ARGS conformance --impl "$<TARGET_FILE:bccmis> replay --quiet --check=none" --traces ${_examples} --random 100 --seed 1
       RUN_TIMEOUT 240
  STDOUT_REGEX "all 103 traces agree")
set(_minimal "minimal trace \\(([1-5]) operations?\\)")
bccmis_cli_test(conformance.wrong_refusal_code 1
  ARGS conformance --impl "sh ${_conf}/wrong_refusal_code.sh $<TARGET_FILE:bccmis>" --traces ${_examples} --random 50 --seed 1
       --dim 2
  STDOUT_REGEX "${_minimal}.*refine [0-9]+ [0-9]+ refused max-level', implementation '[^']*refused coarser-neighbor")
bccmis_cli_test(conformance.missing_boundary_junction 1
  ARGS conformance --impl "sh ${_conf}/missing_boundary_junction.sh $<TARGET_FILE:bccmis>" --random 50 --seed 1 --dim 2
  STDOUT_REGEX "${_minimal}.*only in A: node \\([0-9]+, 0\\)")
bccmis_cli_test(conformance.crash 1
  ARGS conformance --impl "sh ${_conf}/crash_on_coarsen.sh $<TARGET_FILE:bccmis>" --random 50 --seed 1
  STDOUT_REGEX "${_minimal}.*crashed: signal 11")
bccmis_cli_test(conformance.timeout 1
  ARGS conformance --impl "sh ${_conf}/hang_on_long_traces.sh $<TARGET_FILE:bccmis>" --random 20 --seed 1 --timeout 1.5
  STDOUT_REGEX "minimal trace \\(4 operations\\).*timed out")
# 3D: the reference conforms on 3D traces alone and mixed with 2D ones; the
# two wrong 3D implementations pass 2D traces through unchanged, so a mixed
# run must reach its 3D traces to catch them.
bccmis_cli_test(conformance.self_3d 0
  ARGS conformance --impl "$<TARGET_FILE:bccmis> replay --quiet --check=none" --traces ${_examples}/d3 --random 100
       --seed 1 --dim 3 RUN_TIMEOUT 240
  STDOUT_REGEX "all 103 traces agree \\(3 bundled, 100 random: 0 2D and 100 3D, seed 1\\)")
bccmis_cli_test(conformance.self_mixed 0
  ARGS conformance --impl "$<TARGET_FILE:bccmis> replay --quiet --check=none" --traces ${_examples}/d3 --random 100
       --seed 2 --dim mixed RUN_TIMEOUT 240
  STDOUT_REGEX "all 103 traces agree \\(3 bundled, 100 random: 50 2D and 50 3D, seed 2\\)")
set(_point3 "\\([0-9]+, [0-9]+, [0-9]+\\)")
bccmis_cli_test(conformance.d3_junction_missing_cell 1
  ARGS conformance --impl "sh ${_conf}/junction3_missing_cell.sh $<TARGET_FILE:bccmis>" --random 50 --seed 1
  STDOUT_REGEX "DISAGREE on random 3D trace.*${_minimal}:\nlattice [0-9]+ [0-9]+ [0-9]+ [0-9]+\n.*neighbors of ${_point3}: only in A: ${_point3}. only in B: none")
bccmis_cli_test(conformance.d3_coarsen_keeps_face_center 1
  ARGS conformance --impl "sh ${_conf}/coarsen3_keeps_face_center.sh $<TARGET_FILE:bccmis>" --random 50 --seed 1 --dim 3
       --view d3
  STDOUT_REGEX "${_minimal}:\nlattice [0-9]+ [0-9]+ [0-9]+ [0-9]+\n.*only in B: node ${_point3}.*files of the 3D disagreement: d3.trace")
# --view on a 3D disagreement: the minimal trace and both states, as files
# that the CLI reads back (the states differ by the kept face center).
bccmis_add_test(cli.conformance.d3_view_files
         COMMAND ${CMAKE_COMMAND} "-DCMD=$<TARGET_FILE:bccmis>|diff|../conformance.d3_coarsen_keeps_face_center/d3.reference.state|../conformance.d3_coarsen_keeps_face_center/d3.impl.state"
                 -DEXPECT_EXIT=1 "-DEXPECT_STDOUT_REGEX=only in B: node ${_point3}"
                 -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/cli_work/d3_view_files -P ${_run}
         LABELS cli PROPERTIES FIXTURES_REQUIRED cli_d3_disagreement)
bccmis_add_test(cli.conformance.d3_view_trace
         COMMAND ${CMAKE_COMMAND} "-DCMD=$<TARGET_FILE:bccmis>|replay|--quiet|--log|d3.log|../conformance.d3_coarsen_keeps_face_center/d3.trace"
                 -DEXPECT_EXIT=0 -DEXPECT_STDOUT_FILE=${CMAKE_CURRENT_BINARY_DIR}/cli_work/conformance.d3_coarsen_keeps_face_center/d3.reference.state
                 -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/cli_work/d3_view_trace -P ${_run}
         LABELS cli PROPERTIES FIXTURES_REQUIRED cli_d3_disagreement)
set_tests_properties(cli.conformance.d3_coarsen_keeps_face_center PROPERTIES FIXTURES_SETUP cli_d3_disagreement)
bccmis_cli_test(conformance.bad_dim 2 ARGS conformance --impl true --dim 4 STDERR_REGEX "--dim")
bccmis_cli_test(view_3d_trace 2 ARGS view ${_examples}/d3/face.trace -o face.html
                STDERR_REGEX "face.trace:7:1: a 3D trace \\('lattice W H D L'\\): the viewer draws 2D lattices only")
bccmis_cli_test(conformance.no_impl 2 ARGS conformance STDERR_REGEX "impl")
bccmis_cli_test(conformance.bad_trace_dir 2 ARGS conformance --impl true --traces ${_cli}/no-such-dir STDERR_REGEX "not a directory")

# More verbs: diff, stats, render.
bccmis_cli_test(diff_equal 0 ARGS diff ${_examples}/initial_1_1_0.state ${_examples}/initial_1_1_0.state)
bccmis_cli_test(diff_different 1 ARGS diff ${_examples}/initial_1_1_0.state ${_cli}/broken.state
                STDOUT_REGEX "neighbors of \\(2, 2\\): only in A: \\(1, 1\\); only in B: none")
# fig2 by hand: 1 + 8 cells, 17 nodes, one junction (4,2); 5 + 8*4 = 37 stored
# edges; Euler: V - E + F = 26 - (37 + hull) + (37 + 1) = 2 gives 25 hull edges.
bccmis_cli_test(stats_fig2 0 ARGS stats --from-trace ${_examples}/fig2.trace
                STDOUT_REGEX "cells 9\ncells_level_0 1\ncells_level_1 8\nnodes 17\njunctions 1\ngraph_edges 37\nhull_edges 25\ntriangles 37\n")
bccmis_cli_test(render_fig2 0 ARGS render --from-trace ${_examples}/fig2.trace -o fig2.svg)
bccmis_add_test(cli.render_fig2_content
         COMMAND ${CMAKE_COMMAND} -DFILE=${CMAKE_CURRENT_BINARY_DIR}/cli_work/render_fig2/fig2.svg -P ${_cli}/check_svg.cmake
         LABELS cli PROPERTIES FIXTURES_REQUIRED cli_render_fig2)
set_tests_properties(cli.render_fig2 PROPERTIES FIXTURES_SETUP cli_render_fig2)

# explore: the counts are known independently (tests/model: 1 + 2^4 = 17 for
# one cell two levels deep, 2^4 = 16 for four cells one level deep).
bccmis_cli_test(explore_112 0 ARGS explore 1 1 2 --no-progress STDOUT_REGEX "^explore 1 1 2: 17 states, 33 refine edges, 33 coarsen edges, .* ok")
bccmis_cli_test(explore_221_json 0 ARGS explore 2 2 1 --json STDOUT_REGEX "\"states\": 16, .*\"ok\": true")
bccmis_cli_test(explore_bad_lattice 2 ARGS explore 1 1 -1 STDERR_REGEX "L must be >= 0")
# replay --json: fig3 by hand (spec/examples/fig3.expected): three decisions, 6 cells, 13 nodes.
bccmis_cli_test(replay_json 0 ARGS replay --json ${_examples}/fig3.trace
  STDOUT_REGEX "\"decisions\": \\[\"refine 10 2 ok\", \"refine 6 2 ok\", \"coarsen 6 2 ok\"\\].*\"cells\": 6, \"nodes\": 13, \"state\": \"bccmis-state 1\\\\nlattice 3 1 1\\\\n")

# Messages for common slips (spec/cli.md, "Messages").
bccmis_cli_test(did_you_mean 2 ARGS replya ${_examples}/fig2.trace STDERR_REGEX "unknown subcommand 'replya': did you mean 'replay'\\?")
bccmis_cli_test(unknown_subcommand_lists 2 ARGS frobnicate STDERR_REGEX "unknown subcommand 'frobnicate' \\(subcommands: replay check")
bccmis_cli_test(check_given_a_trace 2 ARGS check ${_examples}/fig2.trace
                STDERR_REGEX "fig2.trace:1:1: expected 'bccmis-state 1'.*. this is a trace, not a canonical state: replay it with 'bccmis replay")
bccmis_cli_test(stats_given_a_trace 2 ARGS stats ${_examples}/fig2.trace STDERR_REGEX "this is a trace, not a canonical state: give --from-trace")
bccmis_cli_test(replay_given_a_state 2 ARGS replay ${_examples}/initial_1_1_0.state
                STDERR_REGEX "initial_1_1_0.state:1:1: unknown command 'bccmis-state'.*. this is a canonical state, not a trace: check it with 'bccmis check'")
bccmis_cli_test(missing_file_says_why 2 ARGS replay ${_cli}/no-such-file.trace
                STDERR_REGEX "no-such-file.trace: cannot open for reading: No such file or directory")

# Negative counts are usage errors.
bccmis_cli_test(explore_negative_threads 2 ARGS explore 1 1 1 --threads -1 STDERR_REGEX "--threads")
bccmis_cli_test(explore_negative_max_states 2 ARGS explore 1 1 1 --max-states -5 STDERR_REGEX "--max-states")
bccmis_cli_test(conformance_negative_seed 2 ARGS conformance --impl true --seed -1 STDERR_REGEX "--seed")
bccmis_cli_test(heightfield_negative_seed 2 ARGS heightfield ${PROJECT_SOURCE_DIR}/apps/samples/terrain128.pgm --seed -1
                STDERR_REGEX "--seed")
bccmis_cli_test(conformance_negative_random 2 ARGS conformance --impl true --random -1 STDERR_REGEX "--random")

# explore: a partial run is not a failure; an unreachable space is refused
# with its estimate (2 x 1 cells, L = 3: at least 2^(2*4^2) = 2^32 states).
bccmis_cli_test(explore_partial 0 ARGS explore 1 1 2 --max-states 5 --no-progress
                STDOUT_REGEX "^explore 1 1 2: 5 states, .* incomplete")
bccmis_cli_test(explore_beyond_reach 2 ARGS explore 2 1 3
                STDERR_REGEX "explore: lattice 2 1 3 has at least 4294967296 reachable states \\(at most [0-9]+\\), beyond reach.*--max-states")
bccmis_cli_test(explore_beyond_reach_partial 0 ARGS explore 2 1 3 --max-states 3 --no-progress STDOUT_REGEX "3 states, .*incomplete")
bccmis_cli_test(explore_help_example 0 ARGS explore --help STDOUT_REGEX "bccmis explore 1 1 2 .*bccmis explore 2 2 1 --json")

# conformance: the default run checks random traces; an implementation that
# cannot be run is a harness error.
bccmis_cli_test(conformance.default_random 0 ARGS conformance --impl "$<TARGET_FILE:bccmis> replay --quiet --check=none"
                RUN_TIMEOUT 240 STDOUT_REGEX "all 100 traces agree \\(0 bundled, 100 random: 50 2D and 50 3D, seed 1\\)")
bccmis_cli_test(conformance.not_found 2 ARGS conformance --impl ./no-such-implementation --random 5
                STDERR_REGEX "conformance: cannot run the implementation './no-such-implementation' \\(exit status 127, command not found\\)")
bccmis_cli_test(conformance.not_executable 2 ARGS conformance --impl ${_cli}/fig2.log --random 5
                STDERR_REGEX "cannot run the implementation .*\\(exit status 126, not executable\\)")
# The README's example, as written, with bccmis on the PATH. Half of its 500
# random traces are 3D: about 15 s in Debug, several times that under the
# sanitizers (228 s on a loaded machine), so the run may take up to 600 s.
bccmis_add_test(cli.conformance.readme_example
         COMMAND ${CMAKE_COMMAND} "-DCMD=env|PATH=$<TARGET_FILE_DIR:bccmis>:$ENV{PATH}|bccmis|conformance|--impl|bccmis replay --quiet --check=none|--random|500|--seed|7"
                 -DEXPECT_EXIT=0 "-DEXPECT_STDOUT_REGEX=all 500 traces agree" -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/cli_work/readme_example
                 -DRUN_TIMEOUT=600 -P ${_run}
         LABELS cli TIMEOUT 700)

# spec/cli.md names exactly the options of every subcommand's --help; the
# self-test plants mismatches and requires that they are caught.
find_package(Python3 COMPONENTS Interpreter QUIET)
if(Python3_FOUND)
  bccmis_add_test(cli.spec COMMAND Python3::Interpreter ${_cli}/check_cli_spec.py $<TARGET_FILE:bccmis> ${PROJECT_SOURCE_DIR}/spec/cli.md
    LABELS cli spec)
  bccmis_add_test(cli.spec_self_test
           COMMAND Python3::Interpreter ${_cli}/check_cli_spec.py $<TARGET_FILE:bccmis> ${PROJECT_SOURCE_DIR}/spec/cli.md --self-test
           LABELS cli spec)
endif()

# 3D (spec/formats.md, "3D extension"): the hand-derived examples of
# spec/examples/d3 through replay with every state checked (layers 1-4 and
# the mesh layer), the readers of either dimension, and the 3D counts.
file(GLOB _traces3 ${_examples}/d3/*.trace)
foreach(trace ${_traces3})
  get_filename_component(stem ${trace} NAME_WE)
  bccmis_cli_test(golden.d3.${stem} 0 ARGS replay --check=every --depth 5 --quiet ${trace}
                  STDOUT_FILE ${_examples}/d3/${stem}.expected LABEL golden)
endforeach()
# --impl fast on a 3D trace runs the fast 3D lattice: the same output byte for byte.
foreach(trace ${_traces3})
  get_filename_component(stem ${trace} NAME_WE)
  bccmis_cli_test(d3_replay_fast.${stem} 0 ARGS replay --impl fast --check=every --depth 5 --quiet ${trace}
                  STDOUT_FILE ${_examples}/d3/${stem}.expected LABEL golden)
endforeach()
bccmis_cli_test(d3_replay_summary 0 ARGS replay ${_examples}/d3/face.trace
                STDERR_REGEX "2 refine and 1 coarsen commands \\(1 refused\\), 3 checks passed.*2 cells \\(level 0: 2\\), 12 nodes")
bccmis_cli_test(d3_check_valid 0 ARGS check --depth 5 ${_examples}/d3/face_refined.state
                STDOUT_REGEX "valid \\(depth 5\\): 9 cells \\(level 0: 1, level 1: 8\\), 31 nodes")
bccmis_cli_test(d3_check_broken 1 ARGS check ${_cli}/broken3d.state
                STDERR_REGEX "symmetry: center \\(12, 4, 4\\) lists node \\(8, 4, 4\\), which does not list it")
bccmis_cli_test(d3_diff_different 1 ARGS diff ${_examples}/d3/face_refined.state ${_cli}/broken3d.state
                STDOUT_REGEX "^neighbors of \\(8, 4, 4\\): only in A: \\(12, 4, 4\\); only in B: none\n$")
bccmis_cli_test(d3_diff_equal 0 ARGS diff ${_examples}/d3/face_refined.state ${_examples}/d3/face_refined.state)
bccmis_cli_test(d3_diff_dimensions 1 ARGS diff ${_examples}/initial_1_1_0.state ${_examples}/d3/face_refined.state
                STDOUT_REGEX "^dimension: A is a 2D state, B is a 3D state\n$")
bccmis_cli_test(d3_check_given_a_trace 2 ARGS check ${_examples}/d3/root.trace
                STDERR_REGEX "root.trace:1:[0-9]+: .*; this is a trace, not a canonical state")
# face_refined by hand (spec/lattice3d.md §7): 8 children and the coarse cube;
# nodes: the 27 of [0,8]^3 plus the 4 far corners of the coarse cube = 31;
# junctions: the shared face's center and its 4 midpoints; stored edges
# 8*8 + 13 = 77; green edges: the 54 grid segments of [0,8]^3 plus the coarse
# cube's 8 edges off the shared face = 62; tetrahedra: spec/mesh3d.md (168).
bccmis_cli_test(d3_stats 0 ARGS stats ${_examples}/d3/face_refined.state
                STDOUT_REGEX "^lattice 2 1 1 2\ncells 9\ncells_level_0 1\ncells_level_1 8\nnodes 31\njunctions 5\ngraph_edges 77\ngreen_edges 62\ntetrahedra 168\n")
# root by hand: 8 cells at level 1, the 27 nodes of {0,2,4}^3, no junction,
# 64 stored edges, 54 grid segments, 144 tetrahedra (spec/mesh3d.md).
bccmis_cli_test(d3_stats_json 0 ARGS stats --from-trace --json ${_examples}/d3/root.trace
                STDOUT_REGEX "^\\{\"dimension\": 3, \"lattice\": \\[1, 1, 1, 1\\], \"cells\": 8, \"cells_per_level\": \\{\"1\": 8\\}, \"nodes\": 27, \"junctions\": 0, \"graph_edges\": 64, \"green_edges\": 54, \"tetrahedra\": 144, ")
bccmis_cli_test(d3_replay_json 0 ARGS replay --json ${_examples}/d3/root.trace
                STDOUT_REGEX "\"decisions\": \\[\"refine 2 2 2 ok\", \"refine 1 1 1 refused max-level\"\\].*\"cells\": 8, \"nodes\": 27, \"state\": \"bccmis-state 1\\\\nlattice 1 1 1 1\\\\n")
# bccmis mesh (spec/mesh3d.md §6, hand counts): root refined: 59 vertices,
# 144 tetrahedra, 96 boundary triangles, angles in [45, 90]; face_refined:
# 65, 168, 104, [45, 120].
bccmis_cli_test(d3_mesh_stats_root 0 ARGS mesh --stats ${_examples}/d3/root.trace
                STDOUT_REGEX "^vertices 59\ntetrahedra 144\nboundary_triangles 96\nmin_dihedral 45.000000\nmax_dihedral 90.000000\n")
bccmis_cli_test(d3_mesh_stats_json 0 ARGS mesh --stats --json --check ${_examples}/d3/face_refined.state
                STDOUT_REGEX "^\\{\"vertices\": 65, \"tetrahedra\": 168, \"boundary_triangles\": 104, \"min_dihedral\": 45.000000, \"max_dihedral\": 120.000000, \"dihedral_histogram\": \\{")
bccmis_cli_test(d3_mesh_files 0 ARGS mesh ${_examples}/d3/face_refined.state -o face.vtu -o face.msh -o face.mesh
                STDERR_REGEX "65 vertices, 168 tetrahedra written to 3 files")
bccmis_cli_test(d3_mesh_2d_refused 2 ARGS mesh -o fig2.vtu ${_examples}/fig2.trace
                STDERR_REGEX "fig2.trace: a 2D lattice; bccmis mesh writes the tetrahedra of 3D lattices")
bccmis_cli_test(d3_mesh_unknown_format 2 ARGS mesh ${_examples}/d3/root.trace -o root.obj
                STDERR_REGEX "mesh output 'root.obj': unknown format; the extension names it")
bccmis_cli_test(d3_mesh_nothing_to_do 2 ARGS mesh ${_examples}/d3/root.trace STDERR_REGEX "nothing to do")
bccmis_cli_test(d3_mesh_invalid_state 1 ARGS mesh --stats ${_cli}/broken3d.state STDERR_REGEX "symmetry: center \\(12, 4, 4\\)")
bccmis_cli_test(d3_replay_mesh_2d_refused 2 ARGS replay --mesh fig2.vtu ${_examples}/fig2.trace
                STDERR_REGEX "--mesh writes the tetrahedra of 3D lattices; this trace is 2D")
# The CLI's mesh files read by meshio and gmsh (counts, kinds, levels and the
# exact volume 6 * W*H*D*S^3; spec/mesh3d.md M10, M20-M22).
bccmis_add_test(cli.d3_mesh_readers
         COMMAND ${BCCMIS_SYSTEM_PYTHON3} ${_cli}/mesh_cli_readers.py $<TARGET_FILE:bccmis> ${_examples}/d3/face_refined.state
         LABELS cli)

# bccmis render on 3D states (spec/cli.md, render): the SVG parsed as XML and
# its elements counted by class (tests/cli/d3/check_svg.py). The box panel draws
# the boundary triangles on the three visible faces y = 0, z = max, x = max.
# face_refined by hand (S = 8, box 16 x 8 x 8; spec/mesh3d.md M18): on y = 0
# and on z = 8 the 4 children's faces have 4 triangles each and the coarse
# leaf's face 5 (its edge x = 8 has the midpoint node), 21 per face; x = 16
# is the coarse leaf's face alone, 4: tri = 46 of the 104. Green edges on y = 0:
# the lines z = 0 and z = 8 have 3 segments (0-4, 4-8, 8-16), z = 4 has 2, the
# lines x = 0, 4, 8 have 2 each and x = 16 has 1: 15; z = 8 the same, 15; the
# edge y = 0, z = 8 (3 segments) is on both; x = 16 adds its 2 edges y = 8 and
# z = 0: 15 + 15 - 3 + 2 = 29. The slice z = 2 (a plane through the children's
# centers) cuts the 4 children with center z = 2 and the coarse leaf: 5 leaf
# rectangles, 4 centers on the plane, no node (the nodes have z in {0, 4, 8}).
# The default slice z = 4 is the children's face plane: the half-open rule
# takes the 4 children above it and the coarse leaf (5), whose center (12,4,4)
# is on it; nodes on z = 4: the 9 of {0,4,8}^2; junctions among them:
# (8,4,4) with |N| = 5, (8,0,4) and (8,8,4) with |N| = 3.
set(_face3 ${_examples}/d3/face_refined.state)
bccmis_svg_count_tests(d3_render
    "face_z2|tri=46,green=29,slice-trace=2,leaf=5,center=4,node=0,junction=0,legend=2|${_face3};--slice;z=2"
    "face_default|tri=46,green=29,slice-trace=2,leaf=5,center=1,node=9,junction=3|${_face3}"
    # root refined (S = 4, box 4^3): each visible face has 4 quarter faces of
    # 4 triangles (48 of 96) and a 2 x 2 grid of 12 green segments, 2 on each
    # of the 3 edges shared by two visible faces: 36 - 6 = 30. The slice x = 1
    # cuts the 4 children with center x = 1, all 4 centers on it, no node.
    "root_x1|tri=48,green=30,slice-trace=2,leaf=4,center=4,node=0,junction=0,legend=1|--from-trace;${_examples}/d3/root.trace;--slice;x=1")
bccmis_cli_test(d3_render_slice_outside 2 ARGS render ${_face3} --slice z=9 -o face.svg
                STDERR_REGEX "--slice 'z=9': outside the box: z in \\[0, 8\\]")
bccmis_cli_test(d3_render_slice_bad_axis 2 ARGS render ${_face3} --slice w=2 -o face.svg
                STDERR_REGEX "--slice 'w=2': expected AXIS=VALUE with AXIS x, y or z")
bccmis_cli_test(d3_render_slice_2d 2 ARGS render --from-trace ${_examples}/fig2.trace --slice z=1 -o fig2.svg
                STDERR_REGEX "fig2.trace: a 2D lattice; --slice applies to 3D states")
# docs/d3-face-refined.svg is the README's command's output as drawn now.
bccmis_add_test(cli.d3_render_docs_current
         COMMAND sh -c "\"$1\" render spec/examples/d3/face_refined.state -o - | cmp - docs/d3-face-refined.svg" sh
                 $<TARGET_FILE:bccmis>
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
         LABELS cli)

# bccmis render on a tetrahedral Medit mesh (spec/cli.md, render), counted as
# above. tests/stuff/two_tets.mesh by hand (tests/stuff/mesh_picture_test.cpp): 4 of
# its 6 boundary triangles face the viewer (direction (1, -2, 1.5)), 2 of each
# level, one legend entry per level; the cut z = 0.25 removes the first
# tetrahedron and leaves 2 facing triangles of the second; the 12 dihedral
# angles are 8 of 60 degrees (bin 12) and 4 of 90 (bin 18): 2 bars.
set(_two_tets ${PROJECT_SOURCE_DIR}/tests/stuff/two_tets.mesh)
bccmis_svg_count_tests(mesh_render
    "whole|tri=4,cut-tri=0,legend=2|${_two_tets}"
    "cut|tri=4,cut-tri=2,legend=2|${_two_tets};--slice;z=0.25"
    "histogram|bar=2,min=1,max=1,tri=0,legend=0|${_two_tets};--histogram")
# The lattice's own mesh (bccmis mesh face_refined.state -o face.mesh): the
# viewer sees exactly the box faces y = 0, z = 8 and x = 16 (outward normals
# with a positive component along (1, -2, 1.5)), the 46 triangles counted
# above; its angles are the lattice shapes' 45, 60, 90 and 120 degrees
# (spec/mesh3d.md): 4 bars.
bccmis_add_test(cli.mesh_render_lattice_mesh
         COMMAND sh -c "mkdir -p \"$4\" && cd \"$4\" && \"$2\" mesh \"$3\" -o face.mesh -q &&
                        \"$1\" \"$5\" \"$2\" tri=46,legend=2 face.mesh &&
                        \"$1\" \"$5\" \"$2\" bar=4,min=1,max=1 face.mesh --histogram"
                 sh ${BCCMIS_SYSTEM_PYTHON3} $<TARGET_FILE:bccmis> ${_face3} ${CMAKE_CURRENT_BINARY_DIR}/cli_work/mesh_render_lattice
                 ${_cli}/d3/check_svg.py
         LABELS cli)
bccmis_cli_test(mesh_render_slice_outside 2 ARGS render ${_two_tets} --slice z=1.5 -o out.svg
                STDERR_REGEX "--slice 'z=1.5': outside the mesh: z in \\[-1, 1\\]")
bccmis_cli_test(mesh_render_slice_not_a_number 2 ARGS render ${_two_tets} --slice x=half -o out.svg
                STDERR_REGEX "--slice 'x=half': the value must be a number")
bccmis_cli_test(mesh_render_histogram_and_slice 2 ARGS render ${_two_tets} --histogram --slice z=0 -o out.svg
                STDERR_REGEX "--histogram draws no cut-away; drop --slice")
bccmis_cli_test(mesh_render_histogram_of_a_state 2 ARGS render ${_face3} --histogram -o out.svg
                STDERR_REGEX "face_refined.state: --histogram applies to a mesh file [(].mesh, .msh, .vtu[)]")
bccmis_cli_test(mesh_render_from_trace 2 ARGS render --from-trace ${_two_tets} -o out.svg
                STDERR_REGEX "two_tets.mesh: a mesh file; --from-trace applies to traces")
# docs/stuff-sphere.svg and docs/stuff-sphere-angles.svg are the README's
# commands' output as drawn now: the unit sphere stuffed at level 4 on 3
# cells, levels 2 to 4 in the cut-away.
bccmis_add_test(cli.mesh_render_docs_current
         COMMAND sh -c "mkdir -p \"$2\" && cd \"$2\" && \"$1\" stuff --shape sphere -L 4 --cells 3 -o sphere.mesh -q &&
                        \"$1\" render sphere.mesh --slice z=0 -o - | cmp - \"$3/docs/stuff-sphere.svg\" &&
                        \"$1\" render sphere.mesh --histogram -o - | cmp - \"$3/docs/stuff-sphere-angles.svg\""
                 sh $<TARGET_FILE:bccmis> ${CMAKE_CURRENT_BINARY_DIR}/cli_work/mesh_render_docs ${PROJECT_SOURCE_DIR}
         LABELS cli)
