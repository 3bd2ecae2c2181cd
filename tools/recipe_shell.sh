#!/usr/bin/env bash
# recipe_shell.sh TARGET -c CMD -- the shell of make's recipes while a suite
# runs (make test / make check set ALB_SUITE; tools/mk/suite.mk makes this
# script SHELL, with the target's name first).  It times every recipe line
# into build/results/recipes.tsv (target, wall ms, exit status, CPU ms, start
# in ms since the epoch), so that builds
# are measured too, not only the tests' runs.  A build's output goes to
# build/results/builds/TARGET.log and reaches the console only if the build
# fails; a test's recipe (test-*: tools/run_test.sh, which prints the verdict
# line) keeps its console.  $(shell ...) calls (no target) run unchanged.
if [ "${1-}" = "-c" ] || [ $# -lt 3 ]; then
    exec /bin/bash "$@"
fi
target=$1; shift
dir=build/results
mkdir -p "$dir/builds"
t0=$(date +%s%N)
case "$target" in
    test-*)
        /bin/bash "$@"; rc=$? ;;
    *)
        log=$dir/builds/${target//\//_}.log
        /bin/bash "$@" >>"$log" 2>&1; rc=$?
        if [ "$rc" -ne 0 ]; then
            echo "BUILD FAILED $target (exit $rc); the last lines of $log:"
            tail -n 25 "$log" | sed 's/^/    /'
        fi ;;
esac
# The CPU time of the recipe's processes (user + system, bash's `times`):
# what the recipe costs whatever else runs on the machine.
times > "$dir/.times.$$"
cpu=$(tail -n 1 "$dir/.times.$$" | awk '{ s = 0; for (i = 1; i <= 2; i++) { split($i, a, "m"); s += a[1] * 60 + a[2] } printf "%d", s * 1000 }'); rm -f "$dir/.times.$$"
printf '%s\t%d\t%d\t%d\t%d\n' "$target" $(( ($(date +%s%N) - t0) / 1000000 )) "$rc" "$cpu" $(( t0 / 1000000 )) >> "$dir/recipes.tsv"
exit "$rc"
