#!/usr/bin/env bash
# negative.sh BIN SEED ACCESSES -- prove that each checker of test_cdc can fail.
# Runs test_cdc once per injected fault (--inject=MODE, a fault in the harness,
# never in the RTL) and passes only if the checker meant to catch that fault
# reports failures: test_cdc exits 64 + a bit mask of the failed checkers.
set -u
bin=$1; seed=$2; accesses=${3:-20000}
status=0
for spec in torn:1:atomicity latency:2:latency write:4:visibility ram:8:ram; do
    IFS=: read -r mode bit checker <<< "$spec"
    out=$("$bin" --seed="$seed" --accesses="$accesses" --inject="$mode" 2>&1)
    rc=$?
    echo "$out" | grep -E '^FAIL' | head -n 2 | sed 's/^FAIL/  caught (injected fault):/'
    if (( rc >= 64 && rc < 128 && ((rc - 64) & bit) )); then
        echo "negative $mode: checker $checker failed as it must (exit $rc)"
    else
        echo "negative $mode: expected checker $checker to fail (exit 64 with bit $bit set), came exit $rc"
        echo "$out" | tail -n 8
        status=1
    fi
done
if (( status )); then echo "cdc-negative: FAILED, a checker did not catch its fault"; exit 1; fi
echo "cdc-negative: PASSED, every checker caught its injected fault"
