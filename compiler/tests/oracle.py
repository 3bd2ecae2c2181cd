"""The compiler tests' shared pieces (compiler/tests/test_schedule.py, test_contract.py):
the paths and command line of the build, the independent oracles of the ROM contract
(ROM format, CRC, validation rules, memory map; written without the compiler's
contract module and checked against rtl/albatross_contract.toml by test_contract.py),
and a small model of the controller executing rom.hex on the boards' RAM images.
No tests here: unittest discovers test*.py only.
"""

import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
COMPILER_DIR = os.path.dirname(HERE)
REPO = os.path.dirname(COMPILER_DIR)
# The command line, as the build runs it: the albatross-schedule command that
# make deps installs (pip install -e ./compiler) beside this Python (build/venv/bin).
TOOL = [os.path.join(os.path.dirname(sys.executable), "albatross-schedule")]
TOOL_ENV = dict(os.environ)
if not os.path.exists(TOOL[0]):
    sys.exit(f"{TOOL[0]} not found: run the tests with the project's Python (build/venv/bin/python) "
             "after make deps, which installs the compiler there")
EXAMPLES = os.path.join(REPO, "sim")  # the MOBOT-III robot's descriptions
BAD = os.path.join(HERE, "bad")
OUT = os.path.join(REPO, "build", "compiler-tests")
CFLAGS = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
CINC = ["-I" + os.path.join(REPO, "c-driver"), "-I" + os.path.join(REPO, "c-driver", "port", "mmio")]

import albatross_schedule as S  # noqa: E402  (installed by make deps)

EXAMPLE_FILES = ["mobot3.toml", "mobot3_possync.toml"]


# ---------------------------------------------------------------------------
# Independent checkers of the ROM contract (docs/controller.md).  They are deliberate oracles,
# written without the compiler's contract module; compiler/tests/test_contract.py
# checks their field positions and constants against rtl/albatross_contract.toml.

# The channel layout the controller model below assumes (byte offsets from the
# channel base; buffer index values; words after a destination value).
ORACLE_LAYOUT = {"off_actual": 0, "off_readlocked": 1, "off_buffers": 4, "buffer1": 1, "buffers": 3,
                 "taken_at_words": 1}
# The four-slot kind: E0 flag bit 1, a fourth buffer, the producer's
# slot bytes Slot0/Slot1 at offsets 2 and 3 (both 0 at the start).  Buffer b is
# pair (b-1)>>1, slot (b-1)&1; buf(p, s) = 1 + 2p + s.
ORACLE_FOUR_SLOT = {"flag": 2, "buffers": 4, "off_slot": (2, 3), "initial_slot": 0}


def crc(words, seed=0xFFFFFFFF):
    """CRC of ROM words, H3 (word 3) included: polynomial division over GF(2)
    by P = x^32 + x^7 + x^5 + x^3 + x^2 + x + 1, written as the remainder of
    the image's polynomial (the seed prepended).  A valid image's CRC is 0."""
    p = (1 << 32) | 0xAF
    r = seed
    for w in words:
        r = (r << 32) | w
        for b in range(63, 31, -1):          # reduce the degree below 32
            if r >> b & 1:
                r ^= p << (b - 32)
    return r


def check_word(words):
    """The H3 (word 3) that makes the image's CRC 0.  The remainder is linear
    in H3: solve M h = c0 over GF(2) by elimination, where c0 is the CRC with
    H3 = 0 and column j of M the remainder of H3 = 2^j alone (seed 0)."""
    ws = list(words)
    ws[3] = 0
    c0 = crc(ws)
    n = len(ws)
    cols = [crc([0, 0, 0, 1 << j] + [0] * (n - 4), seed=0) for j in range(32)]
    # rows: equation i is bit i of sum_j h_j cols[j] = bit i of c0
    rows = [(sum(((cols[j] >> i) & 1) << j for j in range(32)), (c0 >> i) & 1) for i in range(32)]
    h, piv = 0, []
    for j in range(32):
        k = next(k for k in range(len(piv), 32) if rows[k][0] >> j & 1)
        rows[len(piv)], rows[k] = rows[k], rows[len(piv)]
        for k2 in range(32):
            if k2 != len(piv) and rows[k2][0] >> j & 1:
                rows[k2] = (rows[k2][0] ^ rows[len(piv)][0], rows[k2][1] ^ rows[len(piv)][1])
        piv.append(j)
    for i, j in enumerate(piv):
        h |= rows[i][1] << j
    return h


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
            "base": e[6] & 0x7FFF, "rep": (e[6] >> 16) & 0xF, "e6_high": e[6] & ~0xF7FFF,
            "frag": e[7] & 0xFFF, "e7_high": e[7] >> 12,
            "src_board": (e[3] >> 12) & 0xF, "src_word": e[3] & 0xFFF,
            "dst": [((d >> 12) & 0xF, d & 0xFFF) for d in dst[:nd]], "unused_dst": dst[nd:]})
    return {"magic": h0 >> 16, "ne": ne, "flags": h0 & 0xFF, "cycle": words[1] & 0xFFFF,
            "cycle_high": words[1] >> 16, "drop_run": words[2] & 0xFF, "cluster": (words[2] >> 20) & 0xF,
            "h2_high": (words[2] >> 8) & ~0xF000}, entries


