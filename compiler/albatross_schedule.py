#!/usr/bin/env python3
"""albatross_schedule.py -- the ALBATROSS schedule compiler (seed 3.3, 4.a, 4.d).

    python3 compiler/albatross_schedule.py DESCRIPTION.toml --out DIR

reads a human-written system description and builds the pre-calculated
cyclic plan that albatross_controller executes: the worst case is the normal
case, and spare bus capacity becomes redundant transfers.  Standard library
only (Python 3.11, tomllib).  Bad input ends with a clear message naming the
file, line, channel and field, and exit status 2; nothing is written then.

Description (TOML)
------------------
[system]
  name          C identifier, names the system (header guards, report)
  clock_hz      controller / bus clock in Hz (positive integer)
  boards        list of board names (C identifiers), index = position, 1..16
  ram_bytes     dual-ported RAM per board: a power of two (default 4096),
                or a table {board = bytes, ...} (missing boards: 4096)
  mode          "time-rigid" (default) | "position-synchronised"
  types_header  optional C header that the board headers #include for the
                user types named in `type`

[bus]           timing model of the controller RTL, all optional (default)
  access_cycles       2   clocks per bus access, fault-free, back to back
  first_access_extra  1   phase alignment of the first access of a slot
  fetch_cycles        10  the controller's per-slot entry fetch
  timeout_cycles      8   clocks until an unanswered access fails
  retries_per_slot    2   failed accesses every slot must absorb
  guard_cycles        6   idle clocks at the end of every slot (the controller starts
                          no access later than deadline - timeout - 2: >= timeout - retries)
  n_chan              16  the controller's N_CHAN (channel ids 0..n_chan-1)
  poll_cycles         16  position poll interval (position-synchronised)

[[channel]]     one per channel; the id is the position (0, 1, ...)
  name          C identifier (LookForNew<name>, Make<name>Available)
  kind          "copy" (default) | "time" | "status"
  type          C type of the value; default: a generated <name>_t
                (copy: struct { uint8_t bytes[size]; }, time: uint32_t,
                status: struct { uint32_t word[1 + 2*n_chan]; })
  size          value bytes (copy only; 1..16380)
  producer      board that publishes the value (copy only)
  consumers     1..4 boards (not the producer), or "all"
  max_period_us required maximal period between two transfers (integer us)
  sync          true: the position channel that starts every cycle
                (position-synchronised mode only, exactly one, copy)
  priority      integer, default 0; higher gets redundant slots first
  max_slots     optional cap on this channel's slots per cycle

Plan
----
Slot length L = fetch + first_access_extra + access_cycles*A
                + retries_per_slot*(timeout + access_cycles + 1) + guard,
A = fault-free accesses when the value is new at every destination:
COPY 3 + W + ND*(W + 3), TIME/STATUS ND*(W + 3).  The cycle C is the
smallest max_period (clocks); every channel gets one slot per cycle, then
redundant slots are added round-robin (priority, then shortest period) while
they fit (time and the 255-entry ROM), and all slots are placed so each
channel's slots are spread evenly (its largest gap minimised).  In
position-synchronised mode the sync channel is entry 0 at start 0 (SYNC
flag) and poll_cycles stay idle at the end of the cycle.

Outputs in DIR: rom.hex, <board>.h, <board>.c, <board>_ram.hex,
report.json, report.txt, timeline.svg (see compiler/README.md).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import os
import random
import re
import sys
import tomllib
from typing import Any, Optional

# ---------------------------------------------------------------------------
# Constants of the README contract (schedule ROM).

ROM_MAGIC = 0xA1BA
CHECKSUM_SEED = 0xA1BA7055
MAX_ENTRIES = 255
MAX_BOARDS = 16
MAX_WORDS = 4095           # E0[11:0]
MAX_BASE_WORD = 4095       # 12-bit base word fields
MAX_DESTS = 4
KIND_CODE = {"idle": 0, "copy": 1, "time": 2, "status": 3}
KIND_NAME = {v: k for k, v in KIND_CODE.items()}
FLAG_SYNC = 1
MODE_RIGID = "time-rigid"
MODE_SYNC = "position-synchronised"
DEFAULT_RAM_BYTES = 4096

BUS_DEFAULTS = {
    "access_cycles": 2,
    "first_access_extra": 1,
    "fetch_cycles": 10,
    "timeout_cycles": 8,
    "retries_per_slot": 2,
    "guard_cycles": 6,
    "n_chan": 16,
    "poll_cycles": 16,
}
BUS_MINIMUM = {
    "access_cycles": 1, "first_access_extra": 0, "fetch_cycles": 1,
    "timeout_cycles": 1, "retries_per_slot": 0, "guard_cycles": 0,
    "n_chan": 1, "poll_cycles": 1,
}

SYSTEM_KEYS = {"name", "clock_hz", "boards", "ram_bytes", "mode", "types_header"}
CHANNEL_KEYS = {"name", "kind", "type", "size", "producer", "consumers",
                "max_period_us", "sync", "priority", "max_slots"}

IDENT_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
CTYPE_RE = re.compile(r"^((struct|union|enum)\s+)?[A-Za-z_][A-Za-z0-9_]*$")
HEADER_RE = re.compile(r'^[A-Za-z0-9_./+-]+\.h$')
# File names a board header must not take: the driver's own headers.
RESERVED_FILES = {"albatross", "albatross_layout", "alb_port", "alb_port_impl"}


class ScheduleError(Exception):
    """Bad input: one or more messages, each naming the problem and where."""

    def __init__(self, messages):
        if isinstance(messages, str):
            messages = [messages]
        self.messages = list(messages)
        super().__init__("\n".join(self.messages))


def rotl32(x: int, n: int) -> int:
    x &= 0xFFFFFFFF
    return ((x << n) | (x >> (32 - n))) & 0xFFFFFFFF


def checksum(words) -> int:
    """README checksum: c = 0xA1BA7055; for each w: c = rotl32(c, 5) ^ w."""
    c = CHECKSUM_SEED
    for w in words:
        c = rotl32(c, 5) ^ (w & 0xFFFFFFFF)
    return c


def us(clocks: float, clock_hz: int) -> float:
    return clocks * 1e6 / clock_hz


# ---------------------------------------------------------------------------
# Data model.

@dataclasses.dataclass
class Bus:
    access_cycles: int = 2
    first_access_extra: int = 1
    fetch_cycles: int = 10
    timeout_cycles: int = 8
    retries_per_slot: int = 2
    guard_cycles: int = 6
    n_chan: int = 16
    poll_cycles: int = 16

    @property
    def retry_budget(self) -> int:
        return self.retries_per_slot * (self.timeout_cycles + self.access_cycles + 1)

    @property
    def sample_offset(self) -> int:
        return self.fetch_cycles + self.access_cycles


@dataclasses.dataclass
class Channel:
    index: int                      # position in the description = channel id
    name: str
    kind: str                       # copy | time | status
    ctype: Optional[str]            # user type, or None (generated <name>_t)
    size: int                       # value bytes (time: 4, status: 4*W)
    words: int                      # W
    producer: Optional[int]         # board index (copy)
    consumers: list                 # board indices, destination order
    max_period_us: int
    period_clocks: int = 0
    sync: bool = False
    priority: int = 0
    max_slots: Optional[int] = None
    # filled by the plan
    src_base: Optional[int] = None  # byte offset in the producer's RAM
    dst_bases: list = dataclasses.field(default_factory=list)
    accesses: int = 0               # A
    slot_len: int = 0               # L
    slots: list = dataclasses.field(default_factory=list)   # starts, sorted

    @property
    def id(self) -> int:
        return self.index

    @property
    def type_name(self) -> str:
        if self.ctype:
            return self.ctype
        if self.kind == "time":
            return "uint32_t"
        return f"{self.name}_t"

    @property
    def dst_size(self) -> int:
        return 4 * self.words + 4


@dataclasses.dataclass
class System:
    name: str
    clock_hz: int
    boards: list
    ram_bytes: list                 # per board
    mode: str
    types_header: Optional[str]
    bus: Bus
    channels: list
    source: str = "<description>"

    @property
    def sync_mode(self) -> bool:
        return self.mode == MODE_SYNC


@dataclasses.dataclass
class Slot:
    channel: Channel
    start: int
    length: int
    redundant: bool
    sync: bool = False


@dataclasses.dataclass
class Plan:
    cycle: int                      # C = H1, clocks
    capacity: int                   # clocks usable by slots
    slots: list                     # Slot, in entry order (= start order)
    limiter: Channel                # channel whose max_period sets C


# ---------------------------------------------------------------------------
# Reading the description.

class Locator:
    """Best-effort line numbers for [system], [bus] and the i-th [[channel]]."""

    HEADER_RE = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.\"' -]+?)\s*\]\]?\s*(#.*)?$")

    def __init__(self, path: str, text: str):
        self.path = path
        self.lines = text.splitlines()
        self.tables = []            # (name, is_array, line index)
        for i, line in enumerate(self.lines):
            m = self.HEADER_RE.match(line)
            if m and not line.lstrip().startswith("#"):
                self.tables.append((m.group(1).strip(), line.lstrip().startswith("[["), i))

    def _table_line(self, name, nth=0):
        k = 0
        for tname, _, i in self.tables:
            if tname == name:
                if k == nth:
                    return i
                k += 1
        return None

    def line(self, table, nth=0, field=None):
        start = self._table_line(table, nth)
        if start is None:
            return None
        if field is not None:
            key_re = re.compile(r"^\s*[\"']?" + re.escape(field) + r"[\"']?\s*=")
            for i in range(start + 1, len(self.lines)):
                if self.HEADER_RE.match(self.lines[i]) and not self.lines[i].lstrip().startswith("#"):
                    break
                if key_re.match(self.lines[i]):
                    return i + 1
        return start + 1

    def where(self, table, nth=0, field=None):
        ln = self.line(table, nth, field)
        return f"{self.path}:{ln}" if ln else self.path


class Errors:
    def __init__(self, loc: Locator):
        self.loc = loc
        self.messages = []

    def system(self, field, msg, table="system"):
        where = self.loc.where(table, 0, field)
        fld = f", field '{field}'" if field else ""
        self.messages.append(f"{where}: [{table}]{fld}: {msg}")

    def channel(self, i, name, field, msg):
        where = self.loc.where("channel", i, field)
        who = f"channel '{name}'" if isinstance(name, str) and name else f"channel #{i + 1}"
        fld = f", field '{field}'" if field else ""
        self.messages.append(f"{where}: {who}{fld}: {msg}")

    def general(self, msg):
        self.messages.append(f"{self.loc.path}: {msg}")

    def raise_if_any(self):
        if self.messages:
            raise ScheduleError(self.messages)


def _is_int(v) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)


def _describe(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return repr(v)
    if isinstance(v, float):
        return f"{v:g}"
    return repr(v) if not isinstance(v, (dict, list)) else type(v).__name__


def load_toml(path: str):
    """Read and decode a TOML file; errors name the file, line and column."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as e:
        raise ScheduleError(f"{path}: cannot read the description: {e.strerror}")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as e:
        raise ScheduleError(f"{path}: not UTF-8 text (byte {e.start})")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        msg = str(e)
        m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
        if m:
            base = msg[:m.start()].strip()
            raise ScheduleError(f"{path}:{m.group(1)}:{m.group(2)}: invalid TOML: {base} "
                                f"(line {m.group(1)}, column {m.group(2)})")
        raise ScheduleError(f"{path}: invalid TOML: {msg}")
    return data, text


