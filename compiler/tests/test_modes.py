"""Tests of schedule modes ([[mode]], compiler/albatross_schedule/modes.py):
the description's modes, each mode planned and checked on its own over one
RAM layout, the errors that name the mode, and the outputs.

    python3 -m unittest discover -s compiler/tests -p test_modes.py -v
"""

import os
import subprocess
import sys
import tomllib
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from oracle import OUT, REPO, TOOL, TOOL_ENV  # noqa: E402
import albatross_schedule as S  # noqa: E402
from albatross_schedule import contract  # noqa: E402

ROBOT = os.path.join(REPO, "sim", "mobot3.toml")
with open(ROBOT) as _f:
    ROBOT_TEXT = _f.read()

# The navigation board's mode requests.
REQ_CHANNEL = """
[[channel]]
name          = "ModeRequest"
kind          = "mode_request"
producer      = "navigation"
size          = 4
max_period_us = 1000
"""
# cruise: the robot as it is; dock: Position and MotorCmd twice as often, no RadarMap, no Status.
TWO_MODES = REQ_CHANNEL + """
[[mode]]
name = "cruise"
next = ["dock"]

[[mode]]
name     = "dock"
channels = ["Position", "MotorCmd", "GlobalTime"]
periods  = { Position = 25, MotorCmd = 25 }
"""


def system_of(extra: str):
    text = ROBOT_TEXT + extra
    return S.parse_description(tomllib.loads(text), "robot-modes.toml", text)


def errors_of(extra: str) -> list:
    try:
        system_of(extra)
    except S.ScheduleError as e:
        return e.messages
    return []


