"""Schedule modes ([[mode]] in the description): several schedules of one
system.  A mode names the channels it refreshes and may change their
max_period_us; the first mode is the start-up mode.  Each mode is planned
and checked on its own, as a system of its channels, over the one RAM layout
of the whole description (a channel keeps its places in every mode).

Rules:
  * name: an identifier, unique.  channels: the mode's channel names
    (default: every channel; the mode_request channel is added to every
    mode that may switch: the controller reads the requests there, once a
    cycle).  periods: {channel: max_period_us} for channels
    of the mode (default: the channel's own).  next: the modes it may switch
    to (default: every other mode).
  * Without [[mode]] the system has one schedule, exactly as before.
    [[mode]] needs one channel of kind mode_request (a word published by
    one board: the number of the mode it asks for), and that kind needs
    [[mode]].  Every mode keeps [bus] mode_switch_cycles idle at the end of
    its cycle, for the controller's reads of the next mode.
  * The ROM image holds every mode (rom.encode_rom_modes: the entries of
    each mode, then a descriptor per mode); the controller runs the start-up
    mode.  The board headers hold the start-up mode, so it must list every
    channel.
  * The modes share the ROM's entries (plan_modes): a slot per channel of
    each mode and a descriptor per mode must fit, the rest holds redundant
    slots, shared in proportion to what the bus time allows each mode when
    they do not all fit; report.json "redundant_slots" says what was cut.
  * Modes need the time-rigid time mode.  report.json "modes", report.txt
    and timeline.svg (a lane group each) show every mode."""

from __future__ import annotations

import copy
import dataclasses

from .model import IDENT_RE, REQUEST_KIND, ScheduleError, System
from .plan import redundancy_estimate
from .rom import MAX_ENTRIES

MODE_KEYS = {"name", "channels", "periods", "next"}
# The suffixes of a channel's generated macros (cgen.py): a mode name equal to
# one would make ALB_MODE_<NAME> the macro of a channel named "Mode".
MACRO_SUFFIXES = ("ID", "BASE", "SIZE", "WORDS", "KIND", "PERIOD_CLOCKS", "LATENCY_CLOCKS", "AGE_CLOCKS",
                  "MAX_AGE_CLOCKS", "IMPORT_MAX_PASSES", "IMPORT_MAX_ACCESSES", "T_DEFINED")
MAX_MODES = 16


@dataclasses.dataclass
class Mode:
    name: str
    channels: list                  # channel indices, description order
    periods: dict                   # channel index -> max_period_us
    next: list                      # mode indices it may switch to


