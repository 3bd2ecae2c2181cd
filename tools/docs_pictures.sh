#!/usr/bin/env bash
# docs_pictures.sh COMMITTED FRESH [COMMITTED FRESH ...] -- the pictures
# committed for the manual (docs/img/) are generated files: each COMMITTED copy
# must equal, byte for byte, the FRESH one the build has just made.  Fails
# naming every stale or missing picture and the command that refreshes them
# (make docs-pictures).  Used by test-docs-pictures (tools/mk/docs.mk).
set -u
if [ $# -eq 0 ] || [ $(($# % 2)) -ne 0 ]; then
    echo "usage: $0 COMMITTED FRESH [COMMITTED FRESH ...]"; exit 2
fi
bad=0; n=0
while [ $# -gt 0 ]; do
    committed=$1 fresh=$2; shift 2; n=$((n + 1))
    if [ ! -f "$fresh" ]; then
        echo "docs-pictures: the build made no $fresh (to compare with $committed)"; bad=1
    elif [ ! -f "$committed" ]; then
        echo "docs-pictures: $committed is missing (the build made $fresh)"; bad=1
    elif ! cmp -s "$committed" "$fresh"; then
        echo "docs-pictures: $committed is stale: it differs from $fresh" \
             "($(cmp "$committed" "$fresh" 2>&1 | head -n 1 | sed 's/.*differ: //'))"; bad=1
    else
        echo "docs-pictures: $committed is current"
    fi
done
if [ $bad -ne 0 ]; then
    echo "docs-pictures: FAIL: refresh the committed pictures with 'make docs-pictures' and commit them"
    exit 1
fi
echo "docs-pictures: all $n committed pictures are current"
