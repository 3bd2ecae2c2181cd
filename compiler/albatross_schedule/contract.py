"""The ALBATROSS contract, defined once in rtl/albatross_contract.toml: the
schedule ROM format and the memory layout of one channel.  This module
loads and checks the definition; the compiler's encoder and verify_rom use
it, and contract_gen.py generates the Verilog include, the C and C++
headers and the markdown tables from it (see docs/contract.md):

    python -m albatross_schedule.contract_gen [--check]     (the project's venv python)
                                  [--definition FILE] [--root DIR] [FILE.md ...]

ALB_CONTRACT=FILE in the environment makes the compiler read another
definition (the negative test of the contract uses that)."""

from __future__ import annotations

import dataclasses
import os
import tomllib

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(PACKAGE_DIR))
DEFINITION = "rtl/albatross_contract.toml"            # relative to the repository
# The package's albatross_contract.toml is a symbolic link to the definition in
# the checkout (an editable install or the checkout itself resolves it there); a
# wheel built by pip install ./compiler carries the file itself.
DEFAULT_PATH = os.path.realpath(os.path.join(PACKAGE_DIR, "albatross_contract.toml"))


class ContractError(Exception):
    """The definition is unreadable or inconsistent."""


@dataclasses.dataclass(frozen=True)
class Field:
    word: str           # H0..H3, E0..E7, or "place"
    index: int          # word index within the header or the entry
    name: str
    lsb: int
    width: int
    doc: str = ""
    place: bool = False

    @property
    def mask(self) -> int:
        """The field's bits in place."""
        return ((1 << self.width) - 1) << self.lsb

    @property
    def max(self) -> int:
        return (1 << self.width) - 1

    def get(self, word: int) -> int:
        return (word >> self.lsb) & self.max

    def put(self, value: int) -> int:
        return (value & self.max) << self.lsb

    @property
    def bits(self) -> str:
        """[msb:lsb] as in Verilog and the documentation."""
        return f"[{self.lsb + self.width - 1}:{self.lsb}]"


@dataclasses.dataclass
class Word:
    name: str
    index: int
    fields: list
    reserved: bool = False
    crc: bool = False
    doc: str = ""


@dataclasses.dataclass
class ControlByte:
    name: str
    offset: int
    size: int
    contents: str
    writer: str


