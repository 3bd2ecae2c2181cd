#!/usr/bin/env python3
"""plot_ages.py AGES.csv REPORT.json OUT.svg -- each channel's data age over time.

AGES.csv (sim/mobot_sim.cpp --ages) has one row per time bucket: its first
cycle, then per series (a channel at one consumer) two columns: the worst age
seen by an Import in that bucket, in controller clocks (empty: no Import),
and the largest bound in force its ages were judged by (empty: none, a
schedule mode without the channel).  The header names each series
"Channel@consumer(bound=N),bound" (N: the bound at the end of the run, in
the start-up mode).  REPORT.json gives the clock, the crash, the first stale
report, the mode switches and per series the worst judged age / bound.

One panel per series that has ages: the worst age against time (ms), in us,
or in ms for a slow channel (a panel whose scale reaches 10 ms: the robot's
RadarScan and NavLog beside its 50 us loops),
blue where a bound applies, grey where none does (a mode without the
channel, or the settling after a switch back to one with it), the bound in
force dashed, ages above it red.  The scale is set by the judged ages and
the bound; grey ages above it are clipped at the panel's top and their
largest is written there.  A series with no Import at all (a consumer whose
program never reads the channel) gets no panel, and the picture says so.
A description with schedule modes gets its modes as bands behind the panels
and a line at every switch.  The legend under the panels explains every
mark and why the bound of a copy channel steps up (the producer's longest
gap between two Exports so far is part of it).  Standard library only.
"""
import csv
import json
import re
import sys
import textwrap

W, PANEL_H, GAP, LEFT, RIGHT, TOP, MARGIN = 900, 70, 26, 190, 20, 46, 12
LINE = 15  # legend line height
BLUE, GREEN, RED, GREY, PURPLE, ORANGE = "#1f5fb4", "#2a7", "#d22", "#999", "#73c", "#e90"


def fail(msg):
    sys.exit(f"plot_ages: {msg}")


def read(ages_path, report_path):
    try:
        with open(report_path) as f:
            report = json.load(f)
        with open(ages_path) as f:
            rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    except (OSError, ValueError) as e:
        fail(f"cannot read input: {e}")
    if len(rows) < 2 or rows[0][0] != "cycle":
        fail(f"{ages_path}: no header row 'cycle,...' or no data")
    series = []
    names = rows[0][1:]
    if len(names) % 2:
        fail(f"{ages_path}: expected two columns per series (age, bound), got {len(names)} columns")
    for name, second in zip(names[::2], names[1::2]):
        m = re.fullmatch(r"(.+)@(.+)\(bound=(\d+)\)", name)
        if not m or second != "bound":
            fail(f"{ages_path}: cannot read series name {name!r},{second!r}")
        series.append({"channel": m[1], "consumer": m[2], "bound": int(m[3]), "points": []})
    try:
        for r in rows[1:]:
            t = int(r[0])
            for k, s in enumerate(series):
                v, b = (r[1 + 2 * k: 3 + 2 * k] + ["", ""])[:2]
                if v:
                    s["points"].append((t, int(v), int(b) if b else None))
    except ValueError as e:
        fail(f"{ages_path}: not a number: {e}")
    bucket = int(rows[2][0]) - int(rows[1][0]) if len(rows) > 2 else max(1, int(report.get("cycles", 1)))
    # the sim's own verdict figures per series: the worst judged age / its bound in force
    by = {(e.get("channel"), e.get("consumer")): e for e in report.get("series") or []}
    for s in series:
        e = by.get((s["channel"], s["consumer"]), {})
        s["ratio"] = e.get("worst_ratio")
        s["kind"] = e.get("kind", "")
    return report, series, max(1, bucket)


def mode_bands(report, t_end):
    """[(first cycle, end cycle, mode name)] from the report's mode switches."""
    switches = report.get("mode_switches") or []
    if not switches:
        return []
    bands, start, name = [], 0, switches[0]["from"]
    for sw in switches:
        bands.append((start, int(sw["cycle"]), name))
        start, name = int(sw["cycle"]), sw["to"]
    bands.append((start, t_end, name))
    return bands


def runs(points, judged):
    """The stretches of consecutive points that are (judged=True) or are not judged."""
    out, cur = [], []
    for p in points:
        if (p[2] is not None) == judged:
            cur.append(p)
        elif cur:
            out.append(cur)
            cur = []
    if cur:
        out.append(cur)
    return out


