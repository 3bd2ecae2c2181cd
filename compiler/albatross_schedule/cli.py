"""The command line: albatross-schedule DESCRIPTION.toml -o DIR (the console
command that pip install ./compiler provides; python -m albatross_schedule is
the same)."""

from __future__ import annotations

import argparse
import os
import sys

from .model import ScheduleError, us
from .pipeline import compile_file


def _cut(rep: dict) -> str:
    """The console's note when the ROM cut a plan's redundant slots (report.json redundant_slots)."""
    r = rep.get("redundant_slots") or {}
    return (f"; redundancy cut to fit the ROM ({r['planned']} of the {r['bus_allows']} redundant slots the bus "
            "time allows)") if r.get("cut") else ""


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="albatross-schedule", description="ALBATROSS schedule compiler: system description (TOML) "
                                 "-> schedule ROM, board headers, RAM images, reports.")
    ap.add_argument("description", help="system description (.toml)")
    ap.add_argument("-o", "--out", required=True, metavar="DIR",
                    help="output folder, replaced whole by the outputs (created if missing; an earlier run's files "
                         "are dropped, files of others kept; a folder holding no earlier run must be empty)")
    ap.add_argument("-q", "--quiet", action="store_true", help="print nothing on success")
    ap.add_argument("--no-redundancy", action="store_true",
                    help="one slot per channel and cycle (to measure what redundancy buys)")
    ap.add_argument("--faults", metavar="RATE[,BURST[,PROBABILITY]]",
                    help="plan for this fault hypothesis instead of the description's [faults] "
                         "(per-access rate; mean burst length, empty or absent: independent accesses; "
                         "target probability, absent: the description's or 1 - 1e-9)")
    args = ap.parse_args(argv)
    try:
        faults = None
        if args.faults is not None:
            try:
                parts = args.faults.split(",")
                if not 1 <= len(parts) <= 3 or not parts[0].strip():
                    raise ValueError
                faults = [float(x) if x.strip() else None for x in parts]
            except ValueError:
                raise ScheduleError(f"--faults {args.faults!r}: expected RATE[,BURST[,PROBABILITY]] (numbers)")
        system, plan, rep, files = compile_file(args.description, args.out, args.no_redundancy, faults)
    except ScheduleError as e:
        for m in e.messages:
            print(f"error: {m}", file=sys.stderr)
        return 2
    except Exception as e:  # a bug of the compiler, never a bad description
        if os.environ.get("ALB_DEBUG"):
            raise
        print(f"internal error of the schedule compiler (albatross-schedule): {type(e).__name__}: {e} "
              "(set ALB_DEBUG=1 for the traceback)", file=sys.stderr)
        return 3
    if not args.quiet:
        shape = (f"multi-rate: minor cycle {plan.cycle} clocks ({us(plan.cycle, system.clock_hz):g} us), cluster of "
                 f"{plan.cluster}" if plan.multirate else
                 f"cycle {plan.cycle} clocks ({us(plan.cycle, system.clock_hz):g} us)")
        print(f"{args.description}: {shape}, "
              f"{len(plan.slots)} entries, bus utilisation {100 * rep['bus_utilisation']:.1f} % "
              f"-> {args.out}/ ({len(files)} files)" + ("" if rep.get("modes") else _cut(rep)))
        for m in rep.get("modes", []):
            print(f"  mode {m['name']}{' (start-up)' if m['start_up'] else ''}: "
                  + ("multi-rate: minor cycle " if m.get("planner") == "multi-rate" else "cycle ")
                  + f"{m['cycle']['clocks']} clocks"
                  + (f", cluster of {m['cluster']['minor_cycles']}" if m.get("planner") == "multi-rate" else "")
                  + f", {m['entries']} entries, bus utilisation "
                  f"{100 * m['bus_utilisation']:.1f} %{_cut(m)}")
        if rep.get("modes"):
            print("  (rom.hex holds every mode; the controller starts in the first and switches at a cycle "
                  "boundary when the mode_request channel asks)")
    return 0
