# The trace viewer (bccmis view, issue 11; spec/viewer.md).
#   label viewer:  the model a page embeds against bccmis replay and stats, the
#                  size budget, bad input, the --states and conformance pages;
#   label browser: the page in headless Chromium (skipped without Chromium).
find_package(Python3 3.9 COMPONENTS Interpreter)
set(_viewer ${CMAKE_CURRENT_SOURCE_DIR}/viewer)
set(_viewer_work ${CMAKE_CURRENT_BINARY_DIR}/viewer_work)

if(Python3_FOUND)
  # The embedded model, step by step, against bccmis replay and stats.
  foreach(stem fig2 fig3 refusals)
    bccmis_add_test(viewer.model.${stem}
             COMMAND Python3::Interpreter ${_viewer}/check_model.py $<TARGET_FILE:bccmis>
                     ${PROJECT_SOURCE_DIR}/spec/examples/${stem}.trace ${_viewer_work}/model_${stem}
             LABELS viewer TIMEOUT 300)
  endforeach()
  # check_model.py on a trace that make_trace.py writes first
  # (tests/viewer/with_trace.cmake): make_trace.py's arguments, the trace's
  # file name and the model's folder in viewer_work/, then check_model.py's
  # further arguments.
  function(bccmis_viewer_random_trace_test name make_trace_args trace model)
    set(check "${Python3_EXECUTABLE};${_viewer}/check_model.py;$<TARGET_FILE:bccmis>;${_viewer_work}/${trace}")
    list(APPEND check ${_viewer_work}/${model} ${ARGN})
    bccmis_add_test(${name}
             COMMAND ${CMAKE_COMMAND} -DPYTHON=${Python3_EXECUTABLE} -DGEN=${_viewer}/make_trace.py
                     "-DGEN_ARGS=${make_trace_args}" -DTRACE=${_viewer_work}/${trace} "-DCMD=${check}"
                     -P ${_viewer}/with_trace.cmake
             LABELS viewer TIMEOUT 300)
  endfunction()
  # A random trace of 300 operations (many refusals, some checks).
  bccmis_viewer_random_trace_test(viewer.model.random "6;6;3;300;2" random300.trace model_random)
  # Size: 1,000 operations on a 40 x 40 lattice of maximum level 3 (1,600 cells
  # at first, about 2,600 at the end) must stay below 2 MB.
  bccmis_viewer_random_trace_test(viewer.size_budget "40;40;3;1000;1" big.trace size_budget
                                  --check=end --budget 2000000)

  # In a real browser; exit 77 (skipped) without Chromium.
  bccmis_add_test(viewer.browser
           COMMAND Python3::Interpreter ${_viewer}/browser_test.py $<TARGET_FILE:bccmis> ${PROJECT_SOURCE_DIR}
                   ${_viewer_work}/browser
           LABELS browser TIMEOUT 600 PROPERTIES SKIP_RETURN_CODE 77)
endif()

# The CLI: page written, exit codes, messages (tests/cli/run_cli.cmake).
set(_states ${_viewer}/states)
bccmis_cli_test(view.fig2 0 ARGS view ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace -o fig2.html
                STDERR_REGEX "fig2.html: 4 steps, [0-9]+ bytes" LABEL viewer)
bccmis_cli_test(view.help 0 ARGS view --help STDOUT_REGEX "Example:.*bccmis view .*-o .*spec/viewer.md|spec/viewer.md.*Example:"
                LABEL viewer)
bccmis_cli_test(view.stdout 0 ARGS view ${PROJECT_SOURCE_DIR}/spec/examples/fig3.trace -o -
                STDOUT_REGEX "^<!DOCTYPE html>.*\"format\":\"bccmis-view 1\".*</html>" LABEL viewer)
bccmis_cli_test(view.states_violation 1 ARGS view --states ${_states} -o states.html
                STDERR_REGEX "invariant violated at step 2 \\(the page opens there\\): symmetry: node \\(2, 4\\)" LABEL viewer)
bccmis_cli_test(view.states_files 0 ARGS view --states ${_states}/0000.state ${_states}/0001.state ${_states}/0003.state
                -o states.html STDERR_REGEX "states.html: 2 steps" LABEL viewer)