def parse_description(data: dict, path: str = "<description>", text: str = "") -> System:
    """Validate the decoded TOML and build the System (no plan yet)."""
    loc = Locator(path, text)
    err = Errors(loc)

    for key in data:
        if key not in ("system", "bus", "channel"):
            err.general(f"unknown section [{key}] (expected [system], [bus], [[channel]])")

    # ---- [system]
    sysd = data.get("system")
    if sysd is None:
        err.general("missing section [system] (name, clock_hz, boards, ...)")
        err.raise_if_any()
    if not isinstance(sysd, dict):
        err.general("[system] must be a table")
        err.raise_if_any()
    for key in sysd:
        if key not in SYSTEM_KEYS:
            err.system(key, f"unknown field (expected one of {', '.join(sorted(SYSTEM_KEYS))})")

    name = sysd.get("name")
    if name is None:
        err.system("name", "missing (a C identifier naming the system)")
        name = "system"
    elif not isinstance(name, str) or not IDENT_RE.match(name):
        err.system("name", f"{_describe(name)} is not a C identifier")
        name = "system"

    clock_hz = sysd.get("clock_hz")
    if clock_hz is None:
        err.system("clock_hz", "missing (the controller clock in Hz)")
        clock_hz = 1
    elif not _is_int(clock_hz) or clock_hz <= 0:
        err.system("clock_hz", f"{_describe(clock_hz)} is not a positive integer")
        clock_hz = 1

    boards = sysd.get("boards")
    board_ok = True
    if boards is None:
        err.system("boards", "missing (a list of board names)")
        boards, board_ok = [], False
    elif not isinstance(boards, list) or not boards:
        err.system("boards", "must be a non-empty list of board names")
        boards, board_ok = [], False
    else:
        if len(boards) > MAX_BOARDS:
            err.system("boards", f"{len(boards)} boards, at most {MAX_BOARDS} fit the 4-bit board fields of the ROM")
            board_ok = False
        seen = {}
        for b in boards:
            if not isinstance(b, str) or not IDENT_RE.match(b):
                err.system("boards", f"board name {_describe(b)} is not a C identifier")
                board_ok = False
                continue
            if b.lower() in seen:
                err.system("boards", f"duplicate board name '{b}'"
                           + (f" (same file name as '{seen[b.lower()]}')" if seen[b.lower()] != b else ""))
                board_ok = False
            seen[b.lower()] = b
            if b.lower() in RESERVED_FILES:
                err.system("boards", f"board name '{b}' would overwrite the driver header {b}.h")
                board_ok = False
        boards = [b for b in boards if isinstance(b, str)]
    board_index = {b: i for i, b in enumerate(boards)}

    mode = sysd.get("mode", MODE_RIGID)
    if mode not in (MODE_RIGID, MODE_SYNC):
        err.system("mode", f"{_describe(mode)}: expected \"{MODE_RIGID}\" or \"{MODE_SYNC}\"")
        mode = MODE_RIGID

    types_header = sysd.get("types_header")
    if types_header is not None:
        if not isinstance(types_header, str) or not HEADER_RE.match(types_header):
            err.system("types_header", f"{_describe(types_header)} is not a header file name (x.h)")
            types_header = None
        else:
            stem = os.path.splitext(os.path.basename(types_header))[0]
            if stem in boards:
                err.system("types_header", f"'{types_header}' has the name of the generated header of board '{stem}'")

    ram = sysd.get("ram_bytes", DEFAULT_RAM_BYTES)
    ram_bytes = [DEFAULT_RAM_BYTES] * len(boards)

    def check_ram(v, what):
        if not _is_int(v) or v <= 0:
            err.system("ram_bytes", f"{what}: {_describe(v)} is not a positive integer")
            return False
        if v & (v - 1) or v < 16:
            err.system("ram_bytes", f"{what}: {v} is not a power of two >= 16")
            return False
        return True

    if isinstance(ram, dict):
        for b, v in ram.items():
            if b not in board_index:
                err.system("ram_bytes", f"unknown board '{b}' (boards: {', '.join(boards)})")
            elif check_ram(v, f"board '{b}'"):
                ram_bytes[board_index[b]] = v
    elif check_ram(ram, "every board"):
        ram_bytes = [ram] * len(boards)

    # ---- [bus]
    bus = Bus()
    busd = data.get("bus", {})
    if not isinstance(busd, dict):
        err.general("[bus] must be a table")
        busd = {}
    for key, v in busd.items():
        if key not in BUS_DEFAULTS:
            err.system(key, f"unknown field (expected one of {', '.join(BUS_DEFAULTS)})", table="bus")
            continue
        lo = BUS_MINIMUM[key]
        if not _is_int(v) or v < lo:
            err.system(key, f"{_describe(v)} is not an integer >= {lo}", table="bus")
            continue
        if key == "n_chan" and v > 256:
            err.system(key, f"{v} exceeds 256 (the channel id is an 8-bit ROM field)", table="bus")
            continue
        setattr(bus, key, v)

    # ---- [[channel]]
    chans = data.get("channel")
    if chans is None:
        err.general("missing section [[channel]] (at least one channel)")
        err.raise_if_any()
    if isinstance(chans, dict):
        err.general("[channel] must be an array of tables: write [[channel]] for every channel")
        err.raise_if_any()
    if not isinstance(chans, list) or not chans:
        err.general("[[channel]] must list at least one channel")
        err.raise_if_any()

    channels = []
    names = {}
    n_sync = 0
    status_words = 1 + 2 * bus.n_chan
    for i, cd in enumerate(chans):
        if not isinstance(cd, dict):
            err.channel(i, None, None, "must be a table")
            continue
        cname = cd.get("name")
        ok = True
        if cname is None:
            err.channel(i, None, "name", "missing (a C identifier)")
            ok = False
        elif not isinstance(cname, str) or not IDENT_RE.match(cname):
            err.channel(i, None, "name", f"{_describe(cname)} is not a C identifier "
                        "(a letter, then letters, digits or _)")
            ok = False
        else:
            if cname.upper() in names:
                other = names[cname.upper()]
                err.channel(i, cname, "name", f"duplicate channel name (already used by channel #{other[1] + 1}"
                            + (f" '{other[0]}', the same macro ALB_{cname.upper()}_*" if other[0] != cname else "")
                            + ")")
                ok = False
            else:
                names[cname.upper()] = (cname, i)
        label = cname if isinstance(cname, str) else None

        for key in cd:
            if key not in CHANNEL_KEYS:
                err.channel(i, label, key, f"unknown field (expected one of {', '.join(sorted(CHANNEL_KEYS))})")
                ok = False

        kind = cd.get("kind", "copy")
        if kind not in ("copy", "time", "status"):
            err.channel(i, label, "kind", f"{_describe(kind)}: expected \"copy\", \"time\" or \"status\"")
            kind, ok = "copy", False

        ctype = cd.get("type")
        if ctype is not None and (not isinstance(ctype, str) or not CTYPE_RE.match(ctype.strip())):
            err.channel(i, label, "type", f"{_describe(ctype)} is not a C type name "
                        "(an identifier, or struct/union/enum identifier)")
            ctype, ok = None, False
        elif ctype is not None:
            ctype = " ".join(ctype.split())

        size = 0
        words = 0
        producer = None
        if kind == "copy":
            size = cd.get("size")
            if size is None:
                err.channel(i, label, "size", "missing (the value's size in bytes)")
                ok = False
            elif not _is_int(size) or size <= 0:
                err.channel(i, label, "size", f"{_describe(size)} is not a positive integer number of bytes")
                ok = False
            elif (size + 3) // 4 > MAX_WORDS:
                err.channel(i, label, "size", f"{size} bytes = {(size + 3) // 4} words; the ROM's W field "
                            f"holds at most {MAX_WORDS} words ({4 * MAX_WORDS} bytes)")
                ok = False
            if not ok or not _is_int(size) or size <= 0:
                size = 4
            words = (size + 3) // 4
            p = cd.get("producer")
            if p is None:
                err.channel(i, label, "producer", "missing (the board that publishes the value)")
                ok = False
            elif not isinstance(p, str) or p not in board_index:
                if board_ok:
                    err.channel(i, label, "producer", f"unknown board {_describe(p)} (boards: {', '.join(boards)})")
                ok = False
            else:
                producer = board_index[p]
        else:
            for fld in ("producer", "size"):
                if fld in cd:
                    err.channel(i, label, fld, f"a {kind} channel has no {fld}: the controller "
                                f"generates its value ({'W = 1' if kind == 'time' else f'W = 1 + 2*n_chan = {status_words}'})")
                    ok = False
            words = 1 if kind == "time" else status_words
            size = 4 * words

        consumers = []
        cons = cd.get("consumers")
        if cons is None:
            err.channel(i, label, "consumers", "missing (a list of 1..4 boards)")
            ok = False
        else:
            if cons == "all":
                cons = [b for b in boards if producer is None or board_index[b] != producer]
                if len(cons) > MAX_DESTS:
                    err.channel(i, label, "consumers", f"\"all\" means {len(cons)} boards; a transfer has "
                                f"at most {MAX_DESTS} destinations")
                    ok = False
            if not isinstance(cons, list) or not cons:
                err.channel(i, label, "consumers", "must be a non-empty list of board names (or \"all\")")
                ok = False
            else:
                if len(cons) > MAX_DESTS:
                    err.channel(i, label, "consumers", f"{len(cons)} consumers; a transfer has at most "
                                f"{MAX_DESTS} destinations (split the channel)")
                    ok = False
                for c in cons:
                    if not isinstance(c, str) or c not in board_index:
                        if board_ok:
                            err.channel(i, label, "consumers", f"unknown board {_describe(c)} "
                                        f"(boards: {', '.join(boards)})")
                        ok = False
                        continue
                    bi = board_index[c]
                    if producer is not None and bi == producer:
                        err.channel(i, label, "consumers", f"board '{c}' is the producer; a consumer must be "
                                    "another board")
                        ok = False
                    elif bi in consumers:
                        err.channel(i, label, "consumers", f"board '{c}' is listed twice")
                        ok = False
                    else:
                        consumers.append(bi)

        mp = cd.get("max_period_us")
        if mp is None:
            err.channel(i, label, "max_period_us", "missing (the required maximal period between "
                        "transfers, in whole microseconds)")
            ok, mp = False, 1
        elif not _is_int(mp) or mp <= 0:
            err.channel(i, label, "max_period_us", f"{_describe(mp)} is not a positive integer number "
                        "of microseconds")
            ok, mp = False, 1

        sync = cd.get("sync", False)
        if not isinstance(sync, bool):
            err.channel(i, label, "sync", f"{_describe(sync)}: expected true or false")
            sync, ok = False, False
        if sync:
            n_sync += 1
            if mode != MODE_SYNC:
                err.channel(i, label, "sync", f"sync = true needs [system] mode = \"{MODE_SYNC}\" "
                            f"(this system is {mode})")
                ok = False
            elif kind != "copy":
                err.channel(i, label, "sync", f"the sync channel must be a copy channel (the position), "
                            f"not {kind}")
                ok = False
            elif n_sync > 1:
                err.channel(i, label, "sync", "more than one sync channel (exactly one starts the cycle)")
                ok = False

        prio = cd.get("priority", 0)
        if not _is_int(prio) or abs(prio) > 1000000:
            err.channel(i, label, "priority", f"{_describe(prio)} is not an integer")
            prio, ok = 0, False
        max_slots = cd.get("max_slots")
        if max_slots is not None and (not _is_int(max_slots) or max_slots <= 0):
            err.channel(i, label, "max_slots", f"{_describe(max_slots)} is not a positive integer")
            max_slots, ok = None, False

        if ok:
            channels.append(Channel(index=i, name=cname, kind=kind, ctype=ctype, size=size,
                                    words=words, producer=producer, consumers=consumers,
                                    max_period_us=mp, sync=sync, priority=prio,
                                    max_slots=max_slots))

    if len(chans) > bus.n_chan:
        err.general(f"too many channels: {len(chans)} channels but the controller has "
                    f"n_chan = {bus.n_chan} channel ids ([bus] n_chan)")
    if len(chans) > MAX_ENTRIES:
        err.general(f"too many channels: {len(chans)} channels need {len(chans)} ROM entries, "
                    f"at most {MAX_ENTRIES}")
    if mode == MODE_SYNC and n_sync == 0:
        err.system("mode", f"{MODE_SYNC} mode needs exactly one channel with sync = true "
                   "(the position channel that starts the cycle)")
    err.raise_if_any()

    system = System(name=name, clock_hz=clock_hz, boards=boards, ram_bytes=ram_bytes,
                    mode=mode, types_header=types_header, bus=bus, channels=channels, source=path)
    for ch in channels:
        ch.period_clocks = ch.max_period_us * clock_hz // 1_000_000
        if ch.period_clocks < 1:
            err.channel(ch.index, ch.name, "max_period_us", f"{ch.max_period_us} us is less than "
                        f"one clock at clock_hz = {clock_hz}")
    err.raise_if_any()
    return system


