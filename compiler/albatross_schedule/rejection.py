"""Why a description has no multi-rate plan (multirate.build_multirate_plan
gave up), and what would make it fit: docs/compiler.md "Plan", "Rejections".

  * a proof that the demand exceeds the bus: every plan carries each
    channel's whole transfer (at least its slot length L; fragments cost
    more) once per max_period, every entry costs at least the skip cost in
    every minor cycle, and a minor cycle is at most 2^time_bits - 1 clocks
    with the mode window idle;
  * with OR-Tools installed, a proof on the grid: the exact search
    (exact.solve_grid) finds no placement at the best candidate minor cycles,
    with whole values and one entry per channel (the skip costs counted);
  * else the planner gave up without a proof.
Each names the cut or the period to relax that would make it fit (a relaxed
period is tried: the planner places everything with it)."""

from __future__ import annotations

from .model import ScheduleError, System, us
from .multirate import MAX_REP, Attempt, attempt, fragmentable, item_for, minor_clocks, usable
from .plan import slot_length

# The exact search's deterministic time in all, the candidate minor cycles
# it tries, the largest system it is tried on.
EXACT_LIMIT = 3.0
EXACT_MINORS = 3
EXACT_MAX_CHANNELS = 64


class MultiRateRejection(ScheduleError):
    """The multi-rate planner found no plan.  kind: "demand" (a proof: the
    channels need more than the bus), "exact" (a proof on the plain grid at
    the best minor cycles) or "gave-up" (no proof)."""

    def __init__(self, messages, kind: str):
        super().__init__(messages)
        self.kind = kind



def demand(system: System) -> float:
    """The channels' bus demand: sum of slot length / period (one whole
    transfer per period, plan.slot_length)."""
    return sum(slot_length(ch, system.bus) / ch.period_clocks for ch in system.channels)


def reject(system: System, tries: list, skip: int, out_of_budget: bool) -> MultiRateRejection:
    """Why no plan: a proof, or the planner's give-up; with what would make
    it fit."""
    bus = system.bus
    src = system.source
    hz = system.clock_hz
    top = (1 << bus.time_bits) - 1
    lengths = {ch.index: slot_length(ch, bus) for ch in system.channels}
    # Proof 1: every plan carries each channel's whole transfer (at least L
    # clocks, fragments cost more) once per period, every entry costs at
    # least the skip cost in every minor cycle, and a minor cycle is at most
    # 2^time_bits - 1 clocks with the mode window idle: the fraction of the
    # bus they need, sum (L - skip) / P + (N skip + window) / 2^time_bits.
    need = sum((lengths[ch.index] - skip) / ch.period_clocks for ch in system.channels) + \
        (len(system.channels) * skip + system.mode_window) / top
    share = sorted(system.channels, key=lambda c: -lengths[c.index] / c.period_clocks)
    total = demand(system)
    if need > 1.0 or total > 1.0:
        worst = ", ".join(f"'{c.name}' {100 * lengths[c.index] / c.period_clocks:.1f} % (slot {lengths[c.index]} "
                          f"clocks every {c.max_period_us} us)" for c in share[:3])
        what = (f"the channels need {100 * total:.1f} % of the bus (sum of slot length / max_period)" if total > 1.0
                else f"the channels need {100 * total:.1f} % of the bus (sum of slot length / max_period), and with "
                f"the skip costs of their {len(system.channels)} entries in every minor cycle ({skip} clocks each, "
                f"a minor cycle at most {top} clocks) {100 * need:.1f} %")
        return MultiRateRejection(
            [f"{src}: infeasible plan (proof): {what}; no schedule carries more than 100 %. To fit, cut the demand "
             f"by {100 * (max(need, total) - 1.0):.1f} points of the bus: the largest shares are {worst}; relax "
             "their max_period_us, shrink their values or raise clock_hz"], "demand")
    best = min((t for t in tries if t.items), key=lambda t: t.load / t.cap, default=None)
    proof = exact_proof(system, tries, skip)
    lines = []
    for t in tries[:6]:
        lines.append(f"minor cycle {t.minor} clocks ({us(t.minor, hz):g} us): {t.reason}")
    more = f" (and {len(tries) - 6} more)" if len(tries) > 6 else ""
    fix = relax_hint(system, best, skip) if best is not None else room_hint(system, tries, skip)
    if proof:
        return MultiRateRejection(
            [f"{src}: infeasible plan (proof on the grid): {proof}; the planner, which may also split values into "
             f"fragments, found none either: " + "; ".join(lines) + more + ". " + fix], "exact")
    why = "its work budget ran out" if out_of_budget else "no candidate minor cycle fits"
    return MultiRateRejection(
        [f"{src}: no plan found: the multi-rate planner gave up without a proof ({why}; the demand, "
         f"{100 * demand(system):.1f} % of the bus, is not above it): " + "; ".join(lines) + more + ". " + fix],
        "gave-up")


