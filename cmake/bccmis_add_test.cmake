# Registering a command test (a script, the CLI, a program run with
# arguments) with ctest, its labels and timeout in the same call; the
# GoogleTest executables go through bccmis_add_gtest (bccmis_add_gtest.cmake).
#
#   bccmis_add_test(<name>
#     COMMAND <command> [<arg>...]          as for add_test
#     [WORKING_DIRECTORY <dir>]
#     [LABELS <label>...]
#     [TIMEOUT <seconds>]
#     [PROPERTIES <property> <value>...])   any other test property
#
# Every argument reaches add_test as it was given: one holding ";" stays one
# argument, and one holding an unbalanced "[" (a regular expression) does not
# swallow the next ones, so each is passed on as a bracket argument.
# A test configured further elsewhere (fixtures) keeps its name, so a later
# set_tests_properties(<name> PROPERTIES FIXTURES_...) still applies to it.

function(bccmis_add_test name)
  set(section "")
  set(command "")
  set(where "")
  set(properties "")
  set(labels "")
  math(EXPR last "${ARGC} - 1")
  if(last LESS 1)
    message(FATAL_ERROR "bccmis_add_test(${name}): no COMMAND")
  endif()
  foreach(i RANGE 1 ${last})
    set(arg "${ARGV${i}}")
    if(arg MATCHES "^(COMMAND|WORKING_DIRECTORY|LABELS|TIMEOUT|PROPERTIES)$")
      set(section ${arg})
    elseif(section STREQUAL "COMMAND")
      string(APPEND command " [==[${arg}]==]")
    elseif(section STREQUAL "WORKING_DIRECTORY")
      string(APPEND where " WORKING_DIRECTORY [==[${arg}]==]")
    elseif(section STREQUAL "LABELS")
      list(APPEND labels "${arg}")
    elseif(section STREQUAL "TIMEOUT")
      string(APPEND properties " TIMEOUT [==[${arg}]==]")
    elseif(section STREQUAL "PROPERTIES")
      string(APPEND properties " [==[${arg}]==]")
    else()
      message(FATAL_ERROR "bccmis_add_test(${name}): unexpected argument '${arg}' before COMMAND")
    endif()
  endforeach()
  if(command STREQUAL "")
    message(FATAL_ERROR "bccmis_add_test(${name}): no COMMAND")
  endif()
  cmake_language(EVAL CODE "add_test(NAME [==[${name}]==] COMMAND${command}${where})")
  if(labels)
    string(PREPEND properties " LABELS [==[${labels}]==]")
  endif()
  if(NOT properties STREQUAL "")
    cmake_language(EVAL CODE "set_tests_properties([==[${name}]==] PROPERTIES${properties})")
  endif()
endfunction()
