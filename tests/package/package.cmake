# The installed package works for a consumer project (find_package(bccmis)).
set(_flags "")
if(BCCMIS_SANITIZERS)
  set(_flags "-fsanitize=${BCCMIS_SANITIZERS}")
endif()
bccmis_add_test(package.consumer
         COMMAND ${CMAKE_COMMAND} -DBUILD=${PROJECT_BINARY_DIR} -DSRC=${CMAKE_CURRENT_SOURCE_DIR}/package
                 -DWORK=${CMAKE_CURRENT_BINARY_DIR}/package_work -DCXX=${CMAKE_CXX_COMPILER} "-DFLAGS=${_flags}"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/package/run.cmake
         LABELS package TIMEOUT 300)
