"""The multi-rate planner (compiler/albatross_schedule/multirate.py,
docs/compiler.md "Plan") against oracles written here from the definitions
alone: every minor cycle of the cluster run entry by entry as the sequencer
does (a due entry needs the sequencer free at its start; one not due costs
its fetch from max(its start, the previous end)), and every channel's runs
over the whole cluster, each F-th run within its max_period.  The three
hand cases that the single-rate plan rejects are planned, their ROMs pass
verify_rom and the independent ROM oracle; random small systems; a
rejection with its reason; a minor cycle and a repetition fixed by the
description, honoured or rejected; a mode of its own minor cycle.  Negative
tests: the timing check and the oracles catch a slot moved into a due
predecessor, a repetition one bit long and a plan made without the skip
cost.  Cost: a few seconds."""

import dataclasses
import json
import re
import random
import unittest
from unittest import mock

from oracle import rom_problems
import albatross_schedule as S
from albatross_schedule import ScheduleError, compile_system, parse_description, verify_rom
from albatross_schedule import multirate as MR
from albatross_schedule.pipeline import self_check
from albatross_schedule.layout import allocate_ram

CLOCK = 50_000_000
C = S.rom.C                         # the contract (rtl/albatross_contract.toml)


def field(rom, at, word, name):
    """A field of the header (at 0), an entry or a mode descriptor (at its first word)."""
    f = C.field(word, name)
    return f.get(rom[at + f.index])


def chan(name, size, prod, cons, period, **kw):
    return dict({"name": name, "size": size, "producer": prod, "consumers": cons, "max_period_us": period}, **kw)


def system(name, chans, boards=("a", "b"), bus=None, **sysd):
    d = {"system": dict({"name": name, "clock_hz": CLOCK, "boards": list(boards), "ram_bytes": 16384}, **sysd),
         "channel": chans}
    if bus:
        d["bus"] = bus
    return d


# The hand cases (docs/compiler.md "Plan"): today's plan rejects them.
def fast_beside_slow():
    """An 8-byte channel at 50 us beside ten 256-byte channels at 10 ms: 3 % of the bus."""
    return system("fast_slow", [chan("fast", 8, "a", ["b"], 50)]
                  + [chan(f"slow{i}", 256, "a", ["b"], 10_000) for i in range(10)])


def fast_beside_map():
    """An 8-byte channel at 50 us beside a 3 KB map at 50 ms: the map's slot is longer than the cycle."""
    return system("fast_map", [chan("fast", 8, "a", ["b"], 50), chan("map", 3072, "a", ["b"], 50_000)])


def slow_only():
    """The fastest channel at 10 ms: 500,000 clocks, beyond 16-bit time within a cycle."""
    return system("slow", [chan("ctl", 16, "a", ["b"], 10_000), chan("log", 64, "b", ["a"], 100_000)])


def plan_of(data, planner="auto", redundancy=True):
    s = parse_description(json.loads(json.dumps(data)), f"<{data['system']['name']}>")
    s.planner = planner
    if not redundancy:
        for ch in s.channels:
            ch.max_slots = 1
    return compile_system(s)


# ---------------------------------------------------------------------------
# The oracles, from the report's entries alone.

def due(e, n):
    return n % e["repetition"] == e["base"]


def timing_oracle(rep, skip):
    """Every minor cycle run entry by entry: [problems]."""
    c = rep["cycle"]["clocks"]
    cluster = rep["cluster"]["minor_cycles"]
    cap = rep["capacity_clocks"]
    out = []
    for n in range(cluster):
        t = 0
        for e in rep["entries_list"]:
            if due(e, n):
                if t > e["start"]:
                    out.append(f"minor cycle {n}: entry {e['entry']} due at {e['start']}, sequencer busy until {t}")
                t = e["start"] + e["length"]
            else:
                t = max(t, e["start"]) + skip
            if e["start"] + e["length"] > c:
                out.append(f"entry {e['entry']} ends after the minor cycle")
        if t > cap:
            out.append(f"minor cycle {n} ends at {t} > {cap}")
    return out


