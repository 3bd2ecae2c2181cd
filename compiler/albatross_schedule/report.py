"""The plan's report: report.json (machine-readable) and report.txt."""

from __future__ import annotations

import dataclasses
import os

from .faults import log10_or_none
from .layout import channel_bytes
from .model import Plan, System, one_minus, us
from .cgen import board_instances
from .plan import channel_bounds, pub_offset
from .termination import channel_termination, termination_summary


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
        mine = [s for s in plan.slots if s.channel is ch]
        if plan.multirate:
            # averaged over the cluster: each entry in 1/rep of the minor cycles, a run of a
            # fragmented value A / F accesses on average
            runs = sum(1.0 / (1 << s.rep_log) for s in mine)
            a_run = ch.accesses / ch.fragments
            busy_bus += runs * bus.access_cycles * a_run
            busy_ctl += runs * (bus.fetch_cycles + bus.first_access_extra + bus.access_cycles * a_run)
            fill += runs * ch.slot_len
        else:
            busy_bus += n * bus.access_cycles * ch.accesses
            busy_ctl += n * pub_offset(ch, bus, False)
            fill += n * ch.slot_len
        term = channel_termination(system, plan, ch)
        src_bytes = channel_bytes(ch.size, ch.layout) if ch.producer is not None else None
        dst_bytes = channel_bytes(ch.dst_size, ch.layout)
        entry = {
            "name": ch.name, "id": ch.id, "kind": ch.kind, "channel_kind": ch.layout, "type": ch.type_name,
            **({"mode_request": True} if ch.request else {}),
            **({"mode_info": True} if ch.mode_info else {}),
            "size": ch.size, "words": ch.words,
            "producer": ({"board": system.boards[ch.producer], "board_index": ch.producer,
                          "base": ch.src_base, "ram_bytes": src_bytes} if ch.producer is not None else None),
            "consumers": [{"board": system.boards[c], "board_index": c, "base": base, "ram_bytes": dst_bytes,
                           "termination": t}
                          for c, base, t in zip(ch.consumers, ch.dst_bases, term)],
            "ram_bytes": (src_bytes or 0) + len(ch.consumers) * dst_bytes,
            "spaced_for_termination": bool(getattr(ch, "spaced_for_termination", False)),
            "max_import_passes": ch.max_import_passes,
            "sync": ch.sync, "priority": ch.priority,
            "max_period": t(ch.period_clocks), "max_period_us_required": ch.max_period_us,
            "accesses": ch.accesses, "slot_length": ch.slot_len,
            "retries_per_slot": bus.retries_of(ch),
            "slots": [{"start": s.start, "length": s.length, "entry": i, "redundant": s.redundant,
                       "sync": s.sync, "repetition": 1 << s.rep_log, "base": s.base}
                      for i, s in enumerate(plan.slots) if s.channel is ch],
            "redundancy": len(mine),
            "repetition": 1 << mine[0].rep_log, "base": mine[0].base,
            "fragments": ch.fragments, "fragment_words": ch.frag_words or ch.words,
            "runs": {"per_span": n, "span": t(ch.run_span or plan.cycle)},
            "guaranteed_period": t(b["guaranteed_period_clocks"]),
            "min_gap": t(b["min_gap_clocks"]),
            "latency": None if b["latency_clocks"] is None else {
                "fault_free": t(b["latency_clocks"]["fault_free"]),
                "with_retries": t(b["latency_clocks"]["with_retries"])},
            "age_bound": None if b["age_bound_clocks"] is None else {
                "fault_free": t(b["age_bound_clocks"]["fault_free"]),
                "with_retries": t(b["age_bound_clocks"]["with_retries"])},
        }
        fe = getattr(system, "fault_eval", None)
        if system.faults is not None and fe is not None:
            ff = (b["latency_clocks"] or b["age_bound_clocks"])["fault_free"]
            rt = (b["latency_clocks"] or b["age_bound_clocks"])["with_retries"]
            back = bus.sample_offset if ch.kind == "copy" else 0
            for cons, x in zip(entry["consumers"], fe[ch.index]):
                p = x["period_at_target_clocks"]
                at = None if p is None else p + b["pub_offset_clocks"]["with_retries"] - back
                cons["faults"] = {
                    "slot_delivery_probability": x["slot_delivery_probability"],
                    "slot_miss_probability": x["slot_miss_probability"],
                    "slot_miss_log10": log10_or_none(x["slot_miss_probability"]),
                    "cycle_delivery_probability": x["cycle_delivery_probability"],
                    "cycle_miss_probability": x["cycle_miss_probability"],
                    "cycle_miss_log10": log10_or_none(x["cycle_miss_probability"]),
                    "slots_needed_at_target": x["slots_needed"],
                    "period_at_target": None if p is None else t(p),
                    "age_bound": {"fault_free": t(ff), "with_retries": t(rt),
                                  "at_target": None if at is None else t(at)},
                }
        chans.append(entry)
    boards = []
    for bi, name in enumerate(system.boards):
        insts = [{"channel": ch.name, "role": role, "base": base,
                  "bytes": channel_bytes(ch.size if role == "source" else ch.dst_size, ch.layout)}
                 for ch, role, base in board_instances(system, bi)]
        boards.append({"name": name, "index": bi, "ram_bytes": system.ram_bytes[bi],
                       "used_bytes": sum(i["bytes"] for i in insts), "instances": insts})
    return {
        "generator": "albatross_schedule (compiler/)",
        "description": os.path.basename(system.source),
        "system": system.name, "mode": system.mode, "clock_hz": hz,
        "cycle": t(plan.cycle),
        "cycle_limited_by": plan.limiter.name,
        "planner": "multi-rate" if plan.multirate else "single-rate",
        "minor_cycle": t(plan.cycle),
        "cluster": {"log2": plan.cluster_log, "minor_cycles": plan.cluster, "span": t(plan.cycle * plan.cluster)},
        **({"minor_cycle_source": plan.minor_source, "not_due_cost_clocks": plan.skip_cost,
            "busiest_minor_cycle_clocks": plan.busiest} if plan.multirate else {}),
        "capacity_clocks": plan.capacity,
        "entries": len(plan.slots),
        "redundant_slots": redundant_slots(plan),
        "bus": dataclasses.asdict(bus),
        "drop_run": system.drop_run,
        "fault_hypothesis": None if system.faults is None else dict(
            system.faults.as_dict(), drop_run=system.drop_run,
            slots_relied_on=getattr(system, "fault_split", None)),
        "definitions": {
            "slot_length": "fetch + first_access_extra + access_cycles*A + retries_per_slot*(timeout+access+1) + guard",
            "guaranteed_period": "largest gap between consecutive slot starts of the channel (cyclic); multi-rate: "
                                 "the runs of its entries over the cluster (an entry runs in the minor cycles n with "
                                 "n mod repetition = base), and a value in F fragments: the longest span from a run "
                                 "to the F-th run after it",
            "cluster": "multi-rate: the plan repeats after 2^log2 minor cycles of `cycle` clocks (H1; H2.cluster = "
                       "log2); single-rate: 1",
            "repetition": "per channel and slot: the entry runs every `repetition` minor cycles, in those n with "
                          "n mod repetition = base (E6); 1 and 0: every cycle",
            "fragments": "F: a value of W words goes in F runs of fragment_words words each (E7; the last the rest); "
                         "the destinations publish after the last",
            "not_due_cost_clocks": "multi-rate: what an entry that is not due costs in a minor cycle, from max(its "
                                   "start, the end of the entry before it) (model.not_due_cost)",
            "busiest_minor_cycle_clocks": "multi-rate: the end of the last entry in the busiest minor cycle, skip "
                                          "costs included (at most capacity_clocks)",
            "runs": "per channel: its runs (slots in a minor cycle in which they are due) in every span clocks",
            "latency": "producer's store of source Actual -> controller's store of the last destination Actual: "
                       "max over slots of start(next)+pub_offset - (start+fetch+access); F fragments: the "
                       "(2F-1)-th run after it in place of the next",
            "age_bound": "TIME/STATUS: guaranteed_period + pub_offset",
            "retries_per_slot": "the slot's retry budget R: failed accesses its length absorbs (sized from the "
                                "fault hypothesis when the description has one)",
            "drop_run": "K (ROM H2): a destination is dropped for the rest of an Export after K failed "
                        "attempts of one access in a row",
            "faults": "per consumer, under the fault hypothesis: slot_delivery_probability q = the worst "
                      "start state's probability that one slot delivers (a new value at every destination); "
                      "cycle_delivery_probability >= 1 - (1 - q)^slots; slots_needed_at_target m = fewest "
                      "slots in a row that all miss with probability <= 1 - probability; period_at_target = "
                      "max over slots of start(i+m) - start(i); age_bound.at_target = period_at_target + "
                      "pub_offset with retries (COPY: - fetch - access, as latency), holding with the target "
                      "probability",
            "redundant_slots": "planned: the slots beyond one per channel and cycle; bus_allows: those the bus "
                               "time allows (the round-robin of the plan without a limit on entries); cut: "
                               "planned < bus_allows, the ROM stopped the round-robin at entries_allowed "
                               "entries (its 255; with modes whose slots do not all fit, the mode's share: "
                               "the redundant slots are shared in proportion to what the bus time allows "
                               "each mode)",
            "bus_utilisation": "sum over slots of access_cycles*A (fault-free bus-busy clocks) / cycle (multi-rate: "
                               "each slot weighted by 1/repetition, A / F a run)",
            "controller_busy": "sum over slots of fetch + first_access_extra + access_cycles*A / cycle (multi-rate: "
                               "as bus_utilisation)",
            "schedule_fill": "sum of slot lengths / cycle (multi-rate: each weighted by 1/repetition)",
            "channel_kind": "three_buffer (the paper's channel) or four_slot (wait-free Import; 4 buffers, "
                            "E0 flag four_slot on every entry)",
            "mode_request": "true on the mode_request channel (the controller reads its value as a mode request)",
            "mode_info": "true on the mode channel (the controller publishes {running mode, time its first cycle began})",
            "switch_latency_at_target": "modes under a fault hypothesis: switch_latency + (m - 1) cycles, m the request "
                                        "slots in a row needed so that all miss with probability <= 1 - probability",
            "termination": "per consumer: D = shortest time between two publishes to it (slot i+1 start + "
                           "fetch + access*(E-1) - slot i end), T / V = its Import loop (controller clocks); "
                           "three-buffer: unbounded if D <= T, else max_passes = ReadLocked stores per Import = "
                           "1 + ceil(V / (D - T)), max_accesses = 1 + 2*max_passes + Wd; four-slot: 1 pass, "
                           "3 + Wd accesses; accesses_old = 1 + Wd; Wd = W + 1 (value and taken_at)",
        },
        "bus_utilisation": round(busy_bus / plan.cycle, 4),
        "controller_busy": round(busy_ctl / plan.cycle, 4),
        "schedule_fill": round(fill / plan.cycle, 4),
        "channels": chans,
        "boards": boards,
        "entries_list": [{"entry": i, "channel": s.channel.name, "id": s.channel.id, "kind": s.channel.kind,
                          "start": s.start, "length": s.length, "redundant": s.redundant, "sync": s.sync,
                          "repetition": 1 << s.rep_log, "base": s.base, "fragment_words": s.frag}
                         for i, s in enumerate(plan.slots)],
    }


