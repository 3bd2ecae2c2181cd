"""The four-slot channel kind in the compiler:
compiler/examples/four_slot.toml compiled, then its ROM (E0 flag four_slot on
every entry of the channel, and only there), RAM layout (four buffers),
RAM images (Actual = ReadLocked = 1, Slot0 = Slot1 = 0), generated C
(alb_channel_setup_kind(..., ALB_FOUR_SLOT)), report, and an end-to-end run
of the Python controller model with the four-slot mapping.  The checks use
the independent oracles of oracle.py; negative tests show that they, and the
compiler's own verify_rom, catch a misplaced flag and a four-buffer extent
past the RAM.

    python3 -m unittest discover -s compiler/tests -v      (from the repository root)
"""

import os
import re
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from oracle import (  # noqa: E402
    CFLAGS, CINC, COMPILER_DIR, ControllerModel, ORACLE_FOUR_SLOT, OUT, REPO, RamImage, TOOL, TOOL_ENV,
    check_word, decode, harness_source, layout_problems, pattern, plan_problems, read_hex, rom_problems)
import albatross_schedule as S  # noqa: E402

EXAMPLE = os.path.join(REPO, "compiler", "examples", "four_slot.toml")
DRIVER_H = os.path.join(REPO, "c-driver", "albatross.h")
# The driver API the generated code calls; used only while the
# driver does not have it yet, so that the generated code is compiled anyway.
STUB = """/* stub of the issue-13 driver API for compiling generated code only */
#include "albatross.h"
enum { ALB_THREE_BUFFER = 0, ALB_FOUR_SLOT = 1 };
int alb_channel_setup_kind(alb_channel_t *ch, uintptr_t base, uint32_t size, unsigned kind);
"""


def driver_has_four_slot():
    with open(DRIVER_H) as f:
        return "alb_channel_setup_kind" in f.read()


def fs_buf(pair, slot):
    return 1 + 2 * pair + slot


