# Generates a trace with make_trace.py, then runs a command on it.
#   cmake -DPYTHON=python3 -DGEN=make_trace.py -DGEN_ARGS="W;H;L;STEPS;SEED" -DTRACE=out.trace
#         -DCMD="prog;arg;..." -P with_trace.cmake
get_filename_component(dir "${TRACE}" DIRECTORY)
file(MAKE_DIRECTORY "${dir}")
execute_process(COMMAND "${PYTHON}" "${GEN}" ${GEN_ARGS} OUTPUT_FILE "${TRACE}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_trace.py failed: ${rc}")
endif()
execute_process(COMMAND ${CMD} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${CMD}: exit ${rc}")
endif()
