#!/usr/bin/env bash
# run_test.sh NAME CMD... -- run one test, record its verdict for the summary.
# The command's exit status is the verdict; its output goes to the console and
# to build/results/NAME.log.  The last line it prints is kept for the summary.
set -u
name=$1; shift
mkdir -p build/results
log=build/results/$name.log
t0=$(date +%s%N)
"$@" 2>&1 | tee "$log"
rc=${PIPESTATUS[0]}
# The run's wall time (its builds, done by make before, not included).
ms=$(( ($(date +%s%N) - t0) / 1000000 ))
echo "$ms" > "build/results/$name.ms"
secs=$(printf '%d.%d s' $((ms / 1000)) $((ms % 1000 / 100)))
if [ "$rc" -eq 0 ]; then
    echo "PASS" > "build/results/$name.status"
    echo "PASS $name ($secs)"
else
    echo "FAIL" > "build/results/$name.status"
    echo "FAIL $name (exit $rc, $secs): $(tail -n 1 "$log")"
fi
exit 0