class FourSlotExampleTests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import json
        import shutil
        cls.out = os.path.join(OUT, "four_slot")
        shutil.rmtree(cls.out, ignore_errors=True)
        r = subprocess.run(TOOL + [EXAMPLE, "--out", cls.out], capture_output=True, text=True, env=TOOL_ENV)
        if r.returncode != 0:
            raise AssertionError(r.stdout + r.stderr)
        with open(os.path.join(cls.out, "report.json")) as f:
            cls.rep = json.load(f)
        cls.rom = read_hex(os.path.join(cls.out, "rom.hex"))
        cls.chans = {c["name"]: c for c in cls.rep["channels"]}

    def ram_words(self):
        return [b["ram_bytes"] // 4 for b in self.rep["boards"]]

    def test_rom_flags(self):
        """FOUR_SLOT on every entry of Sample, on no other entry; the ROM is valid."""
        self.assertEqual(rom_problems(self.rom, self.rep["bus"]["n_chan"], self.ram_words()), [])
        self.assertEqual(S.verify_rom(self.rom, self.rep["bus"]["n_chan"], len(self.rep["boards"]),
                                      self.ram_words())[0], [])
        _, entries = decode(self.rom)
        fs_id = self.chans["Sample"]["id"]
        self.assertGreater(sum(e["id"] == fs_id for e in entries), 1)
        for e in entries:
            self.assertEqual(bool(e["flags"] & ORACLE_FOUR_SLOT["flag"]), e["id"] == fs_id, e)
        self.assertEqual(self.chans["Sample"]["channel_kind"], "four_slot")
        self.assertEqual(self.chans["Command"]["channel_kind"], "three_buffer")
        self.assertEqual(self.chans["GlobalTime"]["channel_kind"], "three_buffer")
        self.assertEqual(plan_problems(self.rep), [])

    def reseal(self, words):
        words = list(words)
        words[3] = check_word(words)
        return words

    def test_flag_on_time_is_valid(self):
        """FOUR_SLOT on a TIME entry is valid (a four-slot GlobalTime): both checkers accept it."""
        _, entries = decode(self.rom)
        k = next(i for i, e in enumerate(entries) if e["kind"] == 2)
        ok = list(self.rom)
        ok[4 + 8 * k] |= ORACLE_FOUR_SLOT["flag"] << 24
        ok = self.reseal(ok)
        self.assertEqual(rom_problems(ok, self.rep["bus"]["n_chan"], self.ram_words()), [])
        self.assertEqual([x for x in S.verify_rom(ok, self.rep["bus"]["n_chan"], len(self.rep["boards"]),
                                                  self.ram_words())[0] if f"entry {k}" in x and "FOUR" in x], [])

    def test_flag_misplaced_is_caught(self):
        """Negative: a flag bit that a TIME entry must not carry (REQUEST, MODE: E0.flags has no
        reserved bit left) fails both checkers."""
        _, entries = decode(self.rom)
        k = next(i for i, e in enumerate(entries) if e["kind"] == 2)
        for bit, what in ((4, "REQUEST on other than"), (8, "MODE on other than")):
            with self.subTest(bit=bit):
                bad = list(self.rom)
                bad[4 + 8 * k] |= bit << 24
                bad = self.reseal(bad)
                p = rom_problems(bad, self.rep["bus"]["n_chan"], self.ram_words())
                self.assertTrue(any(f"entry {k}" in x for x in p), p)
                q = S.verify_rom(bad, self.rep["bus"]["n_chan"], len(self.rep["boards"]), self.ram_words())[0]
                self.assertTrue(any(f"entry {k}" in x and what in x.replace("reserved E0", "reserved")
                                    for x in q), q)

    def test_four_buffer_extent_is_checked(self):
        """Negative: a Sample instance moved to where three buffers fit in the RAM but four
        do not: the oracle and verify_rom reject it (and accept it without the flag)."""
        _, entries = decode(self.rom)
        k = next(i for i, e in enumerate(entries) if e["flags"] & ORACLE_FOUR_SLOT["flag"])
        e = entries[k]
        board, _ = e["dst"][0]
        stride = e["w"] + 1
        rw = self.ram_words()[board]
        base = rw - (1 + 3 * stride)            # three buffers end exactly at the RAM's end
        for flag_on in (True, False):
            with self.subTest(four_slot=flag_on):
                bad = list(self.rom)
                i = 4 + 8 * k
                bad[i + 4] = (bad[i + 4] & 0xFFFF0000) | (board << 12) | base
                if not flag_on:
                    bad[i] &= ~(ORACLE_FOUR_SLOT["flag"] << 24)
                bad = self.reseal(bad)
                p = [x for x in rom_problems(bad, self.rep["bus"]["n_chan"], self.ram_words()) if "extent" in x]
                q = [x for x in S.verify_rom(bad, self.rep["bus"]["n_chan"], len(self.rep["boards"]),
                                             self.ram_words())[0] if "past the RAM" in x]
                self.assertEqual(bool(p), flag_on, p)
                self.assertEqual(bool(q), flag_on, q)

    def test_ram_layout_and_images(self):
        """Four buffers per four-slot instance; the images' control words."""
        self.assertEqual(layout_problems(self.rep), [])
        for c in self.rep["channels"]:
            nbuf = 4 if c["channel_kind"] == "four_slot" else 3
            if c["producer"]:
                self.assertEqual(c["producer"]["ram_bytes"], 4 + nbuf * 4 * c["words"], c["name"])
            for d in c["consumers"]:
                self.assertEqual(d["ram_bytes"], 4 + nbuf * 4 * (c["words"] + 1), c["name"])
            self.assertEqual(c["ram_bytes"], (c["producer"]["ram_bytes"] if c["producer"] else 0)
                             + sum(d["ram_bytes"] for d in c["consumers"]))
        for b in self.rep["boards"]:
            words = read_hex(os.path.join(self.out, f"{b['name']}_ram.hex"))
            self.assertEqual(len(words), b["ram_bytes"] // 4)
            bases = set()
            for i in b["instances"]:
                ctl = words[i["base"] // 4].to_bytes(4, "little")
                # Actual = ReadLocked = Buffer1; four-slot: Slot0 = Slot1 = 0 (and the reserved bytes 0 anyway)
                self.assertEqual(ctl, bytes([1, 1, 0, 0]), (b["name"], i["channel"]))
                bases.add(i["base"] // 4)
            self.assertTrue(all(w == 0 for n, w in enumerate(words) if n not in bases))

    def test_generated_c(self):
        for b in self.rep["boards"]:
            with open(os.path.join(self.out, b["name"] + ".c")) as f:
                src = f.read()
            with open(os.path.join(self.out, b["name"] + ".h")) as f:
                hdr = f.read()
            for i in b["instances"]:
                c = self.chans[i["channel"]]
                N = c["name"].upper()
                kind = "ALB_FOUR_SLOT" if c["channel_kind"] == "four_slot" else "ALB_THREE_BUFFER"
                self.assertIn(f"#define ALB_{N}_KIND   {kind}", hdr)
                if c["channel_kind"] == "four_slot":
                    calls = re.findall(rf"alb_channel_setup_kind\(&alb_ch_{c['name']}, dpram_base \+ ALB_{N}_BASE, "
                                       rf"ALB_{N}_SIZE, ALB_FOUR_SLOT\)", src)
                    self.assertEqual(len(calls), 2, src)      # init_all and attach_all
                    self.assertNotIn(f"alb_channel_setup(&alb_ch_{c['name']},", src)
                else:
                    self.assertEqual(src.count(f"alb_channel_setup(&alb_ch_{c['name']},"), 2)
                if i["role"] == "destination":
                    t = next(d for d in c["consumers"] if d["board"] == b["name"])["termination"]
                    self.assertIn(f"#define ALB_{N}_IMPORT_MAX_PASSES    {t['max_passes']}u", hdr)
                    self.assertIn(f"#define ALB_{N}_IMPORT_MAX_ACCESSES  {t['max_accesses']}u", hdr)

    def test_generated_c_compiles(self):
        """gcc -Werror on every board source and header: against the real driver
        when it has the four-slot API, else against a stub of that API."""
        if subprocess.run(["gcc", "--version"], capture_output=True).returncode != 0:
            self.skipTest("gcc not found: generated C not compiled")
        extra = []
        if not driver_has_four_slot():
            stub = os.path.join(self.out, "four_slot_api_stub.h")
            with open(stub, "w") as f:
                f.write(STUB)
            extra = ["-include", stub]
            print("\n  (c-driver/albatross.h has no alb_channel_setup_kind yet: compiled against a stub of it)",
                  file=sys.stderr)
        for b in self.rep["boards"]:
            for src, opts in ((b["name"] + ".c", []), (b["name"] + ".h", ["-x", "c"])):
                with self.subTest(file=src):
                    r = subprocess.run(["gcc"] + CFLAGS + CINC + extra + ["-I" + self.out] + opts +
                                       ["-c", os.path.join(self.out, src), "-o",
                                        os.path.join(self.out, src.replace(".", "_") + ".o")],
                                       capture_output=True, text=True)
                    self.assertEqual(r.returncode, 0, r.stderr)

    def test_termination_report(self):
        """Four-slot consumers: 1 pass, 3 + W + 1 accesses (1 + W + 1 when Old)."""
        for c in self.rep["channels"]:
            for d in c["consumers"]:
                t = d["termination"]
                wd = c["words"] + 1
                self.assertEqual(t["accesses_old"], 1 + wd)
                if c["channel_kind"] == "four_slot":
                    self.assertEqual((t["max_passes"], t["max_accesses"], t["bounded"]), (1, 3 + wd, True))
                else:
                    self.assertTrue(t["bounded"], (c["name"], d["board"], t))

    # ---- end to end with the Python model of the controller (four-slot mapping)
    def source_export(self, ram, base, words, state):
        """A four-slot producer's Export into a source instance (stride W)."""
        r = ram.rd8(base + 1)
        pair = 1 - ((r - 1) >> 1)
        slot = 1 - ram.rd8(base + 2 + pair)
        b = fs_buf(pair, slot)
        for i, w in enumerate(words):
            ram.wr32(base + 4 + (b - 1) * 4 * len(words) + 4 * i, w)
        ram.wr8(base + 2 + pair, slot)
        ram.wr8(base, b)

    def dest_import(self, ram, base, wd, last):
        """A four-slot consumer's Import (private last buffer): (new, words, last, accesses)."""
        a = ram.rd8(base)
        if a == last:
            return False, None, last, 1 + wd
        ram.wr8(base + 1, a)
        pair = (a - 1) >> 1
        b = fs_buf(pair, ram.rd8(base + 2 + pair))
        return True, [ram.rd32(base + 4 + (b - 1) * 4 * wd + 4 * i) for i in range(wd)], b, 3 + wd

    def test_end_to_end_model(self):
        """Sample exported twice into the source image; the controller model runs the ROM;
        every consumer imports the newest value once (New, exact words, taken_at), then Old."""
        boards = [b["name"] for b in self.rep["boards"]]
        rams = [RamImage(read_hex(os.path.join(self.out, f"{b}_ram.hex"))) for b in boards]
        c = self.chans["Sample"]
        src = rams[c["producer"]["board_index"]]
        model = ControllerModel(self.rom, rams, self.rep["bus"]["n_chan"])
        last = {d["board"]: 0 for d in c["consumers"]}
        for rnd in range(1, 4):
            value = [int.from_bytes(pattern(rnd, 4), "little") + k for k in range(c["words"])]
            self.source_export(src, c["producer"]["base"], [value[0] - 7] * c["words"], None)   # overwritten
            self.source_export(src, c["producer"]["base"], value, None)
            model.run_cycle()
            for d in c["consumers"]:
                ram = rams[d["board_index"]]
                new, words, last[d["board"]], acc = self.dest_import(ram, d["base"], c["words"] + 1, last[d["board"]])
                self.assertTrue(new, (rnd, d["board"]))
                self.assertEqual(words[:c["words"]], value, (rnd, d["board"]))
                self.assertEqual(words[-1], model.state[c["id"]]["taken_at"])
                self.assertEqual(acc, d["termination"]["max_accesses"])
                new, _, last[d["board"]], acc = self.dest_import(ram, d["base"], c["words"] + 1, last[d["board"]])
                self.assertFalse(new)
                self.assertEqual(acc, d["termination"]["accesses_old"])

    def test_end_to_end_driver(self):
        """The generated C with the real driver (once it has the four-slot kind): producers
        export, the model runs the ROM, every consumer imports New once with the exact bytes."""
        if not driver_has_four_slot():
            self.skipTest("c-driver/albatross.h has no four-slot kind yet (alb_channel_setup_kind)")
        if subprocess.run(["gcc", "--version"], capture_output=True).returncode != 0:
            self.skipTest("gcc not found")
        boards = [b["name"] for b in self.rep["boards"]]
        exe = {}
        for b in boards:
            hs = os.path.join(self.out, f"harness_{b}.c")
            with open(hs, "w") as f:
                f.write(harness_source(b, self.rep))
            exe[b] = os.path.join(self.out, f"harness_{b}")
            r = subprocess.run(["gcc"] + CFLAGS + CINC + ["-O1", "-I" + self.out, hs,
                               os.path.join(self.out, b + ".c"), os.path.join(REPO, "c-driver", "albatross.c"),
                               "-o", exe[b]], capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)

        def run(b, ram_in, ram_out, *ops):
            r = subprocess.run([exe[b], ram_in, ram_out, "attach"] + list(ops), capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            return r.stdout.splitlines()

        state = os.path.join(self.out, "e2e")
        os.makedirs(state, exist_ok=True)
        ram = {b: os.path.join(state, f"{b}.hex") for b in boards}
        seeds = {}
        for bi, b in enumerate(boards):
            ops = []
            for i in self.rep["boards"][bi]["instances"]:
                if i["role"] == "source":
                    seeds[i["channel"]] = len(seeds) + 5
                    ops.append(f"export:{i['channel']}:{seeds[i['channel']]}")
            lines = run(b, os.path.join(self.out, f"{b}_ram.hex"), ram[b], *ops)
            self.assertEqual(lines, ["setup 0"] + ["export 0"] * len(ops))
        model = ControllerModel(self.rom, [RamImage(read_hex(ram[b])) for b in boards], self.rep["bus"]["n_chan"])
        model.run_cycle()
        model.run_cycle()
        for bi, b in enumerate(boards):
            with open(ram[b], "w") as f:
                f.write("".join(f"{w:08x}\n" for w in model.rams[bi].words()))
        for bi, b in enumerate(boards):
            ops = [f"import:{i['channel']}" for i in self.rep["boards"][bi]["instances"]
                   if i["role"] == "destination" and self.chans[i["channel"]]["kind"] == "copy"]
            lines = run(b, ram[b], ram[b] + ".after", *ops)
            self.assertEqual(lines[0], "setup 0")
            for k, op in enumerate(ops):
                c = self.chans[op.split(":")[1]]
                head, r, data = lines[1 + 3 * k].rsplit(" ", 2)
                self.assertEqual((head, r), (f"import {c['name']}", "1"), f"{b}: {c['name']} not New")
                self.assertEqual(lines[3 + 3 * k], "typed 0", f"{b}: {c['name']} New twice")
                self.assertEqual(bytes.fromhex(data)[:c["size"]], pattern(seeds[c["name"]], c["size"]))
                self.assertEqual(int(lines[2 + 3 * k].split()[1]), model.state[c["id"]]["taken_at"])


class FourSlotDescriptionTests(unittest.TestCase):
    def test_kind_names(self):
        """kind = "three_buffer" is "copy"; "four_slot" is a copy channel with the four-slot layout."""
        base = ('[system]\nname = "k"\nclock_hz = 50_000_000\nboards = ["a", "b"]\n'
                '[[channel]]\nname = "D"\nsize = 8\nproducer = "a"\nconsumers = ["b"]\nmax_period_us = 100\n')
        for kind, layout in (("copy", "three_buffer"), ("three_buffer", "three_buffer"), ("four_slot", "four_slot")):
            with self.subTest(kind=kind):
                import tomllib
                sysm = S.parse_description(tomllib.loads(base + f'kind = "{kind}"\n'), "k.toml")
                ch = sysm.channels[0]
                self.assertEqual((ch.kind, ch.layout), ("copy", layout))
                _, plan, rom, rep = S.compile_system(sysm)
                self.assertEqual(rep["channels"][0]["channel_kind"], layout)
                self.assertEqual(rep["boards"][0]["instances"][0]["bytes"], 4 + (4 if layout == "four_slot" else 3) * 8)


if __name__ == "__main__":
    unittest.main()
