# Registering a GoogleTest executable with ctest (included by tests/CMakeLists.txt).
#
#   bccmis_add_gtest(<target>
#     SOURCES <file>...           relative to the folder of the calling list file
#     [LIBS <target>...]          linked PRIVATE, before GTest and bccmis::warnings
#     [DEFINITIONS <def>...]      compile definitions, PRIVATE
#     [OWN_MAIN]                  link GTest::gtest instead of GTest::gtest_main
#     [NO_DISCOVERY]              build only; register with bccmis_discover_gtests
#     <discovery options>)        as for bccmis_discover_gtests below
#
# builds the executable (include root tests/, so "testing/twin.h",
# "test_util.h", "model/leaf_model.h") and registers its tests.
#
#   bccmis_discover_gtests(<target>
#     [LABELS <label>...]         every discovered test's labels
#     [TIMEOUT <seconds>]         every discovered test's timeout
#     [ENVIRONMENT <var=value>]   one variable (gtest_discover_tests flattens lists)
#     [FILTER <gtest filter>]     only these tests (TEST_FILTER)
#     [PREFIX <prefix>]           ctest name prefix (TEST_PREFIX)
#     [TEST_LIST <var>]           the variable naming the discovered tests
#     [NO_PRETTY_VALUES])
#
# registers the tests of <target> at test time (DISCOVERY_MODE PRE_TEST); call
# it again with another FILTER to give a part of the tests other labels or
# another timeout.
#
# gtest_discover_tests flattens a list-valued LABELS ("unit;apps" becomes the
# label "unit" and a stray property "apps"), so with several labels the tests
# are discovered with the first and a test include file, run after the
# discovered tests are defined, sets them all.

function(bccmis_discover_gtests target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "NO_PRETTY_VALUES" "TIMEOUT;ENVIRONMENT;FILTER;PREFIX;TEST_LIST" "LABELS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "bccmis_discover_gtests(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT DEFINED arg_TEST_LIST)
    set(arg_TEST_LIST ${target}_TESTS)
  endif()
  if(arg_LABELS)
    list(GET arg_LABELS 0 arg_FIRST_LABEL)
  endif()
  set(options DISCOVERY_MODE PRE_TEST)
  if(arg_NO_PRETTY_VALUES)
    list(APPEND options NO_PRETTY_VALUES)
  endif()
  set(properties)
  # <list to extend>:<gtest_discover_tests keyword or test property>:<argument>
  foreach(entry options:TEST_PREFIX:PREFIX options:TEST_FILTER:FILTER options:TEST_LIST:TEST_LIST
                properties:LABELS:FIRST_LABEL properties:TIMEOUT:TIMEOUT properties:ENVIRONMENT:ENVIRONMENT)
    string(REPLACE ":" ";" entry "${entry}")
    list(POP_FRONT entry into keyword name)
    if(DEFINED arg_${name})
      list(APPEND ${into} ${keyword} "${arg_${name}}")
    endif()
  endforeach()
  if(properties)
    list(APPEND options PROPERTIES ${properties})
  endif()
  gtest_discover_tests(${target} ${options})

  list(LENGTH arg_LABELS label_count)
  if(label_count GREATER 1)
    set(labels_file ${CMAKE_CURRENT_BINARY_DIR}/${arg_TEST_LIST}_labels.cmake)
    file(WRITE ${labels_file}
         "if(${arg_TEST_LIST})\n  set_tests_properties(\${${arg_TEST_LIST}} PROPERTIES LABELS \"${arg_LABELS}\")\nendif()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${labels_file})
  endif()
endfunction()

function(bccmis_add_gtest target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "OWN_MAIN;NO_DISCOVERY;NO_PRETTY_VALUES"
                        "TIMEOUT;ENVIRONMENT;FILTER;PREFIX;TEST_LIST" "SOURCES;LIBS;DEFINITIONS;LABELS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "bccmis_add_gtest(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "bccmis_add_gtest(${target}): no SOURCES")
  endif()
  set(sources)
  foreach(source IN LISTS arg_SOURCES)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${CMAKE_CURRENT_LIST_DIR})
    list(APPEND sources ${source})
  endforeach()
  add_executable(${target} ${sources})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  if(arg_OWN_MAIN)
    set(gtest GTest::gtest)
  else()
    set(gtest GTest::gtest_main)
  endif()
  target_link_libraries(${target} PRIVATE ${arg_LIBS} ${gtest} bccmis::warnings)
  if(arg_DEFINITIONS)
    target_compile_definitions(${target} PRIVATE ${arg_DEFINITIONS})
  endif()
  if(arg_NO_DISCOVERY)
    return()
  endif()

  set(discovery)
  foreach(flag NO_PRETTY_VALUES)
    if(arg_${flag})
      list(APPEND discovery ${flag})
    endif()
  endforeach()
  foreach(key TIMEOUT ENVIRONMENT FILTER PREFIX TEST_LIST)
    if(DEFINED arg_${key})
      list(APPEND discovery ${key} "${arg_${key}}")
    endif()
  endforeach()
  if(arg_LABELS)
    list(APPEND discovery LABELS ${arg_LABELS})
  endif()
  bccmis_discover_gtests(${target} ${discovery})
endfunction()
