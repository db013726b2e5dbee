# Runs `bccmis MODE INPUT` (for MODE render, `bccmis render INPUT -o -`) on
# one malformed input and checks that it is
# refused cleanly:
#   - exit code 2 (bad input), not a crash, not 0/1/3;
#   - nothing on stdout;
#   - stderr is exactly one line `bccmis: NAME:LINE:COLUMN: MESSAGE`, where
#     `LINE:COLUMN: MESSAGE` matches EXPECT (for a directory or a missing file,
#     which have no line, `bccmis: NAME: MESSAGE` with EXPECT matching MESSAGE);
#   - it takes less than MAX_SECONDS of wall time and, when GNU time is
#     available, less than MAX_RSS_MB of peak resident memory.
#
#   cmake -DBCCMIS=path -DMODE=replay|check|render -DINPUT=path -DEXPECT=regex
#         [-DGENERATE=kind -DWORKDIR=dir] [-DNO_LINE=1]
#         [-DMAX_SECONDS=1] [-DMAX_RSS_MB=256] -P run_bad_input.cmake
#
# GENERATE writes a large input into WORKDIR first (too big to keep in git):
#   long_line       a 1 MiB integer token (out of range)
#   many_lines      100,000 valid commands, then an unknown one
#   many_comments   8 MiB of comment lines and no lattice command
#   long_state      a state with 50,000 sorted node lines, then a bad line
foreach(v BCCMIS MODE INPUT EXPECT)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_bad_input.cmake: ${v} is not set")
  endif()
endforeach()
if(NOT MAX_SECONDS)
  set(MAX_SECONDS 1)
endif()
if(NOT MAX_RSS_MB)
  set(MAX_RSS_MB 256)
endif()

if(GENERATE)
  file(MAKE_DIRECTORY "${WORKDIR}")
  if(GENERATE STREQUAL "long_line")
    string(REPEAT "9" 1048576 digits)
    file(WRITE "${INPUT}" "lattice 2 2 1\nrefine 4 ${digits}\n")
  elseif(GENERATE STREQUAL "many_lines")
    string(REPEAT "refine 4 4\ncoarsen 4 4\n" 50000 body)
    file(WRITE "${INPUT}" "lattice 2 2 1\n${body}bogus 1 2\n")
  elseif(GENERATE STREQUAL "many_comments")
    string(REPEAT "# a comment line that goes on and on and on and on and on and on and on and on\n" 16 block)
    string(REPEAT "${block}" 6554 body)
    file(WRITE "${INPUT}" "${body}")
  elseif(GENERATE STREQUAL "long_state")
    # In chunks of 1,000 lines: appending 50,000 times to one string is
    # quadratic in CMake (36 s).
    file(WRITE "${INPUT}" "bccmis-state 1\nlattice 1 1 0\n")
    foreach(k RANGE 0 49)
      set(chunk "")
      foreach(j RANGE 0 999)
        math(EXPR i "${k} * 1000 + ${j}")
        string(APPEND chunk "N ${i} 0 :\n")
      endforeach()
      file(APPEND "${INPUT}" "${chunk}")
    endforeach()
    file(APPEND "${INPUT}" "N 5 -1 :\nend 0 50001\n")
  else()
    message(FATAL_ERROR "run_bad_input.cmake: unknown GENERATE=${GENERATE}")
  endif()
endif()

set(cmd "${BCCMIS}" "${MODE}" "${INPUT}")
if(MODE STREQUAL "render")
  list(APPEND cmd -o -)
endif()
set(rss_file "")
if(EXISTS /usr/bin/time)
  if(WORKDIR)
    file(MAKE_DIRECTORY "${WORKDIR}")
    set(rss_file "${WORKDIR}/rss.txt")
  else()
    set(rss_file "${CMAKE_CURRENT_BINARY_DIR}/rss.txt")
  endif()
  set(cmd /usr/bin/time -f "%M" -o "${rss_file}" ${cmd})
endif()

string(TIMESTAMP t0 "%s%f")
execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 20)
string(TIMESTAMP t1 "%s%f")
math(EXPR elapsed_ms "(${t1} - ${t0}) / 1000")
math(EXPR limit_ms "${MAX_SECONDS} * 1000")

set(fail "")
set(rss_mb "?")
if(NOT "${rc}" STREQUAL "2")
  string(APPEND fail "exit code '${rc}', expected 2\n")
endif()
if(NOT out STREQUAL "")
  string(APPEND fail "stdout is not empty\n")
endif()
# The name the CLI prints is the path as given; escape it for the regex.
string(REGEX REPLACE "([][+.*()^$?|\\\\])" "\\\\\\1" name_re "${INPUT}")
if(NO_LINE)
  set(line_re "^bccmis: ${name_re}: (${EXPECT})[^\n]*\n$")
else()
  set(line_re "^bccmis: ${name_re}:[0-9]+:[0-9]+: [^\n]*\n$")
endif()
if(NOT err MATCHES "${line_re}")
  string(APPEND fail "stderr is not one line 'bccmis: ${INPUT}:LINE:COLUMN: MESSAGE'\n")
elseif(NOT NO_LINE)
  string(LENGTH "bccmis: ${INPUT}:" skip)
  string(SUBSTRING "${err}" ${skip} -1 located)
  if(NOT located MATCHES "^(${EXPECT})")
    string(APPEND fail "location and message do not match '${EXPECT}'\n")
  endif()
endif()
if(elapsed_ms GREATER limit_ms)
  string(APPEND fail "took ${elapsed_ms} ms, limit ${limit_ms} ms\n")
endif()
if(rss_file AND EXISTS "${rss_file}")
  file(STRINGS "${rss_file}" rss_lines)
  list(GET rss_lines -1 rss_kb)
  if(rss_kb MATCHES "^[0-9]+$")
    math(EXPR rss_mb "${rss_kb} / 1024")
    if(rss_mb GREATER MAX_RSS_MB)
      string(APPEND fail "peak RSS ${rss_mb} MiB, limit ${MAX_RSS_MB} MiB\n")
    endif()
  endif()
endif()
if(fail)
  message(FATAL_ERROR "bccmis ${MODE} ${INPUT}\n${fail}--- stdout ---\n${out}--- stderr ---\n${err}")
endif()
message(STATUS "ok: exit 2 in ${elapsed_ms} ms, peak RSS ${rss_mb} MiB: ${err}")
