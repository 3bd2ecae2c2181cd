#!/usr/bin/env bash
# ctrl_equiv.sh [REV] [CLOCKS] -- cycle-by-cycle equivalence of this tree's
# controller (rtl/, its parts) with the controller of git revision REV
# (default main), on random bus traffic (tb/equiv/equiv_main.cpp: acks after
# 0..2 clocks, err, timeouts, random read data, resets, ROM upsets), on the
# robot's two ROMs (time-rigid and position-synchronised, made by make).
# For changes that must not alter behaviour (area work): any difference in
# any output in any clock fails.  CLOCKS per run, default 2000000; 14 runs.
# HAS=0 in the environment compares the core configuration (the four HAS_*
# parameters 0) instead of the full one (HAS=1, the default).  Outputs in
# build/equiv/.  Exit status 0 when every run is equivalent.
set -euo pipefail
rev=${1:-main}
clocks=${2:-2000000}
has=${HAS:-1}
case "$has" in 0|1) ;; *) echo "ctrl_equiv: HAS must be 0 (core configuration) or 1 (full), not '$has'"; exit 2;; esac
out=build/equiv
rm -rf "$out/ref" "$out/obj"
mkdir -p "$out/ref"
git archive "$rev" rtl | tar -x -C "$out/ref"
# Every controller part of either tree, from each tree's controller core
# (tools/corefiles.py; a part the reference does not have is skipped).
part_names() { python3 tools/corefiles.py --root "$1" controller | sed -n 's|^rtl/albatross_\(.*\)\.v$|\1|p'; }
parts=$( { part_names . && part_names "$out/ref"; } | sort -u | tr '\n' ' ')
[ -n "$parts" ] || { echo "ctrl_equiv: no controller parts in the cores of this tree and $rev"; exit 1; }
alt=$(echo $parts | tr ' ' '|')
for p in $parts; do
    [ -f "$out/ref/rtl/albatross_$p.v" ] || continue
    sed -E "s/\balbatross_($alt)\b/ref_albatross_\1/g" "$out/ref/rtl/albatross_$p.v" > "$out/ref/ref_albatross_$p.v"
done
make -s build/schedule/mobot3/rom.hex build/schedule/mobot3_possync/rom.hex >/dev/null
verilator --cc --exe --build -j 2 -O2 -Wno-fatal -Wno-lint -Wno-style --top-module tb_equiv -GHAS=$has \
    -Irtl -y rtl -y "$out/ref" -Mdir "$out/obj" tb/equiv/tb_equiv.v "$(pwd)/tb/equiv/equiv_main.cpp" \
    > "$out/build.log" 2>&1 || { tail -n 20 "$out/build.log"; exit 1; }
bin=$out/obj/Vtb_equiv
fail=0
run() { if ! "$bin" "$@" | tail -n 1 | sed "s|^|$*: |"; then fail=1; fi; }
for rom in mobot3 mobot3_possync; do
    for f in 0 0.05 0.4; do
        run "$clocks" 1 $f 200000 +rom=build/schedule/$rom/rom.hex
        run "$clocks" 2 $f 0 +rom=build/schedule/$rom/rom.hex
    done
done
# A ROM upset (bit 16 of a word flips at time 50000): the background check's path.
for w in 3 7 100 201; do
    run "$clocks" 3 0.05 0 +rom=build/schedule/mobot3/rom.hex +rom_upset_word=$w +rom_upset_at=50000
done
[ $fail -eq 0 ] && echo "ctrl_equiv: every run equivalent to $rev (HAS=$has)" || echo "ctrl_equiv: FAIL: a run differed from $rev (HAS=$has)"
exit $fail
