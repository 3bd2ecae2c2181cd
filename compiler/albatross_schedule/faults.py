"""The fault hypothesis and what the plan derives from it.

The description's [faults] table states the faults the plan must tolerate:
a per-access fault probability `rate` (p) and a mean burst length
`mean_burst` (B), as a two-state Markov chain over the controller's bus
accesses (the test injector's model, tb/common/fault_model.h): after a good
access the next one fails with probability a = p / (B (1 - p)), after a
failed one with b = 1 - 1/B, so bursts are geometric with mean B and the
stationary fault probability is p.  Without mean_burst the accesses are
independent (B = 1 / (1 - p): a = b = p), as the injector without --burst.
`probability` is the target (for example 0.999999999): every age bound the
report gives at the target holds with at least that probability.
Permanently failed boards are not part of the hypothesis: isolation (the
dead-destination rule) tolerates them.

The maths (docs/compiler.md "Fault hypothesis"):
  * A failed access is retried at once, so after any access that succeeds
    the chain is in its good state.  The failures of one access are
    therefore independent of the other accesses' (given the first access's
    starting state): j failures with probability 1 - f0 (j = 0) and
    f0 b^(j-1) (1 - b) (j >= 1), f0 = a (b for the first access of a slot
    that starts right after a failure).
  * A destination is dropped after K consecutive failed attempts of one
    access (the drop run, ROM H2): P(j >= K) = f0 b^(K-1).
  * A slot with retry budget R delivers to its consumer d if the failures
    of the accesses up to d's store of Actual total at most R (the slot
    length holds R worst-case failures) and no destination access among
    them fails K times in a row.  This is a lower bound on the controller
    (a drop of another destination only removes accesses).
  * Given the chain state at a slot's start, the slot is independent of the
    past, so with q the worst start state's delivery probability, n slots
    in a row all miss with probability at most (1 - q)^n.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Optional

from .fourslot import FOUR_SLOT
from .model import ScheduleError, one_minus

FAULT_KEYS = {"rate", "mean_burst", "probability"}
DROP_RUN_MAX = 255           # H2[7:0]: the drop run K
DROP_RUN_DEFAULT = 2         # the rule without a fault hypothesis (and without a hypothesis)
RETRIES_MAX = 4095           # a sanity cap on a slot's retry budget
MAX_SPLIT = 6                # per-slot miss targets eps^(1/j), j = 1..MAX_SPLIT


@dataclasses.dataclass
class Hypothesis:
    rate: float              # p: stationary probability that an access fails
    mean_burst: float        # B: mean length of a run of failed accesses
    probability: float       # the target probability of the bounds

    @property
    def a(self) -> float:
        """P(fail | previous access good)."""
        if self.rate == 0:
            return 0.0
        return min(1.0, self.rate / (self.mean_burst * (1.0 - self.rate)))

    @property
    def b(self) -> float:
        """P(fail | previous access failed)."""
        return 1.0 - 1.0 / self.mean_burst

    @property
    def eps(self) -> float:
        return 1.0 - self.probability

    @property
    def independent(self) -> bool:
        return abs(self.a - self.b) < 1e-12

    def as_dict(self) -> dict:
        return {"rate": self.rate, "mean_burst": self.mean_burst, "independent": self.independent,
                "probability": self.probability,
                "miss_probability": self.eps, "p_fail_after_good": self.a, "p_fail_after_fail": self.b}


def parse_faults(table, err, describe) -> Optional[Hypothesis]:
    """[faults] -> Hypothesis (None without the table); errors through err."""
    if table is None:
        return None
    if not isinstance(table, dict):
        err.general("[faults] must be a table (rate, mean_burst, probability)")
        return None
    ok = True
    for key in table:
        if key not in FAULT_KEYS:
            err.system(key, f"unknown field (expected one of {', '.join(sorted(FAULT_KEYS))})", table="faults")
            ok = False

    def num(key, default=None):
        v = table.get(key, default)
        if v is None:
            err.system(key, "missing", table="faults")
            return None
        if isinstance(v, bool) or not isinstance(v, (int, float)) or math.isnan(v):
            err.system(key, f"{describe(v)} is not a number", table="faults")
            return None
        return float(v)

    rate, prob = num("rate"), num("probability")
    # no mean_burst: independent accesses, B = 1 / (1 - rate) (a = b = rate)
    burst = num("mean_burst") if "mean_burst" in table else (None if rate is None or not 0 <= rate < 1
                                                              else 1.0 / (1.0 - rate))
    if rate is not None and not 0.0 <= rate < 1.0:
        err.system("rate", f"{describe(rate)} is not a probability in [0, 1) (per bus access)", table="faults")
        ok = False
    if burst is not None and burst < 1.0:
        err.system("mean_burst", f"{describe(burst)} is below 1 (a burst is at least one failed access)",
                   table="faults")
        ok = False
    if prob is not None and not 0.0 < prob <= 1.0 - 1e-12:
        err.system("probability", f"{describe(prob)} is not a probability between 0 and 1 - 1e-12 "
                   "(for example 0.999999999; closer to 1 is below the precision of the sums)", table="faults")
        ok = False
    if None in (rate, burst, prob) or not ok:
        return None
    if rate > 0 and burst * (1.0 - rate) < rate * (1.0 - 1e-12):
        err.system("mean_burst", f"{describe(burst)}: at rate {describe(rate)} the bursts must last at least "
                   f"rate / (1 - rate) = {rate / (1 - rate):.4g} accesses on average (the good runs between "
                   "them cannot be shorter than one access)", table="faults")
        return None
    return Hypothesis(rate=rate, mean_burst=burst, probability=prob)


# ---------------------------------------------------------------------------
# The access sequence of one transfer (docs/controller.md "Execution").

def access_sequence(ch, d: int) -> list:
    """The accesses of a transfer that is new at every destination, up to
    and including destination d's store of Actual: 's' (source: retried
    until the deadline) or 'd' (destination: dropped after K failures in a
    row).  Its length is the A_d of docs/compiler.md."""
    nd = len(ch.consumers)
    four = ch.layout == FOUR_SLOT
    seq = []
    if ch.kind == "copy":
        seq += ["s"] * 3                           # load Actual, store ReadLocked, load Actual
    seq += ["d"] * nd                              # load ReadLocked (four-slot: the control word)
    for _ in range(ch.words):                      # each value word: source load, then the stores
        if ch.kind == "copy":
            seq.append("s")
        seq += ["d"] * nd
    seq += ["d"] * nd                              # taken_at
    if four:
        seq += ["d"] * nd                          # the Slot byte
    seq += ["d"] * (d + 1)                         # the stores of Actual, destination order
    return seq


# ---------------------------------------------------------------------------
# Probabilities.

def _access_failures(f0: float, b: float, jmax: int, truncate: Optional[int]) -> list:
    """P(an access fails exactly j times before it succeeds), j = 0..jmax;
    with truncate = K the mass of j >= K (a drop) is left out."""
    top = jmax if truncate is None else min(jmax, truncate - 1)
    out = [0.0] * (jmax + 1)
    out[0] = 1.0 - f0
    pj = f0
    for j in range(1, top + 1):
        out[j] = pj * (1.0 - b)
        pj *= b
    return out


def _convolve(x: list, y: list, n: int) -> list:
    out = [0.0] * (n + 1)
    for i, xi in enumerate(x):
        if xi == 0.0:
            continue
        for j in range(0, n + 1 - i):
            out[i + j] += xi * y[j]
    return out


def failure_distribution(h: Hypothesis, seq: list, rmax: int, drop_run: int, start_failed: bool) -> list:
    """dist[f] = P(the accesses of seq all succeed after f failures in all,
    no destination access failing drop_run times in a row), f = 0..rmax; the
    access before the first in the failed state (start_failed) or the good
    one.  sum(dist[:R + 1]) is the delivery probability with budget R."""
    a, b = h.a, h.b
    total = [1.0] + [0.0] * rmax
    cache = {}
    for i, kind in enumerate(seq):
        f0 = (b if start_failed else a) if i == 0 else a
        key = (i == 0, kind)
        if key not in cache:
            x = _access_failures(f0, b, rmax, drop_run if kind == "d" else None)
            while len(x) > 1 and x[-1] == 0.0:
                x.pop()
            cache[key] = x
        total = _convolve(cache[key], total, rmax)
    return total


def slot_delivery(h: Hypothesis, seq: list, retries: int, drop_run: int, start_failed: bool) -> float:
    """P(seq delivers within a budget of `retries` failures): see failure_distribution."""
    return min(1.0, max(0.0, sum(failure_distribution(h, seq, retries, drop_run, start_failed))))


def slot_delivery_min(h: Hypothesis, seq: list, retries: int, drop_run: int) -> float:
    """The worst starting state's delivery probability: a lower bound for
    the slot whatever happened before it."""
    return min(slot_delivery(h, seq, retries, drop_run, False), slot_delivery(h, seq, retries, drop_run, True))


def delivery_curve(h: Hypothesis, seq: list, rmax: int, drop_run: int) -> list:
    """curve[R] = the worst starting state's delivery probability with budget R, R = 0..rmax."""
    out = []
    for sf in (False, True):
        d = failure_distribution(h, seq, rmax, drop_run, sf)
        acc, c = 0.0, []
        for x in d:
            acc += x
            c.append(min(1.0, acc))
        out.append(c)
    return [min(x, y) for x, y in zip(*out)]


