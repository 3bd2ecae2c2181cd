#!/usr/bin/env python3
"""fault_plan_bench.py DESC.toml OUT.json -- the compiler's predictions for one
description planned for several fault hypotheses:
per hypothesis (independent accesses at 5, 20, 30, 50 %, with the first
target of 1 - 1e-9, 1 - 1e-6, 1 - 1e-3, 0.99 that plans; bursts of mean 2
and 5 at 1 - 1e-9), per channel and consumer, the slots per cycle, the retry
budget, the slot and cycle delivery probabilities and the age bounds
(fault-free, with retries, at the target), or the compiler's rejection.
Runs the compiler as make does (albatross-schedule --faults, from build/venv).
Standard library only."""
import json
import os
import subprocess
import sys
import tempfile

RATES = (0.05, 0.2, 0.3, 0.5)
BURSTS = (None, 2, 5)        # None: independent accesses
# Targets tried in turn for the independent runs until one plans (the
# lowest rate at which the robot's 50 us channels cannot hold 1 - 1e-9 shows
# the probability it can still promise); bursts at 1 - 1e-9 only.
TARGETS = (1 - 1e-9, 1 - 1e-6, 1 - 1e-3, 0.99)


def compile_one(desc, rate, burst, prob, env):
    with tempfile.TemporaryDirectory() as d:
        spec = f"{rate},{'' if burst is None else burst},{prob!r}"
        r = subprocess.run(["albatross-schedule", desc, "-o", d, "-q", "--faults", spec],
                           capture_output=True, text=True, env=env)
        run = {"rate": rate, "mean_burst": burst, "independent": burst is None, "probability": prob,
               "planned": r.returncode == 0}
        if r.returncode == 0:
            with open(os.path.join(d, "report.json")) as f:
                rep = json.load(f)
            run["drop_run"] = rep["drop_run"]
            run["mean_burst"] = rep["fault_hypothesis"]["mean_burst"]
            run["channels"] = [
                {"channel": c["name"], "consumer": k["board"], "slots": c["redundancy"],
                 "retries_per_slot": c["retries_per_slot"], **k["faults"]}
                for c in rep["channels"] for k in c["consumers"]]
        else:
            run["error"] = r.stderr.strip().splitlines()[0] if r.stderr.strip() else f"exit {r.returncode}"
        return run


def main():
    desc, out = sys.argv[1], sys.argv[2]
    env = dict(os.environ)
    runs = []
    for burst in BURSTS:
        for rate in RATES:
            for prob in (TARGETS if burst is None else TARGETS[:1]):
                run = compile_one(desc, rate, burst, prob, env)
                if run["planned"] or prob == TARGETS[-1] or burst is not None:
                    break
            runs.append(run)
            what = "independent" if burst is None else f"burst {burst}"
            print(f"fault plan {os.path.basename(desc)} rate {rate} {what} probability 1 - {1 - run['probability']:.1e}: "
                  + (f"K {run['drop_run']}, " + ", ".join(
                      f"{c['channel']}->{c['consumer']} x{c['slots']} q 1 - {c['slot_miss_probability']:.1e} "
                      f"age {c['age_bound']['at_target']['us']} us" for c in run["channels"])
                     if run["planned"] else "rejected: " + run["error"][:200]))
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    with open(out, "w") as f:
        json.dump({"description": desc, "runs": runs}, f, indent=1)
    print(f"fault plan: {out}")


if __name__ == "__main__":
    main()
