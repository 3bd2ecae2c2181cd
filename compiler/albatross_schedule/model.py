"""Data model of the schedule compiler: the description's constants, the
error type, and the Bus, Channel, System, Slot and Plan records."""

from __future__ import annotations

import dataclasses
import re
from typing import Optional

from .contract import load as load_contract

MODE_RIGID = "time-rigid"
REQUEST_KIND = "mode_request"      # [[channel]] kind: the board's mode requests, read by the controller
MODE_KIND = "mode"                 # [[channel]] kind: the running mode, published by the controller
MODE_SYNC = "position-synchronised"
DEFAULT_RAM_BYTES = 4096

BUS_DEFAULTS = {
    "access_cycles": 2,
    "first_access_extra": 1,
    "fetch_cycles": 7,
    "timeout_cycles": 8,
    "retries_per_slot": 2,
    "guard_cycles": 6,
    "n_chan": 16,
    "poll_cycles": 16,
    "time_bits": 16,
    "mode_switch_cycles": 6,
}
BUS_MINIMUM = {
    "access_cycles": 1, "first_access_extra": 0, "fetch_cycles": 1,
    "timeout_cycles": 1, "retries_per_slot": 0, "guard_cycles": 0,
    "n_chan": 1, "poll_cycles": 1, "time_bits": 4, "mode_switch_cycles": 1,
}

SYSTEM_KEYS = {"name", "clock_hz", "boards", "ram_bytes", "mode", "types_header"}
# [board.<name>]: a consumer board's Import loop timing (compiler/albatross_schedule/termination.py)
BOARD_KEYS = {"core", "clock_hz", "import_t_clocks", "import_v_clocks"}
CHANNEL_KEYS = {"name", "kind", "type", "size", "producer", "consumers",
                "max_period_us", "sync", "priority", "max_slots", "max_import_passes",
                "four_slot", "repetition"}

IDENT_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
CTYPE_RE = re.compile(r"^((struct|union|enum)\s+)?[A-Za-z_][A-Za-z0-9_]*$")
HEADER_RE = re.compile(r'^[A-Za-z0-9_./+-]+\.h$')


class ScheduleError(Exception):
    """Bad input: one or more messages, each naming the problem and where."""

    def __init__(self, messages):
        if isinstance(messages, str):
            messages = [messages]
        self.messages = list(messages)
        super().__init__("\n".join(self.messages))


def not_due_cost(bus) -> int:
    """The clocks an entry costs in a minor cycle in which it is not due (a
    multi-rate plan, docs/compiler.md "Plan"): the sequencer waits for the
    entry's start as for any entry, fetches it and skips it, so it takes
    this many clocks from max(its start, the end of the entry before it).
    The one place of that cost: the planner and the plan's check
    (multirate.py) read it here."""
    return bus.fetch_cycles


def us(clocks: float, clock_hz: int) -> float:
    return clocks * 1e6 / clock_hz


def one_minus(miss) -> str:
    """A probability close to 1 written as 1 minus its complement, "1 - 4.0e-10",
    so that it never reads as certainty (0.9999999996 printed to 9 places is
    1.000000000).  miss: the probability of failure."""
    return "1" if not miss or miss <= 0 else f"1 - {miss:.1e}"


# ---------------------------------------------------------------------------
# Data model.

