# The Python module (python/, spec/python.md): pytest on the module of this
# build against the CLI of this build, under the label `python`. Registered
# when the module is built (BCCMIS_PYTHON).
if(TARGET bccmis_python)
  add_test(NAME python.module
           COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_LIST_DIR})
  set_tests_properties(python.module PROPERTIES
    LABELS python TIMEOUT 300
    ENVIRONMENT "PYTHONPATH=$<TARGET_FILE_DIR:bccmis_python>;BCCMIS_CLI=$<TARGET_FILE:bccmis>;MPLBACKEND=Agg")
endif()
