"""Tests of the schedule compiler (the package compiler/albatross_schedule/).

    python3 -m unittest discover -s compiler/tests -v      (from the repository root)

The checkers below re-implement the ROM contract (docs/controller.md) independently of the
compiler (ROM format, checksum, validation rules, memory map) and are
themselves checked on deliberately corrupted ROMs and plans.  The
end-to-end test runs the generated C (board headers, set-up functions, RAM
images) with the real driver on the host, and moves the values between the
boards' RAM images with a small Python model of the controller executing
rom.hex.  Outputs go to build/compiler-tests/ only.
"""

import json
import os
import re
import shutil
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
COMPILER_DIR = os.path.dirname(HERE)
REPO = os.path.dirname(COMPILER_DIR)
# The command line, as the build runs it: python3 -m albatross_schedule with compiler/ on the path.
TOOL = [sys.executable, "-m", "albatross_schedule"]
TOOL_ENV = dict(os.environ, PYTHONPATH=COMPILER_DIR)
EXAMPLES = os.path.join(REPO, "sim")  # the MOBOT-III robot's descriptions
BAD = os.path.join(HERE, "bad")
OUT = os.path.join(REPO, "build", "compiler-tests")
CFLAGS = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
CINC = ["-I" + os.path.join(REPO, "c-driver"), "-I" + os.path.join(REPO, "c-driver", "port", "mmio")]

sys.path.insert(0, COMPILER_DIR)
import albatross_schedule as S  # noqa: E402

EXAMPLE_FILES = ["mobot3.toml", "mobot3_possync.toml"]


# ---------------------------------------------------------------------------
# Independent checkers of the ROM contract (docs/controller.md).  They are deliberate oracles,
# written without the compiler's contract module; compiler/tests/test_contract.py
# checks their field positions and constants against rtl/albatross_contract.toml.

# The channel layout the controller model below assumes (byte offsets from the
# channel base; buffer index values; words after a destination value).
ORACLE_LAYOUT = {"off_actual": 0, "off_readlocked": 1, "off_buffers": 4, "buffer1": 1, "buffers": 3,
                 "taken_at_words": 1}


def crc(words):
    """CRC of a ROM image, H3 (word 3) read as 0: polynomial division over
    GF(2) by P = x^32 + x^7 + x^5 + x^3 + x^2 + x + 1, written as the
    remainder of the image's polynomial (seed 0xFFFFFFFF prepended)."""
    p = (1 << 32) | 0xAF
    r = 0xFFFFFFFF
    for i, w in enumerate(words):
        r = (r << 32) | (0 if i == 3 else w)
        for b in range(63, 31, -1):          # reduce the degree below 32
            if r >> b & 1:
                r ^= p << (b - 32)
    return r


def read_hex(path):
    words = []
    with open(path) as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not re.fullmatch(r"[0-9a-f]{8}", line):
                raise AssertionError(f"{path}:{n}: {line!r} is not 8 lower-case hex digits")
            words.append(int(line, 16))
    return words


def decode(words):
    h0 = words[0]
    ne = (h0 >> 8) & 0xFF
    entries = []
    for k in range(ne):
        e = words[4 + 8 * k: 12 + 8 * k]
        if len(e) < 8:
            break
        nd = (e[0] >> 12) & 0xF
        dst = [e[4] & 0xFFFF, e[4] >> 16, e[5] & 0xFFFF, e[5] >> 16]
        entries.append({
            "raw": e, "kind": e[0] >> 28, "flags": (e[0] >> 24) & 0xF, "id": (e[0] >> 16) & 0xFF,
            "nd": nd, "w": e[0] & 0xFFF, "start": e[1] & 0xFFFF, "length": e[2] & 0xFFFF,
            "time_high": (e[1] | e[2]) >> 16,
            "src_board": (e[3] >> 12) & 0xF, "src_word": e[3] & 0xFFF,
            "dst": [((d >> 12) & 0xF, d & 0xFFF) for d in dst[:nd]], "unused_dst": dst[nd:]})
    return {"magic": h0 >> 16, "ne": ne, "flags": h0 & 0xFF, "cycle": words[1] & 0xFFFF,
            "cycle_high": words[1] >> 16}, entries


def rom_problems(words, n_chan, ram_words):
    """Every violation of the ROM format (docs/controller.md) and validation rules."""
    p = []
    if len(words) < 4:
        return ["shorter than the header"]
    hdr, entries = decode(words)
    if hdr["magic"] != 0xA1BA:
        p.append("bad magic")
    if crc(words) != words[3]:
        p.append("ROM CRC")
    if hdr["cycle_high"]:
        p.append("H1 above 16 bits")
    if words[2] != 0:
        p.append("H2 not 0")
    if not 1 <= hdr["ne"] <= 255:
        p.append("entry count")
    if len(words) != 4 + 8 * hdr["ne"]:
        p.append("length does not match the entry count")
    sync = hdr["flags"] & 1
    prev_end = 0
    for k, e in enumerate(entries):
        if e["time_high"]:
            p.append(f"entry {k}: time above 16 bits")
        if e["raw"][7] != 0:
            p.append(f"entry {k}: E7 not 0")
        if e["kind"] not in (1, 2, 3):
            p.append(f"entry {k}: kind {e['kind']}")
        if not 1 <= e["nd"] <= 4:
            p.append(f"entry {k}: ND")
        if e["id"] >= n_chan:
            p.append(f"entry {k}: channel id")
        if any(e["unused_dst"]):
            p.append(f"entry {k}: unused destination field not 0")
        if e["raw"][6] != 0:
            p.append(f"entry {k}: E6 not 0")
        if e["kind"] == 2 and e["w"] != 1:
            p.append(f"entry {k}: TIME W")
        if e["kind"] == 3 and e["w"] != 1 + 2 * n_chan:
            p.append(f"entry {k}: STATUS W")
        if e["kind"] != 1 and e["raw"][3] != 0:
            p.append(f"entry {k}: source on a non-COPY")
        exts = [(b, w, e["w"] + 1) for b, w in e["dst"]]
        if e["kind"] == 1:
            exts.append((e["src_board"], e["src_word"], e["w"]))
        for b, base, stride in exts:
            if b >= len(ram_words):
                p.append(f"entry {k}: board {b} does not exist")
            elif base + 1 + 3 * stride > ram_words[b]:
                p.append(f"entry {k}: extent outside the RAM")
        if e["flags"] & 1 and not (k == 0 and sync):
            p.append(f"entry {k}: SYNC flag misplaced")
        if sync and k == 0 and not (e["flags"] & 1 and e["kind"] == 1 and e["start"] == 0):
            p.append("entry 0 of a sync ROM is not a SYNC COPY at 0")
        if e["start"] < prev_end:
            p.append(f"entry {k}: overlaps or precedes the previous slot")
        if e["start"] + e["length"] > hdr["cycle"]:
            p.append(f"entry {k}: ends after the cycle")
        prev_end = e["start"] + e["length"]
    return p