@dataclasses.dataclass
class Bus:
    access_cycles: int = 2
    first_access_extra: int = 1
    fetch_cycles: int = 7
    timeout_cycles: int = 8
    retries_per_slot: int = 2
    guard_cycles: int = 6
    n_chan: int = 16
    poll_cycles: int = 16
    time_bits: int = 16             # the controller's TIME_BITS: time within a cycle
    mode_switch_cycles: int = 6     # with modes: idle clocks at every cycle's end (the mode table's reads)

    @property
    def retry_budget(self) -> int:
        return self.retries_per_slot * (self.timeout_cycles + self.access_cycles + 1)

    def retries_of(self, ch) -> int:
        """The retry budget (failed accesses) of ch's slots."""
        return self.retries_per_slot if ch.retries is None else ch.retries

    def retry_budget_of(self, ch) -> int:
        """The clocks of ch's retry budget: each failure costs at most timeout + access + 1."""
        return self.retries_of(ch) * (self.timeout_cycles + self.access_cycles + 1)

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
    layout: str = "three_buffer"    # channel kind: three_buffer | four_slot (copy, time, status)
    max_import_passes: Optional[int] = None   # three-buffer consumers: passes per Import at most
    retries: Optional[int] = None   # this channel's slot retry budget (None: [bus] retries_per_slot)
    request: bool = False           # a mode_request channel: a copy with no consumer, read by the controller
    mode_info: bool = False         # a mode channel: a status-like channel of {mode, since}, W = 2
    repetition: Optional[int] = None  # multi-rate: the repetition the description fixes (a power of two)
    # filled by the plan
    src_base: Optional[int] = None  # byte offset in the producer's RAM
    dst_bases: list = dataclasses.field(default_factory=list)
    accesses: int = 0               # A
    slot_len: int = 0               # L
    slots: list = dataclasses.field(default_factory=list)   # starts, sorted (multi-rate: its runs, see run_span)
    # filled by a multi-rate plan (multirate.py); a single-rate plan leaves them as they are
    fragments: int = 1              # F: runs that carry one value (E7: frag_words words each, the last the rest)
    frag_words: int = 0             # E7.frag (0: the whole value in one run)
    pub_accesses: int = 0           # the accesses of the run that publishes, up to the last Actual (0: accesses)
    run_span: int = 0               # the clocks after which its runs repeat (0: the cycle); slots are the
                                    # starts of its runs within it, from the cluster's start

    @property
    def id(self) -> int:
        return self.index

    @property
    def type_name(self) -> str:
        if self.ctype:
            return self.ctype
        if self.kind == "time":
            return "uint32_t"
        if self.mode_info:
            return "alb_mode_t"
        return f"{self.name}_t"

    @property
    def dst_size(self) -> int:
        """Destination payload bytes: the value's words, then taken_at."""
        return load_contract().dest_payload(self.words)


@dataclasses.dataclass
class BoardTiming:
    """A board's three-buffer Import loop, in controller clocks:
    t = the longest time between two loads of Actual in the loop, v = from the load
    whose value is stored into ReadLocked to the next load.  source says where
    the figures come from (a core type of the table, or the description)."""
    t: int
    v: int
    source: str


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
    timing: dict = dataclasses.field(default_factory=dict)  # board index -> BoardTiming
    faults: Optional[object] = None  # the fault hypothesis ([faults], faults.Hypothesis) or None
    drop_run: int = 2               # K: a destination is dropped after K failures in a row (ROM H2)
    modes: list = dataclasses.field(default_factory=list)   # modes.Mode, [[mode]]; empty: one schedule
    mode_window: int = 0            # clocks kept idle at the end of every cycle for a mode switch
    minor_cycle_us: Optional[int] = None  # [bus] minor_cycle_us: the minor cycle the description fixes
    planner: str = "auto"           # auto (single-rate when it fits, else multi-rate) | single-rate | multi-rate

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
    rep_log: int = 0                # multi-rate: due in the minor cycles n with n mod 2^rep_log = base
    base: int = 0
    frag: int = 0                   # E7.frag: words per fragment (0: whole values)


@dataclasses.dataclass
class Plan:
    cycle: int                      # C = H1, clocks
    capacity: int                   # clocks usable by slots
    slots: list                     # Slot, in entry order (= start order)
    limiter: Channel                # channel whose max_period sets C
    cluster_log: int = 0            # c: the plan repeats after 2^c cycles (minor cycles of C clocks)
    multirate: bool = False         # planned by multirate.py (repetitions, bases, fragments)

    @property
    def cluster(self) -> int:
        return 1 << self.cluster_log