def load_description(path: str) -> System:
    data, text = load_toml(path)
    return parse_description(data, path, text)


# ---------------------------------------------------------------------------
# RAM allocation.

def channel_bytes(payload: int) -> int:
    """ALB_CHANNEL_BYTES: 4 control bytes + 3 buffers of the word-rounded payload."""
    return 4 + 3 * ((payload + 3) & ~3)


def allocate_ram(system: System):
    """Pack every board's channel instances word-aligned from address 0, in
    channel-id order (source and destination instances alike).  Returns
    {board index: [(channel, role, base, bytes), ...]}."""
    layout = {b: [] for b in range(len(system.boards))}
    nxt = [0] * len(system.boards)
    for ch in system.channels:
        ch.dst_bases = []
        if ch.producer is not None:
            size = channel_bytes(ch.size)
            ch.src_base = nxt[ch.producer]
            layout[ch.producer].append((ch, "source", ch.src_base, size))
            nxt[ch.producer] += size
        for b in ch.consumers:
            size = channel_bytes(ch.dst_size)
            ch.dst_bases.append(nxt[b])
            layout[b].append((ch, "destination", nxt[b], size))
            nxt[b] += size
    msgs = []
    for b, used in enumerate(nxt):
        ram = system.ram_bytes[b]
        if used > ram:
            detail = ", ".join(f"{ch.name} {role} {size} B" for ch, role, _, size in layout[b])
            msgs.append(f"{system.source}: board '{system.boards[b]}': RAM overflow: its channel instances "
                        f"need {used} bytes but ram_bytes is {ram} ({detail})")
        for ch, role, base, size in layout[b]:
            if base // 4 > MAX_BASE_WORD:
                msgs.append(f"{system.source}: board '{system.boards[b]}', channel '{ch.name}' ({role}): "
                            f"base word {base // 4} exceeds the 12-bit ROM field (max {MAX_BASE_WORD})")
    if msgs:
        raise ScheduleError(msgs)
    return layout


# ---------------------------------------------------------------------------
# Plan.

def transfer_accesses(ch: Channel) -> int:
    nd = len(ch.consumers)
    if ch.kind == "copy":
        return 3 + ch.words + nd * (ch.words + 3)
    return nd * (ch.words + 3)


def slot_length(ch: Channel, bus: Bus) -> int:
    return (bus.fetch_cycles + bus.first_access_extra + bus.access_cycles * transfer_accesses(ch)
            + bus.retry_budget + bus.guard_cycles)


def pub_offset(ch: Channel, bus: Bus, retries: bool) -> int:
    off = bus.fetch_cycles + bus.first_access_extra + bus.access_cycles * ch.accesses
    return off + (bus.retry_budget if retries else 0)


def channel_gaps(starts, cycle):
    """Gaps between consecutive slot starts of one channel, cyclic."""
    s = sorted(starts)
    return [(s[(i + 1) % len(s)] + (cycle if i + 1 == len(s) else 0)) - s[i] for i in range(len(s))]


def _score(order, starts, cycle, counts):
    """Per channel: largest gap * slots (C = perfectly even); sorted descending
    so tuples compare leximin-style (worst channel first)."""
    per = {}
    for sl, s in zip(order, starts):
        per.setdefault(sl[0], []).append(s)
    vals = []
    for k, ss in per.items():
        vals.append(max(channel_gaps(ss, cycle)) * counts[k])
    return tuple(sorted(vals, reverse=True))


