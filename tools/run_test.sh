#!/usr/bin/env bash
# run_test.sh NAME CMD... -- run one test, record its verdict for the summary.
# The command's exit status is the verdict; its output goes to
# build/results/NAME.log.  Alone (make test-NAME) the output also goes to the
# console; in a suite (make test, make check: ALB_SUITE set) only the verdict
# line does, with the progress [n/N] (build/results/.total, .count), and
# for a failure the log's last lines.  The verdict line ends with the run's
# wall time (its builds, done by make before, are timed by
# tools/recipe_shell.sh); build/results/NAME.ms keeps it for the summary.
set -u
name=$1; shift
dir=build/results
mkdir -p "$dir"
log=$dir/$name.log
suite=${ALB_SUITE-}
unset ALB_SUITE
t0=$(date +%s%N)
if [ -n "$suite" ]; then
    "$@" >"$log" 2>&1 </dev/null
    rc=$?
else
    "$@" 2>&1 | tee "$log"
    rc=${PIPESTATUS[0]}
fi
ms=$(( ($(date +%s%N) - t0) / 1000000 ))
echo "$ms" > "$dir/$name.ms"
# Its CPU time (user + system of its processes): what it costs on an idle machine.
times > "$dir/.times.$$"
tail -n 1 "$dir/.times.$$" | awk '{ s = 0; for (i = 1; i <= 2; i++) { split($i, a, "m"); s += a[1] * 60 + a[2] } printf "%d\n", s * 1000 }' \
    > "$dir/$name.cpu_ms"
rm -f "$dir/.times.$$"
secs=$(printf '%d.%d s' $((ms / 1000)) $((ms % 1000 / 100)))
progress=
if [ -n "$suite" ] && [ -f "$dir/.total" ]; then
    n=$(flock "$dir/.count.lock" bash -c 'n=$(( $(cat "$1" 2>/dev/null || echo 0) + 1 )); echo $n > "$1"; echo $n' \
        _ "$dir/.count")
    progress="[$n/$(cat "$dir/.total")] "
fi
if [ "$rc" -eq 0 ]; then
    echo "PASS" > "$dir/$name.status"
    echo "${progress}PASS $name ($secs)"
else
    echo "FAIL" > "$dir/$name.status"
    echo "${progress}FAIL $name (exit $rc, $secs): $(tail -n 1 "$log")"
    if [ -n "$suite" ]; then
        tail -n 15 "$log" | sed 's/^/    | /'
        echo "    (the whole output: $log)"
    fi
fi
exit 0