def gap_steps(points, switches, bucket):
    """[(cycle, new bound)] of the rises of the bound in force between two
    buckets of one mode once it has settled after a switch (the bound grows
    after a switch and then drops to the new mode's: settled from that drop
    on, or 40 buckets after the switch).  For a copy channel such a rise is
    its producer's longest gap growing.  A run of rises in consecutive
    buckets (a slow channel's gap still open, growing with time) gets one
    marker, at its start."""
    out, last_t, prev_b, settled, start, rising = [], -1, None, True, 0, False
    for t, _, b in points:
        crossed = [c for c in switches if last_t < c <= t]
        last_t = t
        if crossed:
            settled, start, prev_b = False, crossed[-1], None
        if b is None:
            prev_b, rising = None, False
            continue
        up = False
        if not settled and ((prev_b is not None and b < prev_b) or t >= start + 40 * bucket):
            settled = True
        elif settled and prev_b is not None and b > prev_b:
            up = True
            if not rising:
                out.append((t, b))
        prev_b, rising = b, up
    return out


def esc(text):
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def main():
    if len(sys.argv) != 4:
        fail("usage: plot_ages.py AGES.csv REPORT.json OUT.svg")
    report, all_series, bucket = read(sys.argv[1], sys.argv[2])
    hz = float(report.get("clock_hz", 50e6))
    t_end = max(1, int(report.get("cycles", 1)))
    crash = int(report.get("crash_cycle", 0)) if report.get("crash_board") else 0
    stale = int(report.get("first_stale_cycle", 0)) if report.get("stale_events", 0) else 0
    us = 1e6 / hz
    # the channel whose producer crashes: the sim judges none of its ages, and its
    # bound in force grows with the producer's open gap: drawn grey from the crash on
    crashed = {p.get("channel") for p in report.get("producers") or []
               if crash and p.get("producer") == report.get("crash_board")}
    for s in all_series:
        s["crashed"] = s["channel"] in crashed
        s["modes"] = set()   # the modes that carry the channel (a bound applied there)
        if s["crashed"]:
            s["points"] = [(t, v, None if t + bucket > crash else b) for t, v, b in s["points"]]
    series = [s for s in all_series if s["points"]]
    unread = [s for s in all_series if not s["points"]]
    plot_w = W - LEFT - RIGHT
    x = lambda t: LEFT + plot_w * min(t, t_end) / t_end
    bands = mode_bands(report, t_end)
    shades = {}
    for _, _, name in bands:
        shades.setdefault(name, ["#fafafa", "#e8eefc", "#fcefdc", "#e6f5e6", "#f5e6f5"][len(shades) % 5])

    def mode_at(t):
        return next((name for t0, t1, name in bands if t0 <= t < t1), None)

    for s in series:
        s["modes"] = {mode_at(t) for t, _, b in s["points"] if b is not None}

    # ---- the legend, line by line: each a list of (colour or None, text) ----
    copies = sorted({s["channel"] for s in series if s["kind"] == "copy"})
    legend = [[(BLUE, "—— worst age"), (None, f" per bucket of {bucket * us:.0f} us   "),
               (GREEN, "- - - bound in force"), (None, "   "), (RED, "● above it")]
              + ([(None, "   "), (GREEN, "▼ the bound steps up"), (None, " (a copy channel: see below)")] if copies else [])]
    if any(p[2] is None for s in series for p in s["points"]):
        legend.append([(GREY, "—— no bound applies"), (None, " (a mode without the channel" + (
            ", or its producer crashes" if crashed else "") + "): not judged; above the scale, drawn at the top "
            "with the largest written")])
    marks = []
    if bands:
        colour = {"#fafafa": "white", "#e8eefc": "blue", "#fcefdc": "orange", "#e6f5e6": "green"}
        marks += [(PURPLE, "| mode switch"), (None, "   bands: " + ", ".join(
            f"{name} ({colour.get(shade, 'pink')})" for name, shade in shades.items()) + "   ")]
    if crash:
        marks += [(RED, f"| {report['crash_board']} crashes"), (None, "   ")]
    if stale:
        marks += [(ORANGE, "| navigation first reports RadarMap stale"),
                  (None, " (after the crash)" if crash else
                   " (expected: a stay in a mode without RadarMap)" if bands else "")]
    if marks:
        legend.append(marks)
    notes = []
    if copies:
        notes.append(f"The bound of a copy channel ({', '.join(copies)}) is the compiler's latency plus the longest "
                     "gap between two Exports its producer has shown so far: it steps up when a longer gap is first "
                     "seen, and each age is judged by the bound as it stood at its Import.")
    if bands:
        notes.append("Right after a switch the bound is the old mode's plus the time since the switch (the spike at "
                     "each switch), until one cycle and one bound of the new mode have passed; a channel the new mode "
                     "brings back is judged meanwhile by the bound it had when it was last carried plus the time "
                     "since (a value in fragments cut by the switch goes on after the return, its taken_at from its "
                     "first fragment).")
    if unread:
        by_ch = {}
        for s in unread:
            by_ch.setdefault(s["channel"], []).append(s["consumer"])
        notes.append("No panel: " + "; ".join(f"{ch} at {', '.join(c)}" for ch, c in by_ch.items())
                     + ": the channel reaches those boards, but their programs never import it (no age to draw).")
    for note in notes:   # about 6 px a character at 11 px: 135 characters fit the width
        legend += [[(None, line)] for line in textwrap.wrap(note, 135)]

    height = TOP + len(series) * (PANEL_H + GAP) + 14 + LINE * (len(legend) + 1)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{height}" '
           f'font-family="sans-serif" font-size="11">',
           f'<rect width="{W}" height="{height}" fill="white"/>',
           f'<text x="{MARGIN}" y="18" font-size="14" font-weight="bold">Data age at each consumer '
           f'(worst per time bucket) against the guaranteed bound</text>',
           f'<text x="{MARGIN}" y="34" fill="#555">{esc(report.get("label", ""))}: '
           f'{t_end * 1e3 / hz:.1f} ms, fault rate {report.get("fault_rate", 0)}, '
           f'{report.get("faults_injected", 0)} faults injected'
           + (f', {report["crash_board"]} crashes at {crash * 1e3 / hz:.2f} ms' if crash else "")
           + (f', {len(bands) - 1} mode switches' if bands else "")
           + "; ages in us, or ms where the panel says so</text>"]
    for i, s in enumerate(series):
        top = TOP + i * (PANEL_H + GAP)
        bottom = top + PANEL_H
        judged = [v for _, v, b in s["points"] if b is not None]
        free = [(t, v) for t, v, b in s["points"] if b is None]
        worst = max(judged, default=0)
        # the scale: the judged ages and the bound (grey ages above it are clipped)
        ymax = max(1.3 * s["bound"], 1.1 * worst, 1)
        y = lambda v: bottom - PANEL_H * min(v, ymax) / ymax
        # the unit: ms for a slow channel (its scale reaches 10 ms), else us
        unit, per = ("ms", us / 1e3) if ymax * us >= 1e4 else ("us", us)
        out.append(f'<rect x="{LEFT}" y="{top}" width="{plot_w}" height="{PANEL_H}" fill="#fafafa" stroke="#ccc"/>')
        for t0, t1, name in bands:
            out.append(f'<rect x="{x(t0):.1f}" y="{top}" width="{x(t1) - x(t0):.1f}" height="{PANEL_H}" '
                       f'fill="{shades[name]}"/>')
            if i == 0 and x(t1) - x(t0) > 30:
                out.append(f'<text x="{(x(t0) + x(t1)) / 2:.1f}" y="{top - 4}" text-anchor="middle" '
                           f'fill="#555" font-size="9">{esc(name)}</text>')
        for t0, _, _ in bands[1:]:
            out.append(f'<line x1="{x(t0):.1f}" x2="{x(t0):.1f}" y1="{top}" y2="{bottom}" stroke="{PURPLE}" '
                       f'stroke-width="0.8"/>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 14}" text-anchor="end" font-weight="bold">'
                   f'{esc(s["channel"])}</text>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 28}" text-anchor="end" fill="#555">at {esc(s["consumer"])}</text>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 42}" text-anchor="end" fill="#555">'
                   f'worst {worst * per:.1f} {unit}</text>')
        if s["crashed"]:
            out.append(f'<text x="{LEFT - 8}" y="{top + 56}" text-anchor="end" fill="#555">'
                       f'not judged: {esc(report["crash_board"])} crashes</text>')
        elif s["ratio"] is not None:
            out.append(f'<text x="{LEFT - 8}" y="{top + 56}" text-anchor="end" fill="#555">'
                       f'{s["ratio"]:.2f} of its bound</text>')
        out.append(f'<text x="{LEFT + 3}" y="{top + 10}" fill="{GREY}" font-size="9">{ymax * per:.0f} {unit}</text>')
        # the bound in force: a step line over the buckets that had one
        for run in runs(s["points"], True):
            pts = []
            for t, _, b in run:
                pts += [f'{x(t):.1f},{y(b):.1f}', f'{x(t + bucket):.1f},{y(b):.1f}']
            out.append(f'<polyline points="{" ".join(pts)}" fill="none" stroke="{GREEN}" stroke-dasharray="5,3"/>')
        # the ages: judged stretches blue, the others grey, each stretch joined to the next
        pts = s["points"]
        line, colour = [], None
        for k in range(len(pts) - 1):
            (t, v, b), (t2, v2, b2) = pts[k], pts[k + 1]
            c = BLUE if b is not None and b2 is not None else GREY
            if c != colour and line:
                out.append(f'<polyline points="{" ".join(line)}" fill="none" stroke="{colour}" stroke-width="1"/>')
                line = []
            if not line:
                line = [f'{x(t):.1f},{y(v):.1f}']
            line.append(f'{x(t2):.1f},{y(v2):.1f}')
            colour = c
        if line:
            out.append(f'<polyline points="{" ".join(line)}" fill="none" stroke="{colour}" stroke-width="1"/>')
        for t, v, b in pts:
            if b is not None and v > b:
                out.append(f'<circle cx="{x(t):.1f}" cy="{y(v):.1f}" r="1.8" fill="{RED}"/>')
        # each step up of the bound within a mode, once it has settled after a switch: a marker
        for t_step, b_high in gap_steps(s["points"] if s["kind"] == "copy" else [], [t0 for t0, _, _ in bands[1:]], bucket):
            xs, ys = x(t_step), y(b_high)
            out.append(f'<polygon points="{xs:.1f},{ys - 1:.1f} {xs - 3:.1f},{ys - 7:.1f} {xs + 3:.1f},{ys - 7:.1f}" '
                       f'fill="{GREEN}"/>')
        # the grey ages clipped at the top: their largest, written at the first clipped stretch
        clipped = [(t, v) for t, v in free if v > ymax]
        if clipped:
            t_hi, v_hi = max(free, key=lambda p: p[1])
            first = clipped[0][0]
            where = mode_at(t_hi)
            why = (f' (after the crash of {report["crash_board"]})' if s["crashed"] and t_hi + bucket > crash else
                   f' (in {where}, no {s["channel"]})' if where and where not in s["modes"] else "")
            label = f'not judged: up to {v_hi * per:.0f} {unit}{why}'
            anchor_x = x(first) + 4
            out.append(f'<text x="{anchor_x:.1f}" y="{top + 13}" fill="#666" font-size="9">{esc(label)}</text>')
        for t, colour in ((crash, RED), (stale, ORANGE)):
            if t:
                out.append(f'<line x1="{x(t):.1f}" x2="{x(t):.1f}" y1="{top}" y2="{bottom}" stroke="{colour}"/>')
    base = TOP + len(series) * (PANEL_H + GAP) - GAP + 14
    for k in range(6):
        t = t_end * k / 5
        out.append(f'<text x="{x(t):.1f}" y="{base}" text-anchor="{"end" if k == 5 else "middle"}" fill="#555">'
                   f'{t * 1e3 / hz:.1f} ms</text>')
    for n, line in enumerate(legend):
        spans = "".join(f'<tspan fill="{c}">{esc(text)}</tspan>' if c else esc(text) for c, text in line)
        out.append(f'<text x="{MARGIN}" y="{base + LINE * (n + 1) + 4}" xml:space="preserve">{spans}</text>')
    out.append("</svg>")
    try:
        with open(sys.argv[3], "w") as f:
            f.write("\n".join(out) + "\n")
    except OSError as e:
        fail(f"cannot write {sys.argv[3]}: {e}")


if __name__ == "__main__":
    main()
