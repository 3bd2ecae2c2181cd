"""The whole compilation: plan, ROM, self-check against the contract,
generated files, and writing them."""

from __future__ import annotations

import json
import os
from typing import Optional

from .cgen import render_board_c, render_board_header, render_ram_hex
from .description import load_description, load_toml, parse_description
from .faults import plan_for_hypothesis
from .layout import allocate_ram, verify_ram_layout
from .model import Plan, ScheduleError, System
from .modes import mode_summary, plan_modes
from .picture import render_modes_svg
from .plan import build_plan, channel_gaps
from .report import build_report, render_report_txt
from .rom import MAX_ENTRIES, encode_rom, encode_rom_modes, rom_hex, verify_rom
from .termination import enforce as enforce_termination, violations


def self_check(system: System, plan: Plan, rom: list, layout: dict):
    """Verify our own output against the contract before writing anything."""
    problems, entries = verify_rom(rom, n_chan=system.bus.n_chan, n_boards=len(system.boards),
                                   ram_words=[r // 4 for r in system.ram_bytes],
                                   sync_expected=system.sync_mode)
    for b, insts in layout.items():
        problems += verify_ram_layout([(f"{ch.name} {role}", base, size) for ch, role, base, size in insts],
                                      system.ram_bytes[b])
    for ch in system.channels:
        if not ch.slots:
            problems.append(f"channel {ch.name} has no slot")
        elif max(channel_gaps(ch.slots, plan.cycle)) > ch.period_clocks:
            problems.append(f"channel {ch.name}: guaranteed period exceeds max_period")
    for ch, who in violations(system, plan):
        problems.append(f"channel {ch.name}: three-buffer Import over its bound at {', '.join(w[0] for w in who)}")
    if system.sync_mode and plan.slots[-1].start + plan.slots[-1].length + system.bus.poll_cycles > plan.cycle:
        problems.append("no poll window at the end of the cycle")
    if problems:
        raise AssertionError("internal error, the plan breaks the contract: " + "; ".join(problems))


def _plan(system: System):
    # build_plan, spacing slots for bounded Imports, with retry budgets, drop run
    # and redundancy sized for the fault hypothesis (if the description has one)
    return plan_for_hypothesis(system, lambda s: enforce_termination(s, build_plan))


def compile_system(system: System):
    """(system, plan, rom, report): with [[mode]], every mode planned and
    checked over the one RAM layout, the image of all modes (rom), and the
    start-up mode's system and plan (its channels carry its slots) for the
    other outputs, the report listing every mode (report["modes"]); without,
    the description's system."""
    layout = allocate_ram(system)
    if not system.modes:
        plan = _plan(system)
        rom = encode_rom(system, plan)
        self_check(system, plan, rom, layout)
        return system, plan, rom, build_report(system, plan)
    planned = []
    for m, (ms, plan) in zip(system.modes, plan_modes(system, _plan)):
        rom = encode_rom(ms, plan)
        try:
            self_check(ms, plan, rom, layout)
        except AssertionError as e:
            raise AssertionError(f"mode '{m.name}': {e}")
        planned.append((ms, plan, rom, build_report(ms, plan)))
    total = sum(len(p.slots) for _, p, _, _ in planned) + len(planned)
    if total > MAX_ENTRIES:     # plan_modes shares the ROM: never
        raise AssertionError(f"internal error, the modes take {total} ROM entries, at most {MAX_ENTRIES}")
    rom = encode_rom_modes([(s, p, m.next) for m, (s, p, _, _) in zip(system.modes, planned)])
    problems, _ = verify_rom(rom, n_chan=system.bus.n_chan, n_boards=len(system.boards),
                             ram_words=[r // 4 for r in system.ram_bytes], sync_expected=system.sync_mode)
    if problems:
        raise AssertionError("internal error, the image of the modes breaks the contract: " + "; ".join(problems))
    ms, plan, _, rep = planned[0]
    rep["modes"] = [mode_summary(system, system.modes, i, r, s) for i, (s, _, _, r) in enumerate(planned)]
    ms.mode_plans = [(m, s, p, r) for m, (s, p, _, r) in zip(system.modes, planned)]
    return ms, plan, rom, rep


def generate(system: System, plan: Plan, rom: list, rep: dict) -> dict:
    """All output files: {file name: text}."""
    desc = os.path.basename(system.source)
    files = {"rom.hex": rom_hex(rom),
             "report.json": json.dumps(rep, indent=2) + "\n",
             "report.txt": render_report_txt(rep),
             "timeline.svg": render_modes_svg(system, plan, rep)}
    for b, name in enumerate(system.boards):
        files[f"{name}.h"] = render_board_header(system, b, desc, plan)
        files[f"{name}.c"] = render_board_c(system, b, desc)
        files[f"{name}_ram.hex"] = render_ram_hex(system, b)
    return files


def write_outputs(files: dict, out_dir: str):
    try:
        os.makedirs(out_dir, exist_ok=True)
        # rom.hex last: its time stamp (the make target) is the newest
        for name in sorted(files, key=lambda n: n == "rom.hex"):
            text = files[name]
            path = os.path.join(out_dir, name)
            tmp = path + ".tmp"
            with open(tmp, "w", newline="\n") as f:
                f.write(text)
            os.replace(tmp, path)
    except OSError as e:
        raise ScheduleError(f"{out_dir}: cannot write the outputs: {e.strerror or e}")


def compile_file(path: str, out_dir: Optional[str] = None, no_redundancy: bool = False, faults=None):
    """faults: [rate, mean_burst, probability] replacing the description's
    [faults]; mean_burst None: independent accesses; probability None (or
    absent): the description's, else 1 - 1e-9."""
    if faults is None:
        system = load_description(path)
    else:
        data, text = load_toml(path)
        old = data.get("faults") if isinstance(data.get("faults"), dict) else {}
        faults = list(faults) + [None] * (3 - len(faults))
        new = {"rate": faults[0],
               "probability": faults[2] if faults[2] is not None else old.get("probability", 1.0 - 1e-9)}
        if faults[1] is not None:
            new["mean_burst"] = faults[1]
        data["faults"] = new
        system = parse_description(data, path, text)
    if no_redundancy:   # one slot per channel and cycle: the spare capacity stays idle
        for ch in system.channels:
            ch.max_slots = 1
    system, plan, rom, rep = compile_system(system)
    files = generate(system, plan, rom, rep)
    if out_dir is not None:
        write_outputs(files, out_dir)
    return system, plan, rep, files
