# The Python module (python/, spec/python.md): pytest on the module of this
# build against the CLI of this build, under the label `python`. Registered
# when the module is built (BCCMIS_PYTHON).
#
# Under AddressSanitizer (the asan preset) the interpreter is not
# instrumented, so the sanitizer's runtime is preloaded before it starts;
# leak detection is off, because the interpreter keeps its own allocations
# to the end by design. test_memory.py's resident-set check is deselected
# there: ASan's allocator holds freed memory in its quarantine and size
# classes (the set grows about 23 MB over 1,000 calls even with the
# quarantine off), so it measures the sanitizer, not the module; it runs in
# every other build.
if(TARGET bccmis_python)
  set(_bccmis_python_env "PYTHONPATH=$<TARGET_FILE_DIR:bccmis_python>" "BCCMIS_CLI=$<TARGET_FILE:bccmis>"
                         "MPLBACKEND=Agg")
  if(BCCMIS_SANITIZERS MATCHES "address")
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libclang_rt.asan-x86_64.so
                    OUTPUT_VARIABLE _bccmis_asan_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT EXISTS "${_bccmis_asan_runtime}")
      message(FATAL_ERROR "the Python tests under AddressSanitizer need its runtime to preload; "
                          "${CMAKE_CXX_COMPILER} names '${_bccmis_asan_runtime}', which does not exist")
    endif()
    list(APPEND _bccmis_python_env "LD_PRELOAD=${_bccmis_asan_runtime}" "ASAN_OPTIONS=detect_leaks=0")
    set(_bccmis_pytest_select -k "not test_rss_stays_flat")
  endif()
  bccmis_add_test(python.module
    COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${_bccmis_pytest_select} ${CMAKE_CURRENT_LIST_DIR}
    LABELS python TIMEOUT 300
    PROPERTIES ENVIRONMENT "${_bccmis_python_env}")
endif()
