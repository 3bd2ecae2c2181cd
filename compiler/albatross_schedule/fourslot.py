"""The channel kinds (layouts) of a COPY channel: the paper's three-buffer
channel and the wait-free four-slot channel (Simpson 1990, mapped
onto single-writer bytes).  Both are defined in rtl/albatross_contract.toml:
[layout] (three buffers) and [layout.four_slot] (a fourth buffer, the
producer's slot bytes Slot0/Slot1 at offsets 2 and 3, both initially 0),
and the E0 entry flag four_slot that marks every ROM entry of a four-slot
channel.

The contract module (contract.py) does not read [layout.four_slot]; this
module reads that table from the same definition file (the raw TOML at
contract.load().path) so that the compiler does not depend on the contract
module's internals.  Everything the compiler needs about the kinds goes
through here: buffers per kind, channel bytes, the initial control word, the
flag."""

from __future__ import annotations

import tomllib

from .contract import ContractError, load as load_contract

THREE_BUFFER = "three_buffer"
FOUR_SLOT = "four_slot"
LAYOUTS = (THREE_BUFFER, FOUR_SLOT)

_cache = {}


class FourSlotLayout:
    """[layout.four_slot]: buffers, the initial slot value and the slot bytes."""

    def __init__(self, table: dict, path: str):
        try:
            self.buffers = int(table["buffers"])
            self.initial_slot = int(table["initial_slot"])
            self.slots = {c["name"]: (int(c["offset"]), int(c["size"])) for c in table["control"]}
        except (KeyError, TypeError, ValueError) as e:
            raise ContractError(f"{path}: [layout.four_slot] malformed ({type(e).__name__}: {e})") from None
        c = load_contract(path)
        problems = []
        if self.buffers != 4:
            problems.append(f"buffers {self.buffers}: the four-slot channel has 4 buffers")
        if set(self.slots) != {"slot0", "slot1"}:
            problems.append("control must name slot0 and slot1")
        used = {o for cb in c.control.values() for o in range(cb.offset, cb.offset + cb.size)}
        for name, (off, size) in self.slots.items():
            if size != 1 or off in used or off + size > c.buffers_offset:
                problems.append(f"{name}: offset {off} size {size} overlaps a control byte or the buffers")
            used.add(off)
        if self.initial_slot not in (0, 1):
            problems.append(f"initial_slot {self.initial_slot} is not 0 or 1")
        if problems:
            raise ContractError(f"{path}: [layout.four_slot]: " + "; ".join(problems))


def four_slot_layout(path: str | None = None) -> FourSlotLayout:
    c = load_contract(path)
    if c.path not in _cache:
        try:
            with open(c.path, "rb") as f:
                data = tomllib.load(f)
        except (OSError, tomllib.TOMLDecodeError) as e:
            raise ContractError(f"{c.path}: cannot read [layout.four_slot]: {e}") from None
        table = data.get("layout", {}).get("four_slot")
        if not isinstance(table, dict):
            raise ContractError(f"{c.path}: no table [layout.four_slot]")
        _cache[c.path] = FourSlotLayout(table, c.path)
    return _cache[c.path]


def buffers(layout: str) -> int:
    return four_slot_layout().buffers if layout == FOUR_SLOT else load_contract().buffers


def channel_bytes(payload: int, layout: str = THREE_BUFFER) -> int:
    """ALB_CHANNEL_BYTES of one instance: the control word and the buffers of
    the word-rounded payload (3 buffers, or 4 for the four-slot kind)."""
    c = load_contract()
    return c.buffers_offset + buffers(layout) * c.stride(payload)


def initial_control_word(layout: str = THREE_BUFFER) -> int:
    """Actual = ReadLocked = Buffer1; four-slot: also Slot0 = Slot1 = initial_slot."""
    c = load_contract()
    w = c.initial_control_word()
    if layout == FOUR_SLOT:
        fs = four_slot_layout()
        for off, _ in fs.slots.values():
            if off < c.word_bytes:
                w = (w & ~(0xFF << (8 * off))) | (fs.initial_slot << (8 * off))
    return w


def flag_four_slot() -> int:
    """The E0 flags mask of a four-slot COPY entry."""
    return load_contract().flag("entry", "four_slot")
