"""Multi-rate plans: a cluster of 2^c minor cycles, each ROM entry due in the
minor cycles n with n mod 2^rep = base, values larger than a free window
carried in fragments (docs/compiler.md "Plan", "Multi-rate plans").

The compiler plans single-rate (plan.build_plan) whenever that fits; this
planner runs when it does not, or when the description fixes a minor cycle
([bus] minor_cycle_us) or a channel's repetition.

The timing model.  The entries run in ROM order in every minor cycle.  A
due entry needs the sequencer free at its start and holds it for its slot
(start .. start + length); an entry that is not due costs
model.not_due_cost(bus) clocks from max(its start, the end of the entry
before it) (the sequencer waits for its start, fetches and skips it).  The
last entry of every minor cycle ends within the usable clocks (the minor
cycle less the mode-switch window).  check_timing expands every minor cycle
of the cluster against this model.

A channel's runs are the due runs of its entries; a value of F fragments
takes F runs (plan.channel_bounds gives the bounds).  With skip cost k:
every entry costs k in every minor cycle, and L - k more in those it is due
in, so a minor cycle's load is N k + the sum of L - k over its due entries.

The planner, for each candidate minor cycle m (the breakpoints P_i / 2^j in
(M/2, M], M the smallest period or the longest minor cycle time_bits
allows, ordered by the average load they give):
  1. repetitions: each channel's largest power of two r with r F m <= P
     (its max_period in clocks; F its fragments), or the one the
     description fixes;
  2. bases and starts, by list scheduling in order of repetition (then the
     longest slot first): each entry at the residue whose minor cycles are
     least loaded, at the time that residue is free.  Every minor cycle's
     time then equals its load exactly, with no idle time (pack);
  3. if the busiest minor cycle is over the usable clocks, the longest
     entry due in it is split into twice as many fragments, and 2 again, up
     to a work budget; a channel whose slot is longer than any minor cycle
     can hold is split first;
  4. the first minor cycle that fits gives the plan; then the spare time
     takes redundant entries (same repetition, the base farthest from the
     channel's others) round-robin by priority, then period, then id, as
     the single-rate plan's redundant slots (spare.py).
A description that fits nowhere is rejected with its reason
(rejection.py): a proof that the demand exceeds the bus, or, with OR-Tools
installed, that the exact search finds no placement on the grid at the best
minor cycles (whole values, one entry per channel), or that the planner
gave up without a proof; each with what would make it fit.  Deterministic:
no clocks, no random numbers."""

from __future__ import annotations

import dataclasses
from typing import Optional

from .fourslot import FOUR_SLOT
from .model import Channel, Plan, ScheduleError, Slot, System, not_due_cost, us
from .plan import slot_length, transfer_accesses
from .rom import C as CONTRACT, MAX_ENTRIES

MAX_CLUSTER_LOG = CONTRACT.field("H2", "cluster").max      # c <= 15
MAX_REP = 1 << MAX_CLUSTER_LOG
MAX_FRAG = CONTRACT.field("E7", "frag").max
# The planner's work budget: list schedulings (pack) per description, over
# all candidate minor cycles; and the candidates tried.
PACK_BUDGET = 600
MAX_CANDIDATES = 24


# The further splits of a fragmented entry tried for room for redundant entries.
FINER_STEPS = 3


def floor_pow2(x: int) -> int:
    """The largest power of two <= x (0 when x < 1)."""
    return 1 << (int(x).bit_length() - 1) if x >= 1 else 0


def wants_multirate(system: System) -> bool:
    """The description fixes a minor cycle or a repetition: plan multi-rate."""
    return system.minor_cycle_us is not None or any(ch.repetition for ch in system.channels)


def minor_clocks(system: System) -> Optional[int]:
    """[bus] minor_cycle_us in clocks (None when the description leaves it)."""
    if system.minor_cycle_us is None:
        return None
    return system.minor_cycle_us * system.clock_hz // 1_000_000


# ---------------------------------------------------------------------------
# Fragments.

def fragmentable(ch: Channel) -> bool:
    """A COPY to destinations of 2 words or more (the contract: E7.frag on a COPY only)."""
    return ch.kind == "copy" and bool(ch.consumers) and not ch.request and ch.words >= 2