# The same limit and message as `bccmis replay --max-vertices`: Fig. 2 ends
# with 9 cells and 17 nodes (spec/examples/fig2.expected), 26 vertices.
bccmis_cli_test(view.max_vertices 2 ARGS view ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace -o x.html --max-vertices 25
                STDERR_REGEX "fig2.trace:9:1: after 'refine 6 2' the lattice has 26 vertices, above the limit of 25 \\(--max-vertices\\)"
                LABEL viewer)
bccmis_cli_test(view.max_vertices_initial 2 ARGS view ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace -o x.html --max-vertices 5
                STDERR_REGEX "fig2.trace:6:1: lattice of 3 x 1 cells exceeds the limit of 5 vertices \\(it has 11\\)" LABEL viewer)
bccmis_cli_test(view.no_input 2 ARGS view -o x.html STDERR_REGEX "give a trace file or --states" LABEL viewer)
bccmis_cli_test(view.both_inputs 2 ARGS view ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace --states ${_states} -o x.html
                STDERR_REGEX "not both" LABEL viewer)
bccmis_cli_test(view.no_output 2 ARGS view ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace STDERR_REGEX "output" LABEL viewer)
bccmis_cli_test(view.bad_trace 2 ARGS view ${CMAKE_CURRENT_SOURCE_DIR}/cli/bad_command.trace -o x.html
                STDERR_REGEX "bad_command.trace:3:1: unknown command 'split'" LABEL viewer)
bccmis_cli_test(view.bad_state 2 ARGS view --states ${_states}/0000.state ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace -o x.html
                STDERR_REGEX "fig2.trace:1:1: expected 'bccmis-state 1'" LABEL viewer)
bccmis_cli_test(view.lattice_mismatch 2 ARGS view --states ${_states}/0000.state ${PROJECT_SOURCE_DIR}/spec/examples/initial_1_1_0.state -o x.html
                STDERR_REGEX "initial_1_1_0.state: lattice 1 1 0 differs from the first state's lattice 1 1 1" LABEL viewer)
bccmis_cli_test(view.empty_dir 2 ARGS view --states ${_viewer} -o x.html
                STDERR_REGEX "no \\*.state files" LABEL viewer)
bccmis_cli_test(view.unwritable 2 ARGS view ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace -o no-such-dir/x.html
                STDERR_REGEX "no-such-dir/x.html: cannot create a temporary file" LABEL viewer)
bccmis_cli_test(view.conformance 1
  ARGS conformance --impl "sh ${CMAKE_CURRENT_SOURCE_DIR}/conformance/missing_boundary_junction.sh $<TARGET_FILE:bccmis>"
       --random 50 --seed 1 --dim 2 --view disagreement.html
  STDOUT_REGEX "viewer page of the disagreement: disagreement.html" LABEL viewer)
# --from-log: another implementation's output on a trace.
set(_fig2 ${PROJECT_SOURCE_DIR}/spec/examples/fig2.trace)
bccmis_cli_test(view.from_log_agrees 0 ARGS view ${_fig2} --from-log ${CMAKE_CURRENT_SOURCE_DIR}/cli/fig2.log -o agree.html
                LABEL viewer)
bccmis_cli_test(view.from_log_expected 0 ARGS view ${_fig2} --from-log ${PROJECT_SOURCE_DIR}/spec/examples/fig2.expected
                -o agree.html LABEL viewer)
bccmis_cli_test(view.from_log_decision 1 ARGS view ${_fig2} --from-log ${_viewer}/fig2_wrong_decision.log -o decision.html
  STDERR_REGEX "fig2_wrong_decision.log disagrees with the reference at step 3 \\(the page opens there\\): decision 2: reference 'refine 6 2 ok', implementation 'refine 6 2 refused coarser-neighbor'"
  LABEL viewer)
bccmis_cli_test(view.from_log_state 1 ARGS view ${_fig2} --from-log ${_viewer}/fig2_wrong_state.out -o state.html
  STDERR_REGEX "disagrees with the reference at step 4 .*final states differ.*neighbors of \\(7, 3\\): only in A: \\(8, 2\\)"
  LABEL viewer)
bccmis_cli_test(view.from_log_with_states 2 ARGS view --states ${_states} --from-log ${_viewer}/fig2_wrong_state.out -o x.html
                STDERR_REGEX "--from-log needs a trace" LABEL viewer)
bccmis_cli_test(view.too_large 2 ARGS view ${_viewer}/too_large.trace -o x.html
                STDERR_REGEX "too_large.trace: view: lattice 1 1 60 is too large for the page: its coordinates exceed 2\\^53"
                LABEL viewer)
