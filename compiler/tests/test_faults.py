"""The fault hypothesis (docs/compiler.md "Fault hypothesis"):
the compiler's probabilities against a Monte-Carlo simulation of the same
model, written here independently of compiler/albatross_schedule/faults.py:
a two-state Markov chain over the controller's bus accesses (after a good
access the next fails with probability a = p / (B (1 - p)), after a failed
one with b = 1 - 1/B), a failed access retried at once, a destination
dropped after K failed attempts of one access in a row, a slot delivering to
a consumer when the accesses up to its store of Actual succeed with at most
R failures in all.  Negative tests: a model blind to bursts, and one that
ignores the state the chain is in when a slot starts, are both caught.
Cost: about 10 s."""

import json
import math
import os
import random
import subprocess
import unittest

from oracle import COMPILER_DIR, EXAMPLES, OUT, TOOL, TOOL_ENV, read_hex  # noqa: F401

import albatross_schedule.faults as F


# ---------------------------------------------------------------------------
# The independent model.

def chain(rate, burst):
    """(a, b) of the two-state chain with stationary fault probability rate
    and geometric bursts of mean length burst."""
    b = 1.0 - 1.0 / burst
    a = 0.0 if rate == 0 else rate * (1.0 - b) / (1.0 - rate)
    return a, b


def accesses(kind, w, nd, four, d):
    """'s' / 'd' per access of a transfer new at every destination, up to
    destination d's store of Actual, in the controller's order
    (docs/controller.md "Execution"): the Import, then per destination the
    ReadLocked (four-slot: control word) load, per word a source load and
    the stores, taken_at, (four-slot: the Slot byte), the stores of Actual."""
    src = kind == "copy"
    out = "sss" if src else ""
    out += "d" * nd
    for _ in range(w):
        out += ("s" if src else "") + "d" * nd
    out += "d" * nd + ("d" * nd if four else "") + "d" * (d + 1)
    return list(out)


class Chain:
    """The access-level chain, one draw per attempt."""

    def __init__(self, rate, burst, seed, failed=False):
        self.a, self.b = chain(rate, burst)
        self.rng = random.Random(seed)
        self.failed = failed

    def attempt(self):
        p = self.b if self.failed else self.a
        self.failed = self.rng.random() < p
        return not self.failed


def run_slot(ch, seq, retries, drop_run):
    """Walk one slot's accesses; True if it delivers."""
    fails = 0
    for kind in seq:
        run = 0
        while not ch.attempt():
            fails += 1
            run += 1
            if kind == "d" and run >= drop_run:
                return False
            if fails > retries:
                return False
    return True


def tolerance(q, n):
    return 4.5 * math.sqrt(max(q * (1 - q), 1e-4) / n) + 1e-3


# ---------------------------------------------------------------------------

class ChainModel(unittest.TestCase):
    def test_rate_and_burst(self):
        """The chain's measured fault fraction and mean burst are the hypothesis's."""
        for rate, burst in ((0.05, 1), (0.2, 2), (0.3, 1), (0.5, 1), (0.5, 4)):
            ch = Chain(rate, burst, seed=7)
            n, fails, bursts, prev = 200000, 0, 0, True
            for _ in range(n):
                ok = ch.attempt()
                if not ok:
                    fails += 1
                    if prev:
                        bursts += 1
                prev = ok
            with self.subTest(rate=rate, burst=burst):
                self.assertAlmostEqual(fails / n, rate, delta=0.01,
                                       msg=f"fault fraction: expected {rate}, got {fails / n:.4f}")
                self.assertAlmostEqual(fails / bursts, burst, delta=0.06 * burst,
                                       msg=f"mean burst: expected {burst}, got {fails / bursts:.3f}")
                h = F.Hypothesis(rate, burst, 0.999)
                self.assertAlmostEqual(h.a, chain(rate, burst)[0], places=12)
                self.assertAlmostEqual(h.b, chain(rate, burst)[1], places=12)

    def test_access_sequence(self):
        """The compiler's access sequence is the controller's (A_d accesses)."""
        class Ch:
            pass
        for kind, w, nd, four in (("copy", 4, 2, False), ("copy", 1, 1, True), ("time", 1, 4, True),
                                  ("status", 33, 1, False), ("copy", 16, 3, False)):
            c = Ch()
            c.kind, c.words, c.consumers, c.layout = kind, w, list(range(nd)), "four_slot" if four else "three_buffer"
            for d in range(nd):
                with self.subTest(kind=kind, w=w, nd=nd, four=four, d=d):
                    self.assertEqual(F.access_sequence(c, d), accesses(kind, w, nd, four, d))
            per = w + (4 if four else 3)
            a = (3 + w + nd * per) if kind == "copy" else nd * per
            self.assertEqual(len(F.access_sequence(c, nd - 1)), a, "A of docs/compiler.md")


