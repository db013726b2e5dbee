# BCCMIS_PYTHON: the Python module (python/, spec/python.md). Defaults to ON
# when pybind11 and the development files of the system's python3 are found
# (Debian: pybind11-dev, python3-dev; numpy at run time: python3-numpy).
# Included before src/: the static libraries the module links are then
# compiled as position-independent code.
#
# The module is built against /usr/bin/python3 when it exists: the packages
# the module and its tests import (numpy, meshio, pytest, matplotlib) are
# Debian's, installed for that interpreter, whatever python3 comes first on
# the PATH.
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python 3.11 QUIET COMPONENTS Interpreter Development.Module)
set(PYBIND11_FINDPYTHON ON)
if(Python_Development.Module_FOUND)
  find_package(pybind11 2.10 CONFIG QUIET)
endif()
set(_bccmis_python_found OFF)
if(Python_Development.Module_FOUND AND pybind11_FOUND)
  set(_bccmis_python_found ON)
endif()
option(BCCMIS_PYTHON "Build the Python module (needs pybind11-dev and python3-dev)" ${_bccmis_python_found})
if(NOT BCCMIS_PYTHON)
  message(STATUS "bccmis: Python module not built (BCCMIS_PYTHON=OFF)")
elseif(NOT _bccmis_python_found)
  message(FATAL_ERROR "BCCMIS_PYTHON=ON but pybind11 or Python's development files were not found; "
                      "install pybind11-dev python3-dev or configure with -DBCCMIS_PYTHON=OFF")
else()
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
endif()
