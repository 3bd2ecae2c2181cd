#!/bin/bash
# The mutant audit's negative: a throw-away repository with one source file
# and three mutants.  The audit must pass the good one and name each stale
# edit of the other two: a multi-edit script whose second edit no longer
# lands (the source reworded), and a script whose '# target:' file does not
# have the line it edits.  Exit 0 only if it does exactly that.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
dir=$(mktemp -d "${TMPDIR:-/tmp}/mutant_audit_neg.XXXXXX")
trap 'rm -rf "$dir"' EXIT
mkdir -p "$dir/rtl" "$dir/tb/mutants"
printf 'module m;\n    wire a = b & c;\n    wire d = e | f;\nendmodule\n' > "$dir/rtl/m.v"
printf '# good\ns/wire a = b & c;/wire a = b | c;/\n/wire d = e | f;/d\n' > "$dir/tb/mutants/good.sed"
printf '# half\ns/wire a = b & c;/wire a = b;/\ns/wire d = e || f;/wire d = e;/\n' > "$dir/tb/mutants/half.sed"
printf '# target: rtl/m.v\ns/wire x = y;/wire x = 0;/\n' > "$dir/tb/mutants/target.sed"
git -C "$dir" init -q && git -C "$dir" add rtl/m.v || { echo "negative: could not make the repository in $dir"; exit 1; }
out=$(python3 "$here/tools/mutant_audit.py" --root "$dir" --scripts tb 2>&1); rc=$?
echo "$out"
fail=0
[ $rc -eq 1 ] || { echo "expected the audit to exit 1 on two stale mutants, came exit $rc"; fail=1; }
echo "$out" | grep -q "STALE tb/mutants/half.sed:3: expected this edit to change rtl/m.v" \
    || { echo "expected the stale second edit of half.sed (line 3) to be named"; fail=1; }
echo "$out" | grep -q "STALE tb/mutants/target.sed:2: expected this edit to change rtl/m.v" \
    || { echo "expected the edit of target.sed (line 2) to be named against its target rtl/m.v"; fail=1; }
if echo "$out" | grep -q "good.sed"; then echo "expected good.sed to pass, it was reported"; fail=1; fi
echo "$out" | grep -q "3 mutants, 2 stale edit(s)" || { echo "expected '3 mutants, 2 stale edit(s)'"; fail=1; }
[ $fail -eq 0 ] && echo "negative: the audit names both stale edits and passes the good mutant"
exit $fail
