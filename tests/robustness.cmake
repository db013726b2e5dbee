# Robustness against bad input and faults (issue 6), ctest label `robustness`.
#
# 1. tests/bad_input/: every file in trace/ must make `bccmis replay`, every
#    file in state/ `bccmis check` and every file in mesh/ `bccmis render`
#    (Medit .mesh files) exit 2 with exactly one line
#    `bccmis: FILE:LINE:COLUMN: MESSAGE` on stderr, nothing on stdout, within
#    a second and bounded memory. expected.txt gives LINE:COLUMN and the start
#    of MESSAGE for each file. Large inputs are generated at test time;
#    a directory and a missing file give `bccmis: PATH: MESSAGE`.
# 2. Output files: atomic writes, untouched on failure, no temporaries left.
# 3. Strong exception guarantee under injected allocation failures
#    (robustness_alloc_test.cpp).
set(_bad ${CMAKE_CURRENT_SOURCE_DIR}/bad_input)
set(_bad_run ${_bad}/run_bad_input.cmake)
set(_bad_work ${CMAKE_CURRENT_BINARY_DIR}/bad_input_work)

# The limits catch a hang or quadratic behaviour (the largest input, 100,002
# lines, is refused in about 0.1 s), with room for a loaded 2-core machine running two
# tests at once; sanitized builds run several times slower and map more
# memory.
if(BCCMIS_SANITIZERS OR BCCMIS_FUZZ)
  set(_bad_limits -DMAX_SECONDS=10 -DMAX_RSS_MB=1024)
else()
  set(_bad_limits -DMAX_SECONDS=3 -DMAX_RSS_MB=256)
endif()

function(bccmis_bad_input_test name mode input expect)
  string(REPLACE ";" "." expect "${expect}")
  bccmis_add_test(robustness.bad_input.${name}
           COMMAND ${CMAKE_COMMAND} -DBCCMIS=$<TARGET_FILE:bccmis> -DMODE=${mode} -DINPUT=${input}
                   "-DEXPECT=${expect}" -DWORKDIR=${_bad_work}/${name} ${_bad_limits} ${ARGN} -P ${_bad_run}
           LABELS robustness TIMEOUT 60)
endfunction()

# The manifest: <file> TAB <line>:<column>: <message regex>.
file(STRINGS ${_bad}/expected.txt _bad_manifest ENCODING UTF-8)
set(_bad_known)
foreach(entry IN LISTS _bad_manifest)
  if(entry MATCHES "^#" OR NOT entry MATCHES "^([^\t]+)\t(.+)$")
    continue()
  endif()
  set(file ${CMAKE_MATCH_1})
  set(expect "${CMAKE_MATCH_2}")
  list(APPEND _bad_known ${file})
  if(file MATCHES "^trace/")
    set(mode replay)
  elseif(file MATCHES "^mesh/")
    set(mode render)
  else()
    set(mode check)
  endif()
  string(REGEX REPLACE "^(trace|state|mesh)/(.*)\\.(trace|state|mesh)$" "\\1.\\2" name "${file}")
  bccmis_bad_input_test(${name} ${mode} ${_bad}/${file} "${expect}")
endforeach()
# A file without a manifest entry fails until it gets one.
file(GLOB _bad_files RELATIVE ${_bad} CONFIGURE_DEPENDS ${_bad}/trace/* ${_bad}/state/* ${_bad}/mesh/*)
foreach(file IN LISTS _bad_files)
  if(NOT file IN_LIST _bad_known)
    string(REGEX REPLACE "[^A-Za-z0-9_.]" "_" name "${file}")
    bccmis_bad_input_test(unlisted.${name} replay ${_bad}/${file} "no entry in tests/bad_input/expected.txt")
  endif()
endforeach()

# Inputs too large to keep in git, written by the script before the run.
bccmis_bad_input_test(generated.long_line replay ${_bad_work}/generated.long_line/in.trace
                      "2:10: y coordinate .9+\\.\\.\\.. is out of range" -DGENERATE=long_line)
bccmis_bad_input_test(generated.many_lines replay ${_bad_work}/generated.many_lines/in.trace
                      "100002:1: unknown command .bogus." -DGENERATE=many_lines)
bccmis_bad_input_test(generated.many_comments replay ${_bad_work}/generated.many_comments/in.trace
                      "104864:1: no .lattice W H L. command" -DGENERATE=many_comments)
bccmis_bad_input_test(generated.long_state check ${_bad_work}/generated.long_state/in.state
                      "50003:3: N lines must be sorted" -DGENERATE=long_state)

# No line to point at: a directory, a missing file.
bccmis_bad_input_test(directory_replay replay ${_bad} "is a directory, expected a file" -DNO_LINE=1)
bccmis_bad_input_test(directory_check check ${_bad} "is a directory, expected a file" -DNO_LINE=1)
bccmis_bad_input_test(missing_replay replay ${_bad}/no-such-file.trace "cannot open for reading" -DNO_LINE=1)
bccmis_bad_input_test(missing_check check ${_bad}/no-such-file.state "cannot open for reading" -DNO_LINE=1)

# Output files.
foreach(case parse_error_keeps_outputs success_leaves_only_outputs missing_output_directory output_is_a_fifo
             replay_outputs_all_or_nothing replay_state_keeps_log_on_stdout stdout_full
             heightfield_outputs_all_or_nothing heightfield_replaces_atomically
             animate_outputs_all_or_nothing animate_replaces_atomically)
  bccmis_add_test(robustness.outputs.${case}
           COMMAND sh ${_bad}/outputs.sh $<TARGET_FILE:bccmis> ${case} ${CMAKE_CURRENT_BINARY_DIR}/outputs_work/${case}
           LABELS robustness TIMEOUT 60)
endforeach()
# output_is_a_fifo: an output that exists and is not a regular file (a FIFO,
# /dev/null) is written in place, never renamed over.

# Strong exception guarantee: every k-th allocation fails, for every k.
bccmis_add_gtest(robustness_alloc_test SOURCES robustness_alloc_test.cpp LIBS bccmis::invariants bccmis::core
                 LABELS robustness)
