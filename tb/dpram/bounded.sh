#!/usr/bin/env bash
# bounded.sh SECONDS CMD... -- run CMD for at most SECONDS of CPU time (and,
# for a CMD that hangs without using the CPU, at most 20 x SECONDS of wall
# time).  The second line of defence behind a bench's own watchdogs (which
# count simulated cycles and name the fault): a regression in those must not
# hang make test or CI.  CPU time, not wall time, so that a busy machine
# (other jobs, make -j) cannot make a healthy run look stuck.  Exit status:
# CMD's, or 124 / 137 (wall bound) / 152 (CPU bound, SIGXCPU) after a last
# line that says what happened.
set -u
if [ $# -lt 2 ]; then echo "usage: $0 SECONDS CMD..." >&2; exit 2; fi
limit=$1; shift
# SIGXCPU at the limit, SIGKILL 5 s of CPU time later if that is ignored.
(ulimit -S -t "$limit" && ulimit -H -t "$((limit + 5))" && exec timeout --kill-after=10 "$((20 * limit))" "$@") \
    2>&1
rc=$?
if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ] || [ "$rc" -eq 152 ]; then
    echo "TIMEOUT: '$*' was stopped at its bound, $limit s of CPU time or $((20 * limit)) s of wall time" \
         "(exit $rc); expected it to end on its own well within that (its watchdogs in simulated cycles" \
         "should have stopped it first)"
fi
exit "$rc"