def gaps(starts, cycle):
    s = sorted(starts)
    return [(s[(i + 1) % len(s)] + (cycle if i == len(s) - 1 else 0)) - s[i] for i in range(len(s))]


def plan_problems(rep):
    """Per channel: at least one slot, period <= max_period, the reported
    period equal to the slots' largest cyclic gap."""
    p = []
    cycle = rep["cycle"]["clocks"]
    for c in rep["channels"]:
        starts = [s["start"] for s in c["slots"]]
        if not starts:
            p.append(f"{c['name']}: no slot")
            continue
        g = max(gaps(starts, cycle))
        if g > c["max_period"]["clocks"]:
            p.append(f"{c['name']}: guaranteed period {g} > max_period {c['max_period']['clocks']}")
        if g != c["guaranteed_period"]["clocks"]:
            p.append(f"{c['name']}: reported period {c['guaranteed_period']['clocks']} != {g}")
        if c["redundancy"] != len(starts):
            p.append(f"{c['name']}: redundancy factor")
    return p


def layout_problems(rep):
    """Per board: instances word-aligned, inside the RAM, not overlapping."""
    p = []
    for b in rep["boards"]:
        spans = sorted((i["base"], i["base"] + i["bytes"], i["channel"]) for i in b["instances"])
        for lo, hi, name in spans:
            if lo % 4 or lo < 0 or hi > b["ram_bytes"]:
                p.append(f"{b['name']}: {name} misplaced")
        for (lo1, hi1, n1), (lo2, _, n2) in zip(spans, spans[1:]):
            if hi1 > lo2:
                p.append(f"{b['name']}: {n1} overlaps {n2}")
    return p


def compile_example(name, out):
    shutil.rmtree(out, ignore_errors=True)
    r = subprocess.run(TOOL + [os.path.join(EXAMPLES, name), "--out", out],
                       capture_output=True, text=True, env=TOOL_ENV)
    if r.returncode != 0:
        raise AssertionError(f"{name}: exit {r.returncode}\n{r.stdout}{r.stderr}")
    with open(os.path.join(out, "report.json")) as f:
        return json.load(f)


# ---------------------------------------------------------------------------
# A small model of the controller executing rom.hex on the boards' RAM
# images (fault-free, docs/controller.md "Execution"), for the end-to-end test.

class RamImage:
    def __init__(self, words):
        self.b = bytearray()
        for w in words:
            self.b += w.to_bytes(4, "little")

    def words(self):
        return [int.from_bytes(self.b[i:i + 4], "little") for i in range(0, len(self.b), 4)]

    def rd8(self, a):
        return self.b[a]

    def wr8(self, a, v):
        self.b[a] = v

    def rd32(self, a):
        return int.from_bytes(self.b[a:a + 4], "little")

    def wr32(self, a, v):
        self.b[a:a + 4] = v.to_bytes(4, "little")


class ControllerModel:
    def __init__(self, rom, rams, n_chan):
        self.hdr, self.entries = decode(rom)
        self.rams = rams
        self.n_chan = n_chan
        self.time = 0
        self.state = {}   # id -> dict
        self.cycles = 0

    def st(self, e):
        return self.state.setdefault(e["id"], {"rl": 1, "version": 0, "taken_at": 0, "value": None,
                                               "actual": [1] * 4, "delivered": [0] * 4})

    def export(self, st, k, board, base_word, words, taken_at):
        lay = ORACLE_LAYOUT
        ram = self.rams[board]
        base = 4 * base_word
        rl = ram.rd8(base + lay["off_readlocked"])
        bufs = range(lay["buffer1"], lay["buffer1"] + lay["buffers"])
        buf = [b for b in bufs if b != st["actual"][k] and b != rl][-1]
        stride = 4 * (len(words) + lay["taken_at_words"])
        addr = base + lay["off_buffers"] + (buf - lay["buffer1"]) * stride
        for i, w in enumerate(words):
            ram.wr32(addr + 4 * i, w)
        ram.wr32(addr + 4 * len(words), taken_at)
        ram.wr8(base + lay["off_actual"], buf)
        st["actual"][k] = buf

    def run_cycle(self):
        c0 = self.time
        for e in self.entries:
            self.time = c0 + e["start"]
            st = self.st(e)
            if e["kind"] == 1:                       # COPY: Import from the source
                lay = ORACLE_LAYOUT
                src = self.rams[e["src_board"]]
                base = 4 * e["src_word"]
                actual = src.rd8(base + lay["off_actual"])
                new = False
                while actual != st["rl"]:
                    st["rl"] = actual
                    src.wr8(base + lay["off_readlocked"], actual)
                    actual = src.rd8(base + lay["off_actual"])
                    new = True
                if new:
                    st["version"] += 1
                    st["taken_at"] = self.time
                    addr = base + lay["off_buffers"] + (st["rl"] - lay["buffer1"]) * 4 * e["w"]
                    st["value"] = [src.rd32(addr + 4 * i) for i in range(e["w"])]
                for k, (b, bw) in enumerate(e["dst"]):
                    if st["delivered"][k] != st["version"]:
                        self.export(st, k, b, bw, st["value"], st["taken_at"])
                        st["delivered"][k] = st["version"]
            elif e["kind"] == 2:                     # TIME
                for k, (b, bw) in enumerate(e["dst"]):
                    self.export(st, k, b, bw, [self.time], self.time)
            elif e["kind"] == 3:                     # STATUS: counters of a fault-free run
                words = [self.cycles & 0xFFFF] + [0] * (2 * self.n_chan)
                for k, (b, bw) in enumerate(e["dst"]):
                    self.export(st, k, b, bw, words, self.time)
        self.cycles += 1
        self.time = c0 + self.hdr["cycle"]


