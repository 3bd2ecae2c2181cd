"""Validating the system description (the decoded TOML): every check of the
description itself (sections, fields, ranges, names of the generated C,
periods, modes) runs and all its faults are reported together, before any
planning starts.  Every error names the file, line and column, the entity
and the field (source.py)."""

from __future__ import annotations

import os

from .model import (BUS_DEFAULTS, BUS_MINIMUM, CHANNEL_KEYS, CTYPE_RE, DEFAULT_RAM_BYTES, HEADER_RE,
                    IDENT_RE, MODE_KIND, MODE_RIGID, MODE_SYNC, REQUEST_KIND, SYSTEM_KEYS, Bus, Channel,
                    System)
from .rom import (BOARD_BITS, MAX_BASE_WORD, MAX_BOARDS, MAX_CHAN_IDS, MAX_DESTS, MAX_ENTRIES,
                  MAX_WORDS)
from .contract import load as _load_contract
from .fourslot import FOUR_SLOT, LAYOUTS, THREE_BUFFER
from .cnames import check_names as check_c_names
from .faults import parse_faults
from .modes import check_request_channel, parse_modes
from .source import Errors, Locator, describe as _describe, is_int as _is_int, load_toml, out_of_range
from .termination import parse_board_timing

__all__ = ["load_description", "load_toml", "parse_description"]

CONTRACT_TIME_BITS = _load_contract().time_bits
# Upper bounds of the description's integers (the lower ones are in the checks).
MAX_U32 = (1 << 32) - 1             # a 32-bit figure: the global time, a clock rate in Hz
MAX_RAM_BYTES = 4 * (MAX_BASE_WORD + 1)     # the RAM the ROM's base fields address
MAX_CYCLE = (1 << CONTRACT_TIME_BITS) - 1   # clocks within a cycle: bus counts fit in one
MAX_PRIORITY = 1_000_000
MAX_REPETITION = 1 << _load_contract().field("H2", "cluster").max   # a cluster of at most 2^15 minor cycles


def max_period_us(clock_hz: int) -> int:
    """The longest max_period_us: 2^32 - 1 clocks, the range of the 32-bit
    global time in which ages and periods are measured (now - taken_at)."""
    return MAX_U32 * 1_000_000 // clock_hz


def period_problem(us, clock_hz: int):
    """Why a period of us microseconds is out of range (None if it is not)."""
    if us * clock_hz // 1_000_000 < 1:
        return f"{us} us is less than one clock at clock_hz = {clock_hz}"
    if us > max_period_us(clock_hz):
        return out_of_range(us, 1, max_period_us(clock_hz), f"microseconds: 2^32 - 1 clocks at clock_hz = "
                            f"{clock_hz}, the range of the 32-bit global time that ages are measured in")
    return None


