"""The channel key four_slot = true: a TIME or STATUS channel of the
four-slot kind (and a COPY one, the same as kind = "four_slot").  A
description like the FPGA demo (a SERV sensor importing GlobalTime, whose
three-buffer Import the controller would overtake) is compiled with
GlobalTime and Status four-slot, and checked: the E0 flag on every TIME and
STATUS entry (and both ROM checkers accept it), four buffers at every
destination, the images' control word, the generated setup call, the
termination report (1 pass, 3 + W accesses, no spacing of the slots), and an
end-to-end run of the Python controller model (a four-slot TIME export read
by the four-slot Import).  Negatives: the same description three-buffer is
spaced (or rejected), and malformed or contradictory keys are rejected.

    python3 -m unittest discover -s compiler/tests -v      (from the repository root)
"""

import json
import os
import re
import shutil
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from oracle import (  # noqa: E402
    COMPILER_DIR, ControllerModel, ORACLE_FOUR_SLOT, OUT, RamImage, TOOL, TOOL_ENV, decode, layout_problems,
    plan_problems, read_hex, rom_problems)
import albatross_schedule as S  # noqa: E402

DESC = """
[system]
name      = "fstime"
clock_hz  = 12_000_000
boards    = ["sensor", "actuator"]
ram_bytes = 1024

[bus]
n_chan = 4

[board.sensor]
core = "serv"
[board.actuator]
core = "picorv32"

[[channel]]
name          = "Sample"
size          = 16
producer      = "sensor"
consumers     = ["actuator"]
max_period_us = 100

[[channel]]
name          = "GlobalTime"
kind          = "time"
consumers     = ["sensor", "actuator"]
max_period_us = 100
{time_extra}

[[channel]]
name          = "Status"
kind          = "status"
consumers     = ["sensor"]
max_period_us = 400
{status_extra}
"""


def compile_desc(name, time_extra="four_slot = true", status_extra="four_slot = true"):
    out = os.path.join(OUT, name)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    path = os.path.join(out, name + ".toml")
    with open(path, "w") as f:
        f.write(DESC.replace("{time_extra}", time_extra).replace("{status_extra}", status_extra))
    r = subprocess.run(TOOL + [path, "--out", out], capture_output=True, text=True, env=TOOL_ENV)
    return r, out


