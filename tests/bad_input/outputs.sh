#!/bin/sh
# Output-file robustness of the CLI (issue 6, spec/cli.md "Outputs"): files
# are written atomically (temporary file + rename), a run with several outputs
# writes all or none of them, a failed run leaves existing outputs untouched,
# a failed write to stdout is an error, and no temporary file is ever left
# behind.
#   sh outputs.sh BCCMIS CASE WORKDIR
set -u
bccmis=$1
case_name=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1

fail() {
  echo "FAIL ($case_name): $*" >&2
  exit 1
}
no_temporaries() {
  leftovers=$(find . -name '.*.tmp-*' | head -5)
  [ -z "$leftovers" ] || fail "temporary files left behind: $leftovers"
}

# Runs bccmis with the arguments after the first (stdout.txt, stderr.txt)
# and fails unless it exits with the first (the message shows stderr when 0
# was expected).
run_expecting() {
  expected=$1
  shift
  "$bccmis" "$@" > stdout.txt 2> stderr.txt
  rc=$?
  [ $rc -eq "$expected" ] && return 0
  [ "$expected" -eq 0 ] && fail "exit code $rc, expected 0: $(cat stderr.txt)"
  fail "exit code $rc, expected $expected"
}

printf 'lattice 2 1 1\nrefine 2 2\n' > good.trace
printf 'lattice 2 1 1\nrefine 2 2\nsplit 4 4\n' > bad.trace

case $case_name in
  parse_error_keeps_outputs)
    # A run that fails on its input must not touch existing output files.
    printf 'old state\n' > out.state
    printf 'old log\n' > out.log
    run_expecting 2 replay --quiet --state out.state --log out.log bad.trace
    [ "$(cat out.state)" = "old state" ] || fail "out.state was changed"
    [ "$(cat out.log)" = "old log" ] || fail "out.log was changed"
    no_temporaries
    ;;
  success_leaves_only_outputs)
    run_expecting 0 replay --quiet --state out.state --log out.log good.trace
    [ "$(tail -n 1 out.state)" = "end 5 11" ] || fail "out.state is incomplete: $(tail -n 1 out.state)"
    [ "$(cat out.log)" = "refine 2 2 ok" ] || fail "out.log is wrong: $(cat out.log)"
    [ -s stdout.txt ] && fail "stdout is not empty with --state and --log"
    no_temporaries
    ;;
  missing_output_directory)
    run_expecting 2 replay --quiet --state no/such/dir/out.state good.trace
    [ "$(wc -l < stderr.txt)" -eq 1 ] || fail "stderr is not one line: $(cat stderr.txt)"
    grep -q 'no/such/dir/out.state' stderr.txt || fail "stderr does not name the file: $(cat stderr.txt)"
    no_temporaries
    ;;
  output_is_a_fifo)
    # An output that is not a regular file (a FIFO here; /dev/stdout or
    # /dev/null in practice) must be written to, not replaced by a rename.
    mkfifo out.fifo || fail "mkfifo failed"
    timeout 10 cat out.fifo > got.txt &
    reader=$!
    timeout 10 "$bccmis" replay --quiet --state out.fifo good.trace > stdout.txt 2> stderr.txt
    rc=$?
    if [ ! -p out.fifo ]; then
      kill "$reader" 2> /dev/null
      fail "out.fifo was replaced by a regular file (rename over a special file)"
    fi
    wait "$reader"
    [ $rc -eq 0 ] || fail "exit code $rc, expected 0: $(cat stderr.txt)"
    [ "$(tail -n 1 got.txt)" = "end 5 11" ] || fail "the reader did not get the state"
    no_temporaries
    ;;
  replay_outputs_all_or_nothing)
    # The log is fine, the state cannot be written: neither is.
    run_expecting 2 replay --quiet --log ok.log --state /proc/x good.trace
    [ -e ok.log ] && fail "ok.log was written although --state failed"
    grep -q '/proc/x' stderr.txt || fail "stderr does not name /proc/x: $(cat stderr.txt)"
    no_temporaries
    ;;
  replay_state_keeps_log_on_stdout)
    # --state without --log: the decision log still goes to stdout.
    run_expecting 0 replay --quiet --state out.state good.trace
    [ "$(cat stdout.txt)" = "refine 2 2 ok" ] || fail "stdout is not the decision log: $(cat stdout.txt)"
    [ "$(tail -n 1 out.state)" = "end 5 11" ] || fail "out.state is incomplete"
    no_temporaries
    ;;
  stdout_full)
    # A failed write to standard output is an error, not a success.
    [ -w /dev/full ] || { echo "skipped: no /dev/full"; exit 0; }
    "$bccmis" replay --quiet good.trace > /dev/full 2> stderr.txt
    rc=$?
    [ $rc -eq 2 ] || fail "exit code $rc, expected 2"
    grep -q 'standard output: write error' stderr.txt || fail "stderr: $(cat stderr.txt)"
    ;;
  heightfield_outputs_all_or_nothing)
    printf 'P2\n2 2\n255\n0 10\n20 30\n' > tiny.pgm
    run_expecting 2 heightfield tiny.pgm -q --obj a.obj --svg /proc/x.svg
    [ -e a.obj ] && fail "a.obj was written although --svg failed"
    no_temporaries
    ;;
  heightfield_replaces_atomically)
    # The output is replaced by a rename: a hard link to the old file keeps
    # the old text (writing in place would change both).
    printf 'P2\n2 2\n255\n0 10\n20 30\n' > tiny.pgm
    printf 'old\n' > a.obj
    ln a.obj old.obj
    run_expecting 0 heightfield tiny.pgm -q --obj a.obj --stats s.txt
    [ "$(cat old.obj)" = "old" ] || fail "the old a.obj was written in place, not replaced"
    grep -q '^v ' a.obj || fail "a.obj is not a mesh"
    no_temporaries
    ;;
  animate_outputs_all_or_nothing)
    # A failing --state: no frame is written either.
    mkdir frames
    run_expecting 2 animate -q --frames 3 --svg-dir frames --state /proc/x.state
    [ -z "$(ls frames)" ] || fail "frames were written although --state failed: $(ls frames | head -3)"
    no_temporaries
    ;;
  animate_replaces_atomically)
    printf 'old\n' > final.state
    ln final.state old.state
    run_expecting 0 animate -q --frames 2 --state final.state
    [ "$(cat old.state)" = "old" ] || fail "the old final.state was written in place, not replaced"
    [ "$(head -n 1 final.state)" = "bccmis-state 1" ] || fail "final.state is not a state"
    no_temporaries
    ;;
  *)
    fail "unknown case"
    ;;
esac
echo "ok: $case_name"
