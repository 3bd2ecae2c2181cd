"""RAM layout: every board's channel instances, packed word-aligned."""

from __future__ import annotations

from .contract import load as load_contract
from .fourslot import THREE_BUFFER, channel_bytes as kind_channel_bytes
from .model import ScheduleError, System
from .rom import MAX_BASE_WORD


def channel_bytes(payload: int, layout: str = THREE_BUFFER) -> int:
    """ALB_CHANNEL_BYTES: the control bytes + the buffers of the word-rounded
    payload (three buffers; four for a four-slot channel)."""
    return kind_channel_bytes(payload, layout)


def allocate_ram(system: System):
    """Pack every board's channel instances word-aligned from address 0, in
    channel-id order (source and destination instances alike).  Returns
    {board index: [(channel, role, base, bytes), ...]}."""
    layout = {b: [] for b in range(len(system.boards))}
    nxt = [0] * len(system.boards)
    for ch in system.channels:
        ch.dst_bases = []
        if ch.producer is not None:
            size = channel_bytes(ch.size, ch.layout)
            ch.src_base = nxt[ch.producer]
            layout[ch.producer].append((ch, "source", ch.src_base, size))
            nxt[ch.producer] += size
        for b in ch.consumers:
            size = channel_bytes(ch.dst_size, ch.layout)
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
            word = base // load_contract().word_bytes
            if word > MAX_BASE_WORD:
                msgs.append(f"{system.source}: board '{system.boards[b]}', channel '{ch.name}' ({role}): "
                            f"base word {word} exceeds the {MAX_BASE_WORD.bit_length()}-bit ROM field "
                            f"(max {MAX_BASE_WORD})")
    if msgs:
        raise ScheduleError(msgs)
    return layout


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
