# Included by tests/CMakeLists.txt: the apps' tests (src/bccmis/apps; the
# balance cascade's are the core's, tests/balance_test.cpp).
bccmis_add_gtest(apps_tests
  SOURCES image_test.cpp heightfield_test.cpp moving_disk_test.cpp fast_test.cpp
  LIBS bccmis::apps bccmis::fast bccmis::core bccmis::invariants bccmis::oracle
  DEFINITIONS BCCMIS_APPS_SAMPLES="${PROJECT_SOURCE_DIR}/apps/samples"
  LABELS unit apps)

# The committed sample is what its generator script writes.
find_package(Python3 COMPONENTS Interpreter QUIET)
if(Python3_FOUND)
  bccmis_add_test(apps.sample_terrain_reproducible
           COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/apps/samples/make_terrain.py terrain --size 128 --bits 16
                   --check ${PROJECT_SOURCE_DIR}/apps/samples/terrain128.pgm
           LABELS unit apps)
  bccmis_add_test(apps.sample_terrain256_reproducible
           COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/apps/samples/make_terrain.py terrain --size 256 --bits 16
                   --check ${PROJECT_SOURCE_DIR}/apps/samples/terrain256.pgm
           LABELS unit apps)
endif()

# The height field's streamed writers and fast-lattice mesh paths against the
# texts and values they replace.
bccmis_add_gtest(apps_output_test SOURCES output_test.cpp LIBS bccmis::apps bccmis::fast bccmis::core LABELS unit)

# The CLI of the apps (tools/bccmis/heightfield.cpp, animate.cpp): outputs,
# both implementations, bad input (tests/cli/run_cli.cmake).
set(_samples ${PROJECT_SOURCE_DIR}/apps/samples)
set(_apps_work ${CMAKE_CURRENT_BINARY_DIR}/cli_work)
bccmis_cli_test(heightfield.every_output 0 LABEL apps
  ARGS heightfield ${_samples}/terrain128.pgm --tolerance 0.03 --obj t.obj --ply t.ply --vtu t.vtu --svg t.svg
       --state t.state --json --check
  STDOUT_REGEX "^{.*\"operations\": .*\"nodes\": .*\"cells\": .*\"max_error\": .*\"rms_error\": .*\"within_tolerance\": true.*\"tessellate_seconds\": "
  STDERR_REGEX "^bccmis heightfield: ")
bccmis_cli_test(heightfield.every_output_state_valid 0 LABEL apps ARGS check ${_apps_work}/heightfield.every_output/t.state)
set_tests_properties(cli.heightfield.every_output PROPERTIES FIXTURES_SETUP heightfield_every_output)
set_tests_properties(cli.heightfield.every_output_state_valid PROPERTIES FIXTURES_REQUIRED heightfield_every_output)
foreach(impl reference fast)
  bccmis_cli_test(heightfield.${impl} 0 LABEL apps
    ARGS heightfield ${_samples}/terrain128.pgm --impl ${impl} --tolerance 0.01 --measure samples --state h.state --obj h.obj --check
    STDOUT_REGEX "impl ${impl}\n")
  set_tests_properties(cli.heightfield.${impl} PROPERTIES FIXTURES_SETUP heightfield_impls)
endforeach()
foreach(ext state obj)
  bccmis_add_test(cli.heightfield.fast_same_${ext}
           COMMAND ${CMAKE_COMMAND} -E compare_files ${_apps_work}/heightfield.reference/h.${ext} ${_apps_work}/heightfield.fast/h.${ext}
           LABELS cli apps PROPERTIES FIXTURES_REQUIRED heightfield_impls)
endforeach()
bccmis_cli_test(heightfield.no_input 2 LABEL apps ARGS heightfield STDERR_REGEX "input")
bccmis_cli_test(heightfield.two_stdouts 2 LABEL apps ARGS heightfield ${_samples}/terrain128.pgm --obj -
                STDERR_REGEX "^bccmis heightfield: at most one output can be '-'")
bccmis_cli_test(heightfield.max_level 2 LABEL apps ARGS heightfield ${_samples}/terrain128.pgm -L 25
                STDERR_REGEX "^bccmis heightfield: options: max level 25 is out of range 0..24\n$")
bccmis_cli_test(heightfield.missing 2 LABEL apps ARGS heightfield missing.pgm
                STDERR_REGEX "^bccmis heightfield: missing.pgm: cannot open for reading: No such file or directory\n$")
bccmis_cli_test(heightfield.from_trace 2 LABEL apps ARGS heightfield ${_samples}/terrain128.pgm --from ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace
                STDERR_REGEX "^bccmis heightfield: .*fig2.trace:1:1: expected 'bccmis-state 1'")
bccmis_cli_test(heightfield.unwritable 2 LABEL apps ARGS heightfield ${_samples}/terrain128.pgm --state no/such/dir/x.state
                STDERR_REGEX "^bccmis heightfield: no/such/dir/x.state: cannot create a temporary file")
bccmis_cli_test(animate.outputs 0 LABEL apps
  ARGS animate -L 3 --frames 5 --lift --state final.state --check
  STDOUT_REGEX "^# frame.* lifted\ntotal frames 6 " STDERR_REGEX "^bccmis animate: 6 frames")
bccmis_cli_test(animate.json_fast 0 LABEL apps ARGS animate -W 4 -H 4 -L 3 --frames 5 --lift --json --impl fast
  STDOUT_REGEX "^{\"lattice\": \"4 4 3\", \"frames\": \\[.*\"total\": {\"frames\": 6")
bccmis_cli_test(animate.bad_path 2 LABEL apps ARGS animate --path oops
                STDERR_REGEX "^bccmis animate: path point 1 'oops': expected x,y\n$")
bccmis_cli_test(animate.bad_target 2 LABEL apps ARGS animate --target-level 9
                STDERR_REGEX "^bccmis animate: target level 9 is out of range 0..5 \\(or -1 for the max level\\)\n$")
bccmis_cli_test(animate.bad_svg_dir 2 LABEL apps ARGS animate --svg-dir /nonexistent/frames
                STDERR_REGEX "^bccmis animate: /nonexistent/frames: not an existing directory\n$")
bccmis_cli_test(animate.bad_radius 2 LABEL apps ARGS animate --radius -1 STDERR_REGEX "^bccmis animate: radius must be a number >= 0\n$")
bccmis_cli_test(animate.two_stdouts 2 LABEL apps ARGS animate --state - STDERR_REGEX "at most one output can be '-'")