def parse_description(data: dict, path: str = "<description>", text: str = "") -> System:
    """Validate the decoded TOML and build the System (no plan yet)."""
    loc = Locator(path, text)
    err = Errors(loc)

    for key in data:
        if key not in ("system", "bus", "channel", "board", "faults", "mode"):
            err.general(f"unknown section [{key}] (expected [system], [bus], [faults], [board.<name>], [[channel]], "
                        "[[mode]])")

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
    clock_ok = False
    if clock_hz is None:
        err.system("clock_hz", "missing (the controller clock in Hz)")
    elif not _is_int(clock_hz) or clock_hz <= 0:
        err.system("clock_hz", f"{_describe(clock_hz)} is not a positive integer")
    elif clock_hz > MAX_U32:
        err.system("clock_hz", out_of_range(clock_hz, 1, MAX_U32, "Hz, a 32-bit figure"))
    else:
        clock_ok = True
    if not clock_ok:
        clock_hz = 1_000_000        # stands in for the checks below (1 clock a microsecond)

    boards = sysd.get("boards")
    board_ok = True
    name_boards = []                # the boards whose generated names are checked (None: invalid)
    if boards is None:
        err.system("boards", "missing (a list of board names)")
        boards, board_ok = [], False
    elif not isinstance(boards, list) or not boards:
        err.system("boards", "must be a non-empty list of board names")
        boards, board_ok = [], False
    else:
        if len(boards) > MAX_BOARDS:
            err.system("boards", f"{len(boards)} boards, at most {MAX_BOARDS} fit the {BOARD_BITS}-bit board fields of the ROM")
            board_ok = False
        seen = {}
        for b in boards:
            if not isinstance(b, str) or not IDENT_RE.match(b):
                err.system("boards", f"board name {_describe(b)} is not a C identifier", value=b)
                board_ok = False
                name_boards.append(None)
                continue
            if b.lower() in seen:
                err.system("boards", f"duplicate board name '{b}'"
                           + (f" (same file name as '{seen[b.lower()]}')" if seen[b.lower()] != b else ""),
                           value=b)
                board_ok = False
                name_boards.append(None)
                continue
            seen[b.lower()] = b
            name_boards.append(b)
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
        if v > MAX_RAM_BYTES:
            err.system("ram_bytes", f"{what}: " + out_of_range(v, 16, MAX_RAM_BYTES, f"bytes, the {MAX_BASE_WORD + 1} "
                       "words that the ROM's base fields address"))
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
    minor_us = None                 # [bus] minor_cycle_us: a multi-rate plan's minor cycle, fixed
    for key, v in busd.items():
        if key == "minor_cycle_us":
            if not _is_int(v) or v <= 0:
                err.system(key, f"{_describe(v)} is not a positive integer number of microseconds", table="bus")
            else:
                minor_us = v
            continue
        if key not in BUS_DEFAULTS:
            err.system(key, f"unknown field (expected one of {', '.join(BUS_DEFAULTS)}, minor_cycle_us)",
                       table="bus")
            continue
        lo = BUS_MINIMUM[key]
        if not _is_int(v) or v < lo:
            err.system(key, f"{_describe(v)} is not an integer >= {lo}", table="bus")
            continue
        if key not in ("n_chan", "time_bits") and v > MAX_CYCLE:
            err.system(key, out_of_range(v, lo, MAX_CYCLE, f"a cycle has at most {MAX_CYCLE} clocks, "
                                         f"TIME_BITS = {CONTRACT_TIME_BITS}"), table="bus")
            continue
        if key == "n_chan" and v > MAX_CHAN_IDS:
            bits = MAX_CHAN_IDS.bit_length() - 1
            article = "an" if str(bits).startswith("8") or bits in (11, 18) else "a"
            err.system(key, f"{v} exceeds {MAX_CHAN_IDS} (the channel id is {article} "
                       f"{bits}-bit ROM field)", table="bus")
            continue
        if key == "time_bits" and v > CONTRACT_TIME_BITS:
            err.system(key, f"{v} exceeds {CONTRACT_TIME_BITS} (the ROM's time fields are "
                       f"{CONTRACT_TIME_BITS} bits wide)", table="bus")
            continue
        setattr(bus, key, v)

    if minor_us is not None and clock_ok:
        m = minor_us * clock_hz // 1_000_000
        if not 1 <= m <= (1 << bus.time_bits) - 1:
            err.system("minor_cycle_us", f"{minor_us} us is {m} clocks at clock_hz = {clock_hz}: a minor cycle is "
                       f"1 .. {(1 << bus.time_bits) - 1} clocks (time_bits = {bus.time_bits})", table="bus")
            minor_us = None

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

    channels = []                   # the valid channels
    named = []                      # every channel with a valid, unique name (valid or not): its C names
    names = {}
    n_sync = 0
    n_req = 0
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
        unique_name = ok

        for key in cd:
            if key not in CHANNEL_KEYS:
                err.channel(i, label, key, f"unknown field (expected one of {', '.join(sorted(CHANNEL_KEYS))})")
                ok = False

        kind = cd.get("kind", "copy")
        layout = THREE_BUFFER
        request = kind == REQUEST_KIND   # a copy channel the controller reads: the mode requests
        mode_info = kind == MODE_KIND    # a channel the controller writes: the running mode
        if kind in LAYOUTS:         # a copy channel of that kind ("copy" = "three_buffer")
            kind, layout = "copy", kind
        elif request or mode_info:  # the controller reads a copy / writes a status-like channel
            kind = "copy" if request else "status"
        elif kind not in ("copy", "time", "status"):
            err.channel(i, label, "kind", f"{_describe(kind)}: expected \"copy\" (= \"{THREE_BUFFER}\"), "
                        f"\"{FOUR_SLOT}\" (a copy channel with the wait-free four-slot layout), "
                        f"\"time\", \"status\", \"{REQUEST_KIND}\" or \"{MODE_KIND}\"")
            kind, ok = "copy", False

        fs = cd.get("four_slot")    # the wait-free kind for any channel (time, status, copy)
        if fs is not None:
            if not isinstance(fs, bool):
                err.channel(i, label, "four_slot", f"{_describe(fs)}: expected true or false")
                ok = False
            elif "kind" in cd and cd["kind"] in LAYOUTS and (cd["kind"] == FOUR_SLOT) != fs:
                err.channel(i, label, "four_slot", f"four_slot = {_describe(fs)} contradicts "
                            f"kind = \"{cd['kind']}\"")
                ok = False
            else:
                layout = FOUR_SLOT if fs else THREE_BUFFER

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
            words = 1 if kind == "time" else 2 if mode_info else status_words
            what = MODE_KIND if mode_info else kind
            how = {"time": "W = 1", MODE_KIND: "the running mode and since, W = 2"}.get(
                what, f"W = 1 + 2*n_chan = {status_words}")
            for fld in ("producer", "size"):
                if fld in cd:
                    err.channel(i, label, fld, f"a {what} channel has no {fld}: the controller "
                                f"generates its value ({how})")
                    ok = False
            size = 4 * words

        consumers = []
        cons = cd.get("consumers")
        if request:
            n_req += 1
            ok = check_request_channel(cd, i, label, size, layout == FOUR_SLOT, n_req, err) and ok
        elif cons is None:
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
        elif clock_ok and period_problem(mp, clock_hz):
            err.channel(i, label, "max_period_us", period_problem(mp, clock_hz))
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
            elif layout == FOUR_SLOT:
                err.channel(i, label, "sync", f"the sync channel must be a three-buffer copy channel: the "
                            f"sequencer's position poll compares the source's Actual with the controller's "
                            f"ReadLocked copy, a three-buffer rule ({FOUR_SLOT} sync sources are not supported)")
                ok = False
            elif n_sync > 1:
                err.channel(i, label, "sync", "more than one sync channel (exactly one starts the cycle)")
                ok = False

        prio = cd.get("priority", 0)
        if not _is_int(prio):
            err.channel(i, label, "priority", f"{_describe(prio)} is not an integer")
            prio, ok = 0, False
        elif abs(prio) > MAX_PRIORITY:
            err.channel(i, label, "priority", out_of_range(prio, -MAX_PRIORITY, MAX_PRIORITY))
            prio, ok = 0, False
        max_slots = cd.get("max_slots")
        if max_slots is not None and (not _is_int(max_slots) or max_slots <= 0):
            err.channel(i, label, "max_slots", f"{_describe(max_slots)} is not a positive integer")
            max_slots, ok = None, False
        elif max_slots is not None and max_slots > MAX_ENTRIES:
            err.channel(i, label, "max_slots", out_of_range(max_slots, 1, MAX_ENTRIES, f"a cycle has at most "
                                                           f"{MAX_ENTRIES} ROM entries"))
            max_slots, ok = None, False

        mip = cd.get("max_import_passes")
        if mip is not None and (not _is_int(mip) or mip < 2):
            err.channel(i, label, "max_import_passes", f"{_describe(mip)} is not an integer >= 2 (an Import "
                        "that finds a new value stores ReadLocked at least once, and the bound is finite only "
                        "from 2 passes up)")
            mip, ok = None, False
        elif mip is not None and mip > MAX_U32:
            err.channel(i, label, "max_import_passes", out_of_range(mip, 2, MAX_U32, "a 32-bit figure"))
            mip, ok = None, False

        rep = cd.get("repetition")      # multi-rate: runs every rep minor cycles, fixed
        if rep is not None and (not _is_int(rep) or not 1 <= rep <= MAX_REPETITION or rep & (rep - 1)):
            err.channel(i, label, "repetition", f"{_describe(rep)} is not a power of two from 1 to {MAX_REPETITION} "
                        "(the minor cycles between two runs of the channel's entries)")
            rep, ok = None, False

        if unique_name:
            ch = Channel(index=i, name=cname, kind=kind, ctype=ctype, size=size, words=words, producer=producer,
                         consumers=consumers, max_period_us=mp, sync=sync, priority=prio,
                         max_slots=1 if request else max_slots, layout=layout, max_import_passes=mip,
                         request=request, mode_info=mode_info, repetition=rep)
            ch.period_clocks = mp * clock_hz // 1_000_000
            named.append(ch)
            if ok:
                channels.append(ch)

    if len(chans) > bus.n_chan:
        err.general(f"too many channels: {len(chans)} channels but the controller has "
                    f"n_chan = {bus.n_chan} channel ids ([bus] n_chan)")
    if len(chans) > MAX_ENTRIES:
        err.general(f"too many channels: {len(chans)} channels need {len(chans)} ROM entries, "
                    f"at most {MAX_ENTRIES}")
    if mode == MODE_SYNC and n_sync == 0:
        err.system("mode", f"{MODE_SYNC} mode needs exactly one channel with sync = true "
                   "(the position channel that starts the cycle)")

    timing = parse_board_timing(data.get("board", {}), boards, clock_hz, err, _describe)
    faults = parse_faults(data.get("faults"), err, _describe)

    # The modes, over every channel with a name (one with a fault of its own is
    # no "unknown channel" to a mode); with any fault the system is not built.
    system = System(name=name, clock_hz=clock_hz, boards=boards, ram_bytes=ram_bytes,
                    mode=mode, types_header=types_header, bus=bus, channels=named, source=path,
                    timing=timing, faults=faults, minor_cycle_us=minor_us)
    raw_modes = data.get("mode")
    system.modes = parse_modes(raw_modes, system, err, _describe, _is_int)
    for i, m in enumerate(system.modes):
        for c, us in m.periods.items():
            problem = period_problem(us, clock_hz) if clock_ok else None
            if problem:
                err.mode(i, m.name, "periods", f"{_channel_name(named, c)}: {problem}")

    # The names of the generated C: boards, channels, modes, types, fixed names.
    mode_names = []
    if isinstance(raw_modes, list):
        for md in raw_modes:
            n = md.get("name") if isinstance(md, dict) else None
            ok = isinstance(n, str) and IDENT_RE.match(n) and n not in mode_names
            mode_names.append(n if ok else None)
    check_c_names(name, name_boards, named, mode_names, err)
    err.raise_if_any()
    system.channels = channels
    return system


def _channel_name(channels, index) -> str:
    return next((ch.name for ch in channels if ch.index == index), f"#{index + 1}")


def load_description(path: str) -> System:
    data, text = load_toml(path)
    return parse_description(data, path, text)
