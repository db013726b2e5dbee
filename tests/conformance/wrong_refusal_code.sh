#!/bin/sh
# A deliberately wrong implementation for the conformance tests: reports
# max-level refusals as coarser-neighbor. Usage: wrong_refusal_code.sh BCCMIS TRACE
"$1" replay --quiet --check=none "$2" | sed 's/refused max-level$/refused coarser-neighbor/'
