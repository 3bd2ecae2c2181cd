#!/usr/bin/env bash
# summary.sh TEST... -- print the failed tests from build/results and the
# closing line "N passed, N failed".  A test without a verdict (its build
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
        [ -e "$f" ] && echo "failed: $t (build/results/$t.log)" || echo "failed: $t (did not run: its build failed)"
    fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
