"""An exact reference for multi-rate schedules: an exhaustive search with
OR-Tools' CP-SAT solver for a placement on the plain power-of-two grid.  It
is no part of the compiler's pipeline: the schedulability benchmark
(tools/schedulability_bench.py, docs/compiler.md "Schedulability") measures
planners against it.  OR-Tools is imported only when a search runs
(pip install ortools, which make deps does; or pip install ./compiler[exact]).

The grid.  A cluster of R minor cycles of m clocks each; cycle c (0 .. R-1)
runs the entries due in it.  Every channel i has one ROM entry with a
repetition r_i (a power of two), a base b_i in [0, r_i) and a start s_i: the
entry runs in the minor cycles c with c mod r_i = b_i, at s_i clocks from
the cycle's start.  Its slot is the compiler's own slot length L_i
(plan.slot_length: fetch, the fault-free accesses, the [bus] retry budget,
guard), and it must end within the usable clocks of the cycle:
0 <= s_i <= cap - L_i, cap = m minus the idle clocks at every cycle's end
(the position poll in position-synchronised mode, the mode-switch window
with [[mode]]; none in a plain time-rigid system), as build_plan counts them.

The period.  The compiler's guaranteed period of a channel is the largest
gap between two consecutive starts of its slots (docs/compiler.md "Plan"),
and it must not exceed max_period (P_i clocks = max_period_us * clock_hz /
10^6, rounded down).  On the grid the runs of an entry are exactly r_i * m
apart, so r_i * m <= P_i.  A smaller repetition is due in a superset of the
cycles of a larger one (c mod r = b mod r follows from c mod 2r = b), so the
largest allowed repetition loses nothing: r_i = the largest power of two
with r_i * m <= P_i (and r_i <= max_repetition, the cluster's length).

The rule.  Two entries are due in a common cycle exactly when
b_i = b_j mod min(r_i, r_j) (the smaller repetition divides the larger);
such entries must not overlap in time.  No value is split into fragments
and no channel has a second entry: "plain" grid.

The minor cycle.  m is the smallest period P_min, or a half or a quarter of
it (rounded down): the first `divisions` of P_min / 2^k that fit the
controller's time within a cycle (2^time_bits - 1 clocks).  A finer minor
cycle helps on this grid only through the rounding: when m = 2 m' exactly,
every repetition doubles (r' m' = r m), and a placement on m' is one on m
whose slots keep to one half of the cycle.  So m' is infeasible when m is
(proof "finer"); an odd m leaves m' to the search.

The search.  The residues of the cluster form a binary tree: a node of
depth d is a residue mod 2^d, its children v and v + 2^d.  An entry sits at
the node b_i of depth log2 r_i, and it shares cycles exactly with the
entries at its ancestors, at its node and in its subtree.  Given the bases,
the slots fit exactly when every minor cycle's due slots add up to at most
cap: stacked by depth (stack), each slot ends at most at the sum of the
slots on its path.  So the search chooses the bases alone: first the quick
proofs (a slot longer than cap; the average load of a cycle,
sum L_i / r_i, above cap; the slots due in every cycle beside the longest
other one), then a greedy placement (worst fit by depth), then CP-SAT on
the tree (_tree_model); a second model straight from the pairwise rule,
with the starts as variables (_pairwise_model), cross-checks it in the
tests.  Every placement is checked by check_grid, an explicit expansion of
the cluster.

Outcomes: feasible (a placement), infeasible (a proof for every candidate
minor cycle), or unknown (CP-SAT's limit ran out first).  The limit is
CP-SAT's deterministic time, a measure of its work of about a second per
unit on a typical machine, so that an outcome does not depend on the
machine's load and a run can be repeated; a wall-clock cap of WALL_FACTOR
times as many seconds stops a search on a machine that is very loaded (its
outcome says so)."""

from __future__ import annotations

import dataclasses
import time
from typing import Optional

from .model import System
from .plan import slot_length
from .rom import C as CONTRACT

FEASIBLE, INFEASIBLE, UNKNOWN = "feasible", "infeasible", "unknown"
# The longest cluster, and so the largest repetition: 2^c minor cycles, c the
# contract's largest cluster (ROM word H2.cluster: 15, 1.6 s at a minor cycle
# of 50 us).
MAX_REPETITION = 1 << CONTRACT.field("H2", "cluster").max
# CP-SAT stops at its limit of deterministic time, or after WALL_FACTOR times
# as many seconds of wall time.
WALL_FACTOR = 10

INSTALL_HINT = ("the exact search needs OR-Tools' CP-SAT solver: pip install ortools (make deps installs "
                "it into build/venv), or pip install ./compiler[exact]")


