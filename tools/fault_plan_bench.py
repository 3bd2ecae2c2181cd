#!/usr/bin/env python3
"""fault_plan_bench.py DESC.toml OUT.json -- the compiler's predictions for one
description planned for several fault hypotheses (issue 15 section 2):
per hypothesis, per channel and consumer, the slots per cycle, the retry
budget, the slot and cycle delivery probabilities and the age bounds
(fault-free, with retries, at the target), or the compiler's rejection.
Runs the compiler as make does (python3 -m albatross_schedule --faults).
Standard library only."""
import json
import os
import subprocess
import sys
import tempfile

HYPOTHESES = [(0.05, 1), (0.2, 1), (0.3, 1), (0.5, 1), (0.05, 2), (0.2, 2), (0.3, 2), (0.5, 2)]
PROBABILITY = 1 - 1e-9


def main():
    desc, out = sys.argv[1], sys.argv[2]
    env = dict(os.environ, PYTHONPATH="compiler")
    runs = []
    for rate, burst in HYPOTHESES:
        with tempfile.TemporaryDirectory() as d:
            r = subprocess.run([sys.executable, "-m", "albatross_schedule", desc, "--out", d, "-q",
                                "--faults", f"{rate},{burst},{PROBABILITY!r}"],
                               capture_output=True, text=True, env=env)
            run = {"rate": rate, "mean_burst": burst, "probability": PROBABILITY, "planned": r.returncode == 0}
            if r.returncode == 0:
                with open(os.path.join(d, "report.json")) as f:
                    rep = json.load(f)
                run["drop_run"] = rep["drop_run"]
                run["channels"] = [
                    {"channel": c["name"], "consumer": k["board"], "slots": c["redundancy"],
                     "retries_per_slot": c["retries_per_slot"], **k["faults"]}
                    for c in rep["channels"] for k in c["consumers"]]
            else:
                run["error"] = r.stderr.strip().splitlines()[0] if r.stderr.strip() else f"exit {r.returncode}"
            runs.append(run)
            print(f"fault plan {os.path.basename(desc)} rate {rate} burst {burst}: "
                  + (f"K {run['drop_run']}, " + ", ".join(
                      f"{c['channel']}->{c['consumer']} x{c['slots']} q {c['slot_delivery_probability']:.9f} "
                      f"age {c['age_bound']['at_target']['us']} us" for c in run["channels"])
                     if run["planned"] else "rejected: " + run["error"][:200]))
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    with open(out, "w") as f:
        json.dump({"description": desc, "runs": runs}, f, indent=1)
    print(f"fault plan: {out}")


if __name__ == "__main__":
    main()
