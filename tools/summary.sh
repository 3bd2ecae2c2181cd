#!/usr/bin/env bash
# summary.sh TEST... -- print the failed tests from build/results (each with
# the last lines of its log, so a CI log alone says why) and the closing line
# "N passed, N failed".  A test without a verdict (its build
# failed) counts as failed.  Exits non-zero if any test failed.  (The times:
# tools/suite_report.py, printed before.)
set -u
pass=0; fail=0
for t in "$@"; do
    f=build/results/$t.status
    if [ -e "$f" ] && grep -q PASS "$f"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        if [ -e "$f" ]; then
            echo "failed: $t (build/results/$t.log); its last lines:"
            tail -n 12 "build/results/$t.log" 2>/dev/null | sed 's/^/    | /'
        else
            echo "failed: $t (did not run: its build failed)"
        fi
    fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