class SolverMissing(ImportError):
    """OR-Tools is not installed."""


def _cp_model():
    try:
        from ortools.sat.python import cp_model
    except ImportError as e:
        raise SolverMissing(f"{INSTALL_HINT} ({e})") from None
    return cp_model


def repetition(period: int, minor: int, max_repetition: int = MAX_REPETITION) -> int:
    """The largest power of two r <= max_repetition with r * minor <= period
    (0 if even one minor cycle is longer than the period)."""
    if minor <= 0 or period < minor:
        return 0
    r = 1
    while 2 * r * minor <= period and 2 * r <= max_repetition:
        r *= 2
    return r


def due(cycle: int, rep: int, base: int) -> bool:
    return cycle % rep == base


def check_grid(lengths, periods, minor, cap, reps, bases, starts) -> list:
    """The problems of a placement, by an explicit expansion of the
    cluster (every minor cycle, the entries due in it, their slots):
    independent of the search's pairwise rule.  [] when it is valid."""
    problems = []
    n = len(lengths)
    if not (len(periods) == len(reps) == len(bases) == len(starts) == n):
        return [f"{n} lengths but {len(periods)} periods, {len(reps)} repetitions, {len(bases)} bases, "
                f"{len(starts)} starts"]
    for i in range(n):
        r = reps[i]
        if r < 1 or r & (r - 1):
            problems.append(f"channel {i}: repetition {r} is not a power of two")
        elif r * minor > periods[i]:
            problems.append(f"channel {i}: runs every {r * minor} clocks, longer than its period {periods[i]}")
        if not 0 <= bases[i] < max(r, 1):
            problems.append(f"channel {i}: base {bases[i]} outside [0, {r})")
        if starts[i] < 0 or starts[i] + lengths[i] > cap:
            problems.append(f"channel {i}: slot [{starts[i]}, {starts[i] + lengths[i]}) outside the usable "
                            f"[0, {cap}) of the minor cycle")
    if problems:
        return problems
    cluster = max(reps) if reps else 1
    for c in range(cluster):
        run = sorted((starts[i], i) for i in range(n) if due(c, reps[i], bases[i]))
        for (s0, i0), (s1, i1) in zip(run, run[1:]):
            if s0 + lengths[i0] > s1:
                problems.append(f"minor cycle {c}: channel {i0} [{s0}, {s0 + lengths[i0]}) overlaps "
                                f"channel {i1} at {s1}")
        if len(problems) > 20:
            break
    return problems


@dataclasses.dataclass
class GridResult:
    """One minor cycle's search."""
    status: str                     # feasible | infeasible | unknown
    minor: int                      # m, clocks
    cap: int                        # usable clocks of a minor cycle
    reps: list                      # r_i
    reason: str                     # how the status was reached (a proof's kind, or the limit)
    detail: str = ""                # the proof or the limit in words
    seconds: float = 0.0            # wall time of this search
    work: float = 0.0               # CP-SAT's deterministic time spent (0: decided without it)
    bases: Optional[list] = None    # feasible: b_i
    starts: Optional[list] = None   # feasible: s_i

    def as_dict(self) -> dict:
        d = dataclasses.asdict(self)
        d["seconds"] = round(self.seconds, 3)
        d["work"] = round(self.work, 3)
        d["cluster"] = max(self.reps) if self.reps else 0
        return d


def stack(lengths, reps, bases) -> list:
    """The starts of the stacked placement of given bases: the entries in
    order of repetition (then channel), each at the end of the slots already
    placed that share a cycle with it.  The residues of the cluster form a
    binary tree (a node of depth d is a residue mod 2^d; its children are
    v and v + 2^d mod 2^(d+1)); an entry sits at the node b_i of depth
    log2 r_i, and shares cycles exactly with the entries at its ancestors,
    at its node and below it.  Placed by depth, the slots that share a cycle
    with an entry when it comes are those at its ancestors and before it at
    its node, one stack: each entry ends at most at the sum of the slots on
    its path, so this placement fits exactly when every minor cycle's due
    slots add up to at most the usable clocks."""
    order = sorted(range(len(lengths)), key=lambda i: (reps[i], i))
    top = {}                                # (repetition, residue) -> the stack's height there
    starts = [0] * len(lengths)
    for i in order:
        r, v = reps[i], bases[i]
        h = top.get((r, v))
        if h is None:                       # the height at the nearest ancestor with a stack
            h, q = 0, r // 2
            while q >= 1:
                if (q, v % q) in top:
                    h = top[(q, v % q)]
                    break
                q //= 2
        starts[i] = h
        top[(r, v)] = h + lengths[i]
    return starts


