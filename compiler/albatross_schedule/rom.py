"""The schedule ROM: encoding the plan, the hex image, and the check of a ROM
image against the contract (rtl/albatross_contract.toml; docs/controller.md "Schedule ROM")."""

from __future__ import annotations

import re

from . import contract
from .fourslot import FOUR_SLOT, buffers as kind_buffers, flag_four_slot
from .model import Plan, Slot, System

# The contract (rtl/albatross_contract.toml) gives every field and constant.
C = contract.load()
ROM_MAGIC = C.magic
CRC_SEED = C.crc_seed
CRC_POLY = C.crc_poly
MAX_ENTRIES = C.max_entries
BOARD_BITS = C.place_board.width
MAX_BOARDS = 1 << BOARD_BITS
MAX_WORDS = C.field("E0", "w").max            # the W field
MAX_BASE_WORD = C.place_base.max              # base word fields
MAX_CHAN_IDS = 1 << C.field("E0", "id").width
MAX_DESTS = C.max_dests
KIND_CODE = dict(C.kind)
KIND_NAME = {v: k for k, v in KIND_CODE.items()}
FLAG_SYNC = C.flag("entry", "sync")
FLAG_FOUR_SLOT = flag_four_slot()            # every entry of a four-slot channel (COPY, TIME, STATUS)
HFLAG_SYNC_MODE = C.flag("header", "sync_mode")
FLAG_REQUEST = C.flag("entry", "request")
FLAG_MODE = C.flag("entry", "mode")


def rom_crc(words) -> int:
    """The contract's CRC of a whole ROM image, its check word H3 included: 0 when valid."""
    return C.crc(words)