class Contract:
    """The loaded definition.  ROM words: header[i], entry[j]; fields by
    word and name: c.field("E0", "kind"); the place layout: c.place_board,
    c.place_base; constants as attributes (magic, checksum_seed, ...)."""

    def __init__(self, data: dict, path: str):
        self.path = path
        try:
            self._load(data)
        except (KeyError, TypeError, ValueError) as e:
            raise ContractError(f"{path}: malformed definition ({type(e).__name__}: {e})") from None
        problems = self._problems()
        if problems:
            raise ContractError(f"{path}: " + "; ".join(problems))

    # ---- loading
    def _fields(self, word, index, items, fmt):
        out = []
        for f in items:
            unknown = set(f) - {"name", "lsb", "width", "doc", "place"}
            if unknown:
                raise ValueError(f"{word}: unknown keys {sorted(unknown)}")
            out.append(Field(word, index, f["name"], int(f["lsb"]), int(f["width"]),
                             f.get("doc", "").format(**fmt), bool(f.get("place", False))))
        return out

    def _words(self, items, fmt):
        words = []
        for i, w in enumerate(items):
            words.append(Word(w["word"], i, self._fields(w["word"], i, w.get("fields", []), fmt),
                              bool(w.get("reserved", False)), bool(w.get("crc", False)),
                              w.get("doc", "")))
        return words

    def _load(self, data):
        rom = data["rom"]
        self.word_bits = int(rom["word_bits"])
        self.header_words = int(rom["header_words"])
        self.entry_words = int(rom["entry_words"])
        self.magic = int(rom["magic"])
        self.max_entries = int(rom["max_entries"])
        self.max_dests = int(rom["max_dests"])
        self.crc_poly = int(rom["crc_poly"])
        self.crc_seed = int(rom["crc_seed"])
        self.time_bits = int(rom["time_bits"])
        self.kind = {k: int(v) for k, v in rom["kind"].items()}
        self.header_flags = {k: int(v) for k, v in rom["header_flags"].items()}
        self.entry_flags = {k: int(v) for k, v in rom["entry_flags"].items()}
        fmt = {"magic": f"0x{self.magic:04X}", "max_entries": self.max_entries, "max_dests": self.max_dests}
        place = {f.name: f for f in self._fields("place", 0, rom["place"]["fields"], fmt)}
        self.place_board = place["board"]
        self.place_base = place["base"]
        self.header = self._words(rom["header"], fmt)
        self.entry = self._words(rom["entry"], fmt)
        self.mode = self._words(rom.get("mode", []), fmt)   # D0..: a mode descriptor, in an entry's place
        lay = data["layout"]
        self.word_bytes = int(lay["word_bytes"])
        self.buffers = int(lay["buffers"])
        self.buffer1 = int(lay["buffer1"])
        self.initial_index = int(lay["initial_index"])
        self.not_started = int(lay["not_started"])
        self.buffers_offset = int(lay["buffers_offset"])
        self.taken_at_words = int(lay["taken_at_words"])
        self.control = {c["name"]: ControlByte(c["name"], int(c["offset"]), int(c["size"]), c["contents"],
                                               c["writer"]) for c in lay["control"]}
        fs = lay["four_slot"]
        unknown = set(fs) - {"buffers", "initial_slot", "control"}
        if unknown:
            raise ValueError(f"layout.four_slot: unknown keys {sorted(unknown)}")
        self.fs_buffers = int(fs["buffers"])
        self.fs_initial_slot = int(fs["initial_slot"])
        self.fs_control = {c["name"]: ControlByte(c["name"], int(c["offset"]), int(c["size"]), c["contents"],
                                                  c["writer"]) for c in fs["control"]}

    def _problems(self):
        p = []
        wb = self.word_bits
        if wb != 32:
            p.append(f"word_bits {wb}: the ROM words are 32 bits")
        for group, words, n in (("header", self.header, self.header_words), ("entry", self.entry, self.entry_words),
                                ("mode", self.mode, self.entry_words)):
            if len(words) != n:
                p.append(f"rom.{group} lists {len(words)} words, {group}_words is {n}")
            for w in words:
                used = 0
                for f in w.fields:
                    if f.width < 1 or f.lsb < 0 or f.lsb + f.width > wb:
                        p.append(f"{w.name}.{f.name} {f.bits} is outside a {wb}-bit word")
                    elif used & f.mask:
                        p.append(f"{w.name}.{f.name} {f.bits} overlaps another field of {w.name}")
                    used |= f.mask
                    if f.place and f.width < self.place_board.lsb + self.place_board.width:
                        p.append(f"{w.name}.{f.name}: {f.width} bits cannot hold a place")
                if w.crc and [f.width for f in w.fields] != [wb]:
                    p.append(f"{w.name}: the CRC word is one {wb}-bit field")
        if [w.crc for w in self.header + self.entry + self.mode].count(True) != 1 or \
                any(w.crc for w in self.entry + self.mode):
            p.append("rom: exactly one CRC word, in the header")
        if self.place_board.mask & self.place_base.mask:
            p.append("rom.place: board and base overlap")
        for name in ("ne", "flags", "magic"):
            self._need(p, "H0", name)
        for name in ("kind", "flags", "id", "nd", "w"):
            self._need(p, "E0", name)
        for word, name in (("H2", "table"), ("H2", "modes"), ("H2", "start_end"), ("D0", "cycle"), ("D0", "first"),
                           ("D0", "end"), ("D1", "drop_run"), ("D1", "next"), ("H1", "next"),
                           ("H2", "cluster"), ("D2", "cluster"), ("E6", "base"), ("E6", "rep"), ("E7", "frag")):
            self._need(p, word, name)
        if not p:
            if self.magic > self.field("H0", "magic").max:
                p.append(f"magic {self.magic:#x} does not fit H0.magic")
            if self.max_entries > self.field("H0", "ne").max:
                p.append(f"max_entries {self.max_entries} does not fit H0.ne")
            if self.max_dests > self.field("E0", "nd").max:
                p.append(f"max_dests {self.max_dests} does not fit E0.nd")
            if len(self.dest_fields) != self.max_dests:
                p.append(f"{len(self.dest_fields)} destination places (dst0..), max_dests is {self.max_dests}")
            if len(set(self.kind.values())) != len(self.kind) or \
                    max(self.kind.values()) > self.field("E0", "kind").max:
                p.append("rom.kind: codes must be distinct and fit E0.kind")
            # the multi-rate fields: a repetition up to the largest cluster, a base below it
            cl, rep, base = self.field("H2", "cluster"), self.field("E6", "rep"), self.field("E6", "base")
            if self.field("D2", "cluster").width != cl.width or rep.width != cl.width:
                p.append("H2.cluster, D2.cluster and E6.rep must be equally wide")
            if self.field("D2", "cluster").lsb != cl.lsb:
                p.append("D2.cluster must sit at H2.cluster's bits (the controller loads both through one path)")
            if base.width < cl.max:
                p.append(f"E6.base ({base.width} bits) cannot hold a base below 2^{cl.max}")
            if self.field("E7", "frag").width < self.field("E0", "w").width:
                p.append("E7.frag is narrower than E0.w")
            for fl, word in ((self.header_flags, "H0"), (self.entry_flags, "E0")):
                if any(b >= self.field(word, "flags").width for b in fl.values()):
                    p.append(f"a flag bit outside {word}.flags")
        if not 0 <= self.crc_poly < (1 << wb) or not self.crc_poly & 1 or not 0 <= self.crc_seed < (1 << wb):
            p.append("crc_poly (odd) or crc_seed out of range")
        if not p:
            for word, name in (("H1", "cycle"), ("E1", "start"), ("E2", "length"), ("D0", "cycle")):
                if self.field(word, name).width != self.time_bits:
                    p.append(f"{word}.{name} is not time_bits ({self.time_bits}) wide")
        offs = sorted((c.offset, c.offset + c.size) for c in self.control.values())
        if any(a[1] > b[0] for a, b in zip(offs, offs[1:])) or (offs and offs[-1][1] > self.buffers_offset):
            p.append("layout: control bytes overlap each other or the buffers")
        if self.buffers_offset % self.word_bytes:
            p.append("layout: buffers_offset is not word-aligned")
        for name in ("actual", "readlocked"):
            if name not in self.control:
                p.append(f"layout: no control byte '{name}'")
        p += self._four_slot_problems()
        return p

    def _four_slot_problems(self):
        """[layout.four_slot]: four buffers in two pairs, slot bytes slot0 and
        slot1 of one byte each inside the control word (the bytes before
        Buffer1 that one word load reads), overlapping nothing."""
        p = []
        if self.fs_buffers != 4:
            p.append(f"layout.four_slot: buffers {self.fs_buffers}, expected 4 (two pairs of two slots)")
        if self.fs_initial_slot not in (0, 1):
            p.append(f"layout.four_slot: initial_slot {self.fs_initial_slot}, expected 0 or 1")
        if sorted(self.fs_control) != ["slot0", "slot1"]:
            p.append(f"layout.four_slot: control bytes {sorted(self.fs_control)}, expected slot0 and slot1")
        for cb in self.fs_control.values():
            if cb.size != 1:
                p.append(f"layout.four_slot: {cb.name} is {cb.size} bytes, expected 1 (a byte store is indivisible)")
            if cb.offset < 0 or cb.offset + cb.size > min(self.word_bytes, self.buffers_offset):
                p.append(f"layout.four_slot: {cb.name} at offset {cb.offset} is outside the control word "
                         f"(bytes 0..{min(self.word_bytes, self.buffers_offset) - 1})")
        every = list(self.control.values()) + list(self.fs_control.values())
        offs = sorted((c.offset, c.offset + c.size, c.name) for c in every)
        for a, b in zip(offs, offs[1:]):
            if a[1] > b[0]:
                p.append(f"layout.four_slot: control byte {b[2]} overlaps {a[2]}")
        return p

    def _need(self, p, word, name):
        if not any(w.name == word and any(f.name == name for f in w.fields)
                   for w in self.header + self.entry + self.mode):
            p.append(f"{word} has no field '{name}'")

    # ---- look-ups
    def word(self, name: str) -> Word:
        for w in self.header + self.entry + self.mode:
            if w.name == name:
                return w
        raise KeyError(name)

    def field(self, word: str, name: str) -> Field:
        for f in self.word(word).fields:
            if f.name == name:
                return f
        raise KeyError(f"{word}.{name}")

    @property
    def dest_fields(self) -> list:
        """The destination places dst0, dst1, ... in order."""
        out = [f for w in self.entry for f in w.fields if f.place and f.name.startswith("dst")]
        return sorted(out, key=lambda f: int(f.name[3:]))

    @property
    def src_field(self) -> Field:
        return next(f for w in self.entry for f in w.fields if f.place and f.name == "src")

    def place_fields(self, f: Field):
        """The board and base fields of place f, positioned in its word."""
        return (dataclasses.replace(self.place_board, word=f.word, index=f.index, name=f"{f.name}_board",
                                    lsb=f.lsb + self.place_board.lsb),
                dataclasses.replace(self.place_base, word=f.word, index=f.index, name=f"{f.name}_base",
                                    lsb=f.lsb + self.place_base.lsb))

    def place(self, board: int, base_word: int) -> int:
        """A {board, base word} pair as its 16-bit place value."""
        return self.place_board.put(board) | self.place_base.put(base_word)

    def unplace(self, value: int):
        return self.place_board.get(value), self.place_base.get(value)

    def flag(self, group: str, name: str) -> int:
        """The mask of a flag within its flags field (not shifted into the word)."""
        return 1 << (self.header_flags if group == "header" else self.entry_flags)[name]

    # ---- ROM arithmetic
    @property
    def crc_index(self) -> int:
        """Address of the CRC word (in the header)."""
        return next(w.index for w in self.header if w.crc)

    def crc(self, words) -> int:
        """CRC of ROM words: c = crc_seed; for each word w in address order (the
        CRC word too): c = (c * x^32 + w) mod (x^32 + crc_poly).  A valid image's
        CRC is 0 (its CRC word is check_word)."""
        wb = self.word_bits
        m = (1 << wb) - 1
        c = self.crc_seed
        for w in words:
            for _ in range(wb):
                c = ((c << 1) & m) ^ (self.crc_poly if c >> (wb - 1) else 0)
            c ^= w & m
        return c

    def check_word(self, words) -> int:
        """The CRC word that makes the CRC of the image 0.  The word at index i
        adds w * x^(32 (n - 1 - i)) mod P to the CRC, so the image's CRC c is
        cancelled by adding c * x^-(32 (n - 1 - i)) mod P to the word it holds
        (x is invertible: crc_poly is odd)."""
        wb = self.word_bits
        c = self.crc(words)
        for _ in range(wb * (len(words) - 1 - self.crc_index)):
            # c * x^-1 mod P: c / x, or (c + P) / x when c is odd
            c = ((c ^ self.crc_poly) >> 1) | (1 << (wb - 1)) if c & 1 else c >> 1
        return words[self.crc_index] ^ c

    def entry_address(self, k: int) -> int:
        return self.header_words + self.entry_words * k

    # ---- channel layout
    def stride(self, payload: int) -> int:
        """Bytes between buffers: the payload rounded up to whole words."""
        return (payload + self.word_bytes - 1) // self.word_bytes * self.word_bytes

    def channel_bytes(self, payload: int) -> int:
        return self.buffers_offset + self.buffers * self.stride(payload)

    def dest_payload(self, words: int) -> int:
        """Bytes of a destination payload: the value's words, then taken_at."""
        return self.word_bytes * (words + self.taken_at_words)

    @property
    def buffer_last(self) -> int:
        return self.buffer1 + self.buffers - 1

    @property
    def control_words(self) -> int:
        """Words before Buffer1 (the control bytes and the reserved bytes)."""
        return self.buffers_offset // self.word_bytes

    def fs_channel_bytes(self, payload: int) -> int:
        """Bytes of a four-slot channel: the control word, then four buffers."""
        return self.buffers_offset + self.fs_buffers * self.stride(payload)

    @property
    def fs_buffer_last(self) -> int:
        return self.buffer1 + self.fs_buffers - 1

    def fs_initial_control_word(self) -> int:
        """The first word of a fresh four-slot channel: Actual = ReadLocked =
        initial_index, both slot bytes = initial_slot."""
        return self.initial_control_word() | sum(self.fs_initial_slot << (8 * c.offset)
                                                 for c in self.fs_control.values())

    def initial_control_word(self) -> int:
        """The first word of a freshly initialised channel (every control byte = initial_index)."""
        return sum(self.initial_index << (8 * c.offset) for c in self.control.values()
                   if c.offset < self.word_bytes)


_cache = {}


def load(path: str | None = None) -> Contract:
    """The definition at path (default: $ALB_CONTRACT, else rtl/albatross_contract.toml)."""
    path = path or os.environ.get("ALB_CONTRACT") or DEFAULT_PATH
    if path not in _cache:
        try:
            with open(path, "rb") as f:
                data = tomllib.load(f)
        except OSError as e:
            raise ContractError(f"{path}: cannot read the contract definition: {e.strerror}") from None
        except tomllib.TOMLDecodeError as e:
            raise ContractError(f"{path}: invalid TOML: {e}") from None
        _cache[path] = Contract(data, path)
    return _cache[path]

