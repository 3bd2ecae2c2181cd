#!/usr/bin/env bash
# summary.sh TEST... -- print each test's verdict from build/results and the
# closing line "N passed, N failed".  A test without a verdict (its build
# failed) counts as failed.  Exits non-zero if any test failed.
set -u
pass=0; fail=0
for t in "$@"; do
    f=build/results/$t.status
    if [ -e "$f" ] && grep -q PASS "$f"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        [ -e "$f" ] && echo "failed: $t" || echo "failed: $t (did not run: its build failed)"
    fi
done
# The slowest runs (build/results/NAME.ms, by run_test.sh; builds not included).
slow=$(for t in "$@"; do [ -e "build/results/$t.ms" ] && echo "$(cat "build/results/$t.ms") $t"; done | sort -rn | head -n 8)
if [ -n "$slow" ]; then
    echo "slowest runs:"
    echo "$slow" | awk '{ printf "  %7.1f s  %s\n", $1 / 1000, $2 }'
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