class ModeDescriptionTests(unittest.TestCase):
    def test_request_channel_and_modes_go_together(self):
        self.check_error(REQ_CHANNEL, "ModeRequest", "needs [[mode]]")
        self.check_error(TWO_MODES.replace(REQ_CHANNEL, ""), "needs a channel of kind \"mode_request\"")
        self.check_error(TWO_MODES.replace('producer      = "navigation"', 'producer = "navigation"\nconsumers = ["motor"]'),
                         "ModeRequest", "consumers", "the controller reads it")
        self.check_error(TWO_MODES.replace("size          = 4", "size          = 8"), "ModeRequest", "one word")

    def test_no_modes_is_one_schedule(self):
        system = system_of("")
        self.assertEqual(system.modes, [])
        _, plan, rom, rep = S.compile_system(system)
        self.assertNotIn("modes", rep, "a description without [[mode]] has no modes in its report")

    def test_modes_parsed(self):
        system = system_of(TWO_MODES)
        names = [m.name for m in system.modes]
        self.assertEqual(names, ["cruise", "dock"])
        cruise, dock = system.modes
        self.assertEqual(cruise.channels, [ch.index for ch in system.channels], "channels default to every channel")
        req = next(ch.index for ch in system.channels if ch.request)
        self.assertIn(req, dock.channels, "the mode_request channel is in every mode that may switch")
        self.assertEqual(cruise.next, [1])
        self.assertEqual(dock.next, [0], "next defaults to every other mode")
        by = {ch.name: ch.index for ch in system.channels}
        self.assertEqual(dock.periods, {by["Position"]: 25, by["MotorCmd"]: 25})

    def check_error(self, extra, *words):
        msgs = errors_of(extra)
        self.assertTrue(msgs, f"expected an error naming {words}, got none")
        self.assertTrue(any(all(w in m for w in words) for m in msgs),
                        f"expected an error naming {words}, got {msgs}")

    def test_errors_name_the_mode_and_field(self):
        self.check_error('[[mode]]\nname = "a"\n[[mode]]\nname = "b"\nchannels = ["Nope"]\n',
                         "mode 'b'", "channels", "no channel 'Nope'")
        self.check_error('[[mode]]\nname = "a"\n[[mode]]\nname = "a"\nchannels = ["Position"]\n',
                         "mode 'a'", "name", "comes before")
        self.check_error('[[mode]]\nname = "a"\nnext = ["zz"]\n[[mode]]\nname = "b"\n', "mode 'a'", "next",
                         "no mode 'zz'")
        self.check_error('[[mode]]\nname = "a"\nnext = ["a"]\n[[mode]]\nname = "b"\n', "mode 'a'", "next", "itself")
        self.check_error('[[mode]]\nname = "a"\n[[mode]]\nname = "b"\nchannels = ["Position"]\n'
                         'periods = { MotorCmd = 10 }\n', "mode 'b'", "periods", "not a channel of this mode")
        self.check_error('[[mode]]\nname = "a"\nperiods = { Position = 0 }\n', "mode 'a'", "periods", "positive")
        self.check_error('[[mode]]\nname = "a"\ncolour = 1\n', "mode 'a'", "colour", "unknown field")
        self.check_error('[[mode]]\nname = "3x"\n', "name", "not an identifier")
        self.check_error('[[mode]]\nname = "base"\n', "mode 'base'", "name", "generated macro")
        data = tomllib.loads(ROBOT_TEXT)
        data["mode"] = 1
        with self.assertRaises(S.ScheduleError) as cm:
            S.parse_description(data, "robot-modes.toml", ROBOT_TEXT)
        self.assertTrue(any("array of tables" in m for m in cm.exception.messages), cm.exception.messages)

    def test_modes_need_two_and_time_rigid(self):
        self.check_error('[[mode]]\nname = "a"\n', "mode 'a'", "two or more")
        text = ROBOT_TEXT.replace('mode         = "time-rigid"', 'mode         = "position-synchronised"')
        text = text.replace('name          = "Position"', 'name          = "Position"\nsync          = true')
        with self.assertRaises(S.ScheduleError) as cm:
            S.parse_description(tomllib.loads(text + TWO_MODES), "robot-modes.toml", text + TWO_MODES)
        self.assertTrue(any("time-rigid" in m for m in cm.exception.messages), cm.exception.messages)

    def test_start_up_mode_gets_the_mode_channels(self):
        # a start-up mode that lists the user's channels by name gets the mode_request channel added
        names = '["RadarMap", "Position", "MotorCmd", "GlobalTime", "Status"]'
        system = system_of(TWO_MODES.replace('name = "cruise"\n', f'name = "cruise"\nchannels = {names}\n'))
        self.assertEqual(len(system.modes[0].channels), len(system.channels))

    def test_start_up_mode_lists_every_channel(self):
        self.check_error('[[mode]]\nname = "dock"\nchannels = ["Position", "MotorCmd", "GlobalTime"]\n',
                         "mode 'dock'", "start-up mode", "RadarMap")

    def test_error_line_numbers(self):
        msgs = errors_of('[[mode]]\nname = "a"\n[[mode]]\nname = "b"\nchannels = ["Nope"]\n')
        line = ROBOT_TEXT.count("\n") + 5
        self.assertTrue(any(f"robot-modes.toml:{line}:" in m for m in msgs), f"expected line {line}: {msgs}")


