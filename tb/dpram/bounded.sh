#!/usr/bin/env bash
# bounded.sh SECONDS CMD... -- run CMD for at most SECONDS of wall time.
# The second line of defence behind a bench's own watchdogs (which count
# simulated cycles and name the fault): a regression in those must not hang
# make test or CI.  Exit status: CMD's, or 124 (137 if it had to be killed)
# after a last line that says what happened.
set -u
if [ $# -lt 2 ]; then echo "usage: $0 SECONDS CMD..." >&2; exit 2; fi
limit=$1; shift
timeout --kill-after=10 "$limit" "$@"
rc=$?
if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    echo "TIMEOUT: '$*' was stopped after $limit s of wall time (exit $rc); expected it to end on its own" \
         "well within that (its watchdogs in simulated cycles should have stopped it first)"
fi
exit "$rc"
