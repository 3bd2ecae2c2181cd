"""The whole compilation: plan, ROM, self-check against the contract,
generated files, and writing them."""

from __future__ import annotations

import json
import os
import shutil
import stat
import sys
import tempfile
from typing import Optional

from .cgen import render_board_c, render_board_header, render_ram_hex
from .description import load_description, load_toml, parse_description
from .faults import plan_for_hypothesis
from .layout import allocate_ram, verify_ram_layout
from .model import Plan, ScheduleError, System, not_due_cost
from .modes import mode_summary, plan_modes
from .multirate import build_multirate_plan, check_timing, wants_multirate
from .picture import render_modes_svg
from .plan import build_plan, channel_bounds
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
        elif channel_bounds(system, plan, ch)["guaranteed_period_clocks"] > ch.period_clocks:
            problems.append(f"channel {ch.name}: guaranteed period exceeds max_period")
    if plan.multirate:      # every minor cycle of the cluster, at the model's skip cost (not the plan's word)
        problems += check_timing(plan.slots, plan.cycle, plan.cluster, plan.capacity, not_due_cost(system.bus))
    for ch, who in violations(system, plan):
        problems.append(f"channel {ch.name}: three-buffer Import over its bound at {', '.join(w[0] for w in who)}")
    if system.sync_mode and plan.slots[-1].start + plan.slots[-1].length + system.bus.poll_cycles > plan.cycle:
        problems.append("no poll window at the end of the cycle")
    if problems:
        raise AssertionError("internal error, the plan breaks the contract: " + "; ".join(problems))


def _saved(system: System):
    """What a failed plan may leave changed on the system (plan_for_hypothesis
    and termination.enforce set them), to start the next planner afresh."""
    return (system.drop_run, [(ch, ch.max_slots, ch.retries, ch.__dict__.get("spaced_for_termination"))
                              for ch in system.channels])


def _restore(system: System, saved):
    system.drop_run, chans = saved
    for ch, ms, rt, sp in chans:
        ch.max_slots, ch.retries = ms, rt
        ch.__dict__.pop("spaced_for_termination", None)
        if sp is not None:
            ch.spaced_for_termination = sp
    for k in ("fault_eval", "fault_split"):
        system.__dict__.pop(k, None)


def _plan(system: System):
    """build_plan, spacing slots for bounded Imports, with retry budgets, drop
    run and redundancy sized for the fault hypothesis (if the description has
    one).  The single-rate plan when it fits (system.planner "auto"); else,
    or when the description fixes a minor cycle or a repetition, the
    multi-rate plan (multirate.py).  When neither fits, the single-rate
    plan's errors come first, then the multi-rate planner's."""
    def with_(build):
        return plan_for_hypothesis(system, lambda s: enforce_termination(s, build))

    if system.planner == "single-rate" or (system.planner == "auto" and not wants_multirate(system)):
        saved = _saved(system)
        try:
            return with_(build_plan)
        except ScheduleError as e:
            if system.planner == "single-rate" or system.sync_mode:
                raise
            first = e
        _restore(system, saved)
    else:
        first = None
    if system.sync_mode:
        raise ScheduleError(f"{system.source}: a multi-rate plan ([bus] minor_cycle_us, a channel's repetition) "
                            f"needs the time-rigid time mode ([system] mode): a position-synchronised cycle "
                            "follows the positions, not a count of minor cycles")
    try:
        return with_(build_multirate_plan)
    except ScheduleError as e:
        if first is None:
            raise
        err = ScheduleError(first.messages + [m for m in e.messages if m not in first.messages])
        err.kind = getattr(e, "kind", None)     # the multi-rate planner's rejection (multirate.MultiRateRejection)
        raise err


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


