"""The plan: slot lengths, the cycle, redundant slots and their placement,
and the bounds each channel gets from it."""

from __future__ import annotations

import random

from .fourslot import FOUR_SLOT
from .model import Bus, Channel, Plan, ScheduleError, Slot, System
from .rom import C as CONTRACT, MAX_ENTRIES


def transfer_accesses(ch: Channel) -> int:
    """A: a new transfer's bus accesses (docs/controller.md "Timing"): per
    destination W + 3 (ReadLocked load, W value stores and taken_at, Actual),
    four-slot W + 4 (control-word load, W + 1 stores, Slot byte, Actual)."""
    nd = len(ch.consumers)
    per_dest = ch.words + (4 if ch.layout == FOUR_SLOT else 3)
    if ch.kind == "copy":
        return 3 + ch.words + nd * per_dest
    return nd * per_dest


def slot_length(ch: Channel, bus: Bus) -> int:
    return (bus.fetch_cycles + bus.first_access_extra + bus.access_cycles * transfer_accesses(ch)
            + bus.retry_budget_of(ch) + bus.guard_cycles)


def pub_offset(ch: Channel, bus: Bus, retries: bool) -> int:
    """From a slot's start to the end of its last destination's Actual store
    (a fragmented value: of the run of its last fragment, ch.pub_accesses)."""
    off = bus.fetch_cycles + bus.first_access_extra + bus.access_cycles * (ch.pub_accesses or ch.accesses)
    return off + (bus.retry_budget_of(ch) if retries else 0)


def channel_span(plan: Plan, ch: Channel) -> int:
    """The clocks after which ch's slots (multi-rate: its runs) repeat: the
    cycle, or in a multi-rate plan its largest repetition's minor cycles."""
    return ch.run_span or plan.cycle


def channel_entries(plan: Plan, ch: Channel) -> int:
    """The ROM entries of ch (single-rate: its slots per cycle)."""
    return sum(1 for s in plan.slots if s.channel is ch)