def rom_problems(words, n_chan, ram_words):
    """Every violation of the ROM format (docs/controller.md) and validation rules."""
    p = []
    if len(words) < 4:
        return ["shorter than the header"]
    hdr, entries = decode(words)
    if hdr["magic"] != 0xA1BA:
        p.append("bad magic")
    if crc(words) != 0:
        p.append("ROM CRC")
    if hdr["cycle_high"]:
        p.append("H1 above 16 bits")
    if hdr["h2_high"]:
        p.append("H2 above its 8-bit drop run (the cluster aside)")
    if hdr["drop_run"] < 2:
        p.append("H2 drop run below 2")
    if not 1 <= hdr["ne"] <= 255:
        p.append("entry count")
    if len(words) != 4 + 8 * hdr["ne"]:
        p.append("length does not match the entry count")
    sync = hdr["flags"] & 1
    for k, e in enumerate(entries):
        if e["time_high"]:
            p.append(f"entry {k}: time above 16 bits")
        if e["e7_high"]:
            p.append(f"entry {k}: E7 above its 12-bit fragment size")
        if e["frag"] and (e["kind"] != 1 or e["nd"] == 0):
            p.append(f"entry {k}: a fragment size on other than a COPY to destinations")
        if e["kind"] not in (1, 2, 3):
            p.append(f"entry {k}: kind {e['kind']}")
        if not 1 <= e["nd"] <= 4:
            p.append(f"entry {k}: ND")
        if e["id"] >= n_chan:
            p.append(f"entry {k}: channel id")
        if any(e["unused_dst"]):
            p.append(f"entry {k}: unused destination field not 0")
        if e["e6_high"]:
            p.append(f"entry {k}: E6 bits outside base and rep")
        if e["rep"] > hdr["cluster"]:
            p.append(f"entry {k}: repetition above the cluster")
        if e["base"] >= 1 << e["rep"]:
            p.append(f"entry {k}: base not below the repetition")
        if e["kind"] == 2 and e["w"] != 1:
            p.append(f"entry {k}: TIME W")
        if e["kind"] == 3 and e["w"] != 1 + 2 * n_chan:
            p.append(f"entry {k}: STATUS W")
        if e["kind"] != 1 and e["raw"][3] != 0:
            p.append(f"entry {k}: source on a non-COPY")
        exts = [(b, w, e["w"] + 1) for b, w in e["dst"]]
        if e["kind"] == 1:
            exts.append((e["src_board"], e["src_word"], e["w"]))
        four = e["flags"] & ORACLE_FOUR_SLOT["flag"]
        if four and e["kind"] not in (1, 2, 3):
            p.append(f"entry {k}: FOUR_SLOT flag on an entry that is not COPY, TIME or STATUS")
        if e["flags"] & ~(1 | ORACLE_FOUR_SLOT["flag"]):
            p.append(f"entry {k}: reserved flag bits")
        nbuf = ORACLE_FOUR_SLOT["buffers"] if four else 3
        for b, base, stride in exts:
            if b >= len(ram_words):
                p.append(f"entry {k}: board {b} does not exist")
            elif base + 1 + nbuf * stride > ram_words[b]:
                p.append(f"entry {k}: extent outside the RAM")
        if e["flags"] & 1 and not (k == 0 and sync):
            p.append(f"entry {k}: SYNC flag misplaced")
        if sync and k == 0 and not (e["flags"] & 1 and e["kind"] == 1 and e["start"] == 0):
            p.append("entry 0 of a sync ROM is not a SYNC COPY at 0")
        if e["start"] + e["length"] > hdr["cycle"]:
            p.append(f"entry {k}: ends after the cycle")
    # The slot order, in every minor cycle n (brute force over n below 2^(the
    # largest repetition), which decides every entry's due set): each entry due
    # in n starts at or after the end of every earlier entry due in n.
    late = {}
    for n in range(1 << max([x["rep"] for x in entries] + [0])):
        prev_end = 0
        for k, x in enumerate(entries):
            if n % (1 << x["rep"]) != x["base"]:
                continue
            if x["start"] < prev_end:
                late.setdefault(k, n)   # (the first such n)
            prev_end = max(prev_end, x["start"] + x["length"])
    p += [f"entry {k}: overlaps or precedes the previous slot" for k in sorted(late)]
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
                                               "actual": [1] * 4, "delivered": [0] * 4,
                                               "last": 0})     # four-slot: the buffer read last (0: none)

    @staticmethod
    def fs_buf(pair, slot):
        return 1 + 2 * pair + slot

    def import_four_slot(self, st, ram, base, w):
        """The four-slot consumer's Import (the mapping, with the rule
        test_four_slot_mapping.py shows it needs: reading the buffer read last is
        Old): 1 + W accesses when Actual is the buffer read last, else 3 + W."""
        lay, fs = ORACLE_LAYOUT, ORACLE_FOUR_SLOT
        a = ram.rd8(base + lay["off_actual"])
        if a == st["last"]:
            return False
        ram.wr8(base + lay["off_readlocked"], a)                  # announces pair(a)
        pair = (a - 1) >> 1
        slot = ram.rd8(base + fs["off_slot"][pair])                # the control word loaded again
        b = self.fs_buf(pair, slot)
        if b == st["last"]:
            return False                                           # the same buffer: nothing new
        addr = base + lay["off_buffers"] + (b - 1) * 4 * w
        st["value"] = [ram.rd32(addr + 4 * i) for i in range(w)]
        st["last"] = b
        return True

    def export_four_slot(self, board, base_word, words, taken_at):
        """The four-slot producer's Export into a destination: the pair not
        announced by ReadLocked, the slot of that pair not completed last."""
        lay, fs = ORACLE_LAYOUT, ORACLE_FOUR_SLOT
        ram = self.rams[board]
        base = 4 * base_word
        r = ram.rd8(base + lay["off_readlocked"])
        pair = 1 - ((r - 1) >> 1)
        slot = 1 - ram.rd8(base + fs["off_slot"][pair])
        b = self.fs_buf(pair, slot)
        stride = 4 * (len(words) + lay["taken_at_words"])
        addr = base + lay["off_buffers"] + (b - 1) * stride
        for i, w in enumerate(words):
            ram.wr32(addr + 4 * i, w)
        ram.wr32(addr + 4 * len(words), taken_at)
        ram.wr8(base + fs["off_slot"][pair], slot)
        ram.wr8(base + lay["off_actual"], b)

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
            if e["kind"] == 1 and e["flags"] & ORACLE_FOUR_SLOT["flag"]:     # COPY, four-slot
                src = self.rams[e["src_board"]]
                if self.import_four_slot(st, src, 4 * e["src_word"], e["w"]):
                    st["version"] += 1
                    st["taken_at"] = self.time
                for k, (b, bw) in enumerate(e["dst"]):
                    if st["delivered"][k] != st["version"]:
                        self.export_four_slot(b, bw, st["value"], st["taken_at"])
                        st["delivered"][k] = st["version"]
            elif e["kind"] == 1:                     # COPY: Import from the source
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
            elif e["kind"] in (2, 3):                # TIME, STATUS (counters of a fault-free run)
                words = [self.time] if e["kind"] == 2 else [self.cycles & 0xFFFF] + [0] * (2 * self.n_chan)
                for k, (b, bw) in enumerate(e["dst"]):
                    if e["flags"] & ORACLE_FOUR_SLOT["flag"]:
                        self.export_four_slot(b, bw, words, self.time)
                    else:
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