# The output folder (docs/compiler.md "Outputs").  A run writes every output
# into a new folder beside the target (<out>.tmp-XXXXXXXX), then puts it in
# place: the old folder is renamed aside (<out>.old-XXXXXXXX), the new one
# renamed to <out>, the old one removed.  A failure before the swap removes
# the new folder and leaves the old one as it was.  The manifest lists the
# files a run wrote: the next run drops them (a board renamed leaves no
# stale header behind) and keeps, unchanged, whatever else the folder holds
# (make's tb_plan.txt, the description itself).  A folder that is not empty
# and holds no earlier run (no manifest, and no report.json of this
# compiler: the folders of a compiler without manifests) is never replaced.
MANIFEST = "manifest.txt"
MANIFEST_HEAD = ("# albatross-schedule: the files of this run.  The next run into this folder replaces "
                 "the folder, drops these files and keeps the others.\n")
BASE_OUTPUTS = ("rom.hex", "report.json", "report.txt", "timeline.svg")


def output_order(files: dict) -> list:
    """The order of the writes: rom.hex last (its time stamp, make's target, is
    the newest), the manifest just before it."""
    return sorted(files, key=lambda n: (n == "rom.hex", n == MANIFEST))


def earlier_outputs(folder: str):
    """The names of the files the run that wrote `folder` wrote, or None if
    it holds no run of the compiler: those its manifest lists, or, written
    before manifests, those its report.json names (with the `.tmp` files a
    failed write of those compilers left)."""
    man = os.path.join(folder, MANIFEST)
    if os.path.isfile(man) and not os.path.islink(man):
        try:
            with open(man, encoding="utf-8") as f:
                names = {ln.strip() for ln in f if ln.strip() and not ln.startswith("#")}
        except (OSError, UnicodeError):
            return None
        return {n for n in names if os.sep not in n and n not in (".", "..")} | {MANIFEST}
    try:
        with open(os.path.join(folder, "report.json"), encoding="utf-8") as f:
            rep = json.load(f)
        boards = [b["name"] for b in rep["boards"]]
        if not str(rep["generator"]).startswith("albatross_schedule") or \
                not all(isinstance(b, str) and b and os.sep not in b for b in boards):
            return None
    except (OSError, ValueError, KeyError, TypeError):
        return None
    names = set(BASE_OUTPUTS) | {f"{b}{x}" for b in boards for x in (".h", ".c", "_ram.hex")}
    return names | {n + ".tmp" for n in names}


def _write_file(path: str, text: str):
    with open(path, "w", newline="\n") as f:
        f.write(text)


def _link_or_copy(src: str, dst: str):
    """A file kept from the old folder: a hard link (same data and time
    stamp), or a copy where links are not possible."""
    try:
        os.link(src, dst, follow_symlinks=False)
    except OSError:
        shutil.copy2(src, dst, follow_symlinks=False)


def _keep(src: str, dst: str):
    if os.path.islink(src):
        os.symlink(os.readlink(src), dst)
    elif os.path.isdir(src):
        shutil.copytree(src, dst, symlinks=True, copy_function=_link_or_copy)
    elif os.path.isfile(src):
        _link_or_copy(src, dst)
    else:
        raise OSError(0, "not a file, a folder or a link")


def _kind(path: str) -> str:
    return "a link" if os.path.islink(path) else "a folder" if os.path.isdir(path) else \
        "a file" if os.path.isfile(path) else "a special file"