def parse_modes(raw, system: System, err, describe, is_int) -> list:
    """The [[mode]] array of the description (raw: data.get("mode")) as Modes;
    errors go to err (description.Errors), each naming the mode and field."""
    requests = [ch for ch in system.channels if ch.request]
    infos = [ch for ch in system.channels if ch.mode_info]
    if raw is None:
        if requests:
            err.channel(requests[0].index, requests[0].name, "kind", "a mode_request channel needs [[mode]] "
                        "(two or more modes to switch between)")
        if infos:
            err.channel(infos[0].index, infos[0].name, "kind", "a mode channel needs [[mode]]")
        return []
    if not isinstance(raw, list) or not all(isinstance(m, dict) for m in raw):
        err.general("mode must be an array of tables ([[mode]])")
        return []
    if len(raw) > MAX_MODES:
        err.general(f"{len(raw)} modes, at most {MAX_MODES}")
    by_name = {ch.name: ch for ch in system.channels}
    names = []

    def fail(i, label, field, msg):
        where = err.loc.where("mode", i, field)
        fld = f", field '{field}'" if field else ""
        err.messages.append(f"{where}: mode {label}{fld}: {msg}")

    for i, md in enumerate(raw):
        name = md.get("name")
        label = f"'{name}'" if isinstance(name, str) else f"#{i + 1}"
        for key in md:
            if key not in MODE_KEYS:
                fail(i, label, key, f"unknown field (expected one of {', '.join(sorted(MODE_KEYS))})")
        if not isinstance(name, str) or not IDENT_RE.match(name):
            fail(i, label, "name", f"{describe(name)} is not an identifier" if name is not None else "missing")
        elif name in names:
            fail(i, label, "name", "a mode of that name comes before it")
        elif name.upper() in MACRO_SUFFIXES or name.upper().endswith("_AT_TARGET_CLOCKS"):
            fail(i, label, "name", f"ALB_MODE_{name.upper()} would be the name of a generated macro of a channel "
                 "named Mode: choose another name")
        names.append(name)

    modes = []
    for i, md in enumerate(raw):
        label = f"'{names[i]}'" if isinstance(names[i], str) else f"#{i + 1}"
        chans = md.get("channels")
        if chans is None:
            idx = [ch.index for ch in system.channels]
        elif not isinstance(chans, list) or not chans or not all(isinstance(c, str) for c in chans):
            fail(i, label, "channels", "must be a non-empty list of channel names")
            idx = []
        else:
            idx = []
            for c in chans:
                if c not in by_name:
                    fail(i, label, "channels", f"no channel '{c}' in the description")
                elif by_name[c].index in idx:
                    fail(i, label, "channels", f"'{c}' listed twice")
                else:
                    idx.append(by_name[c].index)
            idx.sort()
        periods = {}
        pd = md.get("periods", {})
        if not isinstance(pd, dict):
            fail(i, label, "periods", "must be a table {channel = max_period_us}")
            pd = {}
        for c, us in pd.items():
            if c not in by_name:
                fail(i, label, "periods", f"no channel '{c}' in the description")
            elif by_name[c].index not in idx:
                fail(i, label, "periods", f"'{c}' is not a channel of this mode")
            elif not is_int(us) or us <= 0:
                fail(i, label, "periods", f"{c}: {describe(us)} is not a positive integer (microseconds)")
            elif us * system.clock_hz // 1_000_000 < 1:
                fail(i, label, "periods", f"{c}: {us} us is less than one clock")
            else:
                periods[by_name[c].index] = us
        nxt = md.get("next")
        if nxt is None:
            targets = [j for j in range(len(raw)) if j != i]
        elif not isinstance(nxt, list) or not all(isinstance(n, str) for n in nxt):
            fail(i, label, "next", "must be a list of mode names")
            targets = []
        else:
            targets = []
            for n in nxt:
                if n not in names:
                    fail(i, label, "next", f"no mode '{n}' in the description")
                elif names.index(n) == i:
                    fail(i, label, "next", "a mode cannot switch to itself")
                elif names.index(n) not in targets:
                    targets.append(names.index(n))
        modes.append(Mode(name=names[i] if isinstance(names[i], str) else f"#{i + 1}", channels=idx,
                          periods=periods, next=targets))
    if modes and not requests:
        err.general("[[mode]] needs a channel of kind \"mode_request\": the board whose requests switch the "
                    "modes publishes it (docs/compiler.md \"Modes\")")
    for m in modes:                 # every mode reads the requests (a mode without next: none to read)
        if requests and m.next and requests[0].index not in m.channels:
            m.channels = sorted(m.channels + [requests[0].index])
    for m in modes:                 # the running mode is published in every mode
        for ch in infos:
            if ch.index not in m.channels:
                m.channels = sorted(m.channels + [ch.index])
    if modes and len(modes[0].channels) != len(system.channels):
        missing = [ch.name for ch in system.channels if ch.index not in modes[0].channels]
        fail(0, f"'{modes[0].name}'", "channels",
             f"the start-up mode (the first) must list every channel: the board headers give the "
             f"start-up mode's bounds (missing: {', '.join(missing)})")
    if modes and system.sync_mode:
        fail(0, f"'{modes[0].name}'", None, "modes need the time-rigid time mode ([system] mode)")
    if len(modes) == 1:
        fail(0, f"'{modes[0].name}'", None, "one mode is the description without [[mode]]: declare two or more")
    return modes


def check_request_channel(cd: dict, i: int, label, size: int, four: bool, n_req: int, err) -> bool:
    """The rules of a mode_request [[channel]] cd (the i-th, the n_req-th of
    its kind): no consumers, one word, three-buffer, one slot a cycle, only
    one such channel.  Errors to err; False if any."""
    ok = True

    def bad(field, msg):
        nonlocal ok
        err.channel(i, label, field, msg)
        ok = False

    if cd.get("consumers") is not None:
        bad("consumers", f"a {REQUEST_KIND} channel has no consumers: the controller reads it")
    if size > 4:
        bad("size", f"{size} bytes: a mode request is one word (size 4 or less)")
    if four:
        bad("four_slot", f"a {REQUEST_KIND} channel is three-buffer")
    if cd.get("max_slots", 1) != 1:
        bad("max_slots", "the controller reads the mode requests once a cycle (1)")
    if n_req > 1:
        bad("kind", f"more than one {REQUEST_KIND} channel")
    return ok


