#!/usr/bin/env python3
"""plan_for_tb.py REPORT.json OUT.txt -- the facts the system testbench needs
from the schedule compiler's report.json, one per line (see tb/common/plan.h),
so the C++ harness needs no JSON parser.  Standard library only."""
import json
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plan_for_tb.py REPORT.json OUT.txt")
    try:
        with open(sys.argv[1]) as f:
            r = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"plan_for_tb: cannot read {sys.argv[1]}: {e}")
    ram = {b["index"]: b["ram_bytes"] for b in r["boards"]}
    if len(set(ram.values())) != 1:
        sys.exit("plan_for_tb: the testbench needs every board's RAM of one size")
    mode = "sync" if r["mode"] == "position-synchronised" else "rigid"
    out = [f"# from {sys.argv[1]}",
           f"system {len(r['boards'])} {r['cycle']['clocks']} {mode} {r['bus']['n_chan']} {ram[0]}"]
    out.append(f"clock {r['clock_hz']}")
    out += [f"board {b['index']} {b['name']}" for b in sorted(r["boards"], key=lambda b: b["index"])]
    for c in r["channels"]:
        bound = c["latency"] if c["kind"] == "copy" else c["age_bound"]
        src = c["producer"] or {"board_index": -1, "base": 0}
        out.append(f"channel {c['id']} {c['name']} {c['kind']} {c['size']} {c['words']} "
                   f"{src['board_index']} {src['base']} {c['guaranteed_period']['clocks']} "
                   f"{bound['fault_free']['clocks']} {bound['with_retries']['clocks']} "
                   f"{1 if c['sync'] else 0} {len(c['slots'])} "
                   f"{1 if c.get('channel_kind') == 'four_slot' else 0}")
        for i, d in enumerate(c["consumers"]):
            out.append(f"dest {c['id']} {i} {d['board_index']} {d['base']}")
    ids = {c["name"]: c["id"] for c in r["channels"]}
    out += [f"mode_request {c['id']}" for c in r["channels"] if c.get("mode_request")]
    out += [f"mode_info {c['id']}" for c in r["channels"] if c.get("mode_info")]
    for k, m in enumerate(r.get("modes") or []):
        at_target = (m.get("switch_latency_at_target") or {}).get("clocks") or 0
        out.append(f"mode {k} {m['name']} {m['cycle']['clocks']} {m['switch_latency']['clocks']} {at_target}")
        for c in m["channels"]:
            bound = c["latency"] if c.get("age_bound") is None else c["age_bound"]
            out.append(f"mode_channel {k} {ids[c['name']]} {c['guaranteed_period']['clocks']} "
                       f"{bound['fault_free']['clocks']} {bound['with_retries']['clocks']}")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