def _plan_swap(files: dict, out_dir: str, target: str, description: Optional[str]) -> list:
    """Check that `target` may be replaced; the names of what the new folder
    keeps from it."""
    if os.path.lexists(target) and not os.path.isdir(target):
        raise ScheduleError(f"{out_dir}: not a folder (the outputs go into a folder of their own)")
    cwd = os.path.realpath(os.getcwd())
    if cwd == target or cwd.startswith(target.rstrip(os.sep) + os.sep):
        raise ScheduleError(f"{out_dir}: the output folder is the current folder or holds it; it is replaced "
                            "whole by each run: name a folder of its own (for example -o out)")
    if not os.path.isdir(target):
        return []
    try:
        names = sorted(os.listdir(target))
    except OSError as e:
        raise ScheduleError(f"{out_dir}: cannot read the output folder: {e.strerror or e}")
    ours = earlier_outputs(target)
    others = [n for n in names
              if ours is None or n not in ours or not os.path.isfile(os.path.join(target, n))
              or os.path.islink(os.path.join(target, n))]
    for n in others:
        if n in files or n == MANIFEST:
            where = os.path.join(out_dir, n)
            raise ScheduleError(f"{where}: {_kind(os.path.join(target, n))} that no earlier run of the compiler "
                                f"wrote ({MANIFEST} does not list it) has the name of an output: the outputs "
                                "cannot replace it; move it away")
    desc = os.path.realpath(description) if description else None
    mine = {n for n in others if desc and os.path.join(target, n) == desc}
    if ours is None and set(others) - mine:
        raise ScheduleError(f"{out_dir}: not empty and not an output folder of the compiler (no {MANIFEST}): it "
                            f"holds {', '.join(sorted(set(others) - mine))}. A run replaces its output folder "
                            "whole: name a new or empty folder, or one that an earlier run wrote")
    return others


def write_outputs(files: dict, out_dir: str, description: Optional[str] = None):
    """Write the outputs {name: text} as the folder out_dir, whole or not at
    all (see MANIFEST above).  description: the file compiled; a folder that
    holds it alone counts as empty (make writes a joined description there)."""
    target = os.path.realpath(out_dir)         # a link to the folder stays a link
    keep = _plan_swap(files, out_dir, target, description)
    parent = os.path.dirname(target)
    base = os.path.basename(target)
    try:
        os.makedirs(parent, exist_ok=True)
        new = tempfile.mkdtemp(prefix=base + ".tmp-", dir=parent)
    except OSError as e:
        raise ScheduleError(f"{out_dir}: cannot create the new output folder beside it, in {parent}: "
                            f"{e.strerror or e}")
    old = None
    try:
        listed = dict(files)
        listed[MANIFEST] = MANIFEST_HEAD + "".join(n + "\n" for n in sorted(files))
        for name in output_order(listed):
            try:
                _write_file(os.path.join(new, name), listed[name])
            except OSError as e:
                raise ScheduleError(f"{os.path.join(out_dir, name)}: cannot write it: {e.strerror or e} "
                                    f"(nothing in {out_dir} changed)")
        for name in keep:
            try:
                _keep(os.path.join(target, name), os.path.join(new, name))
            except (OSError, shutil.Error) as e:
                raise ScheduleError(f"{os.path.join(out_dir, name)}: cannot keep it in the new output folder: "
                                    f"{getattr(e, 'strerror', None) or e} (nothing in {out_dir} changed)")
        try:
            if os.path.isdir(target):
                os.chmod(new, stat.S_IMODE(os.stat(target).st_mode))
                old = tempfile.mkdtemp(prefix=base + ".old-", dir=parent)
                os.rename(target, old)             # onto the empty folder just made
                try:
                    os.rename(new, target)
                except OSError:
                    os.rename(old, target)
                    raise
            else:
                umask = os.umask(0)
                os.umask(umask)
                os.chmod(new, 0o777 & ~umask)
                os.rename(new, target)
        except OSError as e:
            raise ScheduleError(f"{out_dir}: cannot put the new outputs in place: {e.strerror or e} "
                                "(the earlier outputs are as they were)")
    except BaseException:
        shutil.rmtree(new, ignore_errors=True)
        if old is not None and os.path.isdir(old) and not os.listdir(old):
            os.rmdir(old)
        raise
    if old is not None:
        failed = []
        shutil.rmtree(old, onerror=lambda fn, path, exc: failed.append(path))
        if failed:
            print(f"warning: {out_dir}: the earlier outputs, moved to {old}, could not all be removed "
                  f"({failed[0]})", file=sys.stderr)


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
        write_outputs(files, out_dir, path)
    return system, plan, rep, files
