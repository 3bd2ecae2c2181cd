"""Compile-time termination bounds of the consumers' Imports (the derivation is in docs/compiler.md "Termination bounds").

Every consumer imports from a destination instance whose producer is the
controller.  Three-buffer kind: the consumer's loop (load Actual; while it
differs from ReadLocked: store ReadLocked, load Actual) ends unless the
controller publishes (stores Actual) between two of its loads.  With

  T  the longest time between two loads of Actual in the consumer's loop,
  V  the time from the load whose value is stored into ReadLocked to the next load,
  D  the shortest time between two publishes of the channel to that destination,

D <= T gives no bound (the controller may overtake every pass); D > T bounds
the ReadLocked stores (= passes) of one Import by 1 + ceil(V / (D - T)), which
is 2 when D >= T + V.  Accesses of such an Import: 1 + 2*passes + Wd, with Wd
= W + 1 the destination's payload words (the value and taken_at); 1 + Wd when
nothing is new.  Four-slot kind: 1 pass, 3 + Wd accesses (1 + Wd when Old),
whatever the controller does.

All times here are controller clocks.  D per channel and destination comes
from the plan: a publish of slot i ends before the slot's deadline (start +
length, docs/controller.md, rtl/albatross_sequencer.v) and its store of Actual
starts no earlier than fetch + access_cycles*(E - 1) after the slot start, E
being the fewest accesses of a transfer up to and including that store.

The loop timing comes from the description's optional [board.<name>] tables:
  core             "picorv32" or "serv": T and V from CORE_TIMING (the core's clocks)
  clock_hz         the board CPU's clock (default [system] clock_hz); T and V are
                   converted to controller clocks, rounded up
  import_t_clocks  T in the CPU's clocks (overrides the core's figure)
  import_v_clocks  V in the CPU's clocks (default: T)
A board without a table has unknown timing: its three-buffer consumers are
reported as not checked."""

from __future__ import annotations

import math

from .fourslot import FOUR_SLOT
from .model import BOARD_KEYS, BoardTiming, ScheduleError

MAX_U32 = (1 << 32) - 1     # the upper bound of a clock rate or a loop time in clocks

# Import loop timing per core, in the core's own clocks, with the driver
# c-driver/albatross.c built as the firmware is (rv32i, -Os) and the board
# memory of soc/ (pico_core/serv_core, board_memmap, the DPRAM's CPU port).
# The loop does not depend on the payload size (the pass is load Actual,
# compare, check, store ReadLocked, fence, load Actual; the payload is read
# once, after the loop).  Measured by make bench-pico and make bench-import-pass
# (tools/mk/termination.mk, tb/pico/firmware/import_pass.c); see docs/compiler.md
# "Termination bounds".
CORE_TIMING = {
    "picorv32": {"t": 90, "v": 90,
                 "source": "PicoRV32: make bench-pico, alb_import New (one pass) max - Old min = 90 clocks for "
                           "4, 16, 64 and 256 bytes (make bench-import-pass: 83); V taken = T"},
    "serv": {"t": 909, "v": 909,
             "source": "SERV: make bench-import-pass (build/reports/import_pass.json), alb_import New (one "
                       "pass) max - Old min = 3861 - 2952 = 909 clocks; V taken = T"},
}