def redundant_slots(plan: Plan):
    """report.json "redundant_slots" (plan.redundancy, set by plan.build_plan)."""
    r = getattr(plan, "redundancy", None)
    if r is None:
        return None
    return {"planned": r["planned"], "bus_allows": r["bus_allows"], "cut": r["planned"] < r["bus_allows"],
            "entries_allowed": r["entry_cap"]}


def redundancy_txt(r) -> str:
    """The redundant slots of a plan for report.txt, saying when the ROM cut them."""
    if r is None:
        return ""
    if not r["cut"]:
        return f"{r['planned']} redundant slots (all the bus time allows)"
    return (f"{r['planned']} redundant slots of the {r['bus_allows']} the bus time allows: CUT to fit the ROM "
            f"({r['entries_allowed']} entries for all its slots)")


def render_report_txt(rep: dict) -> str:
    def f(x):
        return f"{x:.2f}"

    L = []
    multi = rep.get("planner") == "multi-rate"
    L.append(f"ALBATROSS schedule of '{rep['system']}' ({rep['description']}), {rep['mode']}")
    if multi:
        cl = rep["cluster"]
        L.append(f"clock {rep['clock_hz']} Hz; multi-rate: minor cycle {rep['cycle']['clocks']} clocks = "
                 f"{f(rep['cycle']['us'])} us ({rep['minor_cycle_source']}), cluster 2^{cl['log2']} = "
                 f"{cl['minor_cycles']} minor cycles = {f(cl['span']['us'])} us; {rep['entries']} ROM entries")
        L.append(f"bus utilisation {100 * rep['bus_utilisation']:.1f} % (fault-free accesses, over the cluster), "
                 f"controller busy {100 * rep['controller_busy']:.1f} %, slots fill {100 * rep['schedule_fill']:.1f} "
                 f"% of a minor cycle on average; the busiest minor cycle ends at {rep['busiest_minor_cycle_clocks']} "
                 f"of its {rep['capacity_clocks']} usable clocks (an entry not due costs "
                 f"{rep['not_due_cost_clocks']} clocks)")
    else:
        L.append(f"clock {rep['clock_hz']} Hz; cycle {rep['cycle']['clocks']} clocks = {f(rep['cycle']['us'])} us "
                 f"(smallest max_period: {rep['cycle_limited_by']}); {rep['entries']} ROM entries")
        L.append(f"bus utilisation {100 * rep['bus_utilisation']:.1f} % (fault-free accesses), controller busy "
                 f"{100 * rep['controller_busy']:.1f} %, slots fill {100 * rep['schedule_fill']:.1f} % of the cycle")
    if rep.get("redundant_slots") and not rep.get("modes"):
        L.append(redundancy_txt(rep["redundant_slots"]))
    L.append("")
    hdr = ["id", "channel", "kind", "route", "W", "A", "L", "RAM B", "slots", "max period", "guar. period",
           "latency ff", "latency retry", "age ff", "age retry"]
    if multi:
        hdr[8:9] = ["entries", "rep", "base", "F"]
    rows = []
    for c in rep["channels"]:
        src = c["producer"]["board"] if c["producer"] else "controller"
        route = f"{src}->{','.join(d['board'] for d in c['consumers'])}"
        lat = c["latency"]
        age = c["age_bound"]
        kind = c["kind"] + (" 4-slot" if c["channel_kind"] == "four_slot" else "")
        reps = sorted({s["repetition"] for s in c["slots"]})
        shape = ([str(c["redundancy"]), "/".join(map(str, reps)), ",".join(str(s["base"]) for s in c["slots"]),
                  str(c["fragments"])] if multi else [str(c["redundancy"])])
        rows.append([str(c["id"]), c["name"] + (" (sync)" if c["sync"] else ""), kind, route,
                     str(c["words"]), str(c["accesses"]), str(c["slot_length"]), str(c["ram_bytes"])] + shape + [
                     f(c["max_period"]["us"]), f(c["guaranteed_period"]["us"]),
                     f(lat["fault_free"]["us"]) if lat else "-", f(lat["with_retries"]["us"]) if lat else "-",
                     f(age["fault_free"]["us"]) if age else "-", f(age["with_retries"]["us"]) if age else "-"])
    widths = [max(len(r[i]) for r in rows + [hdr]) for i in range(len(hdr))]
    L.append("  ".join(h.ljust(w) for h, w in zip(hdr, widths)))
    L.append("  ".join("-" * w for w in widths))
    for r in rows:
        L.append("  ".join(v.ljust(w) if i < 4 else v.rjust(w) for i, (v, w) in enumerate(zip(r, widths))))
    if multi:
        L.append("(times in us; W words, A fault-free accesses of a whole value, L slot clocks of one run, RAM B = "
                 "bytes of all its instances; entries = ROM entries, each due in the minor cycles n with n mod rep = "
                 "base; F = fragments, the runs one value takes; 4-slot = the wait-free four-slot kind)")
    else:
        L.append("(times in us; W words, A fault-free accesses, L slot clocks, RAM B = bytes of all its "
                 "instances; slots = redundancy factor; 4-slot = the wait-free four-slot kind)")
    L.append("")
    L.append("Import termination per consumer (clocks; D = shortest time between two publishes to it, "
             "T, V = its Import loop)")
    for c in rep["channels"]:
        for d in c["consumers"]:
            t = d["termination"]
            tv = "" if t["T_clocks"] is None else f", T {t['T_clocks']}, V {t['V_clocks']}"
            spaced = " (slots spaced)" if c["spaced_for_termination"] else ""
            L.append(f"  {c['name']} -> {d['board']}: D {t['D_clocks']}{tv}: {termination_summary(t)}{spaced}")
    L.append("")
    fh = rep.get("fault_hypothesis")
    if fh:
        burst = (f"independent (mean burst {fh['mean_burst']:.3g})" if fh["independent"]
                 else f"mean burst {fh['mean_burst']:g}")
        L.append(f"Fault hypothesis: rate {fh['rate']:g} per access, {burst}, target "
                 f"probability {one_minus(1.0 - fh['probability'])}; drop run K = {fh['drop_run']}")
        if multi:
            L.append("  channel -> consumer: R retries per slot, run delivery q, span delivery (xN runs per span of "
                     "its runs), m runs needed at the target, age bound fault-free / with retries / at the target (us)")
        else:
            L.append("  channel -> consumer: R retries per slot, slot delivery q, cycle delivery (xN slots per "
                     "cycle), m slots needed at the target, age bound fault-free / with retries / at the target (us)")
        L.append("  (probabilities as 1 - the probability of a miss)")
        for c in rep["channels"]:
            for d in c["consumers"]:
                x = d.get("faults")
                if not x:
                    continue
                a = x["age_bound"]
                at = "never" if a["at_target"] is None else f(a["at_target"]["us"])
                L.append(f"  {c['name']} -> {d['board']}: R {c['retries_per_slot']}, q {one_minus(x['slot_miss_probability'])}"
                         f", {'span' if multi else 'cycle'} {one_minus(x['cycle_miss_probability'])} "
                         f"(x{c['runs']['per_span'] if multi else c['redundancy']}"
                         f"), m {x['slots_needed_at_target']}: age "
                         f"{f(a['fault_free']['us'])} / {f(a['with_retries']['us'])} / {at}")
        L.append("")
    L.append("RAM per board (byte offsets)")
    for b in rep["boards"]:
        L.append(f"  {b['name']} (board {b['index']}): {b['used_bytes']} of {b['ram_bytes']} bytes")
        for i in b["instances"]:
            L.append(f"    0x{i['base']:04x}  {i['bytes']:5d} B  {i['channel']} ({i['role']})")
    L.append("")
    if rep.get("modes"):
        L.append("Modes (the ROM image holds every mode, the board headers the start-up mode's bounds; the "
                 "controller switches at a cycle boundary when the mode_request channel asks)")
        for m in rep["modes"]:
            tag = " (start-up)" if m["start_up"] else ""
            L.append(f"  {m['name']}{tag}: cycle {m['cycle']['clocks']} clocks = {f(m['cycle']['us'])} us, "
                     f"{m['entries']} entries, bus utilisation {100 * m['bus_utilisation']:.1f} %, drop run "
                     f"{m['drop_run']}; "
                     + (redundancy_txt(m["redundant_slots"]) + "; " if m.get("redundant_slots") else "")
                     + f"switches to {', '.join(m['next']) or 'none'}"
                     + (f"; leaves out {', '.join(m['left_out'])}" if m["left_out"] else "")
                     + (f"; a request switches within {f(m['switch_latency']['us'])} us"
                        if m.get("switch_latency") else "")
                     + (f" (under the fault hypothesis: {f(m['switch_latency_at_target']['us'])} us)"
                        if (m.get("switch_latency_at_target") or {}).get("us") is not None else ""))
            if m.get("planner") == "multi-rate":
                L.append(f"    multi-rate: minor cycle {m['cycle']['clocks']} clocks, cluster of "
                         f"{m['cluster']['minor_cycles']} minor cycles ({f(m['cluster']['span']['us'])} us)")
            for c in m["channels"]:
                shape = (f"{c['redundancy']} entr{'y' if c['redundancy'] == 1 else 'ies'} of repetition "
                         f"{c['repetition']}" + (f", {c['fragments']} fragments" if c["fragments"] > 1 else "")
                         if m.get("planner") == "multi-rate" else f"x{c['redundancy']} per cycle")
                L.append(f"    {c['name']}: guaranteed period {f(c['guaranteed_period']['us'])} / max "
                         f"{f(c['max_period']['us'])} us, {shape}")
        L.append("")
    L.append("ROM entries")
    if multi:
        L.append("  entry  start    end      rep    base   frag  channel")
    else:
        L.append("  entry  start    end      channel")
    for e in rep["entries_list"]:
        tag = " SYNC" if e["sync"] else (" (redundant)" if e["redundant"] else "")
        due = f"{e['repetition']:5d}  {e['base']:5d}  {e['fragment_words']:5d}  " if multi else ""
        L.append(f"  {e['entry']:5d}  {e['start']:7d}  {e['start'] + e['length']:7d}  {due}{e['channel']}{tag}")
    return "\n".join(L) + "\n"