def import_extra_passes(ch: Channel, bus: Bus) -> int:
    """E: the extra passes of the controller's source Import (figure 3's loop
    in rtl/albatross_import.v) that a producer publishing during it can cause,
    at most.  Each pass stores ReadLocked and loads Actual again (2 accesses);
    one more follows only if the producer stored Actual within the pass.  A
    producer's Export is W + 2 accesses of its DPRAM port, which serves one
    access every 2 clocks, so its Actual stores are m = 2 (W + 2) clocks apart
    at least: e passes in a row need e stores within (e + 1) passes' time,
    (e - 1) m <= 2 access_cycles e.  Copy channels only (the controller
    produces time and status values itself)."""
    if ch.kind != "copy":
        return 0
    m, p = 2 * (ch.words + 2), 2 * bus.access_cycles
    if m <= p:
        raise ScheduleError(f"channel '{ch.name}': a producer can publish faster than one Import pass "
                            f"({m} <= {p} clocks); the controller's Import has no bound")
    return max(1, m // (m - p))


def channel_gaps(starts, cycle):
    """Gaps between consecutive slot starts of one channel, cyclic."""
    s = sorted(starts)
    return [(s[(i + 1) % len(s)] + (cycle if i + 1 == len(s) else 0)) - s[i] for i in range(len(s))]


def _score(order, starts, cycle, counts):
    """Per channel: largest gap * slots (C = perfectly even); sorted descending
    so tuples compare leximin-style (worst channel first)."""
    per = {}
    for sl, s in zip(order, starts):
        per.setdefault(sl[0], []).append(s)
    vals = []
    for k, ss in per.items():
        vals.append(max(channel_gaps(ss, cycle)) * counts[k])
    return tuple(sorted(vals, reverse=True))


def _place(order, targets, lengths, cap, fixed_first):
    """Positions for slots in the given order: min-max deviation from the
    targets (binary search), then slots as close to their targets as the
    corridor allows.  None if the order does not fit."""
    m = len(order)
    total = sum(lengths)
    if total > cap:
        return None

    def corridor(d):
        # (the planner's hot loop: comparisons written out, not min/max calls)
        lo = [0] * m
        prev = 0
        for i in range(m):
            e = targets[i] - d
            if e < prev:
                e = prev
            if fixed_first and i == 0:
                e = 0
            lo[i] = e
            prev = e + lengths[i]
        if prev > cap:
            return None
        hi = [0] * m
        nxt = cap
        for i in range(m - 1, -1, -1):
            h = targets[i] + d
            room = nxt - lengths[i]
            if room < h:
                h = room
            if fixed_first and i == 0 and h > 0:
                h = 0
            if h < lo[i]:
                return None
            hi[i] = h
            nxt = h
        return lo, hi

    lo_d, hi_d = 0, cap
    best = corridor(hi_d)
    if best is None:
        return None
    while lo_d < hi_d:
        mid = (lo_d + hi_d) // 2
        c = corridor(mid)
        if c is None:
            lo_d = mid + 1
        else:
            hi_d, best = mid, c
    lo, hi = best
    pos = []
    prev = 0
    for i in range(m):
        p = min(max(targets[i], lo[i], prev), hi[i])
        pos.append(p)
        prev = p + lengths[i]
    return pos


def _balance(order, pos, lengths, cap, cycle, fixed_first, sweeps=40, work=None):
    """Coordinate descent: move each slot, within the room its neighbours in
    the plan leave, towards the midpoint of its channel neighbours.  work:
    a one-element list that counts the moves tried (slots x sweeps)."""
    m = len(order)
    by_ch = {}
    for i, sl in enumerate(order):
        by_ch.setdefault(sl[0], []).append(i)
    # The moves of one sweep, in order: slot i, its channel neighbours a
    # (before, da = cycle when it wraps) and b (after, db), the room below
    # (the end of slot i - 1; 0 for the first) and above (the start of slot
    # i + 1, or cap, less i's length).  The planner's hot loop: each plan
    # it tries is balanced here.
    steps = []
    for idx in by_ch.values():
        n = len(idx)
        if n < 2:
            continue
        for j, i in enumerate(idx):
            if fixed_first and i == 0:
                continue
            steps.append((i, idx[j - 1], cycle if j == 0 else 0, idx[(j + 1) % n], cycle if j + 1 == n else 0,
                          lengths[i - 1] if i > 0 else None, i + 1 < m, lengths[i]))
    for _ in range(sweeps):
        if work is not None:
            work[0] += len(steps)
        moved = False
        for i, a, da, b, db, len_below, has_above, len_i in steps:
            new = (pos[a] - da + pos[b] + db) // 2
            lo = pos[i - 1] + len_below if len_below is not None else 0
            if new < lo:
                new = lo
            hi = (pos[i + 1] if has_above else cap) - len_i
            if new > hi:
                new = hi
            if new != pos[i]:
                pos[i] = new
                moved = True
        if not moved:
            break
    return pos


# The local search's work per candidate, in slot moves tried by _balance:
# an evaluation costs slots x sweeps, and large plans need many sweeps, so a
# budget of evaluations alone lets a plan of 200 slots search for seconds
# (the examples' plans stay well below it: at most about 190,000).
WORK_BUDGET = 500_000


def place_slots(items, cycle, cap, sync_key=None, seed=1, budget=2500):
    """items: list of (key, length, count).  Returns [(key, start, j)] sorted by
    start, where j numbers the slots of a channel.  The sync channel's first
    slot (sync_key) is fixed at start 0."""
    counts = {k: n for k, _, n in items}
    length = {k: l for k, l, _ in items}
    keys = [k for k, _, _ in items]
    rng = random.Random(seed)
    fixed_first = sync_key is not None
    work = [0]

    def build(phase):
        sl = []
        for k in keys:
            n = counts[k]
            for j in range(n):
                t = (phase[k] + j) * cycle / n
                sl.append((k, j, t))
        # the sync slot first; the rest by target, ties by channel order
        sl.sort(key=lambda x: (0 if (x[0] == sync_key and x[1] == 0) else 1, x[2], keys.index(x[0])))
        order = [(k, j) for k, j, _ in sl]
        targets = [int(t) for _, _, t in sl]
        return order, targets

    def evaluate(order, targets):
        lengths = [length[k] for k, _ in order]
        pos = _place(order, targets, lengths, cap, fixed_first)
        if pos is None:
            return None
        pos = _balance(order, pos, lengths, cap, cycle, fixed_first, work=work)
        return _score(order, pos, cycle, counts), pos

    def perfect(order, pos):
        """No channel's largest gap can shrink: each is ceil(C / n)."""
        per = {}
        for (k, _), p in zip(order, pos):
            per.setdefault(k, []).append(p)
        return all(max(channel_gaps(ss, cycle)) <= -(-cycle // counts[k]) for k, ss in per.items())

    candidates = []
    nk = len(keys)
    phases = [{k: 0.0 for k in keys}]
    phases.append({k: i / nk for i, k in enumerate(keys)})
    phases.append({k: (i + 0.5) / nk for i, k in enumerate(keys)})
    phases.append({k: 1 - (i + 1) / nk for i, k in enumerate(keys)})
    by_len = sorted(keys, key=lambda k: -length[k])
    phases.append({k: by_len.index(k) / nk for k in keys})
    for _ in range(40):
        phases.append({k: rng.random() for k in keys})
    for ph in phases:
        if sync_key is not None:
            ph[sync_key] = 0.0
        order, targets = build(ph)
        r = evaluate(order, targets)
        if r is not None:
            candidates.append((r[0], order, targets, r[1]))
    if not candidates:
        # fall back: back to back in channel order (always fits if the sum fits)
        order = [(k, j) for k in keys for j in range(counts[k])]
        if sync_key is not None:
            order.remove((sync_key, 0))
            order.insert(0, (sync_key, 0))
        pos, t = [], 0
        for k, _ in order:
            pos.append(t)
            t += length[k]
        return [(k, p, j) for (k, j), p in zip(order, pos)]
    candidates.sort(key=lambda c: c[0])

    # Local search on the order from the best few candidates: move one slot
    # to another place in the order (or swap two neighbours), keep the move
    # when the score improves.  A budget of evaluations keeps large plans
    # fast; everything is deterministic.
    m = len(candidates[0][1])
    budget = max(200, min(budget, 150000 // max(m, 1)))
    window = m if m <= 40 else 12
    first = 1 if fixed_first else 0
    best = None
    for score0, order0, targets0, pos0 in candidates[:2]:
        cur = (score0, list(zip(order0, targets0)), pos0)
        evals = 0
        work[0] = 0
        done = perfect(order0, pos0)
        while not done and evals < budget and work[0] < WORK_BUDGET:
            improved = False
            for i in range(first, m):
                for j in range(max(first, i - window), min(m, i + window + 1)):
                    if j == i or evals >= budget or work[0] >= WORK_BUDGET:
                        continue
                    seq = list(cur[1])
                    item = seq.pop(i)
                    if abs(i - j) == 1 and item[0][0] == seq[min(j, len(seq) - 1)][0][0]:
                        continue
                    seq.insert(j, (item[0], cur[2][j]))   # aim at the place it moves to
                    evals += 1
                    r = evaluate([o for o, _ in seq], [t for _, t in seq])
                    if r is not None and r[0] < cur[0]:
                        seq = [(o, p) for (o, _), p in zip(seq, r[1])]
                        cur = (r[0], seq, r[1])
                        improved = True
                        done = perfect([o for o, _ in seq], r[1])
                        break
                if done or evals >= budget or work[0] >= WORK_BUDGET:
                    break
            if not improved:
                break
        if best is None or cur[0] < best[0]:
            best = cur
        if perfect([o for o, _ in best[1]], best[2]):
            break
    best_score = best[0]
    order = [o for o, _ in best[1]]
    pos = best[2]
    # renumber slots of each channel in start order
    seen = {}
    out = []
    for (k, _), p in zip(order, pos):
        j = seen.get(k, 0)
        seen[k] = j + 1
        out.append((k, p, j))
    return out


def build_plan(system: System) -> Plan:
    """The single-rate plan (steps 1-4 of docs/compiler.md "Plan")."""
    bus = system.bus
    for ch in system.channels:
        ch.accesses = transfer_accesses(ch)
        ch.slot_len = slot_length(ch, bus)
        ch.fragments, ch.frag_words, ch.pub_accesses, ch.run_span = 1, 0, 0, 0
    limiter = min(system.channels, key=lambda c: (c.period_clocks, c.index))
    cycle = limiter.period_clocks
    tb = bus.time_bits
    if cycle > (1 << tb) - 1:
        raise ScheduleError(f"{system.source}: channel '{limiter.name}', field 'max_period_us': the cycle "
                            f"of {cycle} clocks does not fit time_bits = {tb} (time within a cycle is "
                            f"{tb} bits in the controller, TIME_BITS; longest cycle {(1 << tb) - 1} clocks): "
                            f"shorten max_period_us or raise [bus] time_bits (at most {CONTRACT.time_bits})")
    cap = cycle - (bus.poll_cycles if system.sync_mode else 0) - system.mode_window
    need = sum(ch.slot_len for ch in system.channels)
    if need > cap:
        detail = ", ".join(f"{ch.name} {ch.slot_len}" for ch in system.channels)
        poll = (f", of which {bus.poll_cycles} stay idle for the position poll ([bus] poll_cycles)"
                if system.sync_mode else "") + \
               (f", of which {system.mode_window} stay idle for a mode switch ([bus] mode_switch_cycles)"
                if system.mode_window else "")
        raise ScheduleError(
            f"{system.source}: infeasible plan: one slot per channel needs {need} clocks per cycle but "
            f"only {max(cap, 0)} are available: the cycle is {cycle} clocks "
            f"({limiter.max_period_us} us, the smallest max_period_us, of channel '{limiter.name}', "
            f"at clock_hz = {system.clock_hz}){poll}. Slot lengths in clocks: {detail}. "
            "Relax max_period_us, shrink or merge channels, or raise clock_hz.")

    # Redundant slots, round-robin by priority then shortest period, up to
    # the entries this plan may take (system.entry_cap: the ROM's 255, or a
    # mode's share of them); bus_entries: where the bus time alone stops it.
    entry_cap = getattr(system, "entry_cap", None) or MAX_ENTRIES
    lengths = {ch.index: ch.slot_len for ch in system.channels}
    counts, entries = redundancy_round_robin(system.channels, lengths, cap, entry_cap)
    _, bus_entries = redundancy_round_robin(system.channels, lengths, cap, None)

    sync_ch = next((c for c in system.channels if c.sync), None)
    items = [(ch.index, ch.slot_len, counts[ch.index]) for ch in system.channels]
    placed = place_slots(items, cycle, cap, sync_key=sync_ch.index if sync_ch else None)
    by_index = {ch.index: ch for ch in system.channels}
    slots = []
    for k, start, j in placed:
        ch = by_index[k]
        slots.append(Slot(channel=ch, start=start, length=ch.slot_len, redundant=j > 0,
                          sync=(sync_ch is not None and ch is sync_ch and start == 0 and j == 0)))
    slots.sort(key=lambda s: (s.start, 0 if s.sync else 1))
    for ch in system.channels:
        ch.slots = sorted(s.start for s in slots if s.channel is ch)
    plan = Plan(cycle=cycle, capacity=cap, slots=slots, limiter=limiter)
    # the redundant slots planned, those the bus time allows (more when the
    # entry cap stopped the round-robin) and that cap (report.py)
    plan.redundancy = {"planned": entries - len(system.channels),
                       "bus_allows": bus_entries - len(system.channels), "entry_cap": entry_cap}
    return plan


def redundancy_round_robin(channels, lengths: dict, cap: int, entry_cap):
    """Step 3 of the plan: with one slot per channel (lengths: {channel
    index: slot clocks}) in the `cap` clocks of a cycle, add a slot at a
    time, round-robin by priority, then shortest period, then id, skipping a
    channel whose slot no longer fits or that reached its max_slots, until
    nothing fits or the entries reach entry_cap (None: no cap).  Returns ({channel index: slots}, entries).
    Capped, it stops on a prefix of the uncapped sequence, so the two
    counts differ only in the slots the cap cut."""
    counts = {ch.index: 1 for ch in channels}
    entries = len(channels)
    used = sum(lengths.values())
    rr = sorted(channels, key=lambda c: (-c.priority, c.period_clocks, c.index))
    progress = True
    while progress and (entry_cap is None or entries < entry_cap):
        progress = False
        for ch in rr:
            if entry_cap is not None and entries >= entry_cap:
                break
            if ch.max_slots is not None and counts[ch.index] >= ch.max_slots:
                continue
            if used + lengths[ch.index] <= cap:
                counts[ch.index] += 1
                used += lengths[ch.index]
                entries += 1
                progress = True
    return counts, entries


def redundancy_estimate(system: System) -> int:
    """The redundant slots the bus time allows a system, from its slot
    lengths with the [bus] retry budget and no termination spacing: the
    figure build_plan's round-robin gives without an entry cap, before the
    fault plan and the termination bounds change the slots (modes.py shares
    the ROM with it before planning)."""
    bus = system.bus
    lengths = {ch.index: slot_length(ch, bus) for ch in system.channels}
    cycle = min(ch.period_clocks for ch in system.channels)
    cap = cycle - (bus.poll_cycles if system.sync_mode else 0) - system.mode_window
    if sum(lengths.values()) > cap:
        return 0
    _, entries = redundancy_round_robin(system.channels, lengths, cap, None)
    return entries - len(system.channels)


def run_at(starts, span: int, i: int) -> int:
    """The start of run i of a channel whose runs start at `starts` (sorted)
    in every span clocks; i counts on past the end into the next spans."""
    n = len(starts)
    return starts[i % n] + span * (i // n)


def channel_bounds(system: System, plan: Plan, ch: Channel) -> dict:
    """The channel's bounds (docs/compiler.md "Plan").  A value in F > 1
    fragments (multi-rate) takes F runs: the period is the longest span of
    F runs, and a value published just after a first fragment's sampling
    load is taken by the next first fragment, F runs on, and published by
    that transfer's last fragment: 2F - 1 runs on."""
    bus = system.bus
    span = channel_span(plan, ch)
    gaps = channel_gaps(ch.slots, span)
    f = ch.fragments
    if f > 1:
        n = len(ch.slots)
        period = max(run_at(ch.slots, span, i + f) - ch.slots[i] for i in range(n))
        spans = [run_at(ch.slots, span, i + 2 * f - 1) - ch.slots[i] for i in range(n)]
    else:
        period = max(gaps)
        spans = gaps
    # A source value published during the Import costs the slot E extra
    # passes (2 accesses each) before the destinations' Actual stores (a
    # fragmented value is published in the run of its last fragment, which
    # has no Import).
    extra = import_extra_passes(ch, bus) * 2 * bus.access_cycles if f == 1 else 0
    pub_ff = pub_offset(ch, bus, False) + extra
    pub_rt = pub_offset(ch, bus, True) + extra
    b = {
        "guaranteed_period_clocks": period,
        "min_gap_clocks": min(gaps),
        "pub_offset_clocks": {"fault_free": pub_ff, "with_retries": pub_rt},
    }
    if ch.kind == "copy":
        ff = max(g + pub_ff - bus.sample_offset for g in spans)
        rt = max(g + pub_rt - bus.sample_offset for g in spans)
        b["latency_clocks"] = {"fault_free": ff, "with_retries": rt}
        b["age_bound_clocks"] = None
    else:
        b["latency_clocks"] = None
        b["age_bound_clocks"] = {"fault_free": period + pub_ff, "with_retries": period + pub_rt}
    return b