def drop_run_for(h: Hypothesis, dest_accesses: int) -> int:
    """K: the shortest run of failures (at least 2) that a live destination's
    accesses in one slot reach with probability at most eps:
    dest_accesses * max(a, b) * b^(K-1) <= eps."""
    f1 = max(h.a, h.b)
    if h.b == 0.0 or f1 == 0.0:
        return DROP_RUN_DEFAULT
    k = DROP_RUN_DEFAULT
    while dest_accesses * f1 * h.b ** (k - 1) > h.eps:
        k += 1
        if k > DROP_RUN_MAX:
            return k
    return k


def slots_needed(miss: float, eps: float, limit: int) -> Optional[int]:
    """The fewest consecutive slots m, each missing with probability at most
    `miss` whatever came before, that all miss with probability <= eps."""
    if miss <= eps:
        return 1
    if miss >= 1.0:
        return None
    m = math.ceil(math.log(eps) / math.log(miss) - 1e-12)
    m = max(1, m)
    return m if m <= limit else None


def runs_needed(miss: float, eps: float, successes: int, limit: int) -> Optional[int]:
    """The fewest runs n, each missing with probability at most `miss`
    whatever came before, among which fewer than `successes` deliver with
    probability <= eps (the binomial tail bounds it: the misses are
    dominated by independent ones); successes = 1 is slots_needed."""
    if successes <= 1:
        return slots_needed(miss, eps, limit)
    if miss >= 1.0:
        return None
    if miss <= 0.0:
        return successes
    lq, lm = math.log1p(-miss), math.log(miss)
    for n in range(successes, limit + 1):
        # P(fewer than `successes` of n deliver) = sum_{j < successes} C(n, j) q^j miss^(n-j), in logs
        tail = sum(math.exp(math.lgamma(n + 1) - math.lgamma(j + 1) - math.lgamma(n - j + 1) + j * lq + (n - j) * lm)
                   for j in range(successes))
        if tail <= eps:
            return n
    return None