class ModePlanTests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.system, cls.plan, cls.rom, cls.rep = S.compile_system(system_of(TWO_MODES))
        _, cls.plan1, cls.rom1, cls.rep1 = S.compile_system(system_of(""))

    def test_modes_under_a_fault_hypothesis(self):
        # The mode_request channel has no destination: the fault plan gives it
        # the default retry budget (it crashed the planner once: no delivery
        # curve to plan from).
        system = system_of(TWO_MODES + "\n[faults]\nrate = 0.2\nprobability = 0.999999999\n")
        _, plan, rom, rep = S.compile_system(system)
        self.assertEqual([m["name"] for m in rep["modes"]], ["cruise", "dock"])
        req = [c for c in rep["channels"] if c.get("mode_request")]
        self.assertEqual(len(req), 1, "the report marks the mode_request channel")
        for m in rep["modes"]:   # the switch latency that holds with the hypothesis' probability
            at, lat = m["switch_latency_at_target"], m["switch_latency"]["clocks"]
            self.assertEqual(at["clocks"], lat + (at["slots_needed"] - 1) * m["cycle"]["clocks"], m["name"])
            self.assertLessEqual(at["slot_miss_probability"] ** at["slots_needed"], 1e-9 * 1.000001, m["name"])
            if at["slots_needed"] > 1:
                self.assertGreater(at["slot_miss_probability"] ** (at["slots_needed"] - 1), 1e-9, m["name"])
        _, _, _, plain = S.compile_system(system_of(TWO_MODES))
        self.assertNotIn("switch_latency_at_target", plain["modes"][0], "no hypothesis, no figure at a target")

    def test_every_mode_planned_and_reported(self):
        modes = {m["name"]: m for m in self.rep["modes"]}
        self.assertEqual(list(modes), ["cruise", "dock"])
        self.assertTrue(modes["cruise"]["start_up"])
        self.assertEqual(modes["dock"]["left_out"], ["RadarMap", "Status"])
        self.assertEqual([c["name"] for c in modes["dock"]["channels"]],
                         ["Position", "MotorCmd", "GlobalTime", "ModeRequest"])
        for m in modes.values():
            for c in m["channels"]:
                self.assertLessEqual(c["guaranteed_period"]["clocks"], c["max_period"]["clocks"],
                                     f"mode {m['name']}, {c['name']}: guaranteed period over its max_period")
        # the switch latency: 2 C - (the request slot's start + the sample offset)
        cruise = modes["cruise"]
        start = min(e["start"] for e in self.rep["entries_list"] if e["channel"] == "ModeRequest")
        bus = self.rep["bus"]
        self.assertEqual(cruise["switch_latency"]["clocks"],
                         2 * cruise["cycle"]["clocks"] - (start + bus["fetch_cycles"] + bus["access_cycles"]))
        for m in modes.values():
            self.assertLess(m["switch_latency"]["clocks"], 2 * m["cycle"]["clocks"], m["name"])
            self.assertGreater(m["switch_latency"]["clocks"], m["cycle"]["clocks"] - 1, m["name"])
        dock = {c["name"]: c for c in modes["dock"]["channels"]}
        self.assertEqual(dock["Position"]["max_period"]["us"], 25, "dock's period of Position is its own")
        self.assertLess(modes["dock"]["cycle"]["clocks"], modes["cruise"]["cycle"]["clocks"],
                        "dock's shorter periods give a shorter cycle")

    def test_rom_holds_every_mode(self):
        # Decoded with literal bit positions (docs/controller.md), not the compiler's contract module.
        rom, one = self.rom, self.rom1
        ne, h2 = (rom[0] >> 8) & 0xFF, rom[2]
        modes = {m["name"]: m for m in self.rep["modes"]}
        e0, e1 = modes["cruise"]["entries"], modes["dock"]["entries"]
        self.assertEqual(((h2 >> 16) & 0xF, (h2 >> 8) & 0xFF, h2 >> 24, h2 & 0xFF),
                         (2, e0 + e1, e0, self.rep["drop_run"]), "H2: modes, table, start_end, drop run")
        self.assertEqual(ne, e0 + e1 + 2, "NE counts every mode's entries and the two descriptors")
        self.assertEqual(len(rom), 4 + 8 * ne)
        self.assertEqual(rom[1], one[1] | (0b10 << 16), "H1: the start-up mode's cycle and next (dock)")
        self.assertEqual(one[1] >> 16, 0, "H1.next is 0 without modes")
        for m, (first, end) in enumerate([(0, e0), (e0, e0 + e1)]):
            reqs = [k for k in range(first, end) if rom[4 + 8 * k] >> 26 & 1]     # E0 flag bit 2: REQUEST
            self.assertEqual(len(reqs), 1, f"mode {m}: one REQUEST entry a cycle, got {len(reqs)}")
            e = rom[4 + 8 * reqs[0]]
            self.assertEqual((e >> 28, e >> 12 & 0xF), (1, 0), f"mode {m}: the REQUEST entry is a COPY with ND 0")
            cyc = rom[4 + 8 * (e0 + e1 + m)] & 0xFFFF
            last = max(rom[4 + 8 * k + 1] + rom[4 + 8 * k + 2] for k in range(first, end))
            self.assertLessEqual(last, cyc - 6, f"mode {m}: the last slot ends {cyc - last} clocks before the cycle "
                                                f"end, expected the mode switch's 6 at least")
        for m, (first, end, cyc, nxt) in enumerate([(0, e0, modes["cruise"]["cycle"]["clocks"], 0b10),
                                                    (e0, e0 + e1, modes["dock"]["cycle"]["clocks"], 0b01)]):
            d = rom[4 + 8 * (e0 + e1 + m):]
            self.assertEqual((d[0] & 0xFFFF, (d[0] >> 16) & 0xFF, d[0] >> 24), (cyc, first, end),
                             f"mode {m}: D0 = cycle, first, end")
            self.assertEqual(d[1] >> 16, nxt, f"mode {m}: D1.next")
            self.assertEqual(d[2:8], [0] * 6, f"mode {m}: D2..D7 reserved")
        crc = S.rom_crc(rom)
        self.assertEqual(crc, 0, "the CRC covers every mode and descriptor")
        problems, entries = S.verify_rom(rom)
        self.assertEqual(problems, [])
        self.assertEqual(sum(1 for e in entries if e["mode"] == 1), e1)

    def test_verify_rom_catches_bad_descriptors(self):
        e0 = self.rep["modes"][0]["entries"]
        e1 = self.rep["modes"][1]["entries"]
        d1 = 4 + 8 * (e0 + e1 + 1)           # mode 1's descriptor
        cases = [(d1 + 1, lambda w: w | (1 << 17), "names a mode that does not exist or the mode itself"),
                 (d1, lambda w: (w & ~(0xFF << 16)) | ((e0 + 1) << 16), "expected a range from"),
                 (d1 + 3, lambda w: 1, "D3 (reserved) is not 0")]
        for at, change, words in cases:
            bad = list(self.rom)
            bad[at] = change(bad[at])
            bad[3] = contract.load().check_word(bad)
            problems, _ = S.verify_rom(bad)
            self.assertTrue(any(words in p for p in problems), f"expected a problem '{words}', got {problems}")

    def test_verify_rom_catches_a_channel_id_that_differs_between_modes(self):
        # the controller keeps a channel's state (a value's fragments, its
        # buffers) by id across modes: an entry of mode 1 whose W differs from
        # mode 0's entry of the same id must be named
        e0 = self.rep["modes"][0]["entries"]
        e1 = self.rep["modes"][1]["entries"]
        entries = S.verify_rom(self.rom)[1]
        ids0 = {e["id"] for e in entries[:e0] if e["kind"] == "copy"}
        k = next(k for k in range(e0, e0 + e1) if entries[k]["kind"] == "copy" and entries[k]["id"] in ids0)
        bad = list(self.rom)
        at = 4 + 8 * k                        # E0: W in bits [11:0] (docs/controller.md)
        bad[at] = (bad[at] & ~0xFFF) | ((bad[at] & 0xFFF) + 1)
        bad[3] = contract.load().check_word(bad)
        problems, _ = S.verify_rom(bad)
        want = f"channel id {entries[k]['id']} has another W than entry"
        self.assertTrue(any(want in p for p in problems), f"expected a problem '{want}', got {problems}")
        self.assertEqual([p for p in S.verify_rom(self.rom)[0]], [], "the good image has none")

    def test_outputs(self):
        self.assertEqual(self.plan.cycle, self.plan1.cycle)
        files = S.generate(self.system, self.plan, self.rom, self.rep)
        svg = files["timeline.svg"]
        self.assertEqual(svg.count("<svg "), 3, "one outer picture and a lane group per mode")
        self.assertIn("mode cruise (start-up), switches to dock", svg)
        self.assertIn("mode dock, switches to cruise", svg)
        self.assertIn("Modes (the ROM image holds every mode", files["report.txt"])
        for b in self.system.boards:
            self.assertIn("#define ALB_MODE_CRUISE 0u", files[f"{b}.h"])
            self.assertIn("#define ALB_MODE_DOCK   1u", files[f"{b}.h"])

    def test_unplannable_mode_is_named(self):
        # 1 us = 50 clocks: no slot of Position fits so often.
        bad = TWO_MODES.replace("Position = 25", "Position = 1")
        with self.assertRaises(S.ScheduleError) as cm:
            S.compile_system(system_of(bad))
        self.assertTrue(cm.exception.messages, "no message")
        for m in cm.exception.messages:
            self.assertTrue(m.startswith("mode 'dock': "), f"expected the message to name mode 'dock', got {m!r}")