def _place(order, targets, lengths, cap, fixed_first):
    """Positions for slots in the given order: min-max deviation from the
    targets (binary search), then slots as close to their targets as the
    corridor allows.  None if the order does not fit."""
    m = len(order)
    total = sum(lengths)
    if total > cap:
        return None

    def corridor(d):
        lo = [0] * m
        prev = 0
        for i in range(m):
            e = max(targets[i] - d, prev)
            if fixed_first and i == 0:
                e = 0
            lo[i] = e
            prev = e + lengths[i]
        if prev > cap:
            return None
        hi = [0] * m
        nxt = cap
        for i in range(m - 1, -1, -1):
            h = min(targets[i] + d, nxt - lengths[i])
            if fixed_first and i == 0:
                h = min(h, 0)
            if h < lo[i]:
                return None
            hi[i] = h
            nxt = h
        return lo, hi

    lo_d, hi_d = 0, cap
    best = corridor(hi_d)
    if best is None:
        return None
    while lo_d < hi_d:
        mid = (lo_d + hi_d) // 2
        c = corridor(mid)
        if c is None:
            lo_d = mid + 1
        else:
            hi_d, best = mid, c
    lo, hi = best
    pos = []
    prev = 0
    for i in range(m):
        p = min(max(targets[i], lo[i], prev), hi[i])
        pos.append(p)
        prev = p + lengths[i]
    return pos


def _balance(order, pos, lengths, cap, cycle, fixed_first, sweeps=40):
    """Coordinate descent: move each slot, within the room its neighbours in
    the plan leave, towards the midpoint of its channel neighbours."""
    m = len(order)
    by_ch = {}
    for i, sl in enumerate(order):
        by_ch.setdefault(sl[0], []).append(i)
    for _ in range(sweeps):
        moved = False
        for k, idx in by_ch.items():
            n = len(idx)
            if n < 2:
                continue
            for j, i in enumerate(idx):
                if fixed_first and i == 0:
                    continue
                p = pos[idx[j - 1]] - (cycle if j == 0 else 0)
                q = pos[idx[(j + 1) % n]] + (cycle if j + 1 == n else 0)
                want = (p + q) // 2
                lo = pos[i - 1] + lengths[i - 1] if i > 0 else 0
                hi = (pos[i + 1] if i + 1 < m else cap) - lengths[i]
                new = min(max(want, lo), hi)
                if new != pos[i]:
                    pos[i] = new
                    moved = True
        if not moved:
            break
    return pos