# Cases with delivery probabilities well inside (0, 1), so that the
# comparison with the simulation means something.
CASES = [  # rate, burst, kind, W, ND, four, d, R, K
    (0.2, 2, "copy", 4, 2, False, 1, 6, 3),
    (0.3, 1, "time", 1, 4, True, 3, 8, 2),
    (0.1, 4, "copy", 16, 1, False, 0, 8, 4),
    (0.5, 1.5, "copy", 2, 1, False, 0, 14, 3),
    (0.05, 6, "status", 9, 1, False, 0, 3, 5),
]
N_SLOTS = 12000


class SlotDelivery(unittest.TestCase):
    def mc(self, case, start_failed, seed):
        rate, burst, kind, w, nd, four, d, r, k = case
        seq = accesses(kind, w, nd, four, d)
        ok = 0
        ch = Chain(rate, burst, seed)
        for _ in range(N_SLOTS):
            ch.failed = start_failed
            ok += run_slot(ch, seq, r, k)
        return ok / N_SLOTS, seq

    def test_against_monte_carlo(self):
        """slot_delivery equals the simulated frequency, both start states."""
        for i, case in enumerate(CASES):
            rate, burst, *_, r, k = case
            h = F.Hypothesis(rate, burst, 0.999)
            for sf in (False, True):
                got, seq = self.mc(case, sf, seed=100 + i)
                want = F.slot_delivery(h, seq, r, k, sf)
                with self.subTest(case=case, start_failed=sf):
                    self.assertGreater(want, 0.05)
                    self.assertLess(want, 0.995)
                    self.assertAlmostEqual(got, want, delta=tolerance(want, N_SLOTS),
                                           msg=f"expected {want:.4f} (compiler), got {got:.4f} (simulation)")
                    self.assertLessEqual(F.slot_delivery_min(h, seq, r, k), want + 1e-12)
            curve = F.delivery_curve(h, seq, r + 3, k)
            self.assertAlmostEqual(curve[r], F.slot_delivery_min(h, seq, r, k), places=12)
            self.assertTrue(all(x <= y + 1e-15 for x, y in zip(curve, curve[1:])), "monotone in R")

    def test_negative_burst_blind(self):
        """A model that takes the faults as independent (same rate) is caught."""
        case = CASES[0]
        rate, burst, *_, r, k = case
        got, seq = self.mc(case, False, seed=5)
        blind = F.Hypothesis(rate, 1.0 / (1.0 - rate), 0.999)   # b = a = rate
        self.assertAlmostEqual(blind.a, blind.b, places=12)
        wrong = F.slot_delivery(blind, seq, r, k, False)
        self.assertGreater(abs(got - wrong), tolerance(wrong, N_SLOTS),
                           f"the burst-blind model ({wrong:.4f}) is not told from the simulation ({got:.4f})")

    def test_negative_start_state(self):
        """A model that always starts a slot in the good state is caught on a
        slot that starts after a failure."""
        case = CASES[2]
        rate, burst, *_, r, k = case
        got, seq = self.mc(case, True, seed=9)
        h = F.Hypothesis(rate, burst, 0.999)
        wrong = F.slot_delivery(h, seq, r, k, False)
        self.assertGreater(wrong - got, tolerance(wrong, N_SLOTS),
                           f"the good-start model ({wrong:.4f}) is not told from the simulation ({got:.4f})")


