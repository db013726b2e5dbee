#!/bin/sh
# Output-file robustness of `bccmis replay` (issue 6): files are written
# atomically (temporary file + rename), a failed run leaves existing outputs
# untouched, and no temporary file is ever left behind.
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

printf 'lattice 2 1 1\nrefine 2 2\n' > good.trace
printf 'lattice 2 1 1\nrefine 2 2\nsplit 4 4\n' > bad.trace

case $case_name in
  parse_error_keeps_outputs)
    # A run that fails on its input must not touch existing output files.
    printf 'old state\n' > out.state
    printf 'old log\n' > out.log
    "$bccmis" replay --quiet --state out.state --log out.log bad.trace > stdout.txt 2> stderr.txt
    rc=$?
    [ $rc -eq 2 ] || fail "exit code $rc, expected 2"
    [ "$(cat out.state)" = "old state" ] || fail "out.state was changed"
    [ "$(cat out.log)" = "old log" ] || fail "out.log was changed"
    no_temporaries
    ;;
  success_leaves_only_outputs)
    "$bccmis" replay --quiet --state out.state --log out.log good.trace > stdout.txt 2> stderr.txt
    rc=$?
    [ $rc -eq 0 ] || fail "exit code $rc, expected 0: $(cat stderr.txt)"
    [ "$(tail -n 1 out.state)" = "end 5 11" ] || fail "out.state is incomplete: $(tail -n 1 out.state)"
    [ "$(cat out.log)" = "refine 2 2 ok" ] || fail "out.log is wrong: $(cat out.log)"
    [ -s stdout.txt ] && fail "stdout is not empty with --state and --log"
    no_temporaries
    ;;
  missing_output_directory)
    "$bccmis" replay --quiet --state no/such/dir/out.state good.trace > stdout.txt 2> stderr.txt
    rc=$?
    [ $rc -eq 2 ] || fail "exit code $rc, expected 2"
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
  *)
    fail "unknown case"
    ;;
esac
echo "ok: $case_name"
