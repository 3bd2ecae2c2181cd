"""The exact search on the plain power-of-two grid
(compiler/albatross_schedule/exact.py) against a brute force written here
from the grid's definition alone: every base and every start of every
entry, tried by backtracking, each minor cycle of the cluster expanded
explicitly.  On random tiny systems the search (quick proofs and greedy,
CP-SAT's tree model alone, and the pairwise model) must give the brute
force's verdict, and on larger ones the two CP-SAT models must agree.  The
stacking argument (the bases alone decide) is checked directly.  Negative
tests: check_grid catches each kind of broken placement, a repetition one
bit too long is caught, and one bit short changes verdicts that the brute
force catches.  Cost: about 10 s."""

import random
import sys
import unittest
from unittest import mock

from albatross_schedule import parse_description
import albatross_schedule.exact as X

CLOCK = 50_000_000


def due_cycles(rep, base, cluster):
    return {c for c in range(cluster) if c % rep == base}


def brute(lengths, periods, minor, cap):
    """Feasible by exhaustion: every (base, start) of every entry, by
    backtracking over the entries; the repetition of each the largest power
    of two whose runs (r * minor apart) keep within its period (a smaller
    one runs in more cycles: never better)."""
    reps = []
    for p in periods:
        r = 0
        while (2 * r if r else 1) * minor <= p:
            r = 2 * r if r else 1
        reps.append(r)
    if 0 in reps:
        return False, reps
    cluster = max(reps)
    n = len(lengths)
    placed = []                                 # (cycles, start, end)

    def place(i):
        if i == n:
            return True
        for b in range(reps[i]):
            cyc = due_cycles(reps[i], b, cluster)
            for s in range(0, cap - lengths[i] + 1):
                e = s + lengths[i]
                if all(not (cyc & c2) or e <= s2 or e2 <= s for c2, s2, e2 in placed):
                    placed.append((cyc, s, e))
                    if place(i + 1):
                        return True
                    placed.pop()
        return False
    return place(0), reps


def tiny(rng, n_max=4, cap_lo=5, cap_hi=9, rep_max=8):
    n = rng.randint(2, n_max)
    minor = rng.randint(cap_lo, cap_hi)
    idle = rng.choice([0, 0, 1])
    cap = minor - idle
    lengths = [rng.randint(1, cap) for _ in range(n)]
    periods = [minor * rng.randint(1, rep_max) + rng.randint(0, minor - 1) for _ in range(n)]
    return lengths, periods, minor, idle


class TestAgainstBruteForce(unittest.TestCase):
    def test_tiny_systems(self):
        rng = random.Random(1)
        verdicts = {True: 0, False: 0}
        searched = {X.FEASIBLE: 0, X.INFEASIBLE: 0}
        for k in range(220):
            lengths, periods, minor, idle = tiny(rng)
            want, reps = brute(lengths, periods, minor, minor - idle)
            verdicts[want] += 1
            for model, quick in (("tree", True), ("tree", False), ("pairwise", False)):
                g = X.solve_grid(lengths, periods, minor, idle, time_limit=10, model=model, quick=quick)
                self.assertNotEqual(g.status, X.UNKNOWN, f"case {k}: {model} gave no answer")
                self.assertEqual(g.status == X.FEASIBLE, want,
                                 f"case {k}: L={lengths} P={periods} m={minor} idle={idle}: brute force says "
                                 f"{'feasible' if want else 'infeasible'}, the {model} search (quick {quick}) "
                                 f"{g.status} ({g.reason}: {g.detail})")
                self.assertEqual(g.reps, reps)
                if g.status == X.FEASIBLE:
                    self.assertEqual(X.check_grid(lengths, periods, minor, minor - idle, g.reps, g.bases, g.starts),
                                     [], f"case {k}: the placement")
                if not quick and g.reason == "search":
                    searched[g.status] += 1
        # Both verdicts often, and CP-SAT deciding each (not only the quick proofs).
        self.assertGreater(verdicts[True], 40, verdicts)
        self.assertGreater(verdicts[False], 40, verdicts)
        self.assertGreater(searched[X.FEASIBLE], 40, searched)
        self.assertGreater(searched[X.INFEASIBLE], 10, searched)

    def test_models_agree_on_larger_systems(self):
        """6 to 12 entries, repetitions up to 16, the average load of a
        cycle 70 to 100 % of it: where the quick proofs rarely decide."""
        rng = random.Random(2)
        both = {X.FEASIBLE: 0, X.INFEASIBLE: 0}
        for k in range(40):
            n = rng.randint(6, 12)
            minor = rng.randint(60, 120)
            mult = [rng.choice([1, 2, 2, 4, 4, 8, 16]) for _ in range(n)]
            periods = [minor * m + rng.randint(0, minor - 1) for m in mult]
            w = [rng.random() for _ in range(n)]
            f = rng.uniform(0.7, 1.0) * minor / sum(wi / m for wi, m in zip(w, mult))
            lengths = [max(1, min(minor, int(wi * f))) for wi in w]
            a = X.solve_grid(lengths, periods, minor, time_limit=5, model="tree", quick=False)
            b = X.solve_grid(lengths, periods, minor, time_limit=5, model="pairwise", quick=False)
            if X.UNKNOWN in (a.status, b.status):
                continue
            self.assertEqual(a.status, b.status, f"case {k}: L={lengths} P={periods} m={minor}: tree {a.status} "
                             f"({a.reason}), pairwise {b.status} ({b.reason})")
            if a.reason == "search":
                both[a.status] += 1
        self.assertGreater(both[X.FEASIBLE], 10, both)
        self.assertGreater(both[X.INFEASIBLE], 5, both)