def greedy(lengths, reps, cap):
    """A quick placement (or None): the entries by repetition, the longest
    first, each at the residue whose stack is lowest (worst fit)."""
    load = [0]                              # per residue mod 2^depth: the stack there
    bases = [0] * len(lengths)
    for i in sorted(range(len(lengths)), key=lambda k: (reps[k], -lengths[k], k)):
        while len(load) < reps[i]:
            load = load + load              # residue v's children v, v + 2^d inherit its stack
        v = min(range(len(load)), key=lambda k: (load[k], k))
        if load[v] + lengths[i] > cap:
            return None
        bases[i] = v
        load[v] += lengths[i]
    return bases


def _tree_model(cp_model, lengths, reps, cap, hint=None):
    """The CP-SAT model of one minor cycle on the tree of residues (see
    stack: the bases alone decide): per entry a choice of one residue
    mod r_i; per node v of depth d (its residue) need(v) >= the slots at v
    plus need(child), for both children, and need(root) <= cap (every
    node's need is at most cap).  Swapping the two subtrees of a node maps
    placements to placements, so need(v) >= need(v + 2^d) for the children
    v, v + 2^d of every node breaks that symmetry."""
    model = cp_model.CpModel()
    n = len(lengths)
    cluster = max(reps)
    depth = cluster.bit_length() - 1
    choice = []
    own = {}                                # (depth, residue) -> [(length, literal)]
    for i in range(n):
        d = reps[i].bit_length() - 1
        lits = [model.NewBoolVar(f"x{i}_{v}") for v in range(reps[i])]
        model.AddExactlyOne(lits)
        choice.append(lits)
        for v, x in enumerate(lits):
            own.setdefault((d, v), []).append((lengths[i], x))
    need = {}
    for d in range(depth, -1, -1):
        for v in range(1 << d):
            terms = own.get((d, v), [])
            nv = model.NewIntVar(0, cap, f"need{d}_{v}")
            load = sum(l * x for l, x in terms)
            if d == depth:
                model.Add(nv >= load)
            else:
                left, right = need[(d + 1, v)], need[(d + 1, v + (1 << d))]
                model.Add(nv >= load + left)
                model.Add(nv >= load + right)
                model.Add(left >= right)
            need[(d, v)] = nv
        for v in range(1 << (d + 1)) if d < depth else ():
            del need[(d + 1, v)]
    if hint is not None:
        for i in range(n):
            for v, x in enumerate(choice[i]):
                model.AddHint(x, int(v == hint[i]))
    return model, choice


def _low(bits, d):
    """The residue of a base modulo 2^d: its d low bits, a linear expression."""
    return sum((1 << t) * bits[t] for t in range(d))


def _pairwise_model(cp_model, lengths, reps, cap, hint=None):
    """A second CP-SAT model of the same grid, straight from its rule,
    without the stacking argument (a cross-check of the tree model in
    compiler/tests/test_exact.py): the bases as bits, the starts, and per
    pair of entries a conflict literal, forced when they are due in a common
    cycle, that enforces their disjunction in time.  A pair whose slots
    together exceed the cycle may never share one; one entry of the largest
    repetition has base 0 (swapping subtrees maps any base to 0)."""
    model = cp_model.CpModel()
    n = len(lengths)
    logs = [r.bit_length() - 1 for r in reps]
    bits = [[model.NewBoolVar(f"b{i}_{t}") for t in range(logs[i])] for i in range(n)]
    starts = [model.NewIntVar(0, cap - lengths[i], f"s{i}") for i in range(n)]
    top = max(range(n), key=lambda i: (reps[i], -i))
    for v in bits[top]:
        model.Add(v == 0)
    for i in range(n):
        for j in range(i + 1, n):
            a, h = (i, j) if reps[i] <= reps[j] else (j, i)
            d = logs[a]
            if lengths[i] + lengths[j] > cap:           # never in a common cycle
                assert d > 0, "solve_grid's pair check lets no such pair through"
                model.Add(_low(bits[a], d) != _low(bits[h], d))
                continue
            order = model.NewBoolVar(f"o{i}_{j}")
            lits = []
            if d > 0:
                c = model.NewBoolVar(f"c{i}_{j}")
                model.Add(_low(bits[a], d) != _low(bits[h], d)).OnlyEnforceIf(c.Not())
                lits = [c]
            model.Add(starts[i] + lengths[i] <= starts[j]).OnlyEnforceIf(lits + [order])
            model.Add(starts[j] + lengths[j] <= starts[i]).OnlyEnforceIf(lits + [order.Not()])
    return model, bits, starts