def place_slots(items, cycle, cap, sync_key=None, seed=1, budget=2500):
    """items: list of (key, length, count).  Returns [(key, start, j)] sorted by
    start, where j numbers the slots of a channel.  The sync channel's first
    slot (sync_key) is fixed at start 0."""
    counts = {k: n for k, _, n in items}
    length = {k: l for k, l, _ in items}
    keys = [k for k, _, _ in items]
    rng = random.Random(seed)
    fixed_first = sync_key is not None

    def build(phase):
        sl = []
        for k in keys:
            n = counts[k]
            for j in range(n):
                t = (phase[k] + j) * cycle / n
                sl.append((k, j, t))
        # the sync slot first; the rest by target, ties by channel order
        sl.sort(key=lambda x: (0 if (x[0] == sync_key and x[1] == 0) else 1, x[2], keys.index(x[0])))
        order = [(k, j) for k, j, _ in sl]
        targets = [int(t) for _, _, t in sl]
        return order, targets

    def evaluate(order, targets):
        lengths = [length[k] for k, _ in order]
        pos = _place(order, targets, lengths, cap, fixed_first)
        if pos is None:
            return None
        pos = _balance(order, pos, lengths, cap, cycle, fixed_first)
        return _score(order, pos, cycle, counts), pos

    def perfect(order, pos):
        """No channel's largest gap can shrink: each is ceil(C / n)."""
        per = {}
        for (k, _), p in zip(order, pos):
            per.setdefault(k, []).append(p)
        return all(max(channel_gaps(ss, cycle)) <= -(-cycle // counts[k]) for k, ss in per.items())

    candidates = []
    nk = len(keys)
    phases = [{k: 0.0 for k in keys}]
    phases.append({k: i / nk for i, k in enumerate(keys)})
    phases.append({k: (i + 0.5) / nk for i, k in enumerate(keys)})
    phases.append({k: 1 - (i + 1) / nk for i, k in enumerate(keys)})
    by_len = sorted(keys, key=lambda k: -length[k])
    phases.append({k: by_len.index(k) / nk for k in keys})
    for _ in range(40):
        phases.append({k: rng.random() for k in keys})
    for ph in phases:
        if sync_key is not None:
            ph[sync_key] = 0.0
        order, targets = build(ph)
        r = evaluate(order, targets)
        if r is not None:
            candidates.append((r[0], order, targets, r[1]))
    if not candidates:
        # fall back: back to back in channel order (always fits if the sum fits)
        order = [(k, j) for k in keys for j in range(counts[k])]
        if sync_key is not None:
            order.remove((sync_key, 0))
            order.insert(0, (sync_key, 0))
        pos, t = [], 0
        for k, _ in order:
            pos.append(t)
            t += length[k]
        return [(k, p, j) for (k, j), p in zip(order, pos)]
    candidates.sort(key=lambda c: c[0])

    # Local search on the order from the best few candidates: move one slot
    # to another place in the order (or swap two neighbours), keep the move
    # when the score improves.  A budget of evaluations keeps large plans
    # fast; everything is deterministic.
    m = len(candidates[0][1])
    budget = max(200, min(budget, 150000 // max(m, 1)))
    window = m if m <= 40 else 12
    first = 1 if fixed_first else 0
    best = None
    for score0, order0, targets0, pos0 in candidates[:2]:
        cur = (score0, list(zip(order0, targets0)), pos0)
        evals = 0
        done = perfect(order0, pos0)
        while not done and evals < budget:
            improved = False
            for i in range(first, m):
                for j in range(max(first, i - window), min(m, i + window + 1)):
                    if j == i or evals >= budget:
                        continue
                    seq = list(cur[1])
                    item = seq.pop(i)
                    if abs(i - j) == 1 and item[0][0] == seq[min(j, len(seq) - 1)][0][0]:
                        continue
                    seq.insert(j, (item[0], cur[2][j]))   # aim at the place it moves to
                    evals += 1
                    r = evaluate([o for o, _ in seq], [t for _, t in seq])
                    if r is not None and r[0] < cur[0]:
                        seq = [(o, p) for (o, _), p in zip(seq, r[1])]
                        cur = (r[0], seq, r[1])
                        improved = True
                        done = perfect([o for o, _ in seq], r[1])
                        break
                if done or evals >= budget:
                    break
            if not improved:
                break
        if best is None or cur[0] < best[0]:
            best = cur
        if perfect([o for o, _ in best[1]], best[2]):
            break
    best_score = best[0]
    order = [o for o, _ in best[1]]
    pos = best[2]
    # renumber slots of each channel in start order
    seen = {}
    out = []
    for (k, _), p in zip(order, pos):
        j = seen.get(k, 0)
        seen[k] = j + 1
        out.append((k, p, j))
    return out


def build_plan(system: System) -> Plan:
    bus = system.bus
    for ch in system.channels:
        ch.accesses = transfer_accesses(ch)
        ch.slot_len = slot_length(ch, bus)
    limiter = min(system.channels, key=lambda c: (c.period_clocks, c.index))
    cycle = limiter.period_clocks
    if cycle > 0xFFFFFFFF:
        raise ScheduleError(f"{system.source}: channel '{limiter.name}', field 'max_period_us': the cycle "
                            f"of {cycle} clocks does not fit the 32-bit ROM field H1")
    cap = cycle - (bus.poll_cycles if system.sync_mode else 0)
    need = sum(ch.slot_len for ch in system.channels)
    if need > cap:
        detail = ", ".join(f"{ch.name} {ch.slot_len}" for ch in system.channels)
        poll = (f", of which {bus.poll_cycles} stay idle for the position poll ([bus] poll_cycles)"
                if system.sync_mode else "")
        raise ScheduleError(
            f"{system.source}: infeasible plan: one slot per channel needs {need} clocks per cycle but "
            f"only {max(cap, 0)} are available: the cycle is {cycle} clocks "
            f"({limiter.max_period_us} us, the smallest max_period_us, of channel '{limiter.name}', "
            f"at clock_hz = {system.clock_hz}){poll}. Slot lengths in clocks: {detail}. "
            "Relax max_period_us, shrink or merge channels, or raise clock_hz.")

    # Redundant slots, round-robin by priority then shortest period.
    counts = {ch.index: 1 for ch in system.channels}
    used = need
    entries = len(system.channels)
    rr = sorted(system.channels, key=lambda c: (-c.priority, c.period_clocks, c.index))
    progress = True
    while progress and entries < MAX_ENTRIES:
        progress = False
        for ch in rr:
            if entries >= MAX_ENTRIES:
                break
            if ch.max_slots is not None and counts[ch.index] >= ch.max_slots:
                continue
            if used + ch.slot_len <= cap:
                counts[ch.index] += 1
                used += ch.slot_len
                entries += 1
                progress = True

    sync_ch = next((c for c in system.channels if c.sync), None)
    items = [(ch.index, ch.slot_len, counts[ch.index]) for ch in system.channels]
    placed = place_slots(items, cycle, cap, sync_key=sync_ch.index if sync_ch else None)
    by_index = {ch.index: ch for ch in system.channels}
    slots = []
    for k, start, j in placed:
        ch = by_index[k]
        slots.append(Slot(channel=ch, start=start, length=ch.slot_len, redundant=j > 0,
                          sync=(sync_ch is not None and ch is sync_ch and start == 0 and j == 0)))
    slots.sort(key=lambda s: (s.start, 0 if s.sync else 1))
    for ch in system.channels:
        ch.slots = sorted(s.start for s in slots if s.channel is ch)
    return Plan(cycle=cycle, capacity=cap, slots=slots, limiter=limiter)


def channel_bounds(system: System, plan: Plan, ch: Channel) -> dict:
    bus = system.bus
    gaps = channel_gaps(ch.slots, plan.cycle)
    period = max(gaps)
    pub_ff = pub_offset(ch, bus, False)
    pub_rt = pub_offset(ch, bus, True)
    b = {
        "guaranteed_period_clocks": period,
        "min_gap_clocks": min(gaps),
        "pub_offset_clocks": {"fault_free": pub_ff, "with_retries": pub_rt},
    }
    if ch.kind == "copy":
        ff = max(g + pub_ff - bus.sample_offset for g in gaps)
        rt = max(g + pub_rt - bus.sample_offset for g in gaps)
        b["latency_clocks"] = {"fault_free": ff, "with_retries": rt}
        b["age_bound_clocks"] = None
    else:
        b["latency_clocks"] = None
        b["age_bound_clocks"] = {"fault_free": period + pub_ff, "with_retries": period + pub_rt}
    return b


# ---------------------------------------------------------------------------
# Schedule ROM.

def dest_field(board: int, base_bytes: int) -> int:
    return ((board & 0xF) << 12) | ((base_bytes // 4) & 0xFFF)


def encode_entry(slot: Slot) -> list:
    ch = slot.channel
    flags = FLAG_SYNC if slot.sync else 0
    e0 = (KIND_CODE[ch.kind] << 28) | (flags << 24) | (ch.id << 16) | (len(ch.consumers) << 12) | ch.words
    e3 = dest_field(ch.producer, ch.src_base) if ch.kind == "copy" else 0
    d = [dest_field(b, base) for b, base in zip(ch.consumers, ch.dst_bases)] + [0] * (4 - len(ch.consumers))
    e4 = d[0] | (d[1] << 16)
    e5 = d[2] | (d[3] << 16)
    words = [e0, slot.start, slot.length, e3, e4, e5, 0]
    return words + [checksum(words)]


def encode_rom(system: System, plan: Plan) -> list:
    ne = len(plan.slots)
    h = [(ROM_MAGIC << 16) | (ne << 8) | (1 if system.sync_mode else 0), plan.cycle, 0]
    words = h + [checksum(h)]
    for s in plan.slots:
        words += encode_entry(s)
    return words


def rom_hex(words) -> str:
    return "".join(f"{w:08x}\n" for w in words)


def parse_rom_hex(text: str) -> list:
    words = []
    for ln, line in enumerate(text.splitlines(), 1):
        line = line.split("//")[0].strip()
        if not line:
            continue
        if not re.fullmatch(r"[0-9a-fA-F]{8}", line):
            raise ValueError(f"line {ln}: {line!r} is not 8 hex digits")
        words.append(int(line, 16))
    return words


def verify_rom(words, n_chan=16, n_boards=16, ram_words=1024, sync_expected=None):
    """Check a ROM image against the README contract (header, checksums,
    entry validation rules).  ram_words: int or list per board.  Returns a
    list of problems (empty: valid) and the decoded entries."""
    problems = []
    entries = []
    if len(words) < 4:
        return ["ROM shorter than its 4-word header"], entries
    h0, h1, h2, h3 = words[:4]
    if h0 >> 16 != ROM_MAGIC:
        problems.append(f"H0 magic {h0 >> 16:#06x}, expected {ROM_MAGIC:#06x}")
    if checksum(words[:3]) != h3:
        problems.append(f"header checksum {h3:#010x}, expected {checksum(words[:3]):#010x}")
    if h2 != 0:
        problems.append("H2 (reserved) is not 0")
    ne = (h0 >> 8) & 0xFF
    sync_mode = bool(h0 & 1)
    if h0 & 0xFE:
        problems.append("H0 reserved flag bits set")
    if sync_expected is not None and sync_mode != sync_expected:
        problems.append(f"H0 sync flag {int(sync_mode)}, expected {int(sync_expected)}")
    if not 1 <= ne <= MAX_ENTRIES:
        problems.append(f"entry count {ne} outside 1..{MAX_ENTRIES}")
    if len(words) != 4 + 8 * ne:
        problems.append(f"ROM has {len(words)} words, header says {ne} entries = {4 + 8 * ne} words")
    cycle = h1
    prev_end = 0
    for k in range(ne):
        e = words[4 + 8 * k: 12 + 8 * k]
        if len(e) < 8:
            break
        tag = f"entry {k}"
        kind, flags = e[0] >> 28, (e[0] >> 24) & 0xF
        cid, nd, w = (e[0] >> 16) & 0xFF, (e[0] >> 12) & 0xF, e[0] & 0xFFF
        ent = {"kind": KIND_NAME.get(kind, kind), "flags": flags, "id": cid, "nd": nd, "w": w,
               "start": e[1], "length": e[2], "src": (e[3] >> 12 & 0xF, e[3] & 0xFFF),
               "dst": [((f >> 12) & 0xF, f & 0xFFF) for f in (e[4] & 0xFFFF, e[4] >> 16, e[5] & 0xFFFF, e[5] >> 16)][:nd]}
        entries.append(ent)
        if checksum(e[:7]) != e[7]:
            problems.append(f"{tag}: checksum {e[7]:#010x}, expected {checksum(e[:7]):#010x}")
        if kind not in KIND_NAME:
            problems.append(f"{tag}: unknown kind {kind}")
            continue
        if e[6] != 0:
            problems.append(f"{tag}: E6 (reserved) is not 0")
        if flags & FLAG_SYNC and (k != 0 or not sync_mode):
            problems.append(f"{tag}: SYNC flag outside entry 0 of a position-synchronised ROM")
        if sync_mode and k == 0 and not (flags & FLAG_SYNC and kind == 1 and e[1] == 0):
            problems.append(f"{tag}: a position-synchronised ROM starts with a SYNC COPY at 0")
        if kind == 0:
            continue
        if not 1 <= nd <= 4:
            problems.append(f"{tag}: ND {nd} outside 1..4")
        if cid >= n_chan:
            problems.append(f"{tag}: channel id {cid} >= N_CHAN {n_chan}")
        if kind == 2 and w != 1:
            problems.append(f"{tag}: TIME with W = {w}, expected 1")
        if kind == 3 and w != 1 + 2 * n_chan:
            problems.append(f"{tag}: STATUS with W = {w}, expected {1 + 2 * n_chan}")
        exts = [(ent["dst"][i], w + 1) for i in range(min(nd, 4))]
        if kind == 1:
            exts.append((ent["src"], w))
        elif e[3] != 0:
            problems.append(f"{tag}: E3 (source) set on a {KIND_NAME[kind]} entry")
        for (board, base), stride in exts:
            if board >= n_boards:
                problems.append(f"{tag}: board {board} >= NB {n_boards}")
                continue
            rw = ram_words[board] if isinstance(ram_words, (list, tuple)) else ram_words
            if base + 1 + 3 * stride > rw:
                problems.append(f"{tag}: channel at board {board} word {base} (stride {stride}) "
                                f"ends past the RAM ({rw} words)")
        if e[1] < prev_end:
            problems.append(f"{tag}: starts at {e[1]}, before the previous slot ends at {prev_end}")
        if e[1] + e[2] > cycle:
            problems.append(f"{tag}: ends at {e[1] + e[2]}, after the cycle ({cycle})")
        prev_end = e[1] + e[2]
    return problems, entries


def verify_ram_layout(instances, ram_bytes):
    """instances: [(name, base, bytes)] of one board.  Returns problems:
    misaligned, outside the RAM, or overlapping instances."""
    problems = []
    spans = sorted(instances, key=lambda x: x[1])
    for name, base, size in spans:
        if base % 4:
            problems.append(f"{name}: base {base} not word-aligned")
        if base < 0 or base + size > ram_bytes:
            problems.append(f"{name}: [{base}, {base + size}) outside the RAM of {ram_bytes} bytes")
    for a, b in zip(spans, spans[1:]):
        if a[1] + a[2] > b[1]:
            problems.append(f"{a[0]} [{a[1]}, {a[1] + a[2]}) overlaps {b[0]} at {b[1]}")
    return problems


# ---------------------------------------------------------------------------
# Generated C.

def _guard(system, board):
    return f"ALB_{system.name.upper()}_{board.upper()}_H"


def board_instances(system: System, b: int):
    out = []
    for ch in system.channels:
        if ch.producer == b:
            out.append((ch, "source", ch.src_base))
        for k, cb in enumerate(ch.consumers):
            if cb == b:
                out.append((ch, "destination", ch.dst_bases[k]))
    return out


def _route(system, ch):
    src = system.boards[ch.producer] if ch.producer is not None else f"controller ({ch.kind})"
    return f"{src} -> {', '.join(system.boards[c] for c in ch.consumers)}"


def render_board_header(system: System, b: int, desc_name: str, plan: Plan) -> str:
    board = system.boards[b]
    B = board.upper()
    insts = board_instances(system, b)
    L = []
    L.append(f"/*\n * {board}.h -- ALBATROSS channels of board '{board}' (index {b}) of system "
             f"'{system.name}'.\n * Generated by compiler/albatross_schedule.py from {desc_name}; "
             "do not edit.\n *")
    L.append(" * Producer side: Make<Name>Available(const Type *v) publishes a value.")
    L.append(" * Consumer side: LookForNew<Name>(<Name>_msg *m) is true for a value never read")
    L.append(" * before; m->taken_at is the controller's global time when it took the value")
    L.append(" * (age = now - taken_at).  Call alb_" + board + "_attach_all() when the RAM was")
    L.append(" * loaded with " + board + "_ram.hex (or on a restart), alb_" + board + "_init_all() on a")
    L.append(" * cold start without that image.  Include only one board header per program.\n */")
    L.append(f"#ifndef {_guard(system, board)}")
    L.append(f"#define {_guard(system, board)}")
    L.append("")
    L.append("#include <stddef.h>")
    L.append("#include <stdint.h>")
    L.append('#include "albatross.h"')
    if system.types_header:
        L.append(f'#include "{system.types_header}"')
    L.append("")
    L.append(f"#define ALB_{B}_BOARD      {b}u")
    L.append(f"#define ALB_{B}_RAM_BYTES  {system.ram_bytes[b]}u")
    L.append("")
    L.append("/* Channel ids of the system (they index the STATUS counters). */")
    w = max(len(c.name) for c in system.channels)
    for ch in system.channels:
        L.append(f"#define ALB_{ch.name.upper() + '_ID':<{w + 3}} {ch.id}u")
    if any(ch.kind == "status" for ch, _, _ in insts):
        L.append("")
        L.append("/* STATUS words (w = <Status>_msg.value.word): word 0 = {rom_errors, cycles},")
        L.append(" * then per channel id {transfers, retries} and {abandoned, corrupt}. */")
        L.append("#define ALB_STATUS_CYCLES(w)         ((uint16_t)((w)[0] & 0xFFFFu))")
        L.append("#define ALB_STATUS_ROM_ERRORS(w)     ((uint16_t)((w)[0] >> 16))")
        L.append("#define ALB_STATUS_RETRIES(w, id)    ((uint16_t)((w)[1u + 2u * (id)] & 0xFFFFu))")
        L.append("#define ALB_STATUS_TRANSFERS(w, id)  ((uint16_t)((w)[1u + 2u * (id)] >> 16))")
        L.append("#define ALB_STATUS_CORRUPT(w, id)    ((uint16_t)((w)[2u + 2u * (id)] & 0xFFFFu))")
        L.append("#define ALB_STATUS_ABANDONED(w, id)  ((uint16_t)((w)[2u + 2u * (id)] >> 16))")
    for ch, role, base in insts:
        N = ch.name.upper()
        T = ch.type_name
        L.append("")
        L.append(f"/* {ch.name}: {ch.kind}, {_route(system, ch)}; this board is the "
                 f"{'producer' if role == 'source' else 'consumer'}. */")
        if ch.ctype is None and ch.kind == "copy":
            L.append(f"typedef struct {{ uint8_t bytes[{ch.size}]; }} {T};")
        elif ch.ctype is None and ch.kind == "status":
            L.append(f"typedef struct {{ uint32_t word[{ch.words}]; }} {T};")
        payload = ch.size if role == "source" else ch.dst_size
        L.append(f"#define ALB_{N}_BASE   0x{base:04x}u  /* byte offset in this board's RAM */")
        L.append(f"#define ALB_{N}_SIZE   {payload}u  /* payload bytes of this instance"
                 + (" (value + taken_at) */" if role == "destination" else " */"))
        L.append(f"#define ALB_{N}_WORDS  {ch.words}u  /* W, the value's words */")
        if role == "destination":
            bnd = channel_bounds(system, plan, ch)
            L.append(f"#define ALB_{N}_PERIOD_CLOCKS  {bnd['guaranteed_period_clocks']}u"
                     "  /* guaranteed: a transfer slot at least this often */")
            if ch.kind == "copy":
                L.append(f"#define ALB_{N}_LATENCY_CLOCKS  {bnd['latency_clocks']['with_retries']}u"
                         "  /* guaranteed: producer's Export -> published here (with retries) */")
            else:
                L.append(f"#define ALB_{N}_AGE_CLOCKS  {bnd['age_bound_clocks']['with_retries']}u"
                         "  /* guaranteed: now - taken_at of the newest value here (with retries) */")
        L.append(f"typedef char alb_check_{ch.name}_size[(sizeof({T}) == {ch.size}u) ? 1 : -1];")
        if role == "source":
            L.append(f"ALB_CHANNEL({ch.name}, {T})")
        else:
            L.append(f"typedef struct {{ {T} value; uint32_t taken_at; }} {ch.name}_msg;")
            L.append(f"typedef char alb_check_{ch.name}_taken_at"
                     f"[(offsetof({ch.name}_msg, taken_at) == 4u * {ch.words}u) ? 1 : -1];")
            L.append(f"ALB_CHANNEL({ch.name}, {ch.name}_msg)")
    L.append("")
    L.append(f"/* Set up every channel of board '{board}' at dpram_base (this CPU's address of")
    L.append(" * its dual-ported RAM).  Both return ALB_OK or the first error. */")
    L.append(f"int alb_{board}_init_all(uintptr_t dpram_base);    /* cold start: own control bytes := Buffer1 */")
    L.append(f"int alb_{board}_attach_all(uintptr_t dpram_base);  /* RAM image loaded, or restart */")
    L.append("")
    L.append(f"#endif /* {_guard(system, board)} */")
    return "\n".join(L) + "\n"


def render_board_c(system: System, b: int, desc_name: str) -> str:
    board = system.boards[b]
    insts = board_instances(system, b)
    src_words = [ch.words for ch, role, _ in insts if role == "source"]
    L = [f"/* {board}.c -- channel objects and set-up of board '{board}' (system '{system.name}').",
         f" * Generated by compiler/albatross_schedule.py from {desc_name}; do not edit. */",
         f'#include "{board}.h"', ""]
    for ch, _, _ in insts:
        L.append(f"ALB_CHANNEL_DEFINE({ch.name});")
    if insts:
        L.append("")
        L.append("static int alb_first_error(int rc, int r)")
        L.append("{")
        L.append("    return rc != ALB_OK ? rc : r;")
        L.append("}")
    for mode in ("init", "attach"):
        L.append("")
        L.append(f"int alb_{board}_{mode}_all(uintptr_t dpram_base)")
        L.append("{")
        if not insts:
            L.append("    (void)dpram_base;")
            L.append("    return ALB_OK;")
            L.append("}")
            continue
        if mode == "init" and src_words:
            L.append(f"    static const uint32_t zero[{max(src_words)}]; /* initial value of every source */")
        L.append("    int rc = ALB_OK;")
        L.append("")
        for ch, role, _ in insts:
            N = ch.name.upper()
            obj = f"&alb_ch_{ch.name}"
            L.append(f"    rc = alb_first_error(rc, alb_channel_setup({obj}, dpram_base + ALB_{N}_BASE, ALB_{N}_SIZE));")
            if role == "source":
                call = f"alb_producer_init({obj}, zero)" if mode == "init" else f"alb_producer_attach({obj})"
            else:
                call = f"alb_consumer_init({obj})" if mode == "init" else f"alb_consumer_attach({obj})"
            L.append(f"    rc = alb_first_error(rc, {call});")
        L.append("    return rc;")
        L.append("}")
    return "\n".join(L) + "\n"


def render_ram_hex(system: System, b: int) -> str:
    words = [0] * (system.ram_bytes[b] // 4)
    for _, _, base in board_instances(system, b):
        words[base // 4] = 0x00000101     # Actual = ReadLocked = Buffer1
    return rom_hex(words)


# ---------------------------------------------------------------------------
# Reports.

def build_report(system: System, plan: Plan) -> dict:
    hz = system.clock_hz
    bus = system.bus

    def t(c):
        return {"clocks": c, "us": round(us(c, hz), 3)}

    chans = []
    busy_bus = busy_ctl = fill = 0
    for ch in system.channels:
        b = channel_bounds(system, plan, ch)
        n = len(ch.slots)
        busy_bus += n * bus.access_cycles * ch.accesses
        busy_ctl += n * pub_offset(ch, bus, False)
        fill += n * ch.slot_len
        entry = {
            "name": ch.name, "id": ch.id, "kind": ch.kind, "type": ch.type_name,
            "size": ch.size, "words": ch.words,
            "producer": ({"board": system.boards[ch.producer], "board_index": ch.producer,
                          "base": ch.src_base} if ch.producer is not None else None),
            "consumers": [{"board": system.boards[c], "board_index": c, "base": base}
                          for c, base in zip(ch.consumers, ch.dst_bases)],
            "sync": ch.sync, "priority": ch.priority,
            "max_period": t(ch.period_clocks), "max_period_us_required": ch.max_period_us,
            "accesses": ch.accesses, "slot_length": ch.slot_len,
            "slots": [{"start": s.start, "length": s.length, "entry": i, "redundant": s.redundant,
                       "sync": s.sync} for i, s in enumerate(plan.slots) if s.channel is ch],
            "redundancy": n,
            "guaranteed_period": t(b["guaranteed_period_clocks"]),
            "min_gap": t(b["min_gap_clocks"]),
            "latency": None if b["latency_clocks"] is None else {
                "fault_free": t(b["latency_clocks"]["fault_free"]),
                "with_retries": t(b["latency_clocks"]["with_retries"])},
            "age_bound": None if b["age_bound_clocks"] is None else {
                "fault_free": t(b["age_bound_clocks"]["fault_free"]),
                "with_retries": t(b["age_bound_clocks"]["with_retries"])},
        }
        chans.append(entry)
    boards = []
    for bi, name in enumerate(system.boards):
        insts = [{"channel": ch.name, "role": role, "base": base,
                  "bytes": channel_bytes(ch.size if role == "source" else ch.dst_size)}
                 for ch, role, base in board_instances(system, bi)]
        boards.append({"name": name, "index": bi, "ram_bytes": system.ram_bytes[bi],
                       "used_bytes": sum(i["bytes"] for i in insts), "instances": insts})
    return {
        "generator": "compiler/albatross_schedule.py",
        "description": os.path.basename(system.source),
        "system": system.name, "mode": system.mode, "clock_hz": hz,
        "cycle": t(plan.cycle),
        "cycle_limited_by": plan.limiter.name,
        "capacity_clocks": plan.capacity,
        "entries": len(plan.slots),
        "bus": dataclasses.asdict(bus),
        "definitions": {
            "slot_length": "fetch + first_access_extra + access_cycles*A + retries_per_slot*(timeout+access+1) + guard",
            "guaranteed_period": "largest gap between consecutive slot starts of the channel (cyclic)",
            "latency": "producer's store of source Actual -> controller's store of the last destination Actual: "
                       "max over slots of start(next)+pub_offset - (start+fetch+access)",
            "age_bound": "TIME/STATUS: guaranteed_period + pub_offset",
            "bus_utilisation": "sum over slots of access_cycles*A (fault-free bus-busy clocks) / cycle",
            "controller_busy": "sum over slots of fetch + first_access_extra + access_cycles*A / cycle",
            "schedule_fill": "sum of slot lengths / cycle",
        },
        "bus_utilisation": round(busy_bus / plan.cycle, 4),
        "controller_busy": round(busy_ctl / plan.cycle, 4),
        "schedule_fill": round(fill / plan.cycle, 4),
        "channels": chans,
        "boards": boards,
        "entries_list": [{"entry": i, "channel": s.channel.name, "id": s.channel.id, "kind": s.channel.kind,
                          "start": s.start, "length": s.length, "redundant": s.redundant, "sync": s.sync}
                         for i, s in enumerate(plan.slots)],
    }


def render_report_txt(rep: dict) -> str:
    def f(x):
        return f"{x:.2f}"

    L = []
    L.append(f"ALBATROSS schedule of '{rep['system']}' ({rep['description']}), {rep['mode']}")
    L.append(f"clock {rep['clock_hz']} Hz; cycle {rep['cycle']['clocks']} clocks = {f(rep['cycle']['us'])} us "
             f"(smallest max_period: {rep['cycle_limited_by']}); {rep['entries']} ROM entries")
    L.append(f"bus utilisation {100 * rep['bus_utilisation']:.1f} % (fault-free accesses), controller busy "
             f"{100 * rep['controller_busy']:.1f} %, slots fill {100 * rep['schedule_fill']:.1f} % of the cycle")
    L.append("")
    hdr = ["id", "channel", "kind", "route", "W", "A", "L", "slots", "max period", "guar. period",
           "latency ff", "latency retry", "age ff", "age retry"]
    rows = []
    for c in rep["channels"]:
        src = c["producer"]["board"] if c["producer"] else "controller"
        route = f"{src}->{','.join(d['board'] for d in c['consumers'])}"
        lat = c["latency"]
        age = c["age_bound"]
        rows.append([str(c["id"]), c["name"] + (" (sync)" if c["sync"] else ""), c["kind"], route,
                     str(c["words"]), str(c["accesses"]), str(c["slot_length"]), str(c["redundancy"]),
                     f(c["max_period"]["us"]), f(c["guaranteed_period"]["us"]),
                     f(lat["fault_free"]["us"]) if lat else "-", f(lat["with_retries"]["us"]) if lat else "-",
                     f(age["fault_free"]["us"]) if age else "-", f(age["with_retries"]["us"]) if age else "-"])
    widths = [max(len(r[i]) for r in rows + [hdr]) for i in range(len(hdr))]
    L.append("  ".join(h.ljust(w) for h, w in zip(hdr, widths)))
    L.append("  ".join("-" * w for w in widths))
    for r in rows:
        L.append("  ".join(v.ljust(w) if i < 4 else v.rjust(w) for i, (v, w) in enumerate(zip(r, widths))))
    L.append("(times in us; W words, A fault-free accesses, L slot clocks; slots = redundancy factor)")
    L.append("")
    L.append("RAM per board (byte offsets)")
    for b in rep["boards"]:
        L.append(f"  {b['name']} (board {b['index']}): {b['used_bytes']} of {b['ram_bytes']} bytes")
        for i in b["instances"]:
            L.append(f"    0x{i['base']:04x}  {i['bytes']:5d} B  {i['channel']} ({i['role']})")
    L.append("")
    L.append("ROM entries")
    L.append("  entry  start    end      channel")
    for e in rep["entries_list"]:
        tag = " SYNC" if e["sync"] else (" (redundant)" if e["redundant"] else "")
        L.append(f"  {e['entry']:5d}  {e['start']:7d}  {e['start'] + e['length']:7d}  {e['channel']}{tag}")
    return "\n".join(L) + "\n"


PALETTE = ["#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948", "#b07aa1",
           "#ff9da7", "#9c755f", "#bab0ac"]


def _esc(s: str) -> str:
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")


def _nice_step(span: float, target: int = 10) -> float:
    raw = span / target
    mag = 10 ** math.floor(math.log10(raw)) if raw > 0 else 1
    for m in (1, 2, 2.5, 5, 10):
        if raw <= m * mag:
            return m * mag
    return 10 * mag


def _lighten(hex_color: str, f: float) -> str:
    r, g, b = (int(hex_color[i:i + 2], 16) for i in (1, 3, 5))
    r, g, b = (round(v + (255 - v) * f) for v in (r, g, b))
    return f"#{r:02x}{g:02x}{b:02x}"


def render_svg(system: System, plan: Plan, rep: dict) -> str:
    hz = system.clock_hz
    C = plan.cycle
    routes = {ch.index: f"{system.boards[ch.producer] if ch.producer is not None else 'controller'} "
                        f"\u2192 {', '.join(system.boards[c] for c in ch.consumers)}" for ch in system.channels}
    label_w = int(max([200] + [5.6 * len(r) + 24 for r in routes.values()]
                      + [7.4 * len(ch.name) + 70 for ch in system.channels]))
    right_w, plot_w = 190, 1000
    width = label_w + plot_w + right_w
    top, lane_h, box_h = 74, 34, 22
    n_lanes = 1 + len(system.channels)
    axis_y = top + n_lanes * lane_h + 6
    legend_y = axis_y + 40
    height = legend_y + 38
    sx = plot_w / C

    def X(clk):
        return label_w + clk * sx

    colors = {ch.index: PALETTE[i % len(PALETTE)] for i, ch in enumerate(system.channels)}
    font = "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\""
    o = []
    o.append(f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
             f'viewBox="0 0 {width} {height}" {font}>')
    o.append('<defs><pattern id="hatch" patternUnits="userSpaceOnUse" width="6" height="6" '
             'patternTransform="rotate(45)"><rect width="2.2" height="6" fill="#ffffff" '
             'fill-opacity="0.55"/></pattern></defs>')
    o.append(f'<rect width="{width}" height="{height}" fill="#ffffff"/>')
    title = (f"{system.name}: one schedule cycle = {C} clocks = {us(C, hz):g} \u00b5s "
             f"({system.mode}, {hz / 1e6:g} MHz)")
    o.append(f'<text x="{label_w}" y="24" font-size="16" font-weight="bold" fill="#222">{_esc(title)}</text>')
    sub = (f"{len(plan.slots)} ROM entries \u00b7 bus utilisation {100 * rep['bus_utilisation']:.1f} % "
           f"(fault-free accesses) \u00b7 slots fill {100 * rep['schedule_fill']:.1f} % of the cycle")
    o.append(f'<text x="{label_w}" y="44" font-size="12" fill="#555">{_esc(sub)}</text>')
    o.append(f'<text x="{label_w + plot_w + 12}" y="{top - 8}" font-size="11" fill="#555">'
             'guaranteed period / required</text>')

    # grid + axis
    step_us = _nice_step(us(C, hz), 10)
    tick = 0.0
    ticks = []
    while tick <= us(C, hz) + 1e-9:
        ticks.append(tick)
        tick += step_us
    for tu in ticks:
        x = X(tu * hz / 1e6)
        o.append(f'<line x1="{x:.1f}" y1="{top - 4}" x2="{x:.1f}" y2="{axis_y}" stroke="#e6e6e6" stroke-width="1"/>')
        o.append(f'<text x="{x:.1f}" y="{axis_y + 16}" font-size="11" fill="#444" text-anchor="middle">{tu:g}</text>')
    o.append(f'<line x1="{X(0)}" y1="{axis_y}" x2="{X(C):.1f}" y2="{axis_y}" stroke="#444" stroke-width="1"/>')
    o.append(f'<text x="{X(C):.1f}" y="{axis_y + 32}" font-size="11" fill="#444" text-anchor="end">'
             'time from cycle start (\u00b5s)</text>')
    o.append(f'<line x1="{X(C):.1f}" y1="{top - 4}" x2="{X(C):.1f}" y2="{axis_y}" stroke="#444" '
             'stroke-width="1" stroke-dasharray="4,3"/>')
    if system.sync_mode:
        x0 = X(plan.capacity)
        o.append(f'<rect x="{x0:.1f}" y="{top}" width="{X(C) - x0:.1f}" height="{n_lanes * lane_h}" '
                 'fill="#999" fill-opacity="0.12"/>')
        o.append(f'<text x="{X(C) - 3:.1f}" y="{top - 8}" font-size="10" fill="#777" text-anchor="end">'
                 'poll for next position</text>')

    short = {}
    for ch in system.channels:
        caps = "".join(c for c in ch.name if c.isupper() or c.isdigit()) or ch.name[:2]
        cand = caps if len(caps) >= 2 else ch.name[:2]
        while cand in short.values() and len(cand) < len(ch.name):
            cand = ch.name[:len(cand) + 1]
        short[ch.index] = cand

    def box(ch, s, y, label_mode):
        x, w = X(s.start), max(s.length * sx, 1.0)
        col = colors[ch.index]
        busy = pub_offset(ch, system.bus, False) * sx
        parts = []
        parts.append(f'<rect x="{x:.2f}" y="{y}" width="{w:.2f}" height="{box_h}" fill="{_lighten(col, 0.65)}"/>')
        parts.append(f'<rect x="{x:.2f}" y="{y}" width="{min(busy, w):.2f}" height="{box_h}" fill="{col}"/>')
        if s.redundant:
            parts.append(f'<rect x="{x:.2f}" y="{y}" width="{w:.2f}" height="{box_h}" fill="url(#hatch)"/>')
        dash = ' stroke-dasharray="3,2"' if s.redundant else ""
        parts.append(f'<rect x="{x:.2f}" y="{y}" width="{w:.2f}" height="{box_h}" fill="none" '
                     f'stroke="{col}" stroke-width="1"{dash}/>')
        if s.sync:
            parts.append(f'<text x="{x + 2:.2f}" y="{y - 2}" font-size="9" font-weight="bold" fill="#222">SYNC</text>')
        # label: the channel name, shortened to what fits
        fits = int((w - 3) / 6.1)
        if label_mode == "name":
            text = next((t for t in (ch.name, short[ch.index]) if len(t) <= fits), "")
        else:
            text = label_mode if len(label_mode) <= fits else ""
        if text:
            parts.append(f'<text x="{x + w / 2:.2f}" y="{y + box_h / 2 + 4}" font-size="10.5" '
                         f'text-anchor="middle" fill="#111" style="paint-order:stroke" stroke="#ffffff" '
                         f'stroke-width="2.5" stroke-opacity="0.75">{_esc(text)}</text>')
        parts.append(f'<title>{_esc(ch.name)} entry slot {s.start}..{s.start + s.length} clocks'
                     f'{" (redundant)" if s.redundant else ""}</title>')
        return "<g>" + "".join(parts) + "</g>"

    # lane 0: the bus, all slots
    y0 = top
    o.append(f'<rect x="0" y="{y0}" width="{width}" height="{lane_h}" fill="#f4f6f8"/>')
    o.append(f'<text x="{label_w - 10}" y="{y0 + lane_h / 2 + 4}" font-size="12" font-weight="bold" '
             f'text-anchor="end" fill="#222">system bus (all slots)</text>')
    for s in plan.slots:
        o.append(box(s.channel, s, y0 + (lane_h - box_h) // 2, "name"))
    # one lane per channel
    for li, ch in enumerate(system.channels, 1):
        y = top + li * lane_h
        if li % 2 == 0:
            o.append(f'<rect x="0" y="{y}" width="{width}" height="{lane_h}" fill="#fafafa"/>')
        route = routes[ch.index]
        o.append(f'<text x="{label_w - 10}" y="{y + 15}" font-size="12" font-weight="bold" text-anchor="end" '
                 f'fill="{colors[ch.index]}">{_esc(ch.name)}{" (sync)" if ch.sync else ""}</text>')
        o.append(f'<text x="{label_w - 10}" y="{y + 28}" font-size="9.5" text-anchor="end" fill="#666">'
                 f'{_esc(route)}</text>')
        for e, s in enumerate(plan.slots):
            if s.channel is ch:
                o.append(box(ch, s, y + (lane_h - box_h) // 2, f"#{e}"))
        c = next(c for c in rep["channels"] if c["id"] == ch.id)
        o.append(f'<text x="{label_w + plot_w + 12}" y="{y + 15}" font-size="11" fill="#222">'
                 f'{c["guaranteed_period"]["us"]:g} / {ch.max_period_us} \u00b5s</text>')
        o.append(f'<text x="{label_w + plot_w + 12}" y="{y + 28}" font-size="9.5" fill="#666">'
                 f'\u00d7{len(ch.slots)} per cycle, L = {ch.slot_len} clk</text>')

    # legend
    lx, ly = label_w, legend_y
    col = "#4e79a7"
    items = [("transfer, fault-free", col, False, False), ("retry reserve + guard", _lighten(col, 0.65), False, False),
             ("redundant slot", col, True, False)]
    for text, fill, hatched, _ in items:
        o.append(f'<rect x="{lx}" y="{ly}" width="26" height="14" fill="{fill}"/>')
        if hatched:
            o.append(f'<rect x="{lx}" y="{ly}" width="26" height="14" fill="url(#hatch)"/>')
            o.append(f'<rect x="{lx}" y="{ly}" width="26" height="14" fill="none" stroke="{col}" stroke-dasharray="3,2"/>')
        o.append(f'<text x="{lx + 32}" y="{ly + 11}" font-size="11" fill="#333">{_esc(text)}</text>')
        lx += 40 + 6.5 * len(text)
    o.append(f'<text x="{lx}" y="{ly + 11}" font-size="11" fill="#666">'
             '#n: ROM entry n \u00b7 first slot of a channel solid, redundant slots hatched</text>')
    o.append("</svg>")
    return "\n".join(o) + "\n"


# ---------------------------------------------------------------------------
# Whole compilation.

def self_check(system: System, plan: Plan, rom: list, layout: dict):
    """Verify our own output against the contract before writing anything."""
    problems, entries = verify_rom(rom, n_chan=system.bus.n_chan, n_boards=len(system.boards),
                                   ram_words=[r // 4 for r in system.ram_bytes],
                                   sync_expected=system.sync_mode)
    for b, insts in layout.items():
        problems += verify_ram_layout([(f"{ch.name} {role}", base, size) for ch, role, base, size in insts],
                                      system.ram_bytes[b])
    for ch in system.channels:
        if not ch.slots:
            problems.append(f"channel {ch.name} has no slot")
        elif max(channel_gaps(ch.slots, plan.cycle)) > ch.period_clocks:
            problems.append(f"channel {ch.name}: guaranteed period exceeds max_period")
    if system.sync_mode and plan.slots[-1].start + plan.slots[-1].length + system.bus.poll_cycles > plan.cycle:
        problems.append("no poll window at the end of the cycle")
    if problems:
        raise AssertionError("internal error, the plan breaks the contract: " + "; ".join(problems))


def compile_system(system: System):
    layout = allocate_ram(system)
    plan = build_plan(system)
    rom = encode_rom(system, plan)
    self_check(system, plan, rom, layout)
    rep = build_report(system, plan)
    return plan, rom, rep


def generate(system: System, plan: Plan, rom: list, rep: dict) -> dict:
    """All output files: {file name: text}."""
    desc = os.path.basename(system.source)
    files = {"rom.hex": rom_hex(rom),
             "report.json": json.dumps(rep, indent=2) + "\n",
             "report.txt": render_report_txt(rep),
             "timeline.svg": render_svg(system, plan, rep)}
    for b, name in enumerate(system.boards):
        files[f"{name}.h"] = render_board_header(system, b, desc, plan)
        files[f"{name}.c"] = render_board_c(system, b, desc)
        files[f"{name}_ram.hex"] = render_ram_hex(system, b)
    return files


def write_outputs(files: dict, out_dir: str):
    try:
        os.makedirs(out_dir, exist_ok=True)
        # rom.hex last: its time stamp (the make target) is the newest
        for name in sorted(files, key=lambda n: n == "rom.hex"):
            text = files[name]
            path = os.path.join(out_dir, name)
            tmp = path + ".tmp"
            with open(tmp, "w", newline="\n") as f:
                f.write(text)
            os.replace(tmp, path)
    except OSError as e:
        raise ScheduleError(f"{out_dir}: cannot write the outputs: {e.strerror or e}")


def compile_file(path: str, out_dir: Optional[str] = None, no_redundancy: bool = False):
    system = load_description(path)
    if no_redundancy:   # one slot per channel and cycle: the spare capacity stays idle
        for ch in system.channels:
            ch.max_slots = 1
    plan, rom, rep = compile_system(system)
    files = generate(system, plan, rom, rep)
    if out_dir is not None:
        write_outputs(files, out_dir)
    return system, plan, rep, files


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description="ALBATROSS schedule compiler: system description (TOML) "
                                 "-> schedule ROM, board headers, RAM images, reports.")
    ap.add_argument("description", help="system description (.toml)")
    ap.add_argument("--out", required=True, help="output directory")
    ap.add_argument("-q", "--quiet", action="store_true", help="print nothing on success")
    ap.add_argument("--no-redundancy", action="store_true",
                    help="one slot per channel and cycle (to measure what redundancy buys)")
    args = ap.parse_args(argv)
    try:
        system, plan, rep, files = compile_file(args.description, args.out, args.no_redundancy)
    except ScheduleError as e:
        for m in e.messages:
            print(f"error: {m}", file=sys.stderr)
        return 2
    except Exception as e:  # a bug of the compiler, never a bad description
        if os.environ.get("ALB_DEBUG"):
            raise
        print(f"internal error of albatross_schedule.py: {type(e).__name__}: {e} "
              "(set ALB_DEBUG=1 for the traceback)", file=sys.stderr)
        return 3
    if not args.quiet:
        print(f"{args.description}: cycle {plan.cycle} clocks ({us(plan.cycle, system.clock_hz):g} us), "
              f"{len(plan.slots)} entries, bus utilisation {100 * rep['bus_utilisation']:.1f} % "
              f"-> {args.out}/ ({len(files)} files)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