class TestStacking(unittest.TestCase):
    def test_bases_alone_decide(self):
        """stack() fits exactly when no minor cycle's due slots exceed the cycle."""
        rng = random.Random(3)
        fits = {True: 0, False: 0}
        for k in range(300):
            n = rng.randint(1, 8)
            cap = rng.randint(10, 40)
            reps = [rng.choice([1, 2, 4, 8, 16]) for _ in range(n)]
            lengths = [rng.randint(1, cap // 2) for _ in range(n)]
            bases = [rng.randrange(r) for r in reps]
            cluster = max(reps)
            worst = max(sum(lengths[i] for i in range(n) if c % reps[i] == bases[i]) for c in range(cluster))
            starts = X.stack(lengths, reps, bases)
            periods = [r * cap for r in reps]
            ok = X.check_grid(lengths, periods, cap, cap, reps, bases, starts) == []
            self.assertEqual(ok, worst <= cap, f"case {k}: reps {reps} bases {bases} L {lengths}: worst cycle "
                             f"{worst} of {cap}, stacked starts {starts}")
            fits[ok] += 1
        self.assertGreater(min(fits.values()), 50, fits)


class TestCheckGrid(unittest.TestCase):
    """The placement checker catches every kind of fault (negative tests)."""
    L, P, M = [4, 3, 3], [10, 20, 40], 10           # reps 1, 2, 4

    def problems(self, reps, bases, starts, cap=10):
        return X.check_grid(self.L, self.P, self.M, cap, reps, bases, starts)

    def test_valid(self):
        self.assertEqual(self.problems([1, 2, 4], [0, 0, 1], [0, 4, 4]), [])

    def test_overlap_in_a_common_cycle(self):
        p = self.problems([1, 2, 4], [0, 0, 2], [0, 4, 4])      # channels 1 and 2 both in cycle 2
        self.assertTrue(any("minor cycle 2" in x and "overlaps" in x for x in p), p)

    def test_overlap_with_the_every_cycle_entry(self):
        p = self.problems([1, 2, 4], [0, 0, 1], [0, 3, 7])
        self.assertTrue(any("overlaps" in x for x in p), p)

    def test_period_exceeded(self):
        p = self.problems([2, 2, 4], [0, 0, 1], [0, 4, 4])      # channel 0 every 20 clocks, period 10
        self.assertTrue(any("longer than its period" in x for x in p), p)

    def test_slot_past_the_cycle(self):
        p = self.problems([1, 2, 4], [0, 0, 1], [0, 4, 8])
        self.assertTrue(any("outside the usable" in x for x in p), p)
        p = self.problems([1, 2, 4], [0, 0, 1], [0, 4, 4], cap=6)  # the idle end of the cycle
        self.assertTrue(any("outside the usable" in x for x in p), p)

    def test_base_and_repetition(self):
        p = self.problems([1, 2, 4], [0, 2, 1], [0, 4, 4])
        self.assertTrue(any("base 2 outside" in x for x in p), p)
        p = self.problems([1, 3, 4], [0, 0, 1], [0, 4, 4])
        self.assertTrue(any("not a power of two" in x for x in p), p)


class TestMutants(unittest.TestCase):
    def test_repetition_one_bit_too_long_is_caught(self):
        real = X.repetition
        with mock.patch.object(X, "repetition", lambda p, m, mx=X.MAX_REPETITION: 2 * real(p, m, mx)):
            with self.assertRaisesRegex(AssertionError, "longer than its period"):
                X.solve_grid([2, 2], [10, 20], 10)

    def test_repetition_one_bit_short_is_caught(self):
        real = X.repetition
        rng = random.Random(4)
        wrong = 0
        with mock.patch.object(X, "repetition", lambda p, m, mx=X.MAX_REPETITION: max(1, real(p, m, mx) // 2)):
            for _ in range(60):
                lengths, periods, minor, idle = tiny(rng)
                want, _ = brute(lengths, periods, minor, minor - idle)
                g = X.solve_grid(lengths, periods, minor, idle, time_limit=10)
                wrong += (g.status == X.FEASIBLE) != want
        self.assertGreater(wrong, 0, "a repetition one bit short changed no verdict of 60 tiny systems")


def described(channels, ram=16384):
    return parse_description({"system": {"name": "t", "clock_hz": CLOCK, "boards": ["a", "b", "c", "d"],
                                         "ram_bytes": ram}, "channel": channels}, "<test>")


def chan(name, size, period, producer="a", consumers=("b",)):
    return {"name": name, "size": size, "producer": producer, "consumers": list(consumers),
            "max_period_us": period}


class TestSystems(unittest.TestCase):
    def test_fast_and_slow_channels(self):
        """An 8-byte channel at 50 us beside ten 256-byte ones at 10 ms:
        each slow one runs once in 128 minor cycles of 2,500 clocks."""
        s = described([chan("fast", 8, 50)] + [chan(f"slow{i}", 256, 10_000) for i in range(10)])
        r = X.exact_grid(s, time_limit=10)
        self.assertEqual((r.status, r.minor), (X.FEASIBLE, 2500), r.reason())
        p = r.placement
        self.assertEqual(p.reps, [1] + [128] * 10)
        self.assertEqual(X.check_grid([X.slot_length(c, s.bus) for c in s.channels],
                                      [c.period_clocks for c in s.channels], p.minor, p.cap, p.reps, p.bases,
                                      p.starts), [])

    def test_proof_by_search(self):
        """Three slots of 2,604 clocks every second cycle of 5,000, and a
        small one in every cycle: the average load fits, two of the big ones
        share their cycles and do not."""
        s = described([chan("tick", 4, 100)] +
                      [chan(f"big{i}", 1700, 200, "abc"[i], [x for x in "abcd" if x != "abc"[i]][:2])
                       for i in range(3)])
        r = X.exact_grid(s, time_limit=10)
        self.assertEqual(r.status, X.INFEASIBLE, r.reason())
        self.assertEqual([(t.minor, t.reason) for t in r.tries], [(5000, "search"), (2500, "finer"), (1250, "finer")])

    def test_finer_minor_cycle_follows_the_coarser(self):
        """Three slots of 1,500 clocks in every cycle of 4,000 (period
        4,000 to 6,000 clocks: repetition 1): the load is the proof at 4,000,
        and 2,000 and 1,000 follow from it."""
        s = described([chan(f"c{i}", 1480, 80 + 20 * i) for i in range(3)])
        r = X.exact_grid(s, time_limit=10)
        self.assertEqual([(t.minor, t.status, t.reason) for t in r.tries],
                         [(4000, X.INFEASIBLE, "load"), (2000, X.INFEASIBLE, "finer"),
                          (1000, X.INFEASIBLE, "finer")], r.reason())

    def test_minor_cycles_fit_the_time_field(self):
        self.assertEqual(X.minor_cycles(2500, 65535), [2500, 1250, 625])
        self.assertEqual(X.minor_cycles(500_000, 65535), [62500, 31250, 15625])
        self.assertEqual(X.minor_cycles(3, 65535), [3, 1])

    def test_solver_missing_is_a_clear_error(self):
        with mock.patch.dict(sys.modules, {"ortools.sat.python": None, "ortools.sat.python.cp_model": None}):
            with self.assertRaisesRegex(X.SolverMissing, "pip install ortools"):
                X.solve_grid([3, 3, 3], [10, 20, 20], 10, quick=False)


if __name__ == "__main__":
    unittest.main()
