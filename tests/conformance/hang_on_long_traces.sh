#!/bin/sh
# A deliberately wrong implementation: hangs on traces with more than three
# operations (the harness must time it out). Usage: hang_on_long_traces.sh BCCMIS TRACE
if [ "$(grep -cE '^(refine|coarsen) ' "$2")" -gt 3 ]; then exec sleep 1000; fi
"$1" replay --quiet --check=none "$2"
