"""Compile-time termination bounds of the consumers' Imports (docs/compiler.md "Termination bounds"):

- the bound itself, 1 + ceil(V / (D - T)) ReadLocked stores when D > T, none
  when D <= T, checked against an exhaustive adversary (the controller
  publishing as early as its spacing D allows, the consumer's loop taking any
  time up to V for its first pass and up to T for the others): the formula is
  never exceeded and is reached;
- D recomputed from the slots in report.json, and every reported figure;
- the spacing: a slow board makes the compiler take redundant slots away
  from the channels it imports until every three-buffer consumer is
  bounded; without board timing the plan is unchanged;
- the robot (sim/mobot3.toml, sim/mobot3_possync.toml) and the FPGA demo
  (fpga/duo.toml, with its SERV sensor importing GlobalTime again) with the
  core table's timing: all bounded.
"""

import json
import math
import os
import re
import subprocess
import sys
import tomllib
import unittest
from functools import lru_cache

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from oracle import COMPILER_DIR, OUT, REPO, TOOL, TOOL_ENV, plan_problems, rom_problems, read_hex  # noqa: E402
import albatross_schedule as S  # noqa: E402
from albatross_schedule import termination as TM  # noqa: E402


def adversary_max_stores(T, V, D, limit=64):
    """The most ReadLocked stores one three-buffer Import can make (integer clocks).
    Loads at t0 < t1 < ...; t1 - t0 <= V, later gaps <= T; the loop stores again
    after load k+1 iff the controller published in (t_k, t_k+1]; publishes are at
    least D apart.  Greedy publishing (as early as allowed) is optimal for the
    adversary; every interval length is tried.  State: s = t_k - last publish."""
    @lru_cache(maxsize=None)
    def more(s, depth):
        if depth > limit:
            return math.inf
        best = 0
        for l in range(1, T + 1):
            if l >= D - s:            # a publish fits in (t_k, t_k + l]
                best = max(best, 1 + more(min(l + s - D, l - 1), depth + 1))
        return best
    # the first interval (after the load whose value is stored): any publish before it was long ago
    return 1 + max(1 + more(l - 1, 1) for l in range(1, V + 1))


def formula(T, V, D):
    return None if D <= T else 1 + math.ceil(V / (D - T))


class BoundTests(unittest.TestCase):
    def test_formula_against_adversary(self):
        n = 0
        for T in range(1, 7):
            for V in range(1, T + 1):
                for D in range(1, T + V + 4):
                    got = adversary_max_stores(T, V, D)
                    want = formula(T, V, D)
                    if want is None:
                        self.assertEqual(got, math.inf, (T, V, D))
                    else:
                        self.assertEqual(got, want, (T, V, D))      # never exceeded, and reached
                        if D >= T + V:
                            self.assertLessEqual(got, 2, (T, V, D))
                    n += 1
        self.assertGreater(n, 100)

    def test_import_bound_figures(self):
        tm = S.model.BoardTiming(t=90, v=80, source="test")
        b = TM.import_bound("three_buffer", 3, 1, 150, tm)
        self.assertEqual((b["max_passes"], b["max_accesses"], b["accesses_old"]), (1 + 2, 1 + 2 * 3 + 4, 5))
        self.assertFalse(TM.import_bound("three_buffer", 3, 1, 90, tm)["bounded"])
        self.assertEqual(TM.import_bound("three_buffer", 3, 1, 170, tm)["max_passes"], 2)
        b = TM.import_bound("four_slot", 3, 1, 10, tm)
        self.assertEqual((b["max_passes"], b["max_accesses"]), (1, 3 + 4))
        self.assertFalse(TM.import_bound("three_buffer", 3, 1, 10, None)["checked"])


def without_boards(text):
    """The description without its [board.<name>] tables (sim/mobot3*.toml have them)."""
    return re.sub(r"(?ms)^\[board\.[^\]]+\]\n.*?(?=^\[)", "", text)


def with_boards(text, tables):
    text = without_boards(text)
    return text + "\n" + "".join(f"\n[board.{b}]\n" + "".join(f"{k} = {json.dumps(v)}\n" for k, v in t.items())
                                 for b, t in tables.items())