# compiler/examples/modes_share.toml: two modes that differ only in one
# channel's period (100 us, relaxed to 200 us).  Each mode alone fills its
# spare bus time with redundant slots, and the two together want more
# entries than the ROM's 255.
with open(os.path.join(REPO, "compiler", "examples", "modes_share.toml")) as _f:
    ROM_SHARE = _f.read()
# Its system and channels, no modes: the pieces of the other descriptions below.
SHARE_SYSTEM = ROM_SHARE[ROM_SHARE.index("[system]"):ROM_SHARE.index("[[channel]]")]
REQUEST = """
[[channel]]
name          = "ModeRequest"
kind          = "mode_request"
producer      = "a"
size          = 4
max_period_us = 1000
"""


def compile_text(text, name):
    return S.compile_system(S.parse_description(tomllib.loads(text), name, text))


def rom_slots(rom):
    """{mode: {channel id: entries}} read from the image with literal bit
    positions (docs/controller.md): the mode table's D0 = cycle | first << 16 | end << 24."""
    ne, h2 = (rom[0] >> 8) & 0xFF, rom[2]
    modes, table = (h2 >> 16) & 0xF, (h2 >> 8) & 0xFF
    out = {}
    for m in range(modes):
        d0 = rom[4 + 8 * (table + m)]
        first, end = (d0 >> 16) & 0xFF, d0 >> 24
        ids = {}
        for k in range(first, end):
            cid = (rom[4 + 8 * k] >> 16) & 0xF
            ids[cid] = ids.get(cid, 0) + 1
        out[m] = ids
    return ne, out