class DropRun(unittest.TestCase):
    def test_drop_run(self):
        """K: the smallest K >= 2 with D * max(a, b) * b^(K-1) <= 1 - probability."""
        for rate, burst, prob, dacc in ((0.2, 2, 1 - 1e-9, 20), (0.5, 1, 1 - 1e-9, 20), (0.05, 3, 0.999, 8),
                                        (0.3, 1.5, 1 - 1e-6, 40)):
            a, b = chain(rate, burst)
            k = 2
            while dacc * max(a, b) * b ** (k - 1) > 1 - prob:
                k += 1
            with self.subTest(rate=rate, burst=burst):
                self.assertEqual(F.drop_run_for(F.Hypothesis(rate, burst, prob), dacc), k)
            # a run of K on one access: simulated rarity for a small case
        self.assertEqual(F.drop_run_for(F.Hypothesis(0.5, 1, 1 - 1e-9), 50), 2, "burst 1: runs of 2 never happen")


def compile_desc(name, desc, faults=None, extra=()):
    out = os.path.join(OUT, "faults", name)
    args = TOOL + [desc, "--out", out, "-q"] + (["--faults", faults] if faults else []) + list(extra)
    r = subprocess.run(args, capture_output=True, text=True, env=TOOL_ENV)
    return r, out


