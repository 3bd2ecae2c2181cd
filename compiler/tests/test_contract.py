"""The deliberate independent oracles against the one definition of the
contract (rtl/albatross_contract.toml), and the definition's own checks.

    python3 -m unittest -v compiler/tests/test_contract.py      (from the repository root)

compiler/tests/oracle.py decodes ROMs and models the controller
without the compiler's contract module, on purpose.  Here every field of its
decoder is located by probing it bit by bit and compared with the
definition, its ROM CRC, magic, kind codes and entry addressing are checked
by behaviour, and its layout constants by value, so a definition changed
without the oracle (or an oracle changed without the definition) fails.
ALB_CONTRACT=FILE checks the oracles against another definition (the
negative test in tools/mk/contract.mk).  The controller smoke test's layout
assumptions are static_asserts against the generated C++ header instead."""

import os
import random
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
COMPILER_DIR = os.path.dirname(HERE)
sys.path.insert(0, HERE)

from albatross_schedule import contract  # noqa: E402
from albatross_schedule.contract_gen import render_markdown  # noqa: E402
import oracle as O  # noqa: E402  (the oracles)

C = contract.load()
SCALARS = {   # oracle decode key -> (word, field) of the definition
    "kind": ("E0", "kind"), "flags": ("E0", "flags"), "id": ("E0", "id"), "nd": ("E0", "nd"),
    "w": ("E0", "w"), "start": ("E1", "start"), "length": ("E2", "length"),
    "base": ("E6", "base"), "rep": ("E6", "rep"), "frag": ("E7", "frag")}


def mask_of(fields):
    """{word index: bit mask} of definition fields."""
    m = {}
    for f in fields:
        m[f.index] = m.get(f.index, 0) | f.mask
    return m


def header(ne=1):
    words = [0] * C.header_words
    words[C.field("H0", "ne").index] |= C.field("H0", "ne").put(ne)
    return words