def fragment_shape(words: int, f: int):
    """(E7.frag, fragments) of a value of `words` words asked to go in f
    fragments: ceil(words / f) words each, the last the rest."""
    frag = -(-words // max(1, f))
    n = -(-words // frag)
    return (0, 1) if n <= 1 else (frag, n)


def fragment_accesses(ch: Channel, frag: int) -> list:
    """The fault-free accesses of each fragment's run (frag: E7.frag, 0 the
    whole value).  Fragment 0: the source Import (3), each destination's
    control word and its words (a source load and a store per destination
    each); the others: their words; the last also each destination's
    taken_at and Actual (four-slot: and the Slot byte).  They add up to A
    (plan.transfer_accesses)."""
    if not frag:
        return [transfer_accesses(ch)]
    w, nd = ch.words, len(ch.consumers)
    n = -(-w // frag)
    out = []
    for k in range(n):
        a = min(frag, w - k * frag) * (1 + nd)
        if k == 0:
            a += 3 + nd
        if k == n - 1:
            a += nd * (3 if ch.layout == FOUR_SLOT else 2)
        out.append(a)
    return out


def run_length(ch: Channel, bus, frag: int) -> int:
    """The slot of one run: plan.slot_length with the largest fragment's accesses."""
    if not frag:
        return slot_length(ch, bus)
    return (bus.fetch_cycles + bus.first_access_extra + bus.access_cycles * max(fragment_accesses(ch, frag))
            + bus.retry_budget_of(ch) + bus.guard_cycles)


# ---------------------------------------------------------------------------
# The placement.

@dataclasses.dataclass
class Item:
    """A channel's entry as the planner shapes it."""
    ch: Channel
    frag: int                       # E7.frag (0: whole values)
    fragments: int                  # F
    length: int                     # L, the slot of one run
    rep: int                        # r, a power of two (0: none fits the period)


def item_for(ch: Channel, bus, m: int, f: int, runs=None) -> Item:
    """ch's entry at minor cycle m in (about) f fragments: the largest
    repetition whose runs(ch, F) runs (default F: one value) span at most
    its period."""
    frag, n = fragment_shape(ch.words, f) if fragmentable(ch) else (0, 1)
    k = runs(ch, n) if runs else n
    if ch.repetition:
        rep = ch.repetition if ch.repetition * k * m <= ch.period_clocks else 0
    else:
        rep = min(floor_pow2(ch.period_clocks // (k * m)), MAX_REP)
    return Item(ch=ch, frag=frag, fragments=n, length=run_length(ch, bus, frag), rep=rep)


def runs_for_faults(system: System):
    """runs(ch, F): the runs one value of F fragments needs within its
    period: F, or under a fault hypothesis the runs among which F deliver
    with its target probability (faults.runs_needed, each run missing with
    the whole transfer's probability at its retry budget: a fragment has
    fewer accesses, so this is on the safe side)."""
    h = system.faults
    if h is None or h.rate == 0:
        return None
    from .faults import access_sequence, delivery_curve, runs_needed
    cache = {}

    def runs(ch, f):
        if (ch.index, f) not in cache:
            r = system.bus.retries_of(ch)
            seqs = [access_sequence(ch, d) for d in range(len(ch.consumers))] or [access_sequence(ch, -1)]
            q = min(delivery_curve(h, s, r, system.drop_run)[r] for s in seqs)
            cache[(ch.index, f)] = runs_needed(max(0.0, 1.0 - q), h.eps, f, limit=64 * f) or (1 << 40)
        return cache[(ch.index, f)]
    return runs


def pack(items: list, skip: int):
    """List scheduling in order of repetition, then the longest slot first,
    then channel id: each entry at the residue (mod its repetition) whose
    minor cycles are least loaded, starting when they are free.  Returns
    (busiest minor cycle's end, [(item index, base, start)] in ROM order,
    the end of every residue class of the cluster).  Taken in this order,
    the array of class ends has exactly as many classes as the repetition
    of the entry placed (repetitions only grow), the entry's residue is
    the least loaded class, so every other class is at or after its start:
    they pay the skip cost and nothing waits.  A class ends at
    N skip + the sum of (L - skip) over its due entries."""
    order = sorted(range(len(items)), key=lambda i: (items[i].rep, -items[i].length, items[i].ch.index))
    ends = [0]                      # per residue class, less `off`
    off = 0
    placed = []
    for i in order:
        r = items[i].rep
        if r > len(ends):
            ends = ends * (r // len(ends))
        low = min(ends)
        b = ends.index(low)
        start = low + off
        off += skip
        ends[b] = start + items[i].length - off
        placed.append((i, b, start))
    return max(ends) + off, placed, [e + off for e in ends]


def average_load(items: list, skip: int) -> float:
    """A minor cycle's load averaged over the cluster: N skip + sum (L - skip) / r."""
    return len(items) * skip + sum((it.length - skip) / it.rep for it in items)


def check_timing(slots: list, minor: int, cluster: int, cap: int, skip: int, limit: int = 20) -> list:
    """Every minor cycle of the cluster expanded against the timing model
    (see the module's docstring), independent of the planner: the problems
    (empty: every due entry finds the sequencer free at its start, every
    minor cycle ends within cap).  slots: in ROM order."""
    problems = []
    rel, off = [0] * cluster, 0     # each minor cycle's sequencer free at rel[n] + off
    for k, s in enumerate(slots):
        r = 1 << s.rep_log
        if s.start + s.length > minor or s.base >= r or cluster % r:
            problems.append(f"entry {k}: start {s.start}, length {s.length}, base {s.base} of repetition {r} "
                            f"outside the minor cycle of {minor} clocks or the cluster of {cluster}")
            continue
        due = rel[s.base::r]
        late = max(due) + off
        if late > s.start:
            n = s.base + r * due.index(late - off)
            problems.append(f"entry {k} ({s.channel.name}): due in minor cycle {n} at {s.start}, but the "
                            f"sequencer is busy there until {late}")
        if min(rel) + off < s.start:        # minor cycles that wait for its start
            rel = [max(e, s.start - off) for e in rel]
        off += skip
        rel[s.base::r] = [s.start + s.length - off] * len(due)
        if len(problems) >= limit:
            return problems
    top = max(rel) + off
    if top > cap:
        n = rel.index(top - off)
        problems.append(f"minor cycle {n} ends at {top}, after its {cap} usable clocks")
    return problems


# ---------------------------------------------------------------------------
# The minor cycle.

def longest_minor(system: System) -> int:
    """M: the longest minor cycle: the smallest period, time_bits, and a
    fixed repetition's period / repetition."""
    m = min([ch.period_clocks for ch in system.channels] + [(1 << system.bus.time_bits) - 1])
    for ch in system.channels:
        if ch.repetition:
            m = min(m, ch.period_clocks // ch.repetition)
    return m


def candidate_minors(system: System) -> list:
    """The candidate minor cycles: the description's, or M and every
    P_i / 2^j (rounded down) in (M/2, M]: where a channel's repetition just
    fits its period.  A minor cycle of m/2 gives every channel twice the
    repetition and the same load, with twice the skip costs: never better."""
    fixed = minor_clocks(system)
    if fixed is not None:
        return [fixed]
    top = longest_minor(system)
    out = {top}
    for ch in system.channels:
        p = ch.period_clocks
        while p > top:
            p //= 2
        if 2 * p > top and p >= 1:
            out.add(p)
    return sorted(out, reverse=True)


def usable(system: System, m: int) -> int:
    return m - system.mode_window


def initial_items(system: System, m: int, skip: int, runs=None):
    """Each channel's entry at minor cycle m, split only as far as its slot
    must be to fit a minor cycle beside every other entry's skip cost;
    (items, None) or (None, the reason none fits)."""
    bus, cap = system.bus, usable(system, m)
    room = cap - skip * (len(system.channels) - 1)
    items = []
    for ch in system.channels:
        it = item_for(ch, bus, m, 1, runs)
        f = 1
        while it.length > room and fragmentable(ch) and it.fragments < ch.words and it.rep:
            f = it.fragments * 2
            it = item_for(ch, bus, m, f, runs)
        if not it.rep:
            why = (f"its repetition {ch.repetition}" if ch.repetition else "one run a minor cycle")
            return None, (f"channel '{ch.name}': {why} in {it.fragments} fragment(s) of {m} clocks each "
                          f"exceeds its period of {ch.period_clocks} clocks")
        if it.length > room:
            return None, (f"channel '{ch.name}': its slot of {it.length} clocks does not fit the {room} clocks a "
                          f"minor cycle of {m} leaves beside the other entries' skip costs")
        items.append(it)
    return items, None


@dataclasses.dataclass
class Attempt:
    minor: int
    cap: int
    items: Optional[list]
    load: float                     # the average load (clocks a minor cycle)
    ok: bool = False
    placed: Optional[list] = None
    ends: Optional[list] = None
    top: int = 0                    # the busiest minor cycle's end
    reason: str = ""


def attempt(system: System, m: int, skip: int, budget: list, runs=None) -> Attempt:
    """Plan at minor cycle m (steps 1-3 of the module's docstring);
    budget[0]: the list schedulings left; runs: runs_for_faults."""
    cap = usable(system, m)
    items, why = initial_items(system, m, skip, runs)
    if items is None:
        return Attempt(m, cap, None, float("inf"), reason=why)
    a = Attempt(m, cap, items, average_load(items, skip))
    while budget[0] > 0:
        if a.load > cap:
            a.reason = (f"the minor cycles carry {a.load:.0f} clocks on average, more than their {cap} usable "
                        "clocks")
            return a
        budget[0] -= 1
        a.top, a.placed, a.ends = pack(items, skip)
        if a.top <= cap:
            a.ok = True
            return a
        # Split the longest entry due in the busiest minor cycle further.
        n = a.ends.index(a.top)
        due = [i for i, b, _ in a.placed if n % items[i].rep == b]
        grown = None
        for i in sorted(due, key=lambda i: (-items[i].length, items[i].ch.index)):
            it = items[i]
            if not fragmentable(it.ch) or it.fragments >= it.ch.words:
                continue
            new = item_for(it.ch, system.bus, m, 2 * it.fragments, runs)
            if new.rep and new.length < it.length:
                grown = (i, new)
                break
        if grown is None:
            a.reason = (f"the busiest minor cycle ends at {a.top} clocks, after its {cap} usable ones, and no "
                        "entry due in it can be split further")
            return a
        items[grown[0]] = grown[1]
        a.load = average_load(items, skip)
    a.reason = a.reason or "the planner's work budget ran out"
    return a


# ---------------------------------------------------------------------------
# The plan.

def channel_runs(slots: list, ch: Channel, minor: int):
    """(runs, span): the starts of ch's due runs from the cluster's start
    over its span, the minor cycles of its largest repetition."""
    mine = [s for s in slots if s.channel is ch]
    span_cycles = max(1 << s.rep_log for s in mine)
    runs = sorted(n * minor + s.start for s in mine for n in range(s.base, span_cycles, 1 << s.rep_log))
    return runs, span_cycles * minor


def build_multirate_plan(system: System) -> Plan:
    """The multi-rate plan of a time-rigid system (the module's docstring),
    or rejection.MultiRateRejection."""
    bus = system.bus
    skip = not_due_cost(bus)
    for ch in system.channels:
        ch.accesses = transfer_accesses(ch)
        ch.fragments, ch.frag_words, ch.pub_accesses, ch.run_span = 1, 0, 0, 0
    from .rejection import check_overrides
    check_overrides(system)
    budget = [PACK_BUDGET]
    tries = []
    runs = runs_for_faults(system)
    minors = candidate_minors(system)
    ranked = []
    for m in minors:
        items, why = initial_items(system, m, skip, runs)
        load = average_load(items, skip) if items else float("inf")
        ranked.append((load / max(1, usable(system, m)), -m, m))
    ranked.sort()
    found = None
    for _, _, m in ranked[:MAX_CANDIDATES]:
        if budget[0] <= 0:
            break
        a = attempt(system, m, skip, budget, runs)
        tries.append(a)
        if a.ok:
            found = a
            break
    if found is None:
        from .rejection import reject
        raise reject(system, tries, skip, budget[0] <= 0)
    return make_plan(system, finer_for_redundancy(system, found, skip, runs), skip)


def _redundant_entries(system: System, a: Attempt, skip: int) -> int:
    from .spare import add_redundancy
    entries = [(i, b, s, False) for i, b, s in a.placed]
    add_redundancy(system, a.items, entries, list(a.ends), a.cap, skip,
                   getattr(system, "entry_cap", None) or MAX_ENTRIES)
    return len(entries) - len(a.placed)


def finer_for_redundancy(system: System, a: Attempt, skip: int, runs=None) -> Attempt:
    """The placement split only as far as it must be leaves the busiest
    minor cycle (the one a large fragment runs in) with little room for the
    skip cost of the redundant entries, which every minor cycle pays: split
    the longest fragmented entry further (up to FINER_STEPS times) while
    that lets more redundant entries in, and keep the plan with the most
    (the fewest fragments among equals)."""
    best, best_red = a, _redundant_entries(system, a, skip)
    items = list(a.items)
    for _ in range(FINER_STEPS):
        split = [i for i in range(len(items)) if items[i].frag and items[i].fragments < items[i].ch.words]
        if not split:
            break
        i = max(split, key=lambda i: (items[i].length, -items[i].ch.index))
        new = item_for(items[i].ch, system.bus, a.minor, 2 * items[i].fragments, runs)
        if not new.rep or new.length >= items[i].length:
            break
        items = items[:i] + [new] + items[i + 1:]
        top, placed, ends = pack(items, skip)
        if top > a.cap:
            continue
        b = Attempt(a.minor, a.cap, list(items), average_load(items, skip), ok=True, placed=placed, ends=ends,
                    top=top)
        red = _redundant_entries(system, b, skip)
        if red > best_red:
            best, best_red = b, red
    return best


def make_plan(system: System, a: Attempt, skip: int) -> Plan:
    bus, items, m, cap = system.bus, a.items, a.minor, a.cap
    entry_cap = getattr(system, "entry_cap", None) or MAX_ENTRIES
    from .spare import add_redundancy
    entries = [(i, b, s, False) for i, b, s in a.placed]
    ends = add_redundancy(system, items, entries, list(a.ends), cap, skip, entry_cap)
    bus_allows = len(entries)
    if len(entries) >= entry_cap:     # the ROM stopped it: how far the bus time alone goes (up to twice the ROM)
        more = [(i, b, s, False) for i, b, s in a.placed]
        add_redundancy(system, items, more, list(a.ends), cap, skip, 2 * MAX_ENTRIES)
        bus_allows = len(more)
    cluster = max(len(ends), max(it.rep for it in items))
    slots = []
    for i, b, s, red in entries:
        it = items[i]
        slots.append(Slot(channel=it.ch, start=s, length=it.length, redundant=red,
                          rep_log=it.rep.bit_length() - 1, base=b, frag=it.frag))
    for it in items:
        ch = it.ch
        ch.slot_len, ch.fragments, ch.frag_words = it.length, it.fragments, it.frag
        ch.pub_accesses = fragment_accesses(ch, it.frag)[-1] if it.frag else 0
        ch.slots, ch.run_span = channel_runs(slots, ch, m)
    problems = check_timing(slots, m, cluster, cap, skip)
    if problems:
        raise AssertionError("internal error, the multi-rate plan breaks its timing model: " + "; ".join(problems))
    fastest = min(system.channels, key=lambda c: (c.period_clocks, c.index))
    plan = Plan(cycle=m, capacity=cap, slots=slots, limiter=fastest, cluster_log=cluster.bit_length() - 1,
                multirate=True)
    n = len(system.channels)
    plan.redundancy = {"planned": len(entries) - n, "bus_allows": bus_allows - n, "entry_cap": entry_cap}
    plan.skip_cost = skip
    plan.busiest = max(ends)
    plan.minor_source = ("[bus] minor_cycle_us" if system.minor_cycle_us is not None else
                         "chosen by the planner")
    return plan
