"""The schedule ROM: encoding the plan, the hex image, and the check of a ROM
image against the contract (README "Schedule ROM format")."""

from __future__ import annotations

import re

from .model import Plan, Slot, System

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


def rotl32(x: int, n: int) -> int:
    x &= 0xFFFFFFFF
    return ((x << n) | (x >> (32 - n))) & 0xFFFFFFFF


def checksum(words) -> int:
    """README checksum: c = 0xA1BA7055; for each w: c = rotl32(c, 5) ^ w."""
    c = CHECKSUM_SEED
    for w in words:
        c = rotl32(c, 5) ^ (w & 0xFFFFFFFF)
    return c


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
