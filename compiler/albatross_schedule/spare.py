"""Redundant entries of a multi-rate plan in its spare time (the paper's
over-sampling, as the single-rate plan's redundant slots): appended after
the planned entries (multirate.py), each where the minor cycles it is due
in have room, with the skip costs of the timing model."""

from __future__ import annotations

from .model import System


def append_entry(ends: list, length: int, rep: int, base: int, skip: int):
    """One more entry after all others (the redundant ones): its start (the
    latest end of its due classes) and the class ends after it."""
    due = ends[base::rep]
    start = max(due)
    out = [max(e, start) + skip for e in ends]
    out[base::rep] = [start + length] * len(due)
    return start, out



def _target(used: list, rep: int) -> int:
    """The residue (mod rep) in the middle of the largest cyclic gap between
    the bases `used`: where one more run of the channel spreads its runs most."""
    u = sorted(set(x % rep for x in used))
    if not u:
        return 0
    gaps = [((u[(k + 1) % len(u)] - u[k]) % rep or rep, u[k]) for k in range(len(u))]
    g, at = max(gaps, key=lambda x: (x[0], -x[1]))
    return (at + g // 2) % rep


def _near(target: int, rep: int):
    """The residues mod rep by cyclic distance from target (then the lower)."""
    yield target
    for d in range(1, rep // 2 + 1):
        for b in ((target - d) % rep, (target + d) % rep):
            if b != target:
                yield b
        if 2 * d == rep:
            break


def add_redundancy(system: System, items: list, entries: list, ends: list, cap: int, skip: int, entry_cap):
    """Redundant entries after the others, round-robin by priority, then
    shortest period, then id (as plan.redundancy_round_robin): a channel
    gets one more entry of its repetition, at the base nearest the middle
    of the largest gap between its entries' bases that fits, while one fits
    the minor cycles, its max_slots and the ROM (entry_cap).  A channel
    that finds no room drops out (the minor cycles only fill up).
    entries: [(item index, base, start, redundant)], appended to; returns
    the class ends after them."""
    by_ch = {it.ch.index: i for i, it in enumerate(items)}
    count = {it.ch.index: 0 for it in items}
    bases = {it.ch.index: [] for it in items}
    for i, b, _, _ in entries:
        count[items[i].ch.index] += 1
        bases[items[i].ch.index].append(b)
    rr = sorted((it.ch for it in items), key=lambda c: (-c.priority, c.period_clocks, c.index))
    rr = [ch for ch in rr if ch.max_slots is None or count[ch.index] < ch.max_slots]
    while rr and len(entries) < entry_cap:
        for ch in list(rr):
            if len(entries) >= entry_cap:
                break
            it = items[by_ch[ch.index]]
            r = it.rep
            top = max(ends)
            found = None
            if max(top, min(ends)) + skip <= cap:
                for b in _near(_target(bases[ch.index], r), r):
                    start = max(ends[b::r])
                    if start + it.length <= cap and max(top, start) + skip <= cap:
                        found = b
                        break
            if found is None:
                rr.remove(ch)
                continue
            start, ends = append_entry(ends, it.length, r, found, skip)
            entries.append((by_ch[ch.index], found, start, True))
            count[ch.index] += 1
            bases[ch.index].append(found)
            if ch.max_slots is not None and count[ch.index] >= ch.max_slots:
                rr.remove(ch)
    return ends