def parse_board_timing(table, boards, clock_hz, err, describe):
    """[board.<name>] tables -> {board index: BoardTiming}; errors through err."""
    out = {}
    if not isinstance(table, dict):
        err.general("[board] must hold one table per board: [board.<name>]")
        return out
    index = {b: i for i, b in enumerate(boards) if isinstance(b, str)}
    for bname, bd in table.items():
        tname = f"board.{bname}"
        if bname not in index:
            err.system(None, f"unknown board '{bname}' (boards: {', '.join(map(str, boards))})", table=tname)
            continue
        if not isinstance(bd, dict):
            err.system(None, "must be a table", table=tname)
            continue
        ok = True
        for key in bd:
            if key not in BOARD_KEYS:
                err.system(key, f"unknown field (expected one of {', '.join(sorted(BOARD_KEYS))})", table=tname)
                ok = False
        core = bd.get("core")
        t = v = None
        src = None
        if core is not None:
            if core not in CORE_TIMING:
                err.system("core", f"{describe(core)}: expected one of "
                           f"{', '.join(repr(c) for c in CORE_TIMING)} (or give import_t_clocks)", table=tname)
                ok = False
            else:
                t, v, src = CORE_TIMING[core]["t"], CORE_TIMING[core]["v"], f"core {core}"
        cpu_hz = bd.get("clock_hz", clock_hz)
        if not isinstance(cpu_hz, int) or isinstance(cpu_hz, bool) or cpu_hz <= 0:
            err.system("clock_hz", f"{describe(cpu_hz)} is not a positive integer", table=tname)
            ok = False
        elif cpu_hz > MAX_U32:
            err.system("clock_hz", f"{cpu_hz} is out of range: an integer from 1 to {MAX_U32} (Hz, a 32-bit "
                       "figure)", table=tname)
            ok = False
        for key in ("import_t_clocks", "import_v_clocks"):
            x = bd.get(key)
            if x is None:
                continue
            if not isinstance(x, int) or isinstance(x, bool) or x <= 0:
                err.system(key, f"{describe(x)} is not a positive integer number of clocks", table=tname)
                ok = False
            elif x > MAX_U32:
                err.system(key, f"{x} is out of range: an integer from 1 to {MAX_U32} (clocks, a 32-bit "
                           "figure)", table=tname)
                ok = False
            elif key == "import_t_clocks":
                t, src = x, "the description"
                if "import_v_clocks" not in bd:
                    v = x
            else:
                v, src = x, "the description"
        if ok and t is None:
            err.system("core", "give core or import_t_clocks (the board's Import loop timing)", table=tname)
            ok = False
        if ok and v > t:
            err.system("import_v_clocks", f"{v} exceeds import_t_clocks {t} (V is one of the loop's "
                       "load-to-load times, T the longest)", table=tname)
            ok = False
        if ok:
            conv = lambda x: -(-x * clock_hz // cpu_hz)      # noqa: E731  CPU clocks -> controller clocks
            note = "" if cpu_hz == clock_hz else f", CPU at {cpu_hz} Hz"
            out[index[bname]] = BoardTiming(t=conv(t), v=conv(v), source=src + note)
    return out


def first_publish_accesses(ch) -> int:
    """E: the fewest bus accesses of a transfer up to and including the store
    of one destination's Actual (that destination the only one needing the
    value).  COPY: one load of the source Actual, W source loads, the load of
    ReadLocked, W value stores, taken_at, Actual.  TIME/STATUS: no Import."""
    if ch.kind == "copy":
        return 2 * ch.words + 4
    return ch.words + 3


def min_cycle(system, plan) -> int:
    """The shortest time from a cycle's start to the next one's: H1 in
    time-rigid mode; in position-synchronised mode the next cycle may start as
    soon as the last entry has ended (the poll then sees a new position)."""
    if system.sync_mode:
        return max(s.start + s.length for s in plan.slots)
    return plan.cycle


def publish_gap(system, plan, ch) -> int:
    """D: the shortest time between two publishes of ch to any one of its
    destinations (controller clocks)."""
    bus = system.bus
    early = bus.fetch_cycles + bus.access_cycles * (first_publish_accesses(ch) - 1)
    if getattr(plan, "multirate", False):
        # its runs over its span; a value in F fragments is published at
        # most once in F runs, in the run of its last fragment, whose fewest
        # accesses up to an Actual store are its words' loads and stores,
        # taken_at and Actual (no Import)
        runs, span, f = ch.slots, ch.run_span or plan.cycle, ch.fragments
        if f > 1:
            early = bus.fetch_cycles + bus.access_cycles * (2 * (ch.words - (f - 1) * ch.frag_words) + 1)
        return min(runs[(i + f) % len(runs)] + span * ((i + f) // len(runs)) + early - (runs[i] + ch.slot_len)
                   for i in range(len(runs)))
    slots = sorted((s for s in plan.slots if s.channel is ch), key=lambda s: s.start)
    cyc = min_cycle(system, plan)
    d = None
    for i, s in enumerate(slots):
        nxt = slots[(i + 1) % len(slots)]
        nstart = nxt.start + (cyc if i + 1 == len(slots) else 0)
        g = nstart + early - (s.start + s.length)
        d = g if d is None else min(d, g)
    return d


def import_bound(layout, words, taken_at_words, d, timing):
    """The bound of one consumer's Import.  Returns a dict (None figures: unbounded or unknown)."""
    wd = words + taken_at_words
    b = {"kind": layout, "payload_words": wd, "D_clocks": d,
         "T_clocks": timing.t if timing else None, "V_clocks": timing.v if timing else None,
         "timing_source": timing.source if timing else None,
         "accesses_old": 1 + wd}
    if layout == FOUR_SLOT:
        b.update(checked=True, bounded=True, max_passes=1, max_readlocked_stores=1, max_accesses=3 + wd)
        return b
    if timing is None:
        b.update(checked=False, bounded=None, max_passes=None, max_readlocked_stores=None, max_accesses=None)
        return b
    if d <= timing.t:
        b.update(checked=True, bounded=False, max_passes=None, max_readlocked_stores=None, max_accesses=None)
        return b
    n = 1 + math.ceil(timing.v / (d - timing.t))
    b.update(checked=True, bounded=True, max_passes=n, max_readlocked_stores=n, max_accesses=1 + 2 * n + wd)
    return b


def channel_termination(system, plan, ch, taken_at_words=1):
    """Per destination of ch: the board and its Import bound."""
    d = publish_gap(system, plan, ch)
    out = []
    for b in ch.consumers:
        x = import_bound(ch.layout, ch.words, taken_at_words, d, system.timing.get(b))
        x["board"] = system.boards[b]
        out.append(x)
    return out


def required_gap(timing, limit):
    """The smallest D that gives a finite bound (limit None) or at most limit passes:
    1 + ceil(V / (D - T)) <= limit  <=>  D >= T + ceil(V / (limit - 1))."""
    if limit is None:
        return timing.t + 1
    return timing.t + -(-timing.v // (limit - 1))


def violations(system, plan):
    """Channels with a three-buffer consumer whose Import has no bound, or more
    passes than the channel's max_import_passes: [(channel, [(board, D, T, source, D needed)])]."""
    out = []
    for ch in system.channels:
        lim = ch.max_import_passes
        bad = []
        for b, x in zip(ch.consumers, channel_termination(system, plan, ch)):
            if not x["checked"] or x["kind"] == FOUR_SLOT:
                continue
            if x["bounded"] is False or (lim is not None and x["max_passes"] > lim):
                bad.append((x["board"], x["D_clocks"], x["T_clocks"], x["timing_source"],
                            required_gap(system.timing[b], lim)))
        if bad:
            out.append((ch, bad))
    return out


def enforce(system, build_plan):
    """Build the plan; while a three-buffer consumer has no bound (or more passes
    than max_import_passes), space its channel's slots (fewer redundant slots,
    spread by the placement) and build again.  A channel down to one slot per
    cycle that still fails is an error naming the channel and the consumer."""
    bus = system.bus
    while True:
        plan = build_plan(system)
        bad = violations(system, plan)
        # its ROM entries (single-rate: its slots a cycle; multi-rate: ch.slots are its runs)
        entries = {ch.index: sum(1 for s in plan.slots if s.channel is ch) for ch, _ in bad}
        stuck = [(ch, who) for ch, who in bad if entries[ch.index] <= 1]
        for ch, who in bad:
            if entries[ch.index] > 1:
                # Aim at once at a slot count whose even spacing gives the D needed, then one less per round.
                early = bus.fetch_cycles + bus.access_cycles * (first_publish_accesses(ch) - 1)
                need = max(w[4] for w in who) + ch.slot_len - early
                ch.max_slots = max(1, min(entries[ch.index] - 1, plan.cycle // max(need, 1)))
                ch.spaced_for_termination = True
        if len(stuck) == len(bad):
            break
    if stuck:
        msgs = []
        for ch, who in stuck:
            for board, d, t, src, dneed in who:
                what = ("has no termination bound" if d <= t else
                        f"needs more than max_import_passes = {ch.max_import_passes} passes")
                msgs.append(
                    f"{system.source}: channel '{ch.name}', consumer '{board}': the three-buffer Import {what}: "
                    f"the controller may publish to '{board}' every D = {d} clocks even with one slot per cycle, "
                    f"and the board's Import loop takes T = {t} clocks between two loads of Actual ({src}); "
                    f"D must be at least {dneed}. "
                    + ("Make the channel kind = \"four_slot\", or lengthen" if ch.kind == "copy" else "Lengthen")
                    + " the cycle (the smallest max_period_us)")
        raise ScheduleError(msgs)
    return plan


def termination_summary(bounds) -> str:
    """One line per consumer for report.txt."""
    x = bounds
    if x["kind"] == FOUR_SLOT:
        return f"four-slot: 1 pass, {x['max_accesses']} accesses (Old {x['accesses_old']})"
    if not x["checked"]:
        return "three-buffer: not checked (no [board] timing)"
    if not x["bounded"]:
        return f"three-buffer: UNBOUNDED (D {x['D_clocks']} <= T {x['T_clocks']})"
    return (f"three-buffer: <= {x['max_passes']} passes, {x['max_accesses']} accesses (Old {x['accesses_old']})")