def harness_source(board, rep):
    """A host program for one board: load its RAM image, set up every
    channel (init or attach), run export/import commands, save the RAM."""
    insts = [i for b in rep["boards"] if b["name"] == board for i in b["instances"]]
    chans = {c["name"]: c for c in rep["channels"]}
    L = ['#include <stdio.h>', '#include <stdlib.h>', '#include <string.h>', f'#include "{board}.h"', "",
         "static uint32_t ram[ALB_%s_RAM_BYTES / 4u];" % board.upper(), "",
         "static void load(const char *path)", "{",
         "    FILE *f = fopen(path, \"r\");", "    unsigned long w;", "    size_t n = 0;",
         "    if (f == NULL) exit(3);",
         "    while (n < sizeof ram / sizeof ram[0] && fscanf(f, \"%8lx\", &w) == 1) ram[n++] = (uint32_t)w;",
         "    fclose(f);", "    if (n != sizeof ram / sizeof ram[0]) exit(4);", "}", "",
         "static void save(const char *path)", "{", "    FILE *f = fopen(path, \"w\");", "    size_t n;",
         "    if (f == NULL) exit(3);",
         "    for (n = 0; n < sizeof ram / sizeof ram[0]; ++n) fprintf(f, \"%08lx\\n\", (unsigned long)ram[n]);",
         "    fclose(f);", "}", "",
         "static void dump(const char *what, const void *p, size_t n, int r)", "{",
         "    const unsigned char *b = (const unsigned char *)p;", "    size_t i;",
         "    printf(\"%s %d \", what, r);", "    for (i = 0; i < n; ++i) printf(\"%02x\", b[i]);",
         "    printf(\"\\n\");", "}", "",
         "int main(int argc, char **argv)", "{", "    int i, rc;", "    if (argc < 4) return 2;",
         "    load(argv[1]);",
         f"    rc = strcmp(argv[3], \"init\") == 0 ? alb_{board}_init_all((uintptr_t)ram)"
         f" : alb_{board}_attach_all((uintptr_t)ram);",
         "    printf(\"setup %d\\n\", rc);",
         "    for (i = 4; i < argc; ++i) {", "        const char *op = argv[i];", "        (void)op;"]
    for inst in insts:
        c = chans[inst["channel"]]
        n = c["name"]
        if inst["role"] == "source":
            L += [f"        if (strncmp(op, \"export:{n}:\", {len(n) + 8}) == 0) {{",
                  f"            {c['type']} v;", "            unsigned char *b = (unsigned char *)&v;",
                  "            size_t k;", f"            int seed = atoi(op + {len(n) + 8});",
                  "            for (k = 0; k < sizeof v; ++k) b[k] = (unsigned char)(seed * 31 + (int)k);",
                  f"            rc = Make{n}Available(&v);", "            printf(\"export %d\\n\", rc);", "        }"]
        else:
            L += [f"        if (strcmp(op, \"import:{n}\") == 0) {{", f"            {n}_msg m;",
                  "            memset(&m, 0xEE, sizeof m);",
                  f"            rc = alb_import(&alb_ch_{n}, &m);",
                  f"            dump(\"import {n}\", &m.value, sizeof m.value, rc);",
                  "            printf(\"taken_at %lu\\n\", (unsigned long)m.taken_at);",
                  f"            printf(\"typed %d\\n\", (int)LookForNew{n}(&m));", "        }"]
    L += ["    }", "    save(argv[2]);", "    return 0;", "}"]
    return "\n".join(L) + "\n"


def pattern(seed, size):
    return bytes((seed * 31 + k) & 0xFF for k in range(size))


# ---------------------------------------------------------------------------