def compile_text(text, name):
    path = os.path.join(OUT, "termination", name + ".toml")
    out = os.path.join(OUT, "termination", name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
    r = subprocess.run(TOOL + [path, "--out", out], capture_output=True, text=True, env=TOOL_ENV)
    return r, out


def recompute(tc, rep, cycle_min):
    """Check every consumer's figures of report.json from the slots and the formulas."""
    bus = rep["bus"]
    for c in rep["channels"]:
        W = c["words"]
        E = 2 * W + 4 if c["kind"] == "copy" else W + 3
        early = bus["fetch_cycles"] + bus["access_cycles"] * (E - 1)
        s = sorted((x["start"], x["length"]) for x in c["slots"])
        d = min((s[(i + 1) % len(s)][0] + (cycle_min if i + 1 == len(s) else 0)) + early - (st + ln)
                for i, (st, ln) in enumerate(s))
        for dst in c["consumers"]:
            t = dst["termination"]
            tc.assertEqual(t["D_clocks"], d, (c["name"], dst["board"]))
            wd = W + 1
            tc.assertEqual(t["accesses_old"], 1 + wd)
            if c["channel_kind"] == "four_slot":
                tc.assertEqual((t["max_passes"], t["max_accesses"]), (1, 3 + wd))
            elif t["T_clocks"] is None:
                tc.assertFalse(t["checked"])
            else:
                n = formula(t["T_clocks"], t["V_clocks"], d)
                tc.assertIsNotNone(n, (c["name"], dst["board"], t))
                tc.assertEqual(t["max_passes"], n)
                tc.assertEqual(t["max_accesses"], 1 + 2 * n + wd)


class PlanBoundTests(unittest.TestCase):
    def read(self, path):
        with open(path) as f:
            return f.read()

    def test_robot_and_demo_with_core_timing(self):
        """sim/mobot3*.toml with PicoRV32 boards (and the SERV motor board of test-serv-boards),
        fpga/duo.toml with GlobalTime to the SERV sensor as well: every consumer bounded."""
        pico = {"core": "picorv32"}
        cases = [
            ("mobot3_cores", self.read(os.path.join(REPO, "sim", "mobot3.toml")),
             {"radar": pico, "odometry": pico, "navigation": pico, "motor": {"core": "serv"}}),
            ("mobot3_possync_cores", self.read(os.path.join(REPO, "sim", "mobot3_possync.toml")),
             {"radar": pico, "odometry": pico, "navigation": pico, "motor": pico}),
            # the FPGA demo with its GlobalTime three-buffer (it is four-slot there) and
            # its [board] tables given here
            ("duo_serv_time", re.sub(r"(?m)^four_slot\s*=.*\n|^\[board\.\w+\]\ncore = .*\n", "",
                                     self.read(os.path.join(REPO, "fpga", "duo.toml"))),
             {"sensor": {"core": "serv"}, "actuator": pico}),
        ]
        self.assertIn('consumers     = ["sensor", "actuator"]', cases[2][1])
        self.assertNotRegex(cases[2][1], r"(?m)^four_slot|^\[board\.")
        for name, text, tables in cases:
            with self.subTest(case=name):
                r, out = compile_text(with_boards(text, tables), name)
                self.assertEqual(r.returncode, 0, r.stderr)
                with open(os.path.join(out, "report.json")) as f:
                    rep = json.load(f)
                self.assertEqual(plan_problems(rep), [])
                self.assertEqual(rom_problems(read_hex(os.path.join(out, "rom.hex")), rep["bus"]["n_chan"],
                                              [b["ram_bytes"] // 4 for b in rep["boards"]]), [])
                cmin = (max(s["start"] + s["length"] for c in rep["channels"] for s in c["slots"])
                        if rep["mode"] == "position-synchronised" else rep["cycle"]["clocks"])
                recompute(self, rep, cmin)
                for c in rep["channels"]:
                    for d in c["consumers"]:
                        self.assertTrue(d["termination"]["bounded"], (c["name"], d["board"]))

    def test_without_timing_nothing_changes(self):
        """No [board] tables: the plan is the one of the description alone, nothing checked."""
        for name in ("mobot3.toml", "mobot3_possync.toml"):
            with self.subTest(example=name):
                text = without_boards(self.read(os.path.join(REPO, "sim", name)))
                sysm = S.parse_description(tomllib.loads(text), name, text)
                _, plan, rom, rep = S.compile_system(sysm)
                sysm2 = S.parse_description(tomllib.loads(text), name, text)
                S.allocate_ram(sysm2)
                plan2 = S.plan_for_hypothesis(sysm2, S.build_plan)   # its [faults] sizes the slots
                self.assertEqual(rom, S.encode_rom(sysm2, plan2))
                self.assertFalse(any(c["spaced_for_termination"] for c in rep["channels"]))
                self.assertFalse(any(d["termination"]["checked"] for c in rep["channels"] for d in c["consumers"]
                                     if c["channel_kind"] == "three_buffer"))

    def test_spacing(self):
        """A slow board: its channels lose redundant slots until D > T."""
        text = ('[system]\nname = "sp"\nclock_hz = 50_000_000\nboards = ["a", "b", "c"]\n'
                '[[channel]]\nname = "Fast"\nsize = 8\nproducer = "a"\nconsumers = ["b"]\nmax_period_us = 40\n'
                '[[channel]]\nname = "Slow"\nsize = 8\nproducer = "a"\nconsumers = ["c"]\nmax_period_us = 40\n'
                '[[channel]]\nname = "Time"\nkind = "time"\nconsumers = ["b", "c"]\nmax_period_us = 40\n')
        r0, out0 = compile_text(text, "spacing_free")
        self.assertEqual(r0.returncode, 0, r0.stderr)
        r1, out1 = compile_text(with_boards(text, {"b": {"core": "picorv32"}, "c": {"import_t_clocks": 600}}),
                                "spacing_slow")
        self.assertEqual(r1.returncode, 0, r1.stderr)
        reps = []
        for out in (out0, out1):
            with open(os.path.join(out, "report.json")) as f:
                reps.append({c["name"]: c for c in json.load(f)["channels"]})
        free, slow = reps
        # without timing the slow board's channels are overtaken: D <= 600
        self.assertLessEqual(free["Slow"]["consumers"][0]["termination"]["D_clocks"], 600)
        for ch in ("Slow", "Time"):
            self.assertLess(slow[ch]["redundancy"], free[ch]["redundancy"], ch)
            self.assertTrue(slow[ch]["spaced_for_termination"], ch)
            for d in slow[ch]["consumers"]:
                self.assertGreater(d["termination"]["D_clocks"], d["termination"]["T_clocks"])
                self.assertTrue(d["termination"]["bounded"])
        for d in slow["Fast"]["consumers"]:       # it got the room, then was spaced for b in turn
            self.assertTrue(d["termination"]["bounded"])
        with open(os.path.join(out1, "report.json")) as f:
            recompute(self, json.load(f), 2000)
        with open(os.path.join(out1, "report.txt")) as f:
            txt = f.read()
        self.assertIn("Slow -> c: D ", txt)
        self.assertIn("(slots spaced)", txt)

    def test_max_import_passes(self):
        """max_import_passes = 2: the compiler spaces until D >= T + V; unreachable: rejected."""
        text = ('[system]\nname = "mp"\nclock_hz = 50_000_000\nboards = ["a", "b"]\n'
                '[board.b]\nimport_t_clocks = 300\n'
                '[[channel]]\nname = "D"\nsize = 8\nproducer = "a"\nconsumers = ["b"]\nmax_period_us = 40\n'
                'max_import_passes = LIMIT\n')
        r, out = compile_text(text.replace("LIMIT", "2"), "passes_2")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            rep = json.load(f)
        c = rep["channels"][0]
        t = c["consumers"][0]["termination"]
        self.assertEqual(c["max_import_passes"], 2)
        self.assertLessEqual(t["max_passes"], 2)
        self.assertGreaterEqual(t["D_clocks"], t["T_clocks"] + t["V_clocks"])
        r, _ = compile_text(text.replace("LIMIT", "4"), "passes_4")
        self.assertEqual(r.returncode, 0, r.stderr)
        r, _ = compile_text(text.replace("300", "1500").replace("LIMIT", "2"), "passes_unreachable")
        self.assertEqual(r.returncode, 2)
        self.assertIn("channel 'D', consumer 'b': the three-buffer Import needs more than max_import_passes = 2 "
                      "passes", r.stderr)
        self.assertIn("D must be at least 3000", r.stderr)
        r, _ = compile_text(text.replace("LIMIT", "1"), "passes_1")
        self.assertEqual(r.returncode, 2)
        self.assertIn("field 'max_import_passes': 1 is not an integer >= 2", r.stderr)

    def test_board_clock_conversion(self):
        """T in the CPU's clocks, converted to controller clocks (rounded up)."""
        text = ('[system]\nname = "cv"\nclock_hz = 50_000_000\nboards = ["a", "b"]\n'
                '[board.b]\nimport_t_clocks = 101\nimport_v_clocks = 7\nclock_hz = 20_000_000\n'
                '[[channel]]\nname = "D"\nsize = 8\nproducer = "a"\nconsumers = ["b"]\nmax_period_us = 40\n')
        sysm = S.parse_description(tomllib.loads(text), "cv.toml", text)
        tm = sysm.timing[1]
        self.assertEqual((tm.t, tm.v), (253, 18))          # ceil(101 * 2.5), ceil(7 * 2.5)
        self.assertIn("CPU at 20000000 Hz", tm.source)


if __name__ == "__main__":
    unittest.main()