class FourSlotTimeTests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        r, cls.out = compile_desc("four_slot_time")
        if r.returncode != 0:
            raise AssertionError(r.stdout + r.stderr)
        with open(os.path.join(cls.out, "report.json")) as f:
            cls.rep = json.load(f)
        cls.rom = read_hex(os.path.join(cls.out, "rom.hex"))
        cls.chans = {c["name"]: c for c in cls.rep["channels"]}

    def ram_words(self):
        return [b["ram_bytes"] // 4 for b in self.rep["boards"]]

    def test_rom_flags(self):
        """FOUR_SLOT on every TIME and STATUS entry, not on the COPY; both checkers accept the ROM."""
        n_chan = self.rep["bus"]["n_chan"]
        self.assertEqual(rom_problems(self.rom, n_chan, self.ram_words()), [])
        self.assertEqual(S.verify_rom(self.rom, n_chan, len(self.rep["boards"]), self.ram_words())[0], [])
        _, entries = decode(self.rom)
        kinds = set()
        for e in entries:
            if e["kind"] == 0:
                continue
            kinds.add(e["kind"])
            self.assertEqual(bool(e["flags"] & ORACLE_FOUR_SLOT["flag"]), e["kind"] in (2, 3), e)
        self.assertEqual(kinds, {1, 2, 3})
        self.assertEqual(self.chans["GlobalTime"]["channel_kind"], "four_slot")
        self.assertEqual(self.chans["Status"]["channel_kind"], "four_slot")
        self.assertEqual(self.chans["Sample"]["channel_kind"], "three_buffer")
        self.assertEqual(plan_problems(self.rep), [])

    def test_slot_length_counts_the_slot_byte(self):
        """A four-slot TIME transfer takes ND * (W + 4) accesses (docs/controller.md "Timing")."""
        c = self.chans["GlobalTime"]
        self.assertEqual(c["accesses"], len(c["consumers"]) * (1 + 4))
        s = self.chans["Status"]
        self.assertEqual(s["accesses"], len(s["consumers"]) * (s["words"] + 4))

    def test_layout_and_images(self):
        """Four buffers at every destination; Actual = ReadLocked = 1, Slot0 = Slot1 = 0."""
        self.assertEqual(layout_problems(self.rep), [])
        for name in ("GlobalTime", "Status"):
            c = self.chans[name]
            for d in c["consumers"]:
                self.assertEqual(d["ram_bytes"], 4 + 4 * 4 * (c["words"] + 1), (name, d["board"]))
        for b in self.rep["boards"]:
            words = read_hex(os.path.join(self.out, f"{b['name']}_ram.hex"))
            for i in b["instances"]:
                self.assertEqual(words[i["base"] // 4].to_bytes(4, "little"), bytes([1, 1, 0, 0]))

    def test_generated_setup(self):
        """The consumers set GlobalTime and Status up as four-slot, Sample as three-buffer."""
        with open(os.path.join(self.out, "sensor.c")) as f:
            src = f.read()
        with open(os.path.join(self.out, "sensor.h")) as f:
            hdr = f.read()
        for name in ("GlobalTime", "Status"):
            N = name.upper()
            self.assertEqual(len(re.findall(rf"alb_channel_setup_kind\(&alb_ch_{name}, dpram_base \+ "
                                            rf"ALB_{N}_BASE, ALB_{N}_SIZE, ALB_FOUR_SLOT\)", src)), 2, src)
            self.assertIn(f"#define ALB_{N}_KIND   ALB_FOUR_SLOT", hdr)
        self.assertEqual(src.count("alb_channel_setup(&alb_ch_Sample,"), 2)

    def test_termination_not_spaced(self):
        """The SERV consumer of the four-slot GlobalTime: 1 pass, 3 + 2 accesses, the slots not spaced."""
        c = self.chans["GlobalTime"]
        t = {d["board"]: d["termination"] for d in c["consumers"]}
        self.assertEqual((t["sensor"]["max_passes"], t["sensor"]["max_accesses"], t["sensor"]["accesses_old"]),
                         (1, 5, 3))
        self.assertFalse(c["spaced_for_termination"])
        with open(os.path.join(self.out, "report.txt")) as f:
            self.assertIn("four-slot: 1 pass, 5 accesses (Old 3)", f.read())

    def test_three_buffer_is_spaced_or_rejected(self):
        """Negative: the same description with a three-buffer GlobalTime: the compiler spaces its
        slots for the SERV sensor (or rejects the plan); never the unspaced four-slot plan."""
        r, out = compile_desc("four_slot_time_3b", time_extra="", status_extra="")
        if r.returncode != 0:
            self.assertIn("GlobalTime", r.stdout + r.stderr)
            return
        with open(os.path.join(out, "report.json")) as f:
            rep = json.load(f)
        c = {x["name"]: x for x in rep["channels"]}["GlobalTime"]
        self.assertEqual(c["channel_kind"], "three_buffer")
        self.assertTrue(c["spaced_for_termination"])
        self.assertLess(c["redundancy"], self.chans["GlobalTime"]["redundancy"])
        t = next(d for d in c["consumers"] if d["board"] == "sensor")["termination"]
        self.assertTrue(t["bounded"])
        self.assertGreater(t["max_passes"], 1)

    def test_end_to_end_model(self):
        """The controller model runs the ROM: the sensor's four-slot Import of GlobalTime finds
        New once (value = taken_at = the transfer's time, 3 + W accesses), then Old (1 + W)."""
        boards = [b["name"] for b in self.rep["boards"]]
        rams = [RamImage(read_hex(os.path.join(self.out, f"{b}_ram.hex"))) for b in boards]
        model = ControllerModel(self.rom, rams, self.rep["bus"]["n_chan"])
        c = self.chans["GlobalTime"]
        d = next(x for x in c["consumers"] if x["board"] == "sensor")
        ram, base, last = rams[d["board_index"]], d["base"], 0
        prev = None
        for _ in range(3):
            model.run_cycle()
            a = ram.rd8(base)
            self.assertNotEqual(a, last)
            ram.wr8(base + 1, a)
            pair = (a - 1) >> 1
            b = 1 + 2 * pair + ram.rd8(base + 2 + pair)
            value, taken = ram.rd32(base + 4 + (b - 1) * 8), ram.rd32(base + 4 + (b - 1) * 8 + 4)
            self.assertEqual(value, taken)
            if prev is not None:
                self.assertGreater(value, prev)
            prev, last = value, b
            self.assertEqual(ram.rd8(base), a)      # nothing new until the next cycle: Old
            self.assertEqual(1 + 2 * pair + ram.rd8(base + 2 + pair), last)


class FourSlotKeyErrors(unittest.TestCase):
    def test_bad_keys(self):
        cases = [("four_slot = \"yes\"", "expected true or false"),
                 ("four_slot = 1", "expected true or false")]
        for extra, msg in cases:
            with self.subTest(extra=extra):
                r, _ = compile_desc("four_slot_time_bad", time_extra=extra, status_extra="")
                self.assertNotEqual(r.returncode, 0)
                self.assertIn("field 'four_slot'", r.stdout + r.stderr)
                self.assertIn(msg, r.stdout + r.stderr)

    def test_contradiction_with_kind(self):
        """four_slot contradicting kind = "four_slot" / "three_buffer" is an error; agreeing is fine."""
        sysd = {"name": "x", "clock_hz": 1_000_000, "boards": ["a", "b"]}
        base = {"name": "C", "size": 4, "producer": "a", "consumers": ["b"], "max_period_us": 100}
        for kind, fs, ok in (("four_slot", False, False), ("three_buffer", True, False),
                             ("four_slot", True, True), ("copy", True, True), ("three_buffer", False, True)):
            with self.subTest(kind=kind, four_slot=fs):
                data = {"system": sysd, "channel": [dict(base, kind=kind, four_slot=fs)]}
                if ok:
                    s = S.parse_description(data)
                    self.assertEqual(s.channels[0].layout, "four_slot" if fs else "three_buffer")
                else:
                    with self.assertRaises(S.ScheduleError) as cm:
                        S.parse_description(data)
                    self.assertIn("contradicts", str(cm.exception))


if __name__ == "__main__":
    unittest.main()