class RomShareTests(unittest.TestCase):
    """The modes share the ROM's entries: a description whose modes fit
    without redundant slots is planned, and the report says what was cut."""

    @classmethod
    def setUpClass(cls):
        cls.system, cls.plan, cls.rom, cls.rep = compile_text(ROM_SHARE, "share.toml")

    def test_modes_that_fit_without_redundancy_are_planned(self):
        modes = self.rep["modes"]
        total = sum(m["entries"] for m in modes) + len(modes)
        self.assertLessEqual(total, 255, "the modes' entries and descriptors overflow the ROM")
        self.assertEqual(total, 255, f"expected the ROM filled (the bus time allows more), got {total} entries")
        problems, _ = S.verify_rom(self.rom)
        self.assertEqual(problems, [])

    def test_report_says_the_redundancy_was_cut(self):
        for m in self.rep["modes"]:
            r = m["redundant_slots"]
            self.assertTrue(r["cut"], f"mode {m['name']}: expected its redundancy cut, got {r}")
            self.assertLess(r["planned"], r["bus_allows"], m["name"])
            self.assertEqual(r["planned"], m["entries"] - len(m["channels"]), m["name"])
            self.assertLessEqual(m["entries"], r["entries_allowed"], m["name"])
        # shared in proportion to what the bus time allows each mode (within one slot)
        a, b = (m["redundant_slots"] for m in self.rep["modes"])
        self.assertLessEqual(abs(a["planned"] * b["bus_allows"] - b["planned"] * a["bus_allows"]),
                             max(a["bus_allows"], b["bus_allows"]), f"not proportional: {a}, {b}")
        txt = S.render_report_txt(self.rep)
        for m in self.rep["modes"]:
            r = m["redundant_slots"]
            self.assertIn(f"{r['planned']} redundant slots of the {r['bus_allows']} the bus time allows: CUT", txt)

    def test_bounds_are_those_of_the_planned_slots(self):
        """Each mode's report gives the slots its ROM entries hold, and its
        guaranteed periods from them."""
        ne, per_mode = rom_slots(self.rom)
        self.assertEqual(ne, 255)
        for i, m in enumerate(self.rep["modes"]):
            got = {c["id"]: c["redundancy"] for c in m["channels"]}
            self.assertEqual(per_mode[i], got, f"mode {m['name']}: ROM entries per channel against the report")
            for c in m["channels"]:
                self.assertLessEqual(c["guaranteed_period"]["clocks"], c["max_period"]["clocks"],
                                     f"mode {m['name']}, {c['name']}")

    def test_console_says_the_redundancy_was_cut(self):
        out = os.path.join(OUT, "modes_share")
        r = subprocess.run(TOOL + [os.path.join(REPO, "compiler", "examples", "modes_share.toml"), "-o", out],
                           capture_output=True, text=True, env=TOOL_ENV, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        for m in self.rep["modes"]:
            x = m["redundant_slots"]
            line = (f"mode {m['name']}{' (start-up)' if m['start_up'] else ''}: cycle {m['cycle']['clocks']} "
                    f"clocks, {m['entries']} entries")
            self.assertIn(line, r.stdout)
            self.assertIn(f"{line}, bus utilisation {100 * m['bus_utilisation']:.1f} %; redundancy cut to fit the "
                          f"ROM ({x['planned']} of the {x['bus_allows']} redundant slots", r.stdout)

    def test_modes_that_fit_keep_all_their_redundancy(self):
        """Modes whose redundant slots all fit the ROM: nothing cut."""
        text = ROM_SHARE.replace("periods = { Fast = 200 }", "channels = [\"Fast\"]")
        self.assertNotEqual(text, ROM_SHARE)
        _, _, _, rep = compile_text(text, "share2.toml")
        relaxed = rep["modes"][1]
        self.assertFalse(relaxed["redundant_slots"]["cut"], relaxed["redundant_slots"])

    def test_modes_over_the_rom_without_redundancy(self):
        """16 modes of 16 channels need 272 entries with no redundant slot: an error
        naming each mode's count, before any planning."""
        chans = "".join(f'\n[[channel]]\nname = "C{i}"\nsize = 4\nproducer = "a"\nconsumers = ["b"]\n'
                        f'max_period_us = 1000\n' for i in range(15))
        modes = "".join(f'\n[[mode]]\nname = "m{i}"\n' for i in range(16))
        text = SHARE_SYSTEM + chans + REQUEST + modes
        with self.assertRaises(S.ScheduleError) as cm:
            compile_text(text, "sixteen.toml")
        msg = " ".join(cm.exception.messages)
        for w in ("272 ROM entries", "at most 255", "mode 'm0' 16 channels", "mode 'm15' 16 channels",
                  "16 descriptors"):
            self.assertIn(w, msg)

    def test_one_schedule_over_the_rom(self):
        """Without modes, redundancy alone would overflow the ROM: 255 entries, and the report says
        how many more slots the bus time allows."""
        text = SHARE_SYSTEM + ('[[channel]]\nname = "Tiny"\nsize = 4\nproducer = "a"\nconsumers = ["b"]\n'
                               'max_period_us = 1000\n')
        _, plan, rom, rep = compile_text(text, "one.toml")
        self.assertEqual(len(plan.slots), 255)
        self.assertEqual(S.verify_rom(rom)[0], [])
        r = rep["redundant_slots"]
        self.assertEqual((r["planned"], r["cut"], r["entries_allowed"]), (254, True, 255), r)
        self.assertGreater(r["bus_allows"], 254)
        self.assertIn(f"254 redundant slots of the {r['bus_allows']} the bus time allows: CUT",
                      S.render_report_txt(rep))
        self.assertNotIn("modes", rep)

    def test_shares(self):
        from albatross_schedule.modes import rom_shares
        self.assertEqual(rom_shares(10, [3, 4]), [None, None], "all fit: no cap")
        self.assertEqual(rom_shares(247, [93, 189]), [81, 166])
        for room, wants in ((5, [1, 1, 100]), (7, [3, 3, 3]), (0, [5, 5]), (100, [0, 300])):
            got = rom_shares(room, wants)
            self.assertEqual(sum(got), room, (room, wants, got))
            self.assertTrue(all(0 <= g <= w for g, w in zip(got, wants)), (room, wants, got))


if __name__ == "__main__":
    unittest.main()