def period_oracle(rep):
    """Every channel's due runs over the whole cluster (twice round, for the
    wrap): each run's F-th successor within max_period; the largest such
    span equals the reported guaranteed period.  [problems]."""
    c = rep["cycle"]["clocks"]
    cluster = rep["cluster"]["minor_cycles"]
    span = c * cluster
    out = []
    for ch in rep["channels"]:
        mine = [e for e in rep["entries_list"] if e["channel"] == ch["name"]]
        runs = sorted(n * c + e["start"] for e in mine for n in range(cluster) if due(e, n))
        if not runs:
            out.append(f"{ch['name']}: no run")
            continue
        f = ch["fragments"]
        # enough turns of the cluster for the F-th successor of every run (F may exceed the runs of one turn)
        ext = [r + k * span for k in range(2 + f // len(runs)) for r in runs]
        worst = max(ext[i + f] - ext[i] for i in range(len(runs)))
        if worst > ch["max_period"]["clocks"]:
            out.append(f"{ch['name']}: {f} runs span {worst} > max_period {ch['max_period']['clocks']}")
        if worst != ch["guaranteed_period"]["clocks"]:
            out.append(f"{ch['name']}: guaranteed period {ch['guaranteed_period']['clocks']} reported, {worst} found")
    return out


def fragment_oracle(rep, system_):
    """A fragmented channel: E7 on all its entries, ceil(W / frag) fragments
    as reported, and the fragments' words cover the value."""
    out = []
    for ch in rep["channels"]:
        frags = {e["fragment_words"] for e in rep["entries_list"] if e["channel"] == ch["name"]}
        if len(frags) != 1:
            out.append(f"{ch['name']}: entries with different fragment sizes {frags}")
            continue
        frag = frags.pop()
        want = 1 if frag == 0 else -(-ch["words"] // frag)
        if want != ch["fragments"]:
            out.append(f"{ch['name']}: {ch['fragments']} fragments reported, E7 {frag} gives {want}")
    return out


class Checks:
    def assert_plan_ok(self, system_, plan, rom, rep):
        self.assertTrue(plan.multirate, "expected a multi-rate plan")
        problems, _ = verify_rom(rom, n_chan=system_.bus.n_chan, n_boards=len(system_.boards),
                                 ram_words=[r // 4 for r in system_.ram_bytes])
        self.assertEqual(problems, [], "verify_rom")
        self.assertEqual(rom_problems(rom, system_.bus.n_chan, [r // 4 for r in system_.ram_bytes]), [],
                         "the ROM oracle")
        self.assertEqual(timing_oracle(rep, system_.bus.fetch_cycles), [], "the timing oracle")
        self.assertEqual(period_oracle(rep), [], "the period oracle")
        self.assertEqual(fragment_oracle(rep, system_), [], "the fragment oracle")
        # the ROM carries what the report says
        self.assertEqual(field(rom, 0, "H2", "cluster"), plan.cluster_log, "H2.cluster")
        for k, s in enumerate(plan.slots):
            at = C.entry_address(k)
            self.assertEqual((field(rom, at, "E6", "rep"), field(rom, at, "E6", "base"), field(rom, at, "E7", "frag")),
                             (s.rep_log, s.base, s.frag), f"entry {k}: E6, E7")


class HandCases(unittest.TestCase, Checks):
    def test_hand_cases_single_rate_rejects_multi_rate_plans(self):
        for make in (fast_beside_slow, fast_beside_map, slow_only):
            for red in (False, True):
                with self.subTest(case=make.__name__, redundancy=red):
                    with self.assertRaises(ScheduleError, msg="the single-rate plan must not fit"):
                        plan_of(make(), "single-rate", red)
                    s, plan, rom, rep = plan_of(make(), "auto", red)
                    self.assert_plan_ok(s, plan, rom, rep)
                    if not red:
                        self.assertEqual(len(plan.slots), len(s.channels), "one entry per channel")

    def test_finer_fragments_make_room_for_redundancy(self):
        # the 3 KB map split only as far as it must be leaves its minor cycle
        # too full for the redundant entries' skip costs; split further, the
        # fast channel gets them (the plan still passes every oracle)
        import albatross_schedule.multirate as MR
        saved = MR.FINER_STEPS
        try:
            MR.FINER_STEPS = 0
            _, plain, _, _ = plan_of(fast_beside_map())
        finally:
            MR.FINER_STEPS = saved
        s, plan, rom, rep = plan_of(fast_beside_map())
        self.assert_plan_ok(s, plan, rom, rep)
        by = {c["name"]: c for c in rep["channels"]}
        self.assertGreater(plan.redundancy["planned"], plain.redundancy["planned"],
                           "expected more redundant entries with the map split further")
        plain_fragments = next(x.channel.fragments for x in plain.slots if x.channel.name == "map")
        self.assertGreater(by["map"]["fragments"], plain_fragments, "expected the map in more fragments")

    def test_hand_case_shapes(self):
        s, plan, rom, rep = plan_of(fast_beside_slow(), redundancy=False)
        by = {c["name"]: c for c in rep["channels"]}
        self.assertEqual(by["fast"]["repetition"], 1)
        self.assertTrue(all(by[f"slow{i}"]["repetition"] >= 64 for i in range(10)), by)
        s, plan, rom, rep = plan_of(fast_beside_map(), redundancy=False)
        by = {c["name"]: c for c in rep["channels"]}
        self.assertGreater(by["map"]["fragments"], 1, "the 3 KB map's slot fits no minor cycle whole")
        self.assertLessEqual(by["map"]["slot_length"], plan.capacity)
        s, plan, rom, rep = plan_of(slow_only(), redundancy=False)
        self.assertLessEqual(plan.cycle, (1 << s.bus.time_bits) - 1)
        self.assertEqual(plan.cycle, 62_500, "10 ms / 8: the breakpoint below 2^16 clocks")
        self.assertEqual({c["name"]: c["repetition"] for c in rep["channels"]}, {"ctl": 8, "log": 64})

    def test_report_and_timeline(self):
        s, plan, rom, rep = plan_of(fast_beside_map())
        txt = S.render_report_txt(rep)
        self.assertIn("multi-rate: minor cycle", txt)
        self.assertIn("cluster 2^", txt)
        for c in rep["channels"]:
            for key in ("repetition", "base", "fragments", "guaranteed_period", "latency"):
                self.assertIn(key, c)
        svg = S.generate(s, plan, rom, rep)["timeline.svg"]
        self.assertIn("minor cycle", svg)
        self.assertIn("n = 0", svg)
        rows = svg.count("ends at (clocks)")
        self.assertEqual(rows, 1)


class RandomSystems(unittest.TestCase, Checks):
    def test_random_small_systems_against_the_oracles(self):
        rng = random.Random(40)
        accepted = 0
        for k in range(30):
            n = rng.randint(2, 7)
            chans = []
            for i in range(n):
                p = int(50 * 10 ** rng.uniform(0, 2.7))
                size = int(4 * 2 ** rng.uniform(0, 9))
                prod = rng.choice("abc")
                chans.append(chan(f"c{i}", size, prod, [rng.choice([b for b in "abc" if b != prod])], p))
            data = system(f"r{k}", chans, boards=("a", "b", "c"))
            with self.subTest(system=k):
                try:
                    s, plan, rom, rep = plan_of(data, "multi-rate", redundancy=bool(k % 2))
                except ScheduleError as e:
                    self.assertIn(getattr(e, "kind", None), ("demand", "exact", "gave-up"), e.messages)
                    self.assertIn("To fit", e.messages[-1])
                    continue
                accepted += 1
                self.assert_plan_ok(s, plan, rom, rep)
        self.assertGreaterEqual(accepted, 20, "most of these small systems fit")


class Negatives(unittest.TestCase):
    def plan(self):
        return plan_of(fast_beside_slow(), redundancy=False)

    def test_slot_moved_into_a_due_predecessor(self):
        s, plan, rom, rep = self.plan()
        skip = s.bus.fetch_cycles
        self.assertEqual(MR.check_timing(plan.slots, plan.cycle, plan.cluster, plan.capacity, skip), [])
        k = next(i for i in range(1, len(plan.slots)) if plan.slots[i].start >= plan.slots[0].length)
        bad = list(plan.slots)
        bad[k] = dataclasses.replace(bad[k], start=plan.slots[0].length - 1, base=0, rep_log=0)
        self.assertTrue(MR.check_timing(bad, plan.cycle, plan.cluster, plan.capacity, skip))
        mutated = dict(rep, entries_list=[dict(e, start=bad[e["entry"]].start, base=bad[e["entry"]].base,
                                               repetition=1 << bad[e["entry"]].rep_log) for e in rep["entries_list"]])
        self.assertTrue(timing_oracle(mutated, skip), "the timing oracle catches it")

    def test_repetition_one_bit_long(self):
        s, plan, rom, rep = self.plan()
        slot = next(x for x in plan.slots if x.channel.name == "slow0")
        slot.rep_log += 1
        slot.channel.slots, slot.channel.run_span = MR.channel_runs(plan.slots, slot.channel, plan.cycle)
        plan.cluster_log = max(plan.cluster_log, slot.rep_log)
        with self.assertRaises(AssertionError) as cm:
            self_check(s, plan, S.encode_rom(s, plan), allocate_ram(s))
        self.assertIn("guaranteed period exceeds max_period", str(cm.exception))
        mutated = dict(rep, cluster=dict(rep["cluster"], minor_cycles=plan.cluster),
                       entries_list=[dict(e, repetition=2 * e["repetition"]) if e["channel"] == "slow0" else e
                                     for e in rep["entries_list"]])
        self.assertTrue(period_oracle(mutated), "the period oracle catches it")

    def test_plan_made_without_the_skip_cost(self):
        """Planned as if an entry not due cost nothing: the entries of one
        residue share windows back to back, which the model's skip cost
        breaks; the compiler's self-check refuses the plan."""
        with mock.patch.object(MR, "not_due_cost", lambda bus: 0):
            s = parse_description(json.loads(json.dumps(fast_beside_slow())), "<x>")
            allocate_ram(s)
            plan = MR.build_multirate_plan(s)
            with self.assertRaises(AssertionError) as cm:
                plan_of(fast_beside_slow(), redundancy=False)
        self.assertIn("busy there until", str(cm.exception))
        skip = s.bus.fetch_cycles
        self.assertTrue(MR.check_timing(plan.slots, plan.cycle, plan.cluster, plan.capacity, skip))
        rep = S.build_report(s, plan)
        self.assertTrue(timing_oracle(rep, skip))


class Rejections(unittest.TestCase):
    def test_demand_above_the_bus_is_a_proof(self):
        data = system("over", [chan("a", 400, "a", ["b"], 10), chan("b", 400, "b", ["a"], 10)])
        with self.assertRaises(ScheduleError) as cm:
            plan_of(data, "multi-rate")
        self.assertEqual(cm.exception.kind, "demand")
        msg = cm.exception.messages[-1]
        self.assertIn("infeasible plan (proof)", msg)
        self.assertIn("To fit, cut the demand by", msg)

    def test_no_plan_below_full_demand_names_its_reason_and_a_fix(self):
        """97 % of the bus: channel A's slot (3,000 clocks every 5,000) needs
        every minor cycle, and B's (2,600 every 7,000) fits beside it nowhere,
        whole or in fragments."""
        chans = [chan("A", 2952, "a", ["b"], 100), chan("B", 2552, "c", ["d"], 140)]
        data = system("tight", chans, boards=("a", "b", "c", "d"))
        s = parse_description(json.loads(json.dumps(data)), "<tight>")
        self.assertLess(MR_demand(s), 1.0)
        with self.assertRaises(ScheduleError) as cm:
            plan_of(data)
        self.assertIn(cm.exception.kind, ("exact", "gave-up"))
        msg = cm.exception.messages[-1]
        self.assertTrue("proof on the grid" in msg or "gave up without a proof" in msg, msg)
        self.assertIn("To fit", msg)
        self.assertIn("infeasible plan: one slot per channel needs", cm.exception.messages[0],
                      "the single-rate plan's reason comes first")
        # without the exact search: the planner's give-up, said so
        with mock.patch("albatross_schedule.rejection.exact_proof", lambda *a: ""):
            with self.assertRaises(ScheduleError) as cm:
                plan_of(data, "multi-rate")
        self.assertEqual(cm.exception.kind, "gave-up")
        self.assertIn("gave up without a proof", cm.exception.messages[-1])


def MR_demand(s):
    from albatross_schedule.rejection import demand
    return demand(s)


class Overrides(unittest.TestCase, Checks):
    ROBOT = [chan("Position", 16, "a", ["b"], 50), chan("Cmd", 16, "b", ["a"], 100)]

    def test_fixed_minor_cycle_is_honoured(self):
        data = system("fixed", self.ROBOT, bus={"minor_cycle_us": 25})
        s, plan, rom, rep = plan_of(data)
        self.assert_plan_ok(s, plan, rom, rep)
        self.assertEqual(plan.cycle, 1250)
        self.assertEqual(rep["minor_cycle_source"], "[bus] minor_cycle_us")
        # without it the same system is single-rate
        s, plan, rom, rep = plan_of(system("free", self.ROBOT))
        self.assertFalse(plan.multirate)
        self.assertEqual(field(rom, 0, "H2", "cluster"), 0)
        self.assertTrue(all(rom[C.entry_address(k) + 6] == 0 and rom[C.entry_address(k) + 7] == 0
                            for k in range(len(plan.slots))), "a single-rate image keeps E6 and E7 at 0")

    def test_fixed_minor_cycle_rejected(self):
        with self.assertRaises(ScheduleError) as cm:
            plan_of(system("slow_minor", self.ROBOT, bus={"minor_cycle_us": 75}))
        self.assertIn("max_period_us = 50 is shorter than the minor cycle [bus] minor_cycle_us = 75",
                      "\n".join(cm.exception.messages))
        with self.assertRaises(ScheduleError) as cm:
            plan_of(system("wide", self.ROBOT, bus={"minor_cycle_us": 2000}))
        self.assertIn("a minor cycle is 1 .. 65535 clocks", "\n".join(cm.exception.messages))

    def test_no_minor_cycle_holds_a_slot_names_the_one_that_would(self):
        # a fault hypothesis sizes the big value's retry budget (kept by each
        # fragment's slot) past the fixed minor cycle of 8 us
        data = system("budget", [chan("fast", 8, "a", ["b"], 50), chan("big", 512, "a", ["b"], 10_000)],
                      bus={"minor_cycle_us": 4})
        data["faults"] = {"rate": 0.05, "probability": 0.999999}
        with self.assertRaises(ScheduleError) as cm:
            plan_of(data, redundancy=False)
        msg = "\n".join(cm.exception.messages)
        self.assertRegex(msg, r"To fit: channel 'big''s slot needs at least \d+ clocks even in fragments of one word "
                         r"\(\d+ of them its retry budget of \d+ retries, sized for the fault hypothesis\): raise "
                         r"\[bus\] minor_cycle_us to at least \d+ us", msg)
        need_us = int(re.search(r"minor_cycle_us to at least (\d+) us", msg).group(1))
        data["bus"]["minor_cycle_us"] = need_us
        s, plan, rom, rep = plan_of(data, redundancy=False)
        self.assert_plan_ok(s, plan, rom, rep)

    def test_fixed_repetition_is_honoured(self):
        chans = [dict(self.ROBOT[0]), dict(self.ROBOT[1], max_period_us=1000, repetition=4)]
        s, plan, rom, rep = plan_of(system("rep", chans))
        self.assert_plan_ok(s, plan, rom, rep)
        self.assertEqual({1 << x.rep_log for x in plan.slots if x.channel.name == "Cmd"}, {4})

    def test_fixed_repetition_rejected(self):
        for bad, what in ((3, "is not a power of two"), (1 << 16, "is not a power of two from 1 to 32768")):
            chans = [dict(self.ROBOT[0]), dict(self.ROBOT[1], repetition=bad)]
            with self.assertRaises(ScheduleError) as cm:
                plan_of(system("rep", chans))
            self.assertIn(what, "\n".join(cm.exception.messages))
        # a repetition that leaves no minor cycle within the period
        chans = [dict(self.ROBOT[0]), dict(self.ROBOT[1], repetition=8192)]
        with self.assertRaises(ScheduleError) as cm:
            plan_of(system("rep", chans))
        self.assertIn("repetition = 8192 leaves a minor cycle of at most 0 clocks", "\n".join(cm.exception.messages))
        # with the minor cycle fixed too: a repetition whose runs exceed the period
        chans = [dict(self.ROBOT[0]), dict(self.ROBOT[1], repetition=8)]
        with self.assertRaises(ScheduleError) as cm:
            plan_of(system("rep", chans, bus={"minor_cycle_us": 25}))
        self.assertIn("its repetition 8 times the minor cycle", "\n".join(cm.exception.messages))


    def test_position_synchronised_stays_single_rate(self):
        chans = [dict(self.ROBOT[0], sync=True), dict(self.ROBOT[1], repetition=2)]
        with self.assertRaises(ScheduleError) as cm:
            plan_of(system("sync", chans, mode="position-synchronised"))
        self.assertIn("needs the time-rigid time mode", "\n".join(cm.exception.messages))


class Modes(unittest.TestCase):
    def test_a_mode_of_its_own_minor_cycle(self):
        chans = [chan("fast", 8, "a", ["b"], 50), chan("map", 3072, "a", ["b"], 50_000),
                 {"name": "Req", "kind": "mode_request", "producer": "a", "size": 4, "max_period_us": 1000}]
        data = system("modes", chans)
        data["mode"] = [{"name": "survey"}, {"name": "fast", "channels": ["fast", "Req"]}]
        s, plan, rom, rep = plan_of(data)
        modes = rep["modes"]
        self.assertEqual([m["planner"] for m in modes], ["multi-rate", "single-rate"])
        problems, _ = verify_rom(rom, n_chan=s.bus.n_chan, n_boards=2, ram_words=[4096, 4096])
        self.assertEqual(problems, [])
        self.assertEqual(field(rom, 0, "H2", "cluster"), modes[0]["cluster"]["log2"])
        table = field(rom, 0, "H2", "table")
        d2 = [field(rom, C.entry_address(table + m), "D2", "cluster") for m in range(2)]
        self.assertEqual(d2, [m["cluster"]["log2"] for m in modes], "D2.cluster per mode")
        # the switch latency: a request just after a run's sample waits for the
        # next run of the request channel, and the switch ends that minor cycle
        c = modes[0]["cycle"]["clocks"]
        cl = modes[0]["cluster"]["minor_cycles"]
        req = [e for e in rep["entries_list"] if e["channel"] == "Req"]
        runs = sorted(n * c + e["start"] for e in req for n in range(cl) if n % e["repetition"] == e["base"])
        runs2 = runs + [r + c * cl for r in runs]
        want = max((runs2[i + 1] // c + 1) * c - (runs[i] + s.bus.sample_offset) for i in range(len(runs)))
        self.assertEqual(modes[0]["switch_latency"]["clocks"], want)


class FaultHypothesis(unittest.TestCase, Checks):
    def test_fragmented_value_under_faults(self):
        data = fast_beside_map()
        data["faults"] = {"rate": 1e-4, "probability": 1 - 1e-9}
        s, plan, rom, rep = plan_of(data)
        self.assert_plan_ok(s, plan, rom, rep)
        m = next(c for c in rep["channels"] if c["name"] == "map")
        f = m["consumers"][0]["faults"]
        self.assertIsNotNone(f["age_bound"]["at_target"])
        # 2F - 1 runs at least after a sample missed (fault-free), more at the target
        self.assertGreaterEqual(f["slots_needed_at_target"], 2 * m["fragments"] - 1)
        self.assertGreaterEqual(f["age_bound"]["at_target"]["clocks"], m["latency"]["with_retries"]["clocks"])


class Termination(unittest.TestCase):
    def test_publish_gap_of_a_fragmented_value(self):
        """D of the 3 KB map's consumer: a value is published at most once in
        F runs, in its last fragment's run, whose first Actual store comes
        after that fragment's words (a load and a store each) and taken_at."""
        data = fast_beside_map()
        data["board"] = {"b": {"core": "picorv32"}}
        s, plan, rom, rep = plan_of(data, redundancy=False)
        m = next(c for c in rep["channels"] if c["name"] == "map")
        f, w, frag = m["fragments"], m["words"], m["fragment_words"]
        self.assertGreater(f, 1)
        c, cl = rep["cycle"]["clocks"], rep["cluster"]["minor_cycles"]
        runs = sorted(n * c + e["start"] for e in rep["entries_list"] if e["channel"] == "map"
                      for n in range(cl) if n % e["repetition"] == e["base"])
        ext = [x + k * c * cl for k in range(f + 1) for x in runs]
        last = w - (f - 1) * frag
        early = s.bus.fetch_cycles + s.bus.access_cycles * (2 * last + 1)
        want = min(ext[i + f] + early - (runs[i] + m["slot_length"]) for i in range(len(runs)))
        self.assertEqual(m["consumers"][0]["termination"]["D_clocks"], want)


class Fragments(unittest.TestCase):
    def test_fragment_accesses_add_up_to_the_transfer(self):
        for layout in ("three_buffer", "four_slot"):
            for words, nd in ((2, 1), (7, 2), (512, 4), (768, 1)):
                ch = S.Channel(index=0, name="x", kind="copy", ctype=None, size=4 * words, words=words, producer=0,
                               consumers=list(range(1, nd + 1)), max_period_us=1, layout=layout)
                for f in (1, 2, 3, 5, words):
                    frag, n = MR.fragment_shape(words, f)
                    acc = MR.fragment_accesses(ch, frag)
                    self.assertEqual(len(acc), n)
                    self.assertEqual(sum(acc), S.transfer_accesses(ch), (layout, words, nd, f))


if __name__ == "__main__":
    unittest.main()
