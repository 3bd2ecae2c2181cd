#!/usr/bin/env bash
# make -C <checkout> schedule SCHEDULE_DESC=<relative path>, run from another
# directory, as a user with a description of their own runs it:
#   1. plant.toml (a copy of compiler/examples/faults.toml) in the caller's
#      directory compiles, and the printed report is plant's (its first line
#      names it), with the termination and fault sections, probabilities as 1 - miss;
#   2. with plant.toml gone, the same command fails and names the path it looked
#      for, although build/schedule/plant/ still holds the previous output;
#   3. make ... build/schedule/plant/rom.hex then fails too (no rule treats the
#      missing description as an intermediate file it may skip);
#   4. a path that exists only inside the checkout (sim/mobot3.toml) is not
#      found from the caller's directory;
#   5. a sub-make of the checkout's recipes sees the caller's absolute path.
set -uo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
work="$repo/build/schedule-caller"
rm -rf "$work" "$repo/build/schedule/plant"
mkdir -p "$work"
cp "$repo/compiler/examples/faults.toml" "$work/plant.toml"
# make as from a shell in $work (bash sets PWD there).
mk() { (cd "$work" && make --no-print-directory -C "$repo" "$@" 2>&1); }
fail() { echo "schedule-caller-dir: $*"; exit 1; }

out=$(mk schedule SCHEDULE_DESC=plant.toml); rc=$?
[ $rc = 0 ] || fail "1: expected make schedule SCHEDULE_DESC=plant.toml (in $work) to pass, it exited $rc: $out"
grep -q "^ALBATROSS schedule of .* (plant.toml)" <<<"$out" || fail "1: expected the report of plant.toml, got: $(head -3 <<<"$out")"
grep -q "^Import termination per consumer" <<<"$out" || fail "1: expected the termination section in the printed report"
grep -q "^Fault hypothesis: .*target probability 1 - 1.0e-09" <<<"$out" || fail "1: expected the fault section in the printed report"
grep -Eq "q 1 - [0-9.]+e-[0-9]+, cycle 1 - [0-9.]+e-[0-9]+" <<<"$out" || fail "1: expected delivery probabilities as 1 - miss"
grep -Eq "(q|cycle) (0\.9|1\.0)" <<<"$out" && fail "1: a delivery probability is printed as a decimal that reads as certainty"
[ -f "$repo/build/schedule/plant/rom.hex" ] || fail "1: expected build/schedule/plant/rom.hex"
echo "schedule-caller-dir: 1. plant.toml from $work compiled, its report printed"

rm "$work/plant.toml"
out=$(mk schedule SCHEDULE_DESC=plant.toml); rc=$?
[ $rc != 0 ] || fail "2: expected make schedule to fail without plant.toml, it passed and printed: $(head -3 <<<"$out")"
grep -q "no description $work/plant.toml" <<<"$out" || fail "2: expected the message to name $work/plant.toml, got: $out"
grep -q "^ALBATROSS schedule" <<<"$out" && fail "2: a report was printed although the description is missing"
echo "schedule-caller-dir: 2. missing plant.toml: exit $rc, '$out'"

out=$(mk build/schedule/plant/rom.hex SCHEDULE_DESC=plant.toml); rc=$?
[ $rc != 0 ] || fail "3: expected make build/schedule/plant/rom.hex to fail without plant.toml, it passed: $out"
grep -q "$work/plant.toml" <<<"$out" || fail "3: expected the message to name $work/plant.toml, got: $out"
echo "schedule-caller-dir: 3. the old rom.hex is not taken as current: '$out'"

out=$(mk schedule SCHEDULE_DESC=sim/mobot3.toml); rc=$?
[ $rc != 0 ] || fail "4: expected sim/mobot3.toml not to be found from $work, make passed"
grep -q "no description $work/sim/mobot3.toml" <<<"$out" || fail "4: expected the message to name $work/sim/mobot3.toml, got: $out"
echo "schedule-caller-dir: 4. a checkout-relative path is not looked up in the checkout: '$out'"
# 5. A sub-make of the checkout's own recipes gets the caller's file, not the
#    relative path looked up again from the checkout (make test runs sub-makes).
cp "$repo/compiler/examples/four_slot.toml" "$work/plant.toml"
out=$(mk schedule-probe SCHEDULE_DESC=plant.toml); rc=$?
[ $rc = 0 ] && grep -q "probe: SCHEDULE_DESC=$work/plant.toml" <<<"$out" || \
    fail "5: expected a sub-make to see SCHEDULE_DESC=$work/plant.toml, got (exit $rc): $out"
echo "schedule-caller-dir: 5. a sub-make sees $work/plant.toml"
rm -rf "$work" "$repo/build/schedule/plant"
echo "schedule-caller-dir: pass"