def room_hint(system: System, tries: list, skip: int) -> str:
    """What would make it fit when no candidate minor cycle holds every
    channel's slot, however finely its value is split: the minor cycle the
    longest such slot needs beside the others' skip costs, and where that
    slot's clocks go (its retry budget under a fault hypothesis)."""
    bus, hz = system.bus, system.clock_hz
    m = max((t.minor for t in tries), default=None)
    if m is None:
        return ""
    others = skip * (len(system.channels) - 1) + (m - usable(system, m))

    def smallest(ch):
        return item_for(ch, bus, m, ch.words if fragmentable(ch) else 1).length
    ch = max(system.channels, key=smallest)
    length = smallest(ch)
    need = length + others
    top = (1 << bus.time_bits) - 1
    budget = bus.retry_budget_of(ch)
    why = (f"channel '{ch.name}''s slot needs at least {length} clocks even in fragments of one word "
           f"({budget} of them its retry budget of {bus.retries_of(ch)} retries"
           + (", sized for the fault hypothesis" if system.faults is not None else "") + ")")
    faults = (" or plan for a milder fault hypothesis (a smaller retry budget)"
              if system.faults is not None else f" or give '{ch.name}' fewer retries")
    if need > top:
        return (f"To fit: {why}, more than a minor cycle can hold beside the others' skip costs ({top} clocks "
                f"at most): shrink that slot: fewer destinations{faults}")
    need_us = -(-need * 1_000_000 // hz)
    if minor_clocks(system) is not None:
        return (f"To fit: {why}: raise [bus] minor_cycle_us to at least {need_us} us ({need} clocks){faults}")
    return (f"To fit: {why}, and the shortest max_period_us allows minor cycles of at most {m} clocks: relax "
            f"the shortest periods to at least {need_us} us{faults}")


def relax_hint(system: System, best: Attempt, skip: int) -> str:
    """What would make it fit at the minor cycle that came closest: a
    channel whose period, doubled, lets the planner place everything (tried,
    the largest loads first), or the load to cut."""
    m, cap = best.minor, best.cap
    hz = system.clock_hz
    loads = sorted(best.items, key=lambda it: -(it.length - skip) / it.rep)
    for it in loads[:5]:
        ch = it.ch
        saved = (ch.period_clocks, ch.repetition)
        ch.period_clocks = 2 * ch.period_clocks
        ch.repetition = 2 * ch.repetition if ch.repetition else None
        try:
            a = attempt(system, m, skip, [40])
        finally:
            ch.period_clocks, ch.repetition = saved
        if a.ok:
            need_us = -(-2 * it.rep * it.fragments * m * 1_000_000 // hz)
            if ch.repetition:
                return (f"To fit: double the repetition of channel '{ch.name}' to {2 * ch.repetition}, with a "
                        f"max_period_us of at least {need_us} us (the planner then places every entry at the minor "
                        f"cycle of {m} clocks)")
            return (f"To fit: relax the max_period_us of channel '{ch.name}' from {ch.max_period_us} to {need_us} us "
                    f"(its repetition doubles; the planner then places every entry at the minor cycle of {m} "
                    "clocks)")
    over = (best.top - cap) if best.top else (best.load - cap)
    names = ", ".join(f"'{it.ch.name}'" for it in loads[:3])
    return (f"To fit: cut the busiest minor cycle's load by {max(1, round(over))} clocks at the minor cycle of {m} "
            f"({us(m, hz):g} us), for example by relaxing the max_period_us of {names}, the largest loads")


def exact_proof(system: System, tries: list, skip: int) -> str:
    """With OR-Tools installed: the exact search (exact.solve_grid) on the
    best candidate minor cycles, whole values and one entry per channel,
    each slot less the skip cost and the minor cycle less N skip costs
    (every entry costs the skip cost in every minor cycle, and L in those
    it is due in: a placement needs every minor cycle's due L - skip to fit
    cap - N skip).  The proof in words when every one is infeasible, else
    ""."""
    if len(system.channels) > EXACT_MAX_CHANNELS:
        return ""
    try:
        from .exact import INFEASIBLE, SolverMissing, solve_grid
        from .exact import _cp_model
        _cp_model()
    except (ImportError, SolverMissing):
        return ""
    bus = system.bus
    lengths = [slot_length(ch, bus) - skip for ch in system.channels]
    periods = [ch.period_clocks for ch in system.channels]
    fixed = [ch.repetition for ch in system.channels]
    minors = [t.minor for t in sorted(tries, key=lambda t: t.load / t.cap)][:EXACT_MINORS]
    if not minors or any(fixed):
        return ""
    idle = system.mode_window + skip * len(system.channels)
    done = []
    for m in minors:
        g = solve_grid(lengths, periods, m, idle, time_limit=EXACT_LIMIT / len(minors), workers=1,
                       max_repetition=MAX_REP)
        if g.status != INFEASIBLE:
            return ""
        done.append(f"{m} ({g.reason})")
    return (f"no placement with one entry per channel and whole values exists at the minor cycles "
            f"{', '.join(done)} clocks (exact search)")


def check_overrides(system: System):
    """A fixed minor cycle or repetition that no plan can honour: an error
    naming it and what would."""
    fixed = minor_clocks(system)
    msgs = []
    tb = (1 << system.bus.time_bits) - 1
    if fixed is not None:
        if fixed > tb:
            msgs.append(f"{system.source}: [bus] minor_cycle_us = {system.minor_cycle_us}: {fixed} clocks do not fit "
                        f"time_bits = {system.bus.time_bits} (at most {tb} clocks, "
                        f"{us(tb, system.clock_hz):g} us)")
        if fixed <= system.mode_window:
            msgs.append(f"{system.source}: [bus] minor_cycle_us = {system.minor_cycle_us}: {fixed} clocks leave no time "
                        f"beside the {system.mode_window} clocks kept for a mode switch")
        for ch in system.channels:
            r = ch.repetition or 1
            if r * fixed > ch.period_clocks:
                msgs.append(f"{system.source}: channel '{ch.name}': max_period_us = {ch.max_period_us} is shorter than "
                            + (f"its repetition {r} times " if ch.repetition else "")
                            + f"the minor cycle [bus] minor_cycle_us = {system.minor_cycle_us}: lengthen the period "
                            f"to at least {-(-r * fixed * 1_000_000 // system.clock_hz)} us or shorten the minor cycle"
                            + (" or the repetition" if ch.repetition else ""))
    else:
        for ch in system.channels:
            if ch.repetition and ch.period_clocks // ch.repetition < 1 + system.mode_window:
                msgs.append(f"{system.source}: channel '{ch.name}': repetition = {ch.repetition} leaves a minor "
                            f"cycle of at most {ch.period_clocks // ch.repetition} clocks within its max_period_us "
                            f"= {ch.max_period_us}: lower the repetition")
    if msgs:
        raise ScheduleError(msgs)