def mode_system(system: System, mode: Mode) -> System:
    """The system of one mode: its channels (copies, with the RAM places of the
    whole description and the mode's periods), planned on their own."""
    chans = []
    for ch in system.channels:
        if ch.index in mode.channels:
            c = copy.deepcopy(ch)
            if ch.index in mode.periods:
                c.max_period_us = mode.periods[ch.index]
                c.period_clocks = c.max_period_us * system.clock_hz // 1_000_000
            chans.append(c)
    return dataclasses.replace(system, channels=chans, modes=[], mode_window=system.bus.mode_switch_cycles)


def plan_mode(system: System, mode: Mode, plan_fn, entry_cap=None):
    """plan_fn(mode system) with every message of a failure naming the mode;
    entry_cap: the entries its slots may take (None: the ROM's)."""
    ms = mode_system(system, mode)
    ms.entry_cap = entry_cap
    try:
        return ms, plan_fn(ms)
    except ScheduleError as e:
        share = (f" (planned within its share of the ROM, {entry_cap} entries: the modes' slots and "
                 f"descriptors share its {MAX_ENTRIES})" if entry_cap is not None else "")
        raise ScheduleError([f"mode '{mode.name}': {m}{share}" for m in e.messages])


def rom_shares(room: int, wants: list) -> list:
    """The ROM entries of each mode's redundant slots: None for every mode
    (no cap) when the redundant slots the bus time allows them (wants) fit
    the `room` left by their first slots and descriptors; else `room` shared
    in proportion to the wants (largest remainder, ties to the earlier
    mode), so that every mode keeps the same fraction of its redundancy.  A
    share is never above its want."""
    total = sum(wants)
    if total <= room:
        return [None] * len(wants)
    shares = [room * w // total for w in wants]
    order = sorted(range(len(wants)), key=lambda i: (-(room * wants[i] % total), i))
    for i in order[:room - sum(shares)]:
        shares[i] += 1
    return shares


SHARE_ROUNDS = 3     # plans of the modes before the shares are taken as they are


def plan_modes(system: System, plan_fn) -> list:
    """Every mode planned (plan_fn on its system) within the ROM: [(mode
    system, plan)], the plan's .rom_share the entries of redundant slots it
    was given (None: as many as the bus time allows).

    Each mode needs one slot per channel and a descriptor; more than the
    ROM holds is an error naming every mode's count.  The rest of the ROM
    holds the redundant slots: when those the bus time allows every mode
    fit, each mode gets them all (the plan of the mode alone); else they
    are shared in proportion (rom_shares), first from an estimate of each
    mode's wants (plan.redundancy_estimate, no placement), then from what
    its plan reports (plan.redundancy["bus_allows"]: the fault plan and
    the termination bounds change it), for at most SHARE_ROUNDS plans of a
    mode whose share changed.  The slots of the plans always fit the ROM."""
    modes = system.modes
    first = [len(m.channels) for m in modes]
    total = sum(first) + len(modes)
    if total > MAX_ENTRIES:
        raise ScheduleError(
            f"{system.source}: the modes need {total} ROM entries without a single redundant slot (a slot per "
            f"channel of each mode and a descriptor per mode), at most {MAX_ENTRIES}: "
            + ", ".join(f"mode '{m.name}' {n} channel{'s' if n != 1 else ''}" for m, n in zip(modes, first))
            + f", {len(modes)} descriptors. Leave channels out of modes ([[mode]] channels) or declare fewer modes")
    room = MAX_ENTRIES - total
    wants = [redundancy_estimate(mode_system(system, m)) for m in modes]
    planned = [None] * len(modes)
    given = [None] * len(modes)

    def plan_with(shares):
        for i, m in enumerate(modes):
            if planned[i] is None or shares[i] != given[i]:
                cap = None if shares[i] is None else first[i] + shares[i]
                planned[i] = plan_mode(system, m, plan_fn, cap)
                given[i] = shares[i]
                planned[i][1].rom_share = shares[i]

    for _ in range(SHARE_ROUNDS):
        plan_with(rom_shares(room, wants))
        got = [p.redundancy["bus_allows"] for _, p in planned]
        if got == wants:
            break
        wants = got
    if sum(p.redundancy["planned"] for _, p in planned) > room:
        # the wants grew past the room in the last round: cap every mode
        plan_with(rom_shares(room, wants))
    return planned


def switch_latency(system: System, rep: dict):
    """The worst time from a request's publication to the start of the first
    cycle of the mode it asks for, in clocks, while mode rep runs (None: the
    mode reads no requests).  The controller samples the request channel once
    a cycle, at its slot's start + [bus] sample_offset (fault-free: a retried
    read is later, which only shortens the wait); a value published just
    after that sample is read a cycle later, and the switch follows at the
    end of that cycle: 2 C - sample."""
    req = next((ch.name for ch in system.channels if ch.request), None)
    starts = [e["start"] for e in rep["entries_list"] if e["channel"] == req]
    if not starts:
        return None
    if rep.get("planner") == "multi-rate":
        return _request_wait(system, rep, req, 1)
    return 2 * rep["cycle"]["clocks"] - (min(starts) + system.bus.sample_offset)


def _request_wait(system: System, rep: dict, req: str, m: int) -> int:
    """A multi-rate mode: the request channel's runs x_i over its span (its
    entries' due minor cycles); a request published just after run i's
    sample is read by a run m runs on, and the switch follows at the end of
    that run's minor cycle (a minor-cycle boundary): the largest
    end(minor cycle of x_(i+m)) - (x_i + sample_offset)."""
    c = rep["cycle"]["clocks"]
    mine = [e for e in rep["entries_list"] if e["channel"] == req]
    span_cycles = max(e["repetition"] for e in mine)
    runs = sorted(n * c + e["start"] for e in mine for n in range(e["base"], span_cycles, e["repetition"]))
    span = span_cycles * c

    def at(i):
        return runs[i % len(runs)] + span * (i // len(runs))
    return max((at(i + m) // c + 1) * c - (runs[i] + system.bus.sample_offset) for i in range(len(runs)))


def switch_latency_at_target(ms: System, rep: dict, lat):
    """Under a fault hypothesis: the switch latency that holds with its
    target probability.  The request's slot (one a cycle) reads the source:
    load Actual, store ReadLocked, load Actual, the word, each retried within
    the slot's budget; a slot that misses leaves the request for the next
    cycle.  With m slots in a row needed at the target (as a channel's
    period at the target, docs/compiler.md "Fault hypothesis"), a request
    waits at most m - 1 cycles more: lat + (m - 1) C.  None without a
    hypothesis; clocks None if no number of slots meets the target."""
    from .faults import access_sequence, delivery_curve, slots_needed
    h = ms.faults
    if h is None or lat is None:
        return None
    req = next(ch for ch in ms.channels if ch.request)
    r = ms.bus.retries_of(req)
    q = delivery_curve(h, access_sequence(req, -1), r, ms.drop_run)[r]
    m = slots_needed(max(0.0, 1.0 - q), h.eps, limit=64)
    if m is not None and rep.get("planner") == "multi-rate":
        clocks = _request_wait(ms, rep, req.name, m)
    else:
        clocks = None if m is None else lat + (m - 1) * rep["cycle"]["clocks"]
    return {"clocks": clocks, "us": None if clocks is None else round(clocks * 1e6 / ms.clock_hz, 3),
            "slots_needed": m, "slot_miss_probability": max(0.0, 1.0 - q), "probability": h.probability}


def mode_summary(system: System, modes: list, i: int, rep: dict, ms: System = None) -> dict:
    """report.json's entry of mode i, from that mode's own report rep (ms:
    that mode's system, for the switch latency under a fault hypothesis)."""
    m = modes[i]
    lat = switch_latency(system, rep)
    at_target = switch_latency_at_target(ms, rep, lat) if ms is not None else None
    keep = ("cycle", "cycle_limited_by", "entries", "redundant_slots", "drop_run", "bus_utilisation",
            "controller_busy", "schedule_fill", "planner", "minor_cycle", "cluster", "busiest_minor_cycle_clocks")
    return dict({k: rep[k] for k in keep if k in rep},
                name=m.name, start_up=i == 0, next=[modes[j].name for j in m.next],
                switch_latency=None if lat is None else {"clocks": lat, "us": round(lat * 1e6 / system.clock_hz, 3)},
                **({"switch_latency_at_target": at_target} if at_target else {}),
                channels=[{k: c[k] for k in ("name", "id", "max_period", "guaranteed_period", "redundancy",
                                             "repetition", "base", "fragments", "age_bound", "latency") if k in c}
                          for c in rep["channels"]],
                left_out=[ch.name for ch in system.channels if ch.index not in m.channels])