class CycleMonteCarlo(unittest.TestCase):
    """A compiled plan (the robot at rate 0.2, burst 2, target 0.99) simulated
    cycle by cycle with one chain running through all its slots: every
    consumer's slot and cycle delivery at least the report's, and the
    fraction of slots after which m slots in a row all miss (m = the report's
    slots_needed_at_target) at most 1 - probability."""

    def test_plan_against_monte_carlo(self):
        r, out = compile_desc("mobot3_mc", os.path.join(EXAMPLES, "mobot3.toml"), "0.2,2,0.99")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            rep = json.load(f)
        fh = rep["fault_hypothesis"]
        k = rom_drop_run(out)
        self.assertEqual(k, rep["drop_run"])
        slots = []       # (channel, consumer seqs, R) in entry order
        chans = {c["name"]: c for c in rep["channels"]}
        for e in rep["entries_list"]:
            c = chans[e["channel"]]
            nd = len(c["consumers"])
            seqs = [accesses(c["kind"], c["words"], nd, c["channel_kind"] == "four_slot", d) for d in range(nd)]
            slots.append((c["name"], seqs, c["retries_per_slot"]))
        ch = Chain(fh["rate"], fh["mean_burst"], seed=3)
        cycles = 3000
        hist = {(c["name"], d): [] for c in rep["channels"] for d in range(len(c["consumers"]))}
        for _ in range(cycles):
            for name, seqs, r in slots:
                # the chain runs on through the slot's accesses; a consumer is
                # delivered if its prefix of the accesses delivers
                res = run_slot_all(ch, seqs, r, k)
                for d, ok in enumerate(res):
                    hist[(name, d)].append(ok)
        eps = 1 - fh["probability"]
        for c in rep["channels"]:
            n = c["redundancy"]
            for d, cons in enumerate(c["consumers"]):
                x = cons["faults"]
                h = hist[(c["name"], d)]
                q = sum(h) / len(h)
                per_cycle = [any(h[i:i + n]) for i in range(0, len(h), n)]
                qc = sum(per_cycle) / len(per_cycle)
                m = x["slots_needed_at_target"]
                miss_m = sum(not any(h[i:i + m]) for i in range(len(h) - m)) / (len(h) - m)
                with self.subTest(channel=c["name"], consumer=cons["board"]):
                    self.assertGreaterEqual(q, x["slot_delivery_probability"] - tolerance(q, len(h)),
                                            f"slot delivery: expected >= {x['slot_delivery_probability']:.4f}, got {q:.4f}")
                    self.assertGreaterEqual(qc, x["cycle_delivery_probability"] - tolerance(qc, len(per_cycle)),
                                            f"cycle delivery: expected >= {x['cycle_delivery_probability']:.4f}, got {qc:.4f}")
                    self.assertLessEqual(miss_m, eps + tolerance(eps, len(h)),
                                         f"{m} slots in a row all missed in {miss_m:.4f} of the cases, "
                                         f"expected at most {eps}")
                    # the period at the target, recomputed from the slots
                    starts = sorted(s["start"] for s in c["slots"])
                    cyc = rep["cycle"]["clocks"]
                    per = max(starts[(i + m) % n] + cyc * ((i + m) // n) - starts[i] for i in range(n))
                    self.assertEqual(x["period_at_target"]["clocks"], per)
                    self.assertLessEqual(per, c["max_period"]["clocks"])
                    back = rep["bus"]["fetch_cycles"] + rep["bus"]["access_cycles"] if c["kind"] == "copy" else 0
                    pub = (rep["bus"]["fetch_cycles"] + rep["bus"]["first_access_extra"]
                           + rep["bus"]["access_cycles"] * c["accesses"]
                           + c["retries_per_slot"] * (rep["bus"]["timeout_cycles"] + rep["bus"]["access_cycles"] + 1))
                    if c["kind"] == "copy":   # E extra Import passes (test_schedule.py)
                        m, p2 = 2 * (c["words"] + 2), 2 * rep["bus"]["access_cycles"]
                        pub += max(1, m // (m - p2)) * p2
                    self.assertEqual(x["age_bound"]["at_target"]["clocks"], per + pub - back)


def run_slot_all(ch, seqs, retries, drop_run):
    """One slot for all consumers at once: the longest sequence is walked
    and consumer d is delivered if the walk got past its own length with at
    most R failures and no drop (the sequences are prefixes of each other)."""
    longest = seqs[-1]
    ends = [len(s) for s in seqs]
    fails, done, dead = 0, 0, False
    for kind in longest:
        run = 0
        while not ch.attempt():
            fails += 1
            run += 1
            if (kind == "d" and run >= drop_run) or fails > retries:
                dead = True
                break
        if dead:
            break
        done += 1
    return [done >= e for e in ends]


def rom_drop_run(out):
    words = read_hex(os.path.join(out, "rom.hex"))
    return words[2] & 0xFF


class PlanForHypothesis(unittest.TestCase):
    def test_without_hypothesis(self):
        """No [faults]: the [bus] retry budget everywhere and the drop run 2 in H2."""
        r, out = compile_desc("four_slot", os.path.join(COMPILER_DIR, "examples", "four_slot.toml"))
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            rep = json.load(f)
        self.assertIsNone(rep["fault_hypothesis"])
        self.assertEqual(rep["drop_run"], 2)
        self.assertEqual(rom_drop_run(out), 2)
        for c in rep["channels"]:
            self.assertEqual(c["retries_per_slot"], rep["bus"]["retries_per_slot"], c["name"])
            self.assertNotIn("faults", c["consumers"][0])

    def test_description_states_hypothesis(self):
        """compiler/examples/faults.toml states its hypothesis in [faults]
        (20 %, mean burst 2, 1 - 1e-9): the report plans for exactly that, H2
        carries its K, every consumer meets its period at the target and has
        its delivery probabilities, and R >= K where two consumers share a slot."""
        r, out = compile_desc("faults_example", os.path.join(COMPILER_DIR, "examples", "faults.toml"))
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            rep = json.load(f)
        fh = rep["fault_hypothesis"]
        self.assertEqual((fh["rate"], fh["mean_burst"], fh["probability"]), (0.2, 2.0, 0.999999999))
        self.assertFalse(fh["independent"])
        a, b = chain(0.2, 2.0)
        self.assertAlmostEqual(fh["p_fail_after_good"], a, places=12)
        self.assertAlmostEqual(fh["p_fail_after_fail"], b, places=12)
        self.assertEqual(rom_drop_run(out), fh["drop_run"])
        self.assertEqual(rep["drop_run"], fh["drop_run"])
        for c in rep["channels"]:
            if len(c["consumers"]) >= 2:
                self.assertGreaterEqual(c["retries_per_slot"], fh["drop_run"], c["name"])
            for cons in c["consumers"]:
                x = cons["faults"]
                with self.subTest(channel=c["name"], consumer=cons["board"]):
                    self.assertLessEqual(x["period_at_target"]["clocks"], c["max_period"]["clocks"])
                    self.assertGreaterEqual(x["cycle_delivery_probability"], x["slot_delivery_probability"])
                    self.assertGreater(x["slot_delivery_probability"], 0.99)
                    self.assertGreaterEqual(x["age_bound"]["at_target"]["clocks"],
                                            x["age_bound"]["with_retries"]["clocks"])

    def test_robot_at_rates(self):
        """The robot planned for independent faults at 5, 20, 30 % (probability
        1 - 1e-9) and 50 % (0.99, the first target it plans for): every
        consumer meets its period at the target; R >= K with two or more
        consumers; the slot lengths hold R failures; H2 = K; the header bounds."""
        for rate, spec in ((0.05, "0.05"), (0.2, "0.2"), (0.3, "0.3"), (0.5, "0.5,,0.99")):
            r, out = compile_desc(f"mobot3_{rate}", os.path.join(EXAMPLES, "mobot3.toml"), spec)
            with self.subTest(rate=rate):
                self.assertEqual(r.returncode, 0, r.stderr)
                with open(os.path.join(out, "report.json")) as f:
                    rep = json.load(f)
                fh, bus = rep["fault_hypothesis"], rep["bus"]
                self.assertEqual(fh["rate"], rate)
                self.assertTrue(fh["independent"])
                self.assertAlmostEqual(fh["p_fail_after_good"], rate, places=12)
                self.assertAlmostEqual(fh["p_fail_after_fail"], rate, places=12)
                self.assertEqual(rom_drop_run(out), fh["drop_run"])
                cost = bus["timeout_cycles"] + bus["access_cycles"] + 1
                for c in rep["channels"]:
                    R = c["retries_per_slot"]
                    if len(c["consumers"]) >= 2:
                        self.assertGreaterEqual(R, fh["drop_run"], c["name"])
                    self.assertEqual(c["slot_length"], bus["fetch_cycles"] + bus["first_access_extra"]
                                     + bus["access_cycles"] * c["accesses"] + R * cost + bus["guard_cycles"])
                    for cons in c["consumers"]:
                        x = cons["faults"]
                        with open(os.path.join(out, cons["board"] + ".h")) as f:
                            hdr = f.read()
                        what = "LATENCY" if c["kind"] == "copy" else "AGE"
                        self.assertIn(f"#define ALB_{c['name'].upper()}_{what}_AT_TARGET_CLOCKS  "
                                      f"{x['age_bound']['at_target']['clocks']}u", hdr, "the board header's bound")
                        self.assertLessEqual(x["period_at_target"]["clocks"], c["max_period"]["clocks"])
                        self.assertGreaterEqual(x["age_bound"]["at_target"]["clocks"],
                                                x["age_bound"]["with_retries"]["clocks"])
                        self.assertGreaterEqual(x["slot_delivery_probability"], 0.0)

    def test_robot_at_50_rejected_at_1e_9(self):
        """Independent 50 %: the robot's 50 us channels cannot be planned for
        1 - 1e-9; the error names them."""
        r, out = compile_desc("mobot3_50_1e9", os.path.join(EXAMPLES, "mobot3.toml"), "0.5")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("cannot meet the channels' periods under the fault hypothesis (rate 0.5 per access, "
                      "independent, probability 1 - 1.0e-09", r.stderr)
        for name in ("Position", "MotorCmd", "GlobalTime"):
            self.assertIn(f"channel '{name}' (max_period_us = 50", r.stderr)

    def test_bad_faults_option(self):
        r, out = compile_desc("badopt", os.path.join(EXAMPLES, "mobot3.toml"), "0.2,x")
        self.assertEqual(r.returncode, 2)
        self.assertIn("expected RATE[,BURST[,PROBABILITY]]", r.stderr)


if __name__ == "__main__":
    unittest.main()
