#!/bin/sh
# A deliberately wrong implementation: crashes (SIGSEGV) as soon as a coarsen
# is accepted. Usage: crash_on_coarsen.sh BCCMIS TRACE
out=$("$1" replay --quiet --check=none "$2")
case "$out" in
  *"coarsen "*" ok"*) kill -SEGV $$ ;;
esac
printf '%s\n' "$out"
