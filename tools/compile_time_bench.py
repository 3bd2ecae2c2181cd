#!/usr/bin/env python3
"""compile_time_bench.py OUT.json -- the schedule compiler's time: the
albatross-schedule command (as make runs it, from build/venv) on a few
descriptions, each run REPEATS times into a new folder; per description the
CPU time of the run (user + system, Python's start included) and its wall
time, the median and the range, and the plan's size (ROM entries, modes).
The descriptions:
  * sim/mobot3.toml, the robot (make schedule's default);
  * the robot with its two modes (sim/mobot3.toml + sim/mobot3_modes.toml,
    joined as make does for build/schedule/mobot3-modes/);
  * the same planned for 20 % independent faults (--faults 0.2);
  * compiler/examples/modes_share.toml, two modes that fill the ROM.
Standard library only; run from the checkout (make bench-compile-time)."""
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

REPEATS = 3


def run_once(cmd):
    """(CPU seconds of the child, wall seconds, completed process)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    r = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall, r


def measure(label, desc, extra, tmp):
    cpus, walls = [], []
    rep = None
    for i in range(REPEATS):
        out = os.path.join(tmp, f"{label}-{i}")
        cpu, wall, r = run_once(["albatross-schedule", desc, "-o", out, "-q"] + extra)
        if r.returncode != 0:
            sys.exit(f"compile_time_bench: {desc} {' '.join(extra)}: exit {r.returncode}: {r.stderr.strip()}")
        cpus.append(cpu)
        walls.append(wall)
        with open(os.path.join(out, "report.json")) as f:
            rep = json.load(f)
    modes = rep.get("modes") or []
    entries = sum(m["entries"] for m in modes) + len(modes) if modes else rep["entries"]
    return {"label": label, "description": desc, "options": extra, "repeats": REPEATS,
            "rom_entries": entries, "modes": len(modes),
            "cpu_s": round(statistics.median(cpus), 3), "cpu_s_min": round(min(cpus), 3),
            "cpu_s_max": round(max(cpus), 3),
            "wall_s": round(statistics.median(walls), 3), "wall_s_max": round(max(walls), 3)}


def main():
    out_json = sys.argv[1]
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        joined = os.path.join(tmp, "mobot3-modes.toml")
        with open(joined, "w") as f:
            for part in ("sim/mobot3.toml", "sim/mobot3_modes.toml"):
                with open(part) as p:
                    f.write(p.read())
        cases = [("robot", "sim/mobot3.toml", []),
                 ("robot-modes", joined, []),
                 ("robot-modes-f20", joined, ["--faults", "0.2"]),
                 ("modes-share", "compiler/examples/modes_share.toml", [])]
        load = os.getloadavg()[0]
        for label, desc, extra in cases:
            run = measure(label, desc, extra, tmp)
            if desc == joined:
                run["description"] = "sim/mobot3.toml + sim/mobot3_modes.toml"
            runs.append(run)
            print(f"compile time {label}: {run['rom_entries']} ROM entries, CPU {run['cpu_s']} s "
                  f"({run['cpu_s_min']}-{run['cpu_s_max']}), wall {run['wall_s']} s")
    os.makedirs(os.path.dirname(out_json) or ".", exist_ok=True)
    with open(out_json, "w") as f:
        json.dump({"generator": "tools/compile_time_bench.py", "cpus": os.cpu_count(),
                   "load_average_1min_at_start": round(load, 2), "runs": runs}, f, indent=1)
    print(f"compile time: {out_json}")


if __name__ == "__main__":
    main()