class RomDecoderOracle(unittest.TestCase):
    """oracle.decode and rom_problems against the definition."""

    def probe(self, base_entry, getters, skip_words=()):
        """For each oracle value: the bits of the entry that change it."""
        found = {k: {} for k in getters}
        rom = header() + list(base_entry)
        ref = O.decode(rom)[1][0]
        for j in range(C.entry_words):
            if j in skip_words:
                continue
            for b in range(32):
                r = list(rom)
                r[C.header_words + j] ^= 1 << b
                e = O.decode(r)[1][0]
                for k, get in getters.items():
                    if get(e) != get(ref):
                        found[k][j] = found[k].get(j, 0) | (1 << b)
        return found

    def test_header_fields(self):
        keys = {"magic": ("H0", "magic"), "ne": ("H0", "ne"), "flags": ("H0", "flags"), "cycle": ("H1", "cycle"),
                "drop_run": ("H2", "drop_run"), "cluster": ("H2", "cluster")}
        for key, (w, f) in keys.items():
            fld = C.field(w, f)
            got = {}
            for i in range(C.header_words):
                for b in range(32):
                    words = [0] * C.header_words
                    words[i] = 1 << b
                    if O.decode(words)[0][key] != 0:
                        got[i] = got.get(i, 0) | (1 << b)
            with self.subTest(field=f"{w}.{f}"):
                self.assertEqual(got, {fld.index: fld.mask},
                                 f"the oracle decodes {key} from other bits than {w}.{f} {fld.bits}")

    def test_entry_fields(self):
        getters = {k: (lambda e, k=k: e[k]) for k in SCALARS}
        getters["src_board"] = lambda e: e["src_board"]
        getters["src_word"] = lambda e: e["src_word"]
        found = self.probe([0] * C.entry_words, getters)
        board, base = C.place_fields(C.src_field)
        expect = {k: mask_of([C.field(*wf)]) for k, wf in SCALARS.items()}
        expect["src_board"], expect["src_word"] = mask_of([board]), mask_of([base])
        for k in getters:
            with self.subTest(field=k):
                self.assertEqual(found[k], expect[k], f"the oracle's {k} sits elsewhere than in the definition")

    def test_destination_places(self):
        nd = C.field("E0", "nd")
        base_entry = [0] * C.entry_words
        base_entry[nd.index] |= nd.put(C.max_dests)
        getters = {}
        for i in range(C.max_dests):
            getters[f"dst{i}_board"] = lambda e, i=i: e["dst"][i][0]
            getters[f"dst{i}_base"] = lambda e, i=i: e["dst"][i][1]
        found = self.probe(base_entry, getters, skip_words=(nd.index,))
        for i, f in enumerate(C.dest_fields):
            board, base = C.place_fields(f)
            for k, sub in ((f"dst{i}_board", board), (f"dst{i}_base", base)):
                with self.subTest(field=k):
                    self.assertEqual(found[k], mask_of([sub]), f"the oracle's {k} sits elsewhere than {f.word}")

    def test_crc(self):
        rng = random.Random(1)
        self.assertEqual(O.crc([]), C.crc_seed, "CRC seed")
        self.assertEqual(C.crc_index, 3, "the oracle's check word is H3 (word 3)")
        for n in (1, 3, 4, 12, 20):
            words = [rng.getrandbits(32) for _ in range(n)]
            self.assertEqual(O.crc(words), C.crc(words), f"CRC of {n} words")
        for n in (4, 12, 20, 2044):
            words = [rng.getrandbits(32) for _ in range(n)]
            h = C.check_word(words)
            self.assertEqual(h, O.check_word(words), f"check word of {n} words")
            words[3] = h
            self.assertEqual(C.crc(words), 0, f"CRC of {n} words with their check word")
            words[rng.randrange(n)] ^= 1 << rng.randrange(32)
            self.assertNotEqual(C.crc(words), 0, f"CRC of {n} words with one bit flipped")

    def valid_rom(self, kind="copy", w=1, cluster=0, entries=({},)):
        """A ROM built from the definition alone: one entry of the kind per
        item of entries, whose {(word, field): value} items override it."""
        hdr = header(len(entries))
        hdr[C.field("H0", "magic").index] |= C.field("H0", "magic").put(C.magic)
        hdr[C.field("H1", "cycle").index] |= C.field("H1", "cycle").put(1000)
        hdr[C.field("H2", "drop_run").index] |= C.field("H2", "drop_run").put(2)
        hdr[C.field("H2", "cluster").index] |= C.field("H2", "cluster").put(cluster)
        rom = hdr
        for over in entries:
            e = [0] * C.entry_words
            vals = {("E0", "kind"): C.kind[kind], ("E0", "id"): 0, ("E0", "nd"): 1, ("E0", "w"): w,
                    ("E1", "start"): 0, ("E2", "length"): 100}
            vals.update(over)
            for (wd, fd), v in vals.items():
                e[C.field(wd, fd).index] |= C.field(wd, fd).put(v)
            dst = C.dest_fields[0]
            e[dst.index] |= dst.put(C.place(1, 64))
            if kind == "copy":
                e[C.src_field.index] |= C.src_field.put(C.place(0, 16))
            rom += e
        rom[C.crc_index] = C.check_word(rom)
        return rom

    def test_multirate_rules(self):
        """Due sets, the fragment size and the slot order per minor cycle: the
        oracle and verify_rom agree on ROMs built from the definition alone."""
        from albatross_schedule.rom import verify_rom
        rb = lambda rep, base, start=0, **kw: {("E6", "rep"): rep, ("E6", "base"): base, ("E1", "start"): start, **kw}
        cases = [   # (name, ROM, the oracle's problem or None, verify_rom's or None)
            ("every cycle", self.valid_rom(), None, None),
            ("rep 2 bases 0..3 in one window", self.valid_rom(cluster=2, entries=[rb(2, b) for b in range(4)]),
             None, None),
            ("rep 1 base 1 beside rep 2 base 0 at one start", self.valid_rom(cluster=3, entries=[rb(2, 0), rb(1, 1)]),
             None, None),
            ("rep 1 base 0 beside rep 2 base 2 at one start", self.valid_rom(cluster=3, entries=[rb(1, 0), rb(2, 2)]),
             "entry 1: overlaps or precedes the previous slot", "before the previous slot"),
            ("every cycle beside rep 3 at one start", self.valid_rom(cluster=3, entries=[rb(3, 5), rb(0, 0)]),
             "entry 1: overlaps or precedes the previous slot", "before the previous slot"),
            ("rep above the cluster", self.valid_rom(cluster=1, entries=[rb(2, 0)]),
             "entry 0: repetition above the cluster", "repetition 2^2 above the cluster"),
            ("base not below 2^rep", self.valid_rom(cluster=3, entries=[rb(1, 2)]),
             "entry 0: base not below the repetition", "base 2 not below"),
            ("fragments on a COPY", self.valid_rom(w=8, entries=[{("E7", "frag"): 3}]), None, None),
            ("fragments on a TIME", self.valid_rom("time", 1, entries=[{("E7", "frag"): 1}]),
             "entry 0: a fragment size on other than a COPY to destinations", "fragment size on a time entry"),
        ]
        for name, rom, want_o, want_v in cases:
            with self.subTest(case=name):
                got_o = O.rom_problems(rom, 16, [1024] * 2)
                got_v = verify_rom(rom, n_chan=16, n_boards=2, ram_words=1024)[0]
                if want_o is None:
                    self.assertEqual(got_o, [], f"the oracle rejects a valid ROM ({name})")
                else:
                    self.assertIn(want_o, got_o, f"the oracle misses the fault ({name})")
                if want_v is None:
                    self.assertEqual(got_v, [], f"verify_rom rejects a valid ROM ({name})")
                else:
                    self.assertTrue(any(want_v in x for x in got_v),
                                    f"verify_rom misses the fault ({name}): expected '{want_v}', came {got_v}")

    def test_magic_kinds_and_addressing(self):
        self.assertEqual(O.rom_problems(self.valid_rom(), 16, [1024] * 2), [],
                         "the oracle rejects a ROM built from the definition (magic, CRC, positions)")
        self.assertEqual(O.rom_problems(self.valid_rom("time", 1), 16, [1024] * 2), [])
        self.assertEqual(O.rom_problems(self.valid_rom("status", 33), 16, [1024] * 2), [])
        self.assertIn("entry 0: TIME W", O.rom_problems(self.valid_rom("time", 2), 16, [1024] * 2))
        self.assertIn("entry 0: STATUS W", O.rom_problems(self.valid_rom("status", 2), 16, [1024] * 2))
        self.assertIn(f"entry 0: kind {C.kind['idle']}", O.rom_problems(self.valid_rom("idle"), 16, [1024] * 2))
        # entry k at header_words + entry_words * k
        rom = self.valid_rom() + self.valid_rom()[C.header_words:]
        rom[C.field("H0", "ne").index] = (rom[0] & ~C.field("H0", "ne").mask) | C.field("H0", "ne").put(2)
        start = C.field("E1", "start")
        rom[C.entry_address(1) + start.index] |= start.put(123)
        self.assertEqual([e["start"] for e in O.decode(rom)[1]], [0, 123])