def dest_field(board: int, base_bytes: int) -> int:
    """A place (source or destination): the board and the channel's base word."""
    return C.place(board, base_bytes // C.word_bytes)


def _pack(words, values) -> list:
    """Words of the header or an entry from {(word, field): value} (a value
    that does not fit its field is an error, never cut)."""
    out = [0] * len(words)
    for (w, f), v in values.items():
        fld = C.field(w, f)
        if not 0 <= v <= fld.max:
            raise ValueError(f"{w}.{f} = {v} does not fit {fld.width} bits")
        out[fld.index] |= fld.put(v)
    return out


def encode_entry(slot: Slot) -> list:
    ch = slot.channel
    flags = (FLAG_SYNC if slot.sync else 0) | (FLAG_FOUR_SLOT if ch.layout == FOUR_SLOT else 0) | \
        (FLAG_REQUEST if ch.request else 0) | (FLAG_MODE if ch.mode_info else 0)
    v = {("E0", "kind"): KIND_CODE[ch.kind], ("E0", "flags"): flags,
         ("E0", "id"): ch.id, ("E0", "nd"): len(ch.consumers), ("E0", "w"): ch.words,
         ("E1", "start"): slot.start, ("E2", "length"): slot.length,
         ("E6", "base"): slot.base, ("E6", "rep"): slot.rep_log, ("E7", "frag"): slot.frag}
    if ch.kind == "copy":
        src = C.src_field
        v[(src.word, src.name)] = dest_field(ch.producer, ch.src_base)
    for f, b, base in zip(C.dest_fields, ch.consumers, ch.dst_bases):
        v[(f.word, f.name)] = dest_field(b, base)
    return _pack(C.entry, v)


def encode_rom(system: System, plan: Plan) -> list:
    words = _pack(C.header, {("H0", "magic"): ROM_MAGIC, ("H0", "ne"): len(plan.slots),
                             ("H0", "flags"): HFLAG_SYNC_MODE if system.sync_mode else 0,
                             ("H1", "cycle"): plan.cycle, ("H2", "drop_run"): system.drop_run,
                             ("H2", "cluster"): plan.cluster_log})
    for s in plan.slots:
        words += encode_entry(s)
    words[C.crc_index] = C.check_word(words)
    return words


def encode_rom_modes(planned) -> list:
    """The image of several modes.  planned: [(system, plan, next mode
    indices)] per mode, the start-up mode first.  Every mode's entries in
    mode order, then one descriptor per mode in the places of the last
    entries (H2.table + m); the header is the start-up mode's, with H2's
    table, modes and start_end."""
    system0, plan0, _ = planned[0]
    ranges, n = [], 0
    for _, plan, _ in planned:
        ranges.append((n, n + len(plan.slots)))
        n += len(plan.slots)
    words = _pack(C.header, {("H0", "magic"): ROM_MAGIC, ("H0", "ne"): n + len(planned),
                             ("H0", "flags"): HFLAG_SYNC_MODE if system0.sync_mode else 0,
                             ("H1", "cycle"): plan0.cycle, ("H1", "next"): sum(1 << j for j in planned[0][2]),
                             ("H2", "drop_run"): system0.drop_run, ("H2", "table"): n, ("H2", "modes"): len(planned),
                             ("H2", "start_end"): ranges[0][1], ("H2", "cluster"): plan0.cluster_log})
    for _, plan, _ in planned:
        for s in plan.slots:
            words += encode_entry(s)
    for (system, plan, nxt), (first, end) in zip(planned, ranges):
        words += _pack(C.mode, {("D0", "cycle"): plan.cycle, ("D0", "first"): first, ("D0", "end"): end,
                                ("D1", "drop_run"): system.drop_run, ("D1", "next"): sum(1 << j for j in nxt),
                                ("D2", "cluster"): plan.cluster_log})
    words[C.crc_index] = C.check_word(words)
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
    """Check a ROM image against the contract (header, CRC, entry
    validation rules).  ram_words: int or list per board.  Returns a list of
    problems (empty: valid) and the decoded entries."""
    problems = []
    entries = []
    nh, nw = C.header_words, C.entry_words
    if len(words) < nh:
        return [f"ROM shorter than its {nh}-word header"], entries

    def get(ws, word, field):
        f = C.field(word, field)
        return f.get(ws[f.index])

    hdr = words[:nh]
    magic = get(hdr, "H0", "magic")
    if magic != ROM_MAGIC:
        problems.append(f"H0 magic {magic:#06x}, expected {ROM_MAGIC:#06x}")
    if rom_crc(words) != 0:
        problems.append(f"CRC of the image {rom_crc(words):#010x}, expected 0 "
                        f"(H3 {words[C.crc_index]:#010x}, expected {C.check_word(words):#010x})")
    problems += [f"{w.name} (reserved) is not 0" for w in C.header if w.reserved and hdr[w.index] != 0]
    problems += [f"{w.name}: bits outside its fields are not 0" for w in C.header
                 if not w.reserved and hdr[w.index] & ~sum(f.mask for f in w.fields) & 0xFFFFFFFF]
    drop_run = get(hdr, "H2", "drop_run")
    if drop_run < 2:
        problems.append(f"H2 drop run {drop_run}, the compiler writes 2..255")
    ne = get(hdr, "H0", "ne")
    hflags = get(hdr, "H0", "flags")
    sync_mode = bool(hflags & HFLAG_SYNC_MODE)
    if hflags & ~HFLAG_SYNC_MODE:
        problems.append("H0 reserved flag bits set")
    if sync_expected is not None and sync_mode != sync_expected:
        problems.append(f"H0 sync flag {int(sync_mode)}, expected {int(sync_expected)}")
    if not 1 <= ne <= MAX_ENTRIES:
        problems.append(f"entry count {ne} outside 1..{MAX_ENTRIES}")
    if len(words) != C.entry_address(ne):
        problems.append(f"ROM has {len(words)} words, header says {ne} entries = {C.entry_address(ne)} words")
    cycle = get(hdr, "H1", "cycle")
    ranges, p2 = mode_ranges(words, ne, cycle, drop_run)
    problems += p2
    copy, time, status = KIND_CODE["copy"], KIND_CODE["time"], KIND_CODE["status"]
    src = C.src_field
    mode_of = {k: (m, c, cl) for m, (first, end, c, cl) in enumerate(ranges) for k in range(first, end)}
    earlier, prev_mode = [], None    # the mode's entries so far: (k, rep, base, end)
    for k in sorted(mode_of):
        e = words[C.entry_address(k): C.entry_address(k + 1)]
        if len(e) < nw:
            break
        mode, cycle, cluster = mode_of[k]
        if mode != prev_mode:
            earlier, prev_mode = [], mode
        tag = f"entry {k}" + (f" (mode {mode})" if len(ranges) > 1 else "")
        kind, flags = get(e, "E0", "kind"), get(e, "E0", "flags")
        cid, nd, w = get(e, "E0", "id"), get(e, "E0", "nd"), get(e, "E0", "w")
        start, length = get(e, "E1", "start"), get(e, "E2", "length")
        rep, due_base, frag = get(e, "E6", "rep"), get(e, "E6", "base"), get(e, "E7", "frag")
        ent = {"mode": mode, "kind": KIND_NAME.get(kind, kind), "flags": flags, "id": cid, "nd": nd, "w": w,
               "start": start, "length": length, "src": C.unplace(src.get(e[src.index])),
               "dst": [C.unplace(f.get(e[f.index])) for f in C.dest_fields][:nd],
               "rep": rep, "base": due_base, "frag": frag}
        entries.append(ent)
        for x in (1, 2):
            wd = C.entry[x]
            if e[x] & ~sum(f.mask for f in wd.fields) & 0xFFFFFFFF:
                problems.append(f"{tag}: {wd.name} has bits set above its {C.time_bits}-bit time field")
        if kind not in KIND_NAME:
            problems.append(f"{tag}: unknown kind {kind}")
            continue
        problems += [f"{tag}: {x.name} (reserved) is not 0" for x in C.entry if x.reserved and e[x.index] != 0]
        problems += [f"{tag}: {x.name}: bits outside its fields are not 0" for x in C.entry[3:]
                     if not x.reserved and e[x.index] & ~sum(f.mask for f in x.fields) & 0xFFFFFFFF]
        if rep > cluster:
            problems.append(f"{tag}: repetition 2^{rep} above the cluster of its mode (2^{cluster} minor cycles)")
        if due_base >> rep:
            problems.append(f"{tag}: base {due_base} not below its repetition 2^{rep}")
        if frag and (kind != copy or flags & FLAG_REQUEST):
            problems.append(f"{tag}: fragment size on a {'REQUEST' if kind == copy else KIND_NAME[kind]} entry "
                            "(only a COPY to destinations is fragmented)")
        if flags & ~sum(C.flag("entry", n) for n in C.entry_flags):
            problems.append(f"{tag}: reserved E0 flag bits set ({flags:#x})")
        if flags & FLAG_FOUR_SLOT and kind not in (copy, time, status):
            problems.append(f"{tag}: FOUR_SLOT flag on a {KIND_NAME[kind]} entry (only COPY, TIME and STATUS "
                            "may be four-slot)")
        if flags & FLAG_SYNC and flags & FLAG_FOUR_SLOT:
            problems.append(f"{tag}: SYNC on a FOUR_SLOT entry (the sync channel is three-buffer)")
        if flags & FLAG_SYNC and (k != 0 or not sync_mode):
            problems.append(f"{tag}: SYNC flag outside entry 0 of a position-synchronised ROM")
        if sync_mode and k == 0 and not (flags & FLAG_SYNC and kind == copy and start == 0):
            problems.append(f"{tag}: a position-synchronised ROM starts with a SYNC COPY at 0")
        if flags & FLAG_REQUEST and (kind != copy or nd != 0 or flags & (FLAG_SYNC | FLAG_FOUR_SLOT)):
            problems.append(f"{tag}: REQUEST on other than a three-buffer COPY with ND 0")
        if kind == KIND_CODE["idle"]:
            continue
        if not 1 <= nd <= MAX_DESTS and not (nd == 0 and flags & FLAG_REQUEST):
            problems.append(f"{tag}: ND {nd} outside 1..{MAX_DESTS}")
        if cid >= n_chan:
            problems.append(f"{tag}: channel id {cid} >= N_CHAN {n_chan}")
        if kind == time and w != 1:
            problems.append(f"{tag}: TIME with W = {w}, expected 1")
        if flags & FLAG_MODE and (kind != status or w != 2):
            problems.append(f"{tag}: MODE on other than a STATUS entry with W = 2")
        if kind == status and w != 1 + 2 * n_chan and not flags & FLAG_MODE:
            problems.append(f"{tag}: STATUS with W = {w}, expected {1 + 2 * n_chan}")
        exts = [(ent["dst"][i], w + C.taken_at_words) for i in range(min(nd, MAX_DESTS))]
        if kind == copy:
            exts.append((ent["src"], w))
        elif e[src.index] != 0:
            problems.append(f"{tag}: {src.word} (source) set on a {KIND_NAME[kind]} entry")
        for (board, base), stride in exts:
            if board >= n_boards:
                problems.append(f"{tag}: board {board} >= NB {n_boards}")
                continue
            rw = ram_words[board] if isinstance(ram_words, (list, tuple)) else ram_words
            nbuf = kind_buffers(FOUR_SLOT) if flags & FLAG_FOUR_SLOT else C.buffers
            if base + C.control_words + nbuf * stride > rw:
                problems.append(f"{tag}: channel at board {board} word {base} (stride {stride}) "
                                f"ends past the RAM ({rw} words)")
        # The slot order: the entry starts at or after the end of every earlier
        # entry of its mode due in a minor cycle it is due in (due sets
        # {n mod 2^r = b} meet iff the bases agree modulo the smaller
        # repetition; then both are due in minor cycle n = the base of the larger).
        late = [(end, i, bi if ri > rep else due_base) for i, ri, bi, end in earlier
                if end > start and (bi ^ due_base) & ((1 << min(ri, rep)) - 1) == 0]
        if late:
            end, i, n = max(late)
            problems.append(f"{tag}: starts at {start}, before the previous slot due in its minor cycles ends "
                            f"at {end} (entry {i}, both due in minor cycle {n})")
        if start + length > cycle:
            problems.append(f"{tag}: ends at {start + length}, after the cycle ({cycle})")
        earlier.append((k, rep, due_base, start + length))
    problems += same_channel_everywhere(entries)
    return problems, entries


def same_channel_everywhere(entries) -> list:
    """The controller keeps a channel's state by its id across entries and
    modes (its progress in fragments, its buffers, its counters): every
    entry of an id, in every mode, must name the same kind, four-slot,
    request and mode flags, W, source and destinations (docs/controller.md
    "Fragments": a value cut by a mode switch goes on in the next mode that
    runs its channel).  [problems]"""
    keep = FLAG_FOUR_SLOT | FLAG_REQUEST | FLAG_MODE
    first, out = {}, []
    for k, e in enumerate(entries):
        if e["kind"] == "idle":
            continue
        shape = (e["kind"], e["flags"] & keep, e["w"], e["src"] if e["kind"] == "copy" else None, tuple(e["dst"]))
        if e["id"] not in first:
            first[e["id"]] = (k, e["mode"], shape)
            continue
        j, mj, was = first[e["id"]]
        if shape != was:
            what = [n for n, a, b in zip(("kind", "flags", "W", "source", "destinations"), shape, was) if a != b]
            out.append(f"entry {k} (mode {e['mode']}): channel id {e['id']} has another {', '.join(what)} than "
                       f"entry {j} (mode {mj}); a channel's state is kept by its id, so every entry of it must "
                       "carry the same value between the same places")
    return out


def mode_ranges(words, ne, cycle, drop_run):
    """[(first entry, end, cycle, cluster)] per mode of an image (one range,
    0..NE, without modes) and the problems of its mode descriptors."""
    def get(ws, word, field):
        f = C.field(word, field)
        return f.get(ws[f.index])

    hdr = words[:C.header_words]
    modes, table, start_end = get(hdr, "H2", "modes"), get(hdr, "H2", "table"), get(hdr, "H2", "start_end")
    cluster = get(hdr, "H2", "cluster")
    if modes == 0:
        if table or start_end or get(hdr, "H1", "next"):
            return [(0, ne, cycle, cluster)], ["H1 next, H2 table and start_end are 0 in an image without modes"]
        return [(0, ne, cycle, cluster)], []
    problems, ranges = [], []
    if modes < 2 or table + modes != ne:
        problems.append(f"H2: {modes} modes with their descriptors at entries {table}.. must be 2 or more and "
                        f"end at NE ({ne})")
        return [(0, min(ne, start_end) if start_end else ne, cycle, cluster)], problems
    nxt_end = 0
    for m in range(modes):
        d = words[C.entry_address(table + m): C.entry_address(table + m + 1)]
        if len(d) < C.entry_words:
            problems.append(f"mode {m}: descriptor past the end of the image")
            break
        first, end, mcycle = get(d, "D0", "first"), get(d, "D0", "end"), get(d, "D0", "cycle")
        mdrop, nxt, mcluster = get(d, "D1", "drop_run"), get(d, "D1", "next"), get(d, "D2", "cluster")
        tag = f"mode {m} (descriptor at entry {table + m})"
        if first != nxt_end or not first < end <= table:
            problems.append(f"{tag}: entries {first}..{end - 1}, expected a range from {nxt_end} ending by {table}")
        if m == 0 and (end != start_end or mcycle != cycle or mdrop != drop_run or mcluster != cluster):
            problems.append(f"{tag}: the start-up mode's end, cycle, drop run and cluster must be H2.start_end, H1, "
                            "H2.drop_run and H2.cluster")
        if mdrop < 2:
            problems.append(f"{tag}: drop run {mdrop}, the compiler writes 2..255")
        if nxt >> modes or nxt & (1 << m):
            problems.append(f"{tag}: next {nxt:#06x} names a mode that does not exist or the mode itself")
        if m == 0 and nxt != get(hdr, "H1", "next"):
            problems.append(f"{tag}: the start-up mode's next must be H1.next")
        problems += [f"{tag}: {w.name} (reserved) is not 0" for w in C.mode if w.reserved and d[w.index] != 0]
        problems += [f"{tag}: {w.name}: bits outside its fields are not 0" for w in C.mode
                     if not w.reserved and d[w.index] & ~sum(f.mask for f in w.fields) & 0xFFFFFFFF]
        ranges.append((first, end, mcycle, mcluster))
        nxt_end = end
    if nxt_end != table:
        problems.append(f"the modes' entries end at {nxt_end}, H2.table is {table}")
    return ranges, problems
