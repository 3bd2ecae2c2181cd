#!/usr/bin/env python3
"""bounds_at_target.py REPORT.json OUT.txt -- each consumer's age bound at the
fault hypothesis' target from the schedule compiler's report.json (channels[].
consumers[].faults.age_bound.at_target), one line each:
    at_target <channel name> <board index> <clocks>
for tb_system --bounds-at-target (a run at the planned fault rate judges the
latency / age it measures against them).  Standard library only."""
import json
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: bounds_at_target.py REPORT.json OUT.txt")
    try:
        with open(sys.argv[1]) as f:
            r = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"bounds_at_target: cannot read {sys.argv[1]}: {e}")
    out = [f"# from {sys.argv[1]}"]
    for c in r["channels"]:
        for d in c["consumers"]:
            b = ((d.get("faults") or {}).get("age_bound") or {}).get("at_target")
            if not b:
                sys.exit(f"bounds_at_target: {c['name']} to board {d['board_index']} has no bound at the target "
                         "(a description without [faults]?)")
            out.append(f"at_target {c['name']} {d['board_index']} {b['clocks']}")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