class LayoutOracle(unittest.TestCase):
    def test_controller_model_layout(self):
        lay = O.ORACLE_LAYOUT
        self.assertEqual(lay["off_actual"], C.control["actual"].offset)
        self.assertEqual(lay["off_readlocked"], C.control["readlocked"].offset)
        self.assertEqual(lay["off_buffers"], C.buffers_offset)
        self.assertEqual(lay["buffer1"], C.buffer1)
        self.assertEqual(lay["buffers"], C.buffers)
        self.assertEqual(lay["taken_at_words"], C.taken_at_words)

    def test_four_slot_layout(self):
        """The four-slot mapping (docs/four_slot.md), written out
        independently: slot bytes at offsets 2 and 3 of the control word, four
        buffers after it, both slot bytes 0 at the start."""
        self.assertEqual(C.fs_control["slot0"].offset, 2)
        self.assertEqual(C.fs_control["slot1"].offset, 3)
        self.assertEqual(C.fs_buffers, 4)
        self.assertEqual(C.fs_initial_slot, 0)
        self.assertEqual(C.fs_channel_bytes(5), 4 + 4 * 8)
        self.assertEqual(C.fs_initial_control_word(), 0x0101)


class DefinitionChecks(unittest.TestCase):
    """The loader rejects an inconsistent definition, naming the problem."""

    def load_edited(self, old, new):
        with open(C.path) as f:
            text = f.read()
        self.assertIn(old, text)
        with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
            f.write(text.replace(old, new, 1))
        try:
            return contract.load(f.name)
        finally:
            os.unlink(f.name)

    def test_overlap_is_rejected(self):
        with self.assertRaises(contract.ContractError) as cm:
            self.load_edited('{ name = "nd",    lsb = 12, width = 4,', '{ name = "nd",    lsb = 12, width = 5,')
        self.assertIn("E0.nd [16:12] overlaps", str(cm.exception))

    def test_magic_must_fit(self):
        with self.assertRaises(contract.ContractError) as cm:
            self.load_edited("magic          = 0xA1BA", "magic          = 0x1A1BA")
        self.assertIn("does not fit H0.magic", str(cm.exception))

    def test_time_fields_follow_time_bits(self):
        with self.assertRaises(contract.ContractError) as cm:
            self.load_edited("time_bits      = 16", "time_bits      = 20")
        self.assertIn("H1.cycle is not time_bits (20) wide", str(cm.exception))

    def test_one_crc_word(self):
        with self.assertRaises(contract.ContractError) as cm:
            self.load_edited('word = "H3"\ncrc = true', 'word = "H3"\ncrc = false')
        self.assertIn("exactly one CRC word", str(cm.exception))

    def test_four_slot_slot_outside_control_word(self):
        with self.assertRaises(contract.ContractError) as cm:
            self.load_edited('{ name = "slot1", offset = 3,', '{ name = "slot1", offset = 4,')
        self.assertIn("slot1 at offset 4 is outside the control word", str(cm.exception))

    def test_four_slot_overlap(self):
        with self.assertRaises(contract.ContractError) as cm:
            self.load_edited('{ name = "slot0", offset = 2,', '{ name = "slot0", offset = 1,')
        self.assertIn("control byte slot0 overlaps readlocked", str(cm.exception))

    def test_four_slot_wide_slot(self):
        with self.assertRaises(contract.ContractError) as cm:
            self.load_edited('{ name = "slot0", offset = 2, size = 1,', '{ name = "slot0", offset = 2, size = 2,')
        self.assertIn("slot0 is 2 bytes", str(cm.exception))

    def test_four_slot_buffers(self):
        with self.assertRaises(contract.ContractError) as cm:
            self.load_edited("buffers      = 4", "buffers      = 3")
        self.assertIn("layout.four_slot: buffers 3, expected 4", str(cm.exception))

    def test_markdown_block(self):
        text = "intro\n<!-- contract:rom-entry -->\nold table\n<!-- /contract:rom-entry -->\nend\n"
        out = render_markdown(C, text)
        self.assertTrue(out.startswith("intro\n<!-- contract:rom-entry -->\n<!-- Generated from"))
        self.assertIn(f"| E0 | {C.field('E0', 'kind').bits} |", out)
        self.assertNotIn("old table", out)
        self.assertTrue(out.endswith("<!-- /contract:rom-entry -->\nend\n"))
        self.assertEqual(render_markdown(C, out), out)


if __name__ == "__main__":
    unittest.main()