class ExampleTests(unittest.TestCase):
    """The two MOBOT-III examples: outputs, ROM, plan, layout, headers."""

    @classmethod
    def setUpClass(cls):
        cls.out = {}
        cls.rep = {}
        for name in EXAMPLE_FILES:
            out = os.path.join(OUT, name[:-5])
            cls.rep[name] = compile_example(name, out)
            cls.out[name] = out

    def each(self):
        for name in EXAMPLE_FILES:
            with self.subTest(example=name):
                yield name, self.out[name], self.rep[name]

    def test_outputs_exist(self):
        for name, out, rep in self.each():
            files = ["rom.hex", "report.json", "report.txt", "timeline.svg"]
            for b in rep["boards"]:
                files += [f"{b['name']}.h", f"{b['name']}.c", f"{b['name']}_ram.hex"]
            for f in files:
                self.assertTrue(os.path.getsize(os.path.join(out, f)) > 0, f)
            with open(os.path.join(out, "timeline.svg")) as f:
                svg = f.read()
            self.assertTrue(svg.startswith("<svg") and svg.rstrip().endswith("</svg>"))
            for c in rep["channels"]:
                self.assertIn(c["name"], svg)

    def test_rom_valid(self):
        for name, out, rep in self.each():
            words = read_hex(os.path.join(out, "rom.hex"))
            ram_words = [b["ram_bytes"] // 4 for b in rep["boards"]]
            self.assertEqual(rom_problems(words, rep["bus"]["n_chan"], ram_words), [])
            hdr, entries = decode(words)
            self.assertEqual(hdr["cycle"], rep["cycle"]["clocks"])
            self.assertEqual(hdr["ne"], rep["entries"])
            self.assertEqual(hdr["flags"], 1 if rep["mode"] == "position-synchronised" else 0)
            # the compiler's own verifier agrees
            self.assertEqual(S.verify_rom(words, rep["bus"]["n_chan"], len(rep["boards"]), ram_words)[0], [])

    def test_rom_matches_report(self):
        kinds = {"copy": 1, "time": 2, "status": 3}
        for name, out, rep in self.each():
            _, entries = decode(read_hex(os.path.join(out, "rom.hex")))
            by_id = {c["id"]: c for c in rep["channels"]}
            seen = {i: [] for i in by_id}
            for e in entries:
                c = by_id[e["id"]]
                seen[e["id"]].append((e["start"], e["length"]))
                self.assertEqual(e["kind"], kinds[c["kind"]])
                self.assertEqual(e["w"], c["words"])
                self.assertEqual(e["nd"], len(c["consumers"]))
                self.assertEqual(e["length"], c["slot_length"])
                if c["producer"]:
                    self.assertEqual((e["src_board"], 4 * e["src_word"]),
                                     (c["producer"]["board_index"], c["producer"]["base"]))
                self.assertEqual([(b, 4 * w) for b, w in e["dst"]],
                                 [(d["board_index"], d["base"]) for d in c["consumers"]])
            for i, c in by_id.items():
                self.assertEqual(seen[i], [(s["start"], s["length"]) for s in c["slots"]])

    def test_plan(self):
        for name, out, rep in self.each():
            self.assertEqual(plan_problems(rep), [])
            self.assertEqual(rep["cycle"]["clocks"], min(c["max_period"]["clocks"] for c in rep["channels"]))
            self.assertLessEqual(rep["entries"], 255)
            self.assertTrue(0 < rep["bus_utilisation"] <= rep["controller_busy"] <= rep["schedule_fill"] <= 1)
            # spare capacity is used: no channel's slot would still fit
            cap = rep["capacity_clocks"]
            used = sum(c["slot_length"] * c["redundancy"] for c in rep["channels"])
            self.assertLessEqual(used, cap)
            room = [c for c in rep["channels"] if used + c["slot_length"] <= cap and
                    c["name"] != "Status"]          # Status is capped by max_slots = 2
            self.assertEqual(room, [], "spare capacity left unused")
            if rep["mode"] == "position-synchronised":
                last = max(s["start"] + s["length"] for c in rep["channels"] for s in c["slots"])
                self.assertLessEqual(last + rep["bus"]["poll_cycles"], rep["cycle"]["clocks"])
                first = rep["entries_list"][0]
                self.assertTrue(first["sync"] and first["start"] == 0 and first["channel"] == "Position")

    def test_slot_lengths_and_bounds(self):
        """Recompute A, L, the latency and age bounds from the formulas of docs/compiler.md "Plan"."""
        for name, out, rep in self.each():
            bus = rep["bus"]
            budget = bus["retries_per_slot"] * (bus["timeout_cycles"] + bus["access_cycles"] + 1)
            cycle = rep["cycle"]["clocks"]
            for c in rep["channels"]:
                W, ND = c["words"], len(c["consumers"])
                A = (3 + W + ND * (W + 3)) if c["kind"] == "copy" else ND * (W + 3)
                self.assertEqual(c["accesses"], A, c["name"])
                pub = bus["fetch_cycles"] + bus["first_access_extra"] + bus["access_cycles"] * A
                self.assertEqual(c["slot_length"], pub + budget + bus["guard_cycles"], c["name"])
                starts = sorted(s["start"] for s in c["slots"])
                nxt = starts[1:] + [starts[0] + cycle]
                sample = bus["fetch_cycles"] + bus["access_cycles"]
                if c["kind"] == "copy":
                    ff = max(n + pub - (s + sample) for s, n in zip(starts, nxt))
                    self.assertEqual(c["latency"]["fault_free"]["clocks"], ff, c["name"])
                    self.assertEqual(c["latency"]["with_retries"]["clocks"], ff + budget, c["name"])
                    self.assertIsNone(c["age_bound"])
                else:
                    per = c["guaranteed_period"]["clocks"]
                    self.assertEqual(c["age_bound"]["fault_free"]["clocks"], per + pub)
                    self.assertEqual(c["age_bound"]["with_retries"]["clocks"], per + pub + budget)
                    self.assertIsNone(c["latency"])
                us = c["guaranteed_period"]["clocks"] * 1e6 / rep["clock_hz"]
                self.assertAlmostEqual(c["guaranteed_period"]["us"], us, places=3)

    def test_example_plan_is_spread(self):
        """Redundancy: every channel of mobot3 gets several slots, evenly:
        no gap of a channel is larger than twice its ideal C / n."""
        rep = self.rep["mobot3.toml"]
        cycle = rep["cycle"]["clocks"]
        for c in rep["channels"]:
            n = c["redundancy"]
            self.assertGreaterEqual(n, 2, c["name"])
            self.assertLessEqual(c["guaranteed_period"]["clocks"], 2 * cycle / n, c["name"])
        by = {c["name"]: c["redundancy"] for c in rep["channels"]}
        self.assertEqual(by["Status"], 2)                       # max_slots
        self.assertGreaterEqual(by["Position"], by["RadarMap"])  # priority

    def test_ram_layout_and_images(self):
        for name, out, rep in self.each():
            self.assertEqual(layout_problems(rep), [])
            for b in rep["boards"]:
                words = read_hex(os.path.join(out, f"{b['name']}_ram.hex"))
                self.assertEqual(len(words), b["ram_bytes"] // 4)
                ctl = {i["base"] // 4 for i in b["instances"]}
                for k, w in enumerate(words):
                    self.assertEqual(w, 0x00000101 if k in ctl else 0, f"{b['name']} word {k}")
            # every instance the ROM names is in a board's layout
            inst = {(b["index"], i["base"], i["channel"]) for b in rep["boards"] for i in b["instances"]}
            for c in rep["channels"]:
                if c["producer"]:
                    self.assertIn((c["producer"]["board_index"], c["producer"]["base"], c["name"]), inst)
                for d in c["consumers"]:
                    self.assertIn((d["board_index"], d["base"], c["name"]), inst)

    def test_headers(self):
        for name, out, rep in self.each():
            chans = {c["name"]: c for c in rep["channels"]}
            for b in rep["boards"]:
                with open(os.path.join(out, b["name"] + ".h")) as f:
                    h = f.read()
                self.assertIn('#include "albatross.h"', h)
                self.assertIn('#include "mobot3_types.h"', h)
                self.assertIn(f"int alb_{b['name']}_attach_all(uintptr_t dpram_base);", h)
                self.assertIn(f"int alb_{b['name']}_init_all(uintptr_t dpram_base);", h)
                macros = dict(re.findall(r"#define (ALB_\w+)\s+(\w+)", h))
                for i in b["instances"]:
                    c = chans[i["channel"]]
                    N = c["name"].upper()
                    self.assertEqual(int(macros[f"ALB_{N}_BASE"].rstrip("u"), 16), i["base"])
                    size = c["size"] if i["role"] == "source" else 4 * c["words"] + 4
                    self.assertEqual(int(macros[f"ALB_{N}_SIZE"].rstrip("u")), size)
                    self.assertEqual(i["bytes"], 4 + 3 * ((size + 3) & ~3))
                    self.assertEqual(int(macros[f"ALB_{N}_WORDS"].rstrip("u")), c["words"])
                    if i["role"] == "source":
                        self.assertIn(f"ALB_CHANNEL({c['name']}, {c['type']})", h)
                    else:
                        self.assertIn(f"typedef struct {{ {c['type']} value; uint32_t taken_at; }} "
                                      f"{c['name']}_msg;", h)
                        self.assertIn(f"ALB_CHANNEL({c['name']}, {c['name']}_msg)", h)
                for c in rep["channels"]:
                    self.assertEqual(int(macros[f"ALB_{c['name'].upper()}_ID"].rstrip("u")), c["id"])

    def test_deterministic(self):
        out2 = os.path.join(OUT, "mobot3-again")
        compile_example("mobot3.toml", out2)
        for f in sorted(os.listdir(out2)):
            with open(os.path.join(out2, f)) as a, open(os.path.join(self.out["mobot3.toml"], f)) as b:
                self.assertEqual(a.read(), b.read(), f)


@unittest.skipUnless(shutil.which("gcc"), "gcc not found: the generated C is not compiled (apt-get install gcc)")
class GeneratedCTests(unittest.TestCase):
    """gcc -std=c99 -Wall -Wextra -Werror -pedantic on every generated file,
    and an end-to-end run of the generated C with the real driver."""

    @classmethod
    def setUpClass(cls):
        cls.out = {}
        cls.rep = {}
        for name in EXAMPLE_FILES:
            out = os.path.join(OUT, "c-" + name[:-5])
            cls.rep[name] = compile_example(name, out)
            cls.out[name] = out

    def gcc(self, args):
        r = subprocess.run(["gcc"] + CFLAGS + CINC + args, capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, " ".join(args) + "\n" + r.stderr)

    def test_compile_board_files(self):
        for name in EXAMPLE_FILES:
            out, rep = self.out[name], self.rep[name]
            for b in rep["boards"]:
                with self.subTest(example=name, board=b["name"]):
                    self.gcc(["-I" + out, "-I" + EXAMPLES, "-c", os.path.join(out, b["name"] + ".c"),
                              "-o", os.path.join(out, b["name"] + ".o")])
                    # the header alone is a complete translation unit too
                    self.gcc(["-I" + out, "-I" + EXAMPLES, "-x", "c", "-c", os.path.join(out, b["name"] + ".h"),
                              "-o", os.path.join(out, b["name"] + "_h.o")])

    def test_static_assertion_catches_a_wrong_type(self):
        """Negative test of the generated check: a type of the wrong size
        must not compile."""
        out = self.out["mobot3.toml"]
        bad = os.path.join(out, "wrong_types")
        os.makedirs(bad, exist_ok=True)
        with open(os.path.join(EXAMPLES, "mobot3_types.h")) as f:
            text = f.read()
        with open(os.path.join(bad, "mobot3_types.h"), "w") as f:
            f.write(text.replace("int32_t heading_urad;", "int32_t heading_urad;\n    int32_t extra;"))
        r = subprocess.run(["gcc"] + CFLAGS + CINC + ["-I" + out, "-I" + bad, "-c",
                           os.path.join(out, "navigation.c"), "-o", os.path.join(bad, "nav.o")],
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0, "a 16-byte RobotPosition compiled against size = 12")
        self.assertIn("alb_check_Position_size", r.stderr)

    def build_harness(self, name, board):
        out, rep = self.out[name], self.rep[name]
        src = os.path.join(out, f"harness_{board}.c")
        with open(src, "w") as f:
            f.write(harness_source(board, rep))
        exe = os.path.join(out, f"harness_{board}")
        self.gcc(["-O1", "-I" + out, "-I" + EXAMPLES, src, os.path.join(out, board + ".c"),
                  os.path.join(REPO, "c-driver", "albatross.c"), "-o", exe])
        return exe

    def run_harness(self, exe, ram_in, ram_out, mode, *ops):
        r = subprocess.run([exe, ram_in, ram_out, mode] + list(ops), capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        return r.stdout.splitlines()

    def test_end_to_end(self):
        """Producers export through the generated interface into their RAM
        images; the controller model executes rom.hex; every consumer then
        imports exactly the exported bytes with the model's taken_at, once."""
        for name in EXAMPLE_FILES:
            with self.subTest(example=name):
                self.end_to_end(name)

    def end_to_end(self, name):
        out, rep = self.out[name], self.rep[name]
        boards = [b["name"] for b in rep["boards"]]
        exe = {b: self.build_harness(name, b) for b in boards}
        state = os.path.join(out, "e2e")
        os.makedirs(state, exist_ok=True)
        ram = {b: os.path.join(state, f"{b}.hex") for b in boards}
        chans = {c["name"]: c for c in rep["channels"]}
        seeds = {}
        # producers publish (RAM images loaded: attach)
        for bi, b in enumerate(boards):
            ops = []
            for i in rep["boards"][bi]["instances"]:
                if i["role"] == "source":
                    seeds[i["channel"]] = len(seeds) + 3
                    ops.append(f"export:{i['channel']}:{seeds[i['channel']]}")
            lines = self.run_harness(exe[b], os.path.join(out, f"{b}_ram.hex"), ram[b], "attach", *ops)
            self.assertEqual(lines[0], "setup 0")
            self.assertEqual(lines[1:], ["export 0"] * len(ops))
        # the controller runs two cycles
        model = ControllerModel(read_hex(os.path.join(out, "rom.hex")),
                                [RamImage(read_hex(ram[b])) for b in boards], rep["bus"]["n_chan"])
        model.run_cycle()
        taken = {i: st["taken_at"] for i, st in model.state.items()}
        model.run_cycle()
        for bi, b in enumerate(boards):
            with open(ram[b], "w") as f:
                f.write("".join(f"{w:08x}\n" for w in model.rams[bi].words()))
        # consumers read (attach: a restart with the controller running)
        for bi, b in enumerate(boards):
            ops = [f"import:{i['channel']}" for i in rep["boards"][bi]["instances"] if i["role"] == "destination"]
            lines = self.run_harness(exe[b], ram[b], ram[b] + ".after", "attach", *ops)
            self.assertEqual(lines[0], "setup 0")
            for k, op in enumerate(ops):
                c = chans[op.split(":")[1]]
                head, r, data = lines[1 + 3 * k].rsplit(" ", 2)
                taken_at = int(lines[2 + 3 * k].split()[1])
                self.assertEqual((head, r), (f"import {c['name']}", "1"), f"{b}: {c['name']} not New")
                self.assertEqual(lines[3 + 3 * k], "typed 0", f"{b}: {c['name']} New twice")
                value = bytes.fromhex(data)
                if c["kind"] == "copy":
                    self.assertEqual(value[:c["size"]], pattern(seeds[c["name"]], c["size"]), f"{b}: {c['name']}")
                    self.assertEqual(taken_at, taken[c["id"]], f"{b}: {c['name']} taken_at")
                elif c["kind"] == "time":
                    self.assertEqual(int.from_bytes(value, "little"), taken_at)
                    self.assertGreaterEqual(taken_at, rep["cycle"]["clocks"])   # second cycle
                else:
                    self.assertEqual(int.from_bytes(value[:4], "little") & 0xFFFF, 1)   # cycles
        # cold start on an all-zero RAM: init_all sets the CPU's own bytes
        zero = os.path.join(state, "zero.hex")
        for bi, b in enumerate(boards):
            with open(zero, "w") as f:
                f.write("00000000\n" * (rep["boards"][bi]["ram_bytes"] // 4))
            lines = self.run_harness(exe[b], zero, zero + ".out", "init")
            self.assertEqual(lines[0], "setup 0")
            words = read_hex(zero + ".out")
            for i in rep["boards"][bi]["instances"]:
                w = words[i["base"] // 4]
                self.assertEqual(w, 0x001 if i["role"] == "source" else 0x100, f"{b}: {i['channel']}")


class BadDescriptionTests(unittest.TestCase):
    """compiler/tests/bad/*.toml: exit status 2, the expected message, no
    traceback, nothing written."""

    def test_bad_descriptions(self):
        files = sorted(f for f in os.listdir(BAD) if f.endswith(".toml"))
        self.assertGreater(len(files), 40)
        for f in files:
            with self.subTest(file=f):
                path = os.path.join(BAD, f)
                with open(path) as fh:
                    first = fh.readline()
                m = re.match(r"# expect: (.+)$", first.rstrip("\n"))
                self.assertIsNotNone(m, f"{f}: the first line must be '# expect: <message>'")
                out = os.path.join(OUT, "bad", f[:-5])
                shutil.rmtree(out, ignore_errors=True)
                r = subprocess.run(TOOL + [path, "--out", out], capture_output=True, text=True,
                                   env=TOOL_ENV)
                self.assertEqual(r.returncode, 2, f"{f}: exit {r.returncode}\n{r.stdout}{r.stderr}")
                self.assertIn(m.group(1), r.stderr)
                self.assertNotIn("Traceback", r.stderr)
                self.assertTrue(r.stderr.startswith("error: " + path), r.stderr)
                self.assertFalse(os.path.exists(out), f"{f}: outputs written for a bad description")

    def test_missing_file(self):
        r = subprocess.run(TOOL + [os.path.join(BAD, "no-such.toml"), "--out",
                            os.path.join(OUT, "none")], capture_output=True, text=True, env=TOOL_ENV)
        self.assertEqual(r.returncode, 2)
        self.assertIn("cannot read the description", r.stderr)


class PackageTests(unittest.TestCase):
    """The compiler is a small package run with python3 -m albatross_schedule."""

    def test_modules_are_small(self):
        pkg = os.path.join(COMPILER_DIR, "albatross_schedule")
        for f in sorted(os.listdir(pkg)):
            if f.endswith(".py"):
                with open(os.path.join(pkg, f)) as fh:
                    n = sum(1 for _ in fh)
                self.assertLessEqual(n, 500, f"albatross_schedule/{f} has {n} lines (at most about 500)")

    def test_command_line(self):
        r = subprocess.run(TOOL + ["--help"], capture_output=True, text=True, env=TOOL_ENV)
        self.assertEqual(r.returncode, 0, r.stderr)
        for flag in ("--out", "--quiet", "--no-redundancy", "description"):
            self.assertIn(flag, r.stdout)
        r = subprocess.run(TOOL, capture_output=True, text=True, env=TOOL_ENV)
        self.assertEqual(r.returncode, 2)
        self.assertIn("usage: albatross_schedule", r.stderr)


def description(channels, boards=("a", "b", "c"), extra_system="", bus=""):
    text = (f'[system]\nname = "gen"\nclock_hz = 50_000_000\nboards = {json.dumps(list(boards))}\n'
            f'{extra_system}\n{bus}\n')
    for c in channels:
        text += "\n[[channel]]\n" + "".join(f"{k} = {json.dumps(v)}\n" for k, v in c.items())
    return text


class PlanTests(unittest.TestCase):
    """The planner through the Python API on generated descriptions."""

    def compile_text(self, text, name="gen.toml"):
        os.makedirs(OUT, exist_ok=True)
        path = os.path.join(OUT, name)
        with open(path, "w") as f:
            f.write(text)
        system = S.load_description(path)
        plan, rom, rep = S.compile_system(system)
        return system, plan, rom, rep

    def test_entry_cap(self):
        """Huge spare capacity: redundancy stops at 255 entries, ROM valid."""
        chans = [{"name": f"C{i}", "size": 4, "producer": "a", "consumers": ["b"], "max_period_us": 1000}
                 for i in range(3)]
        system, plan, rom, rep = self.compile_text(description(chans))
        self.assertEqual(len(plan.slots), 255)
        self.assertEqual(rom_problems(rom, 16, [1024] * 3), [])
        self.assertEqual(plan_problems(rep), [])
        self.assertEqual(sorted(c["redundancy"] for c in rep["channels"]), [85, 85, 85])

    def test_too_many_entries(self):
        chans = [{"name": f"C{i}", "size": 4, "producer": "a", "consumers": ["b"], "max_period_us": 10000}
                 for i in range(256)]
        with self.assertRaises(S.ScheduleError) as cm:
            self.compile_text(description(chans, bus="[bus]\nn_chan = 256\n"))
        self.assertIn("256 channels need 256 ROM entries, at most 255", str(cm.exception))

    def test_exactly_full(self):
        """A plan that needs the whole cycle: one slot each, back to back."""
        bus = S.Bus()
        ch = {"name": "X", "size": 8, "producer": "a", "consumers": ["b"], "max_period_us": 1}
        # W = 2, ND = 1: A = 3 + 2 + 5 = 10
        L = bus.fetch_cycles + bus.first_access_extra + 2 * 10 + bus.retry_budget + bus.guard_cycles
        text = description([ch]).replace("50_000_000", str(L * 1_000_000))
        system, plan, rom, rep = self.compile_text(text)
        self.assertEqual([(s.start, s.length) for s in plan.slots], [(0, L)])
        text = description([ch]).replace("50_000_000", str((L - 1) * 1_000_000))
        with self.assertRaises(S.ScheduleError) as cm:
            self.compile_text(text)
        self.assertIn(f"needs {L} clocks per cycle but only {L - 1} are available", str(cm.exception))

    def test_priority_and_max_slots(self):
        chans = [{"name": "Low", "size": 64, "producer": "a", "consumers": ["b"], "max_period_us": 20},
                 {"name": "High", "size": 64, "producer": "a", "consumers": ["b"], "max_period_us": 20,
                  "priority": 5},
                 {"name": "Capped", "size": 4, "producer": "b", "consumers": ["c"], "max_period_us": 20,
                  "max_slots": 1}]
        system, plan, rom, rep = self.compile_text(description(chans))
        n = {c["name"]: c["redundancy"] for c in rep["channels"]}
        self.assertEqual(n["Capped"], 1)
        self.assertGreaterEqual(n["High"], n["Low"])
        self.assertEqual(plan_problems(rep), [])

    def test_sync_plan(self):
        chans = [{"name": "Map", "size": 40, "producer": "a", "consumers": ["b", "c"], "max_period_us": 40},
                 {"name": "Pos", "size": 12, "producer": "b", "consumers": ["a", "c"], "max_period_us": 20,
                  "sync": True},
                 {"name": "T", "kind": "time", "consumers": "all", "max_period_us": 20}]
        system, plan, rom, rep = self.compile_text(description(chans, extra_system='mode = "position-synchronised"'))
        self.assertEqual(rom_problems(rom, 16, [1024] * 3), [])
        self.assertTrue(plan.slots[0].sync and plan.slots[0].start == 0 and plan.slots[0].channel.name == "Pos")
        self.assertEqual(sum(s.sync for s in plan.slots), 1)
        self.assertEqual(rom[0] & 1, 1)
        self.assertLessEqual(plan.slots[-1].start + plan.slots[-1].length + system.bus.poll_cycles, plan.cycle)

    def test_types_and_layout(self):
        chans = [{"name": "Odd", "size": 5, "producer": "a", "consumers": ["b", "c"], "max_period_us": 100},
                 {"name": "St", "kind": "status", "consumers": ["a"], "max_period_us": 100}]
        system, plan, rom, rep = self.compile_text(description(chans, bus="[bus]\nn_chan = 4\n"))
        odd, st = rep["channels"]
        self.assertEqual((odd["words"], odd["type"]), (2, "Odd_t"))
        self.assertEqual((st["words"], st["size"]), (9, 36))
        self.assertEqual(layout_problems(rep), [])
        self.assertEqual(rom_problems(rom, 4, [1024] * 3), [])
        b = {x["name"]: x for x in rep["boards"]}
        # a: Odd source (4 + 3*8 = 28 bytes) then St destination (4 + 3*40)
        self.assertEqual([(i["base"], i["bytes"]) for i in b["a"]["instances"]], [(0, 28), (28, 124)])


class CheckerNegativeTests(unittest.TestCase):
    """The test's own checkers must report deliberately broken ROMs and plans."""

    @classmethod
    def setUpClass(cls):
        cls.rep = compile_example("mobot3.toml", os.path.join(OUT, "neg-mobot3"))
        cls.rom = read_hex(os.path.join(OUT, "neg-mobot3", "rom.hex"))
        cls.ram_words = [b["ram_bytes"] // 4 for b in cls.rep["boards"]]

    def problems(self, rom):
        return rom_problems(rom, 16, self.ram_words)

    def reseal(self, rom, k):
        rom[3] = crc(rom)

    def test_flipped_bit_fails_crc(self):
        for word in (1, 4 + 8 * 3 + 1, 4 + 8 * 7 + 4):
            rom = list(self.rom)
            rom[word] ^= 1 << 9
            self.assertTrue(self.problems(rom), f"bit flip in word {word} not caught")
            self.assertTrue(S.verify_rom(rom, 16, 4, self.ram_words)[0])

    def test_overlapping_slot(self):
        rom = list(self.rom)
        rom[4 + 8 * 5 + 1] = rom[4 + 8 * 4 + 1]   # entry 5 starts where entry 4 starts
        self.reseal(rom, 5)
        self.assertIn("entry 5: overlaps or precedes the previous slot", self.problems(rom))
        self.assertTrue(any("before the previous slot" in p for p in S.verify_rom(rom, 16, 4, self.ram_words)[0]))

    def test_slot_after_cycle(self):
        rom = list(self.rom)
        k = self.rep["entries"] - 1
        rom[4 + 8 * k + 2] += 100
        self.reseal(rom, k)
        self.assertIn(f"entry {k}: ends after the cycle", self.problems(rom))

    def test_extent_outside_ram(self):
        rom = list(self.rom)
        rom[4 + 4] = (rom[4 + 4] & 0xFFFF0000) | (2 << 12) | 1020     # destination 0 near the top
        self.reseal(rom, 0)
        self.assertTrue(any("outside the RAM" in p for p in self.problems(rom)))

    def test_period_and_layout_violations(self):
        rep = json.loads(json.dumps(self.rep))
        rep["channels"][1]["slots"] = rep["channels"][1]["slots"][:1]
        self.assertTrue(plan_problems(rep))
        rep = json.loads(json.dumps(self.rep))
        rep["channels"][0]["slots"] = []
        self.assertIn("RadarMap: no slot", plan_problems(rep))
        rep = json.loads(json.dumps(self.rep))
        rep["boards"][2]["instances"][1]["base"] -= 4
        self.assertTrue(any("overlaps" in p for p in layout_problems(rep)))
        self.assertTrue(S.verify_ram_layout([("a", 0, 40), ("b", 36, 8)], 4096))

    def test_model_detects_a_wrong_destination(self):
        """The end-to-end path depends on the ROM: a destination moved by one
        word (CRC resealed) gives the consumer no new value."""
        rom = list(self.rom)
        ch = next(c for c in self.rep["channels"] if c["name"] == "MotorCmd")
        k = ch["slots"][0]["entry"]
        rams = [RamImage([0x101 if w == 0 else 0 for w in range(1024)]) for _ in range(4)]
        src = RamImage([0] * 1024)
        base = ch["producer"]["base"]
        src.wr8(base, 2)                      # a published value in Buffer2
        src.wr8(base + 1, 1)
        rams[ch["producer"]["board_index"]] = src
        rom[4 + 8 * k + 4] += 1               # destination base word + 1
        self.reseal(rom, k)
        model = ControllerModel(rom, rams, 16)
        model.entries = [model.entries[k]]
        model.run_cycle()
        d = ch["consumers"][0]
        self.assertEqual(rams[d["board_index"]].rd8(d["base"]), 1, "value landed at the right place anyway")


if __name__ == "__main__":
    unittest.main()