def period_at(starts: list, cycle: int, m: int) -> int:
    """The longest span from a slot's start to the start of the m-th slot
    after it (cyclic; the channel's slot starts in one cycle)."""
    s = sorted(starts)
    n = len(s)
    return max(s[(i + m) % n] + cycle * ((i + m) // n) - s[i] for i in range(n))


def log10_or_none(x: float):
    return None if x <= 0 else round(math.log10(x), 3)


# ---------------------------------------------------------------------------
# Planning for the hypothesis.

def _failure_cost(bus) -> int:
    return bus.timeout_cycles + bus.access_cycles + 1


def _describe_h(h: Hypothesis) -> str:
    burst = "independent" if h.independent else f"mean burst {h.mean_burst:g}"
    return f"rate {h.rate:g} per access, {burst}, probability {one_minus(1.0 - h.probability)}"


def evaluate(system, plan, curves) -> dict:
    """Per channel index: one dict per consumer with the slot delivery
    probability q (worst start state), the per-cycle delivery probability
    (lower bound 1 - (1 - q)^n), the slots m needed at the target and the
    period and age bound that hold with the target probability."""
    h, bus = system.faults, system.bus
    out = {}
    for ch in system.channels:
        r = bus.retries_of(ch)
        n = len(ch.slots)
        # a multi-rate plan: ch.slots are its runs over its span; a value in F
        # fragments is published 2F - 1 delivering runs after a sample missed
        # (plan.channel_bounds), so m runs hold that many at the target
        span = ch.run_span or plan.cycle
        need = 2 * ch.fragments - 1
        per = []
        for d in range(len(ch.consumers)):
            q = curves[ch.index][d][min(r, len(curves[ch.index][d]) - 1)]
            miss = max(0.0, 1.0 - q)
            m = runs_needed(miss, h.eps, need, limit=64 * n * need)
            period = period_at(ch.slots, span, m) if m is not None else None
            # the longest span of runs in which a whole value (F fragments)
            # gets through with the target probability: against max_period
            mf = m if ch.fragments == 1 else runs_needed(miss, h.eps, ch.fragments, limit=64 * n * need)
            transfer = period_at(ch.slots, span, mf) if mf is not None else None
            per.append({"slot_delivery_probability": q, "slot_miss_probability": miss,
                        "cycle_delivery_probability": 1.0 - miss ** n, "cycle_miss_probability": miss ** n,
                        "slots_needed": m, "period_at_target_clocks": period,
                        "transfer_period_at_target_clocks": transfer})
        out[ch.index] = per
    return out


def _curves(system, rmax: int) -> dict:
    h = system.faults
    # A channel without a consumer (a mode_request channel, which the
    # controller reads): its slot must read the source, access_sequence(ch, -1).
    return {ch.index: [delivery_curve(h, access_sequence(ch, d), rmax, system.drop_run)
                       for d in range(len(ch.consumers))] or
            [delivery_curve(h, access_sequence(ch, -1), rmax, system.drop_run)] for ch in system.channels}


def plan_for_hypothesis(system, plan_fn):
    """Build the plan (plan_fn) with every slot's retry budget, the drop run
    and the redundancy sized for the system's fault hypothesis; without one,
    plan_fn as before (the [bus] retries_per_slot, the drop run 2).

    K (drop_run_for) depends on the hypothesis only.  Each channel's retry
    budget R is the smallest R >= [bus] retries_per_slot (and >= K when it has
    two or more consumers, so that one dead destination alone never costs its
    co-destinations their slot) whose slots miss with probability at most a
    per-slot target eps^(1/j_c), j_c = min(j, max_period // cycle): j = 1
    asks every slot to meet the target on its own, larger j relies on j slots
    in a row (j cycles at most, so only channels whose period is j cycles or
    more do).  Each j gives a plan
    (redundancy from the capacity left, as without a hypothesis); the one
    whose worst channel has the most room (period at the target / max_period)
    is kept, and one over 1 everywhere is an error naming the channels."""
    system.drop_run = DROP_RUN_DEFAULT
    h = system.faults
    if h is None:
        return plan_fn(system)
    bus = system.bus
    seqs = [access_sequence(ch, len(ch.consumers) - 1) for ch in system.channels]
    dmax = max(s.count("d") for s in seqs)
    k = DROP_RUN_DEFAULT if h.rate == 0 else drop_run_for(h, dmax)
    if k > DROP_RUN_MAX:
        raise ScheduleError(
            f"{system.source}: [faults]: under the fault hypothesis ({_describe_h(h)}) a live board fails "
            f"more than {DROP_RUN_MAX} accesses in a row too often (b = {h.b:.4g}): the controller cannot tell it "
            "from a dead one within the drop run the ROM holds (H2, at most 255). Shorten mean_burst or lower "
            "probability")
    system.drop_run = k
    cost = _failure_cost(bus)
    # the longest slot fits one cycle: the smallest period (a multi-rate
    # plan: a minor cycle, at most what time_bits allows)
    cap = min([ch.period_clocks for ch in system.channels] + [(1 << bus.time_bits) - 1])
    rmax = max(bus.retries_per_slot, min(RETRIES_MAX, cap // cost))
    curves = _curves(system, rmax)
    saved = {ch.index: (ch.max_slots, getattr(ch, "spaced_for_termination", None), ch.retries)
             for ch in system.channels}

    def restore():
        for ch in system.channels:
            ms, sp, rt = saved[ch.index]
            ch.max_slots, ch.retries = ms, rt
            if sp is None:
                if hasattr(ch, "spaced_for_termination"):
                    del ch.spaced_for_termination
            else:
                ch.spaced_for_termination = sp

    cycle = min(ch.period_clocks for ch in system.channels)

    def budgets(j):
        out = {}
        for ch in system.channels:
            # m slots in a row span at most m cycles: a channel whose period is
            # P >= m cycles may rely on m of them whatever its slot count
            target = h.eps ** (1.0 / max(1, min(j, ch.period_clocks // cycle)))
            rmin = max(bus.retries_per_slot, k if len(ch.consumers) >= 2 else 0)
            cs = curves[ch.index]
            r = next((r for r in range(rmin, rmax + 1) if min(c[r] for c in cs) >= 1.0 - target), None)
            out[ch.index] = rmax if r is None else r
        return out

    results = []          # (score, j, budgets, worst)
    infeasible = []
    tried = set()
    for j in range(1, MAX_SPLIT + 1):
        bj = budgets(j)
        key = tuple(sorted(bj.items()))
        if key in tried:
            continue
        tried.add(key)
        for ch in system.channels:
            ch.retries = bj[ch.index]
        try:
            plan = plan_fn(system)
        except ScheduleError as e:
            infeasible.append((j, bj, e))
            restore()
            continue
        ev = evaluate(system, plan, curves)
        worst = []
        for ch in system.channels:
            for d, x in enumerate(ev[ch.index]):
                p = x["transfer_period_at_target_clocks"]
                ratio = float("inf") if p is None else p / ch.period_clocks
                worst.append((ratio, ch, d, x))
        worst.sort(key=lambda w: -w[0])
        results.append((worst[0][0], j, bj, worst))
        restore()
    if not results:
        j, bj, e = infeasible[-1]
        if getattr(e, "kind", None):    # the multi-rate planner's rejection (multirate.MultiRateRejection)
            err = ScheduleError([f"{m} (planned for the fault hypothesis: {_describe_h(h)}, drop run K = {k}, "
                                 f"retry budgets {', '.join(f'{ch.name} {bj[ch.index]}' for ch in system.channels)})"
                                 for m in e.messages])
            err.kind = e.kind
            raise err
        parts = []
        for ch in sorted(system.channels, key=lambda c: -c.slot_len):
            jc = max(1, min(j, ch.period_clocks // cycle))
            parts.append(f"channel '{ch.name}' (max_period_us = {ch.max_period_us}, may rely on {jc} slot"
                         f"{'s' if jc > 1 else ''} in a row, each missing with probability at most "
                         f"{h.eps ** (1.0 / jc):.3g}) needs a retry budget R = {bj[ch.index]} per slot "
                         f"({ch.slot_len} clocks)")
        need = sum(ch.slot_len for ch in system.channels)
        raise ScheduleError(
            f"{system.source}: cannot meet the channels' periods under the fault hypothesis ({_describe_h(h)}, "
            f"drop run K = {k}): one slot per channel needs {need} clocks but the cycle has "
            f"{cycle - (bus.poll_cycles if system.sync_mode else 0)}: " + "; ".join(parts)
            + ". Lower the hypothesis, relax max_period_us, shrink the channels or raise clock_hz")
    results.sort(key=lambda r: (r[0], r[1]))
    score, j, bj, worst = results[0]
    if score > 1.0:
        msgs = []
        for ratio, ch, d, x in worst:
            if ratio <= 1.0:
                continue
            p = x["transfer_period_at_target_clocks"]
            got = ("never (a slot delivers with probability 0)" if p is None else
                   f"{p} clocks ({p * 1e6 / system.clock_hz:.4g} us)")
            msgs.append(
                f"{system.source}: channel '{ch.name}', consumer '{system.boards[ch.consumers[d]]}': cannot meet "
                f"max_period_us = {ch.max_period_us} under the fault hypothesis ({_describe_h(h)}): each of its "
                f"{len(ch.slots)} slots per cycle (retry budget {bj[ch.index]}, drop run {k}) delivers with "
                f"probability {one_minus(x['slot_miss_probability'])}, so {x['slots_needed'] or 'no number of'} slots "
                f"in a row are needed for the target and the period that holds with it is {got} against "
                f"{ch.period_clocks} clocks. Lower the hypothesis, relax max_period_us, shrink the channel or "
                "raise clock_hz")
        raise ScheduleError(msgs)
    for ch in system.channels:
        ch.retries = bj[ch.index]
    plan = plan_fn(system)
    system.fault_eval = evaluate(system, plan, curves)
    system.fault_split = j
    return plan