MODELS = ("tree", "pairwise")


def solve_grid(lengths, periods, minor, idle: int = 0, time_limit: float = 10.0, workers: int = 1,
               seed: int = 0, max_repetition: int = MAX_REPETITION, model: str = "tree",
               quick: bool = True) -> GridResult:
    """Search a placement of one entry per channel (slot lengths and periods
    in clocks) on the grid of minor cycle `minor`, `idle` clocks of it kept
    free at its end.  The quick proofs first (a slot longer than the cycle,
    the average load, the slots due in every cycle beside the longest
    other), then with quick the greedy placement, then CP-SAT (model: tree,
    or pairwise, the cross-check)."""
    if model not in MODELS:
        raise ValueError(f"model {model!r}: expected one of {', '.join(MODELS)}")
    t0 = time.monotonic()
    n = len(lengths)
    cap = minor - idle
    reps = [repetition(p, minor, max_repetition) for p in periods]

    work = 0.0

    def result(status, reason, detail, bases=None, starts=None):
        if status == FEASIBLE:
            problems = check_grid(lengths, periods, minor, cap, reps, bases, starts)
            if problems:
                raise AssertionError("internal error, the exact search's placement breaks the grid: "
                                     + "; ".join(problems[:5]))
        return GridResult(status=status, minor=minor, cap=cap, reps=reps, reason=reason, detail=detail,
                          seconds=time.monotonic() - t0, work=work, bases=bases, starts=starts)

    if n == 0:
        return result(FEASIBLE, "empty", "no channel", [], [])
    short = [i for i in range(n) if reps[i] == 0]
    if short:
        return result(INFEASIBLE, "period", f"channel {short[0]}: period {periods[short[0]]} clocks is shorter "
                      f"than the minor cycle of {minor}")
    long_ = [i for i in range(n) if lengths[i] > cap]
    if long_:
        i = max(long_, key=lambda k: lengths[k])
        return result(INFEASIBLE, "slot", f"channel {i}: its slot of {lengths[i]} clocks is longer than the "
                      f"{cap} usable clocks of the minor cycle")
    cluster = max(reps)
    load = sum(lengths[i] * (cluster // reps[i]) for i in range(n))
    if load > cap * cluster:
        return result(INFEASIBLE, "load", f"the minor cycles carry {load / cluster:.1f} clocks on average "
                      f"(sum of L_i / r_i), more than their {cap} usable clocks")
    every = [i for i in range(n) if reps[i] == 1]
    if every:
        busy = sum(lengths[i] for i in every)
        others = [i for i in range(n) if reps[i] > 1]
        h = max(others, key=lambda k: lengths[k], default=None)
        if h is not None and busy + lengths[h] > cap:
            return result(INFEASIBLE, "pair", f"the entries due in every minor cycle take {busy} clocks, and "
                          f"channel {h}'s slot of {lengths[h]} clocks does not fit beside them "
                          f"in the {cap} usable clocks")
    hint = greedy(lengths, reps, cap)
    if quick and hint is not None:
        return result(FEASIBLE, "greedy", f"the greedy placement fits (cluster of {cluster} minor cycles)",
                      hint, stack(lengths, reps, hint))
    cp_model = _cp_model()
    if model == "tree":
        m, choice = _tree_model(cp_model, lengths, reps, cap, hint)
    else:
        m, bits, starts = _pairwise_model(cp_model, lengths, reps, cap, hint)
    solver = cp_model.CpSolver()
    limit = max(0.01, float(time_limit))
    solver.parameters.max_deterministic_time = limit
    solver.parameters.max_time_in_seconds = WALL_FACTOR * limit
    solver.parameters.num_workers = max(1, int(workers))
    solver.parameters.random_seed = int(seed)
    status = solver.Solve(m)
    work = solver.ResponseProto().deterministic_time
    if status in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        if model == "tree":
            bases = [next(v for v, x in enumerate(choice[i]) if solver.Value(x)) for i in range(n)]
            st = stack(lengths, reps, bases)
        else:
            bases = [sum(solver.Value(v) << t for t, v in enumerate(bits[i])) for i in range(n)]
            st = [solver.Value(s) for s in starts]
        return result(FEASIBLE, "search", f"CP-SAT placed every entry (cluster of {cluster} minor cycles)",
                      bases, st)
    if status == cp_model.INFEASIBLE:
        return result(INFEASIBLE, "search", "CP-SAT's exhaustive search found no placement")
    if status == cp_model.MODEL_INVALID:
        raise AssertionError(f"internal error, the exact search's model is invalid: {m.Validate()}")
    if work < 0.99 * limit:
        return result(UNKNOWN, "wall-clock cap", f"no placement and no proof after {work:.2f} of the {limit:.2f} "
                      f"units of work allowed, stopped by the wall-clock cap of {WALL_FACTOR * limit:.1f} s "
                      "(a loaded machine)")
    return result(UNKNOWN, "time limit", f"no placement and no proof within {limit:.2f} units of work "
                  "(CP-SAT's deterministic time, about seconds)")


def cycle_idle(system: System) -> int:
    """The clocks kept idle at every cycle's end, as build_plan counts them."""
    return (system.bus.poll_cycles if system.sync_mode else 0) + system.mode_window


def minor_cycles(shortest: int, max_minor: int, divisions: int = 3) -> list:
    """The candidate minor cycles: the first `divisions` of shortest / 2^k
    (rounded down) that are at most max_minor clocks."""
    out = []
    k = 0
    while len(out) < divisions and (shortest >> k) >= 1:
        m = shortest >> k
        if m <= max_minor:
            out.append(m)
        k += 1
    return out


@dataclasses.dataclass
class ExactResult:
    status: str                     # feasible | infeasible | unknown
    minor: Optional[int]            # the minor cycle of the placement (feasible)
    tries: list                     # GridResult per minor cycle tried, in order
    seconds: float

    @property
    def placement(self) -> Optional[GridResult]:
        return next((t for t in self.tries if t.status == FEASIBLE), None)

    def reason(self) -> str:
        """The outcome in words: the placement, the proofs, or the limit."""
        if self.status == FEASIBLE:
            p = self.placement
            return f"minor cycle {p.minor} clocks, cluster {max(p.reps)}: {p.detail}"
        if not self.tries:
            return "no candidate minor cycle fits the controller's time field"
        return "; ".join(f"minor cycle {t.minor}: {t.status} ({t.reason}: {t.detail})" for t in self.tries)

    def as_dict(self) -> dict:
        return {"status": self.status, "minor": self.minor, "seconds": round(self.seconds, 3),
                "reason": self.reason(), "tries": [t.as_dict() for t in self.tries]}


# Shares of the time limit per candidate minor cycle (largest first: the
# finer ones are nearly always infeasible when it is); time left over by one
# passes to the next.
SHARES = (0.6, 0.2, 0.2)


def exact_grid(system: System, time_limit: float = 10.0, workers: int = 1, divisions: int = 3,
               max_minor: Optional[int] = None, max_repetition: int = MAX_REPETITION,
               seed: int = 0) -> ExactResult:
    """The exact search on a described system (parse_description's System):
    the compiler's slot lengths and periods, each candidate minor cycle in
    turn until one has a placement.  max_minor: the longest minor cycle
    (default: the controller's time field, 2^time_bits - 1 clocks)."""
    t0 = time.monotonic()
    bus = system.bus
    lengths = [slot_length(ch, bus) for ch in system.channels]
    periods = [ch.period_clocks for ch in system.channels]
    if max_minor is None:
        max_minor = (1 << bus.time_bits) - 1
    idle = cycle_idle(system)
    minors = minor_cycles(min(periods), max_minor, divisions)
    tries = []
    status = INFEASIBLE
    spent = 0.0
    for k, m in enumerate(minors):
        share = sum(SHARES[:k + 1]) / sum(SHARES[:len(minors)]) if len(minors) <= len(SHARES) else (k + 1) / len(minors)
        limit = max(0.05, time_limit * share - spent)
        prev = tries[-1] if tries else None
        if prev is not None and prev.status == INFEASIBLE and prev.minor == 2 * m:
            # Each cycle of prev.minor is two of m: a placement on m would be
            # one on prev.minor (repetitions halved, the second half's
            # starts moved by m), which has none.
            tries.append(GridResult(INFEASIBLE, m, m - idle, [repetition(p, m, max_repetition) for p in periods],
                                    "finer", f"a placement would be one on the minor cycle of {prev.minor} "
                                    "clocks (two of these cycles each), which has none"))
            continue
        g = solve_grid(lengths, periods, m, idle, limit, workers, seed, max_repetition)
        spent += g.work
        tries.append(g)
        if g.status == FEASIBLE:
            return ExactResult(FEASIBLE, m, tries, time.monotonic() - t0)
        if g.status == UNKNOWN:
            status = UNKNOWN
    return ExactResult(status, None, tries, time.monotonic() - t0)
