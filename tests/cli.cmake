# CLI tests: golden traces (spec/examples, hand-derived expected output),
# exit codes and error messages. Each runs tests/cli/run_cli.cmake.
set(_run ${CMAKE_CURRENT_SOURCE_DIR}/cli/run_cli.cmake)
set(_cli ${CMAKE_CURRENT_SOURCE_DIR}/cli)
set(_examples ${PROJECT_SOURCE_DIR}/spec/examples)

function(bccmis_cli_test name exit)
  cmake_parse_arguments(T "" "STDOUT_FILE;STDOUT_REGEX;STDERR_REGEX;STDIN_FILE;LABEL" "ARGS" ${ARGN})
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
  string(REPLACE ";" "|" cmd "$<TARGET_FILE:bccmis>;${T_ARGS}")
  if(NOT T_LABEL)
    set(T_LABEL cli)
  endif()
  add_test(NAME cli.${name} COMMAND ${CMAKE_COMMAND} "-DCMD=${cmd}" ${defs} -P ${_run})
  set_tests_properties(cli.${name} PROPERTIES LABELS ${T_LABEL})
endfunction()

# Golden traces: every spec/examples/*.trace against its .expected.
file(GLOB _traces ${_examples}/*.trace)
foreach(trace ${_traces})
  get_filename_component(stem ${trace} NAME_WE)
  bccmis_cli_test(golden.${stem} 0 ARGS replay --check=every --quiet ${trace}
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
add_test(NAME cli.output_files_content
         COMMAND ${CMAKE_COMMAND} -E compare_files ${CMAKE_CURRENT_BINARY_DIR}/cli_work/output_files/out.log
                 ${_cli}/fig2.log)
set_tests_properties(cli.output_files_content PROPERTIES DEPENDS cli.output_files LABELS cli)
