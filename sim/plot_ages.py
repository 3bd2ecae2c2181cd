#!/usr/bin/env python3
"""plot_ages.py AGES.csv REPORT.json OUT.svg -- each channel's data age over time.

AGES.csv (sim/mobot_sim.cpp --ages) has one row per time bucket: its first
cycle, then per series (a channel at one consumer) two columns: the worst age
seen by an Import in that bucket, in controller clocks (empty: no Import),
and the largest bound in force its ages were judged by (empty: none, a
schedule mode without the channel).  The header names each series
"Channel@consumer(bound=N),bound" (N: the start-up mode's bound).
REPORT.json gives the clock, the crash, the first stale report and the mode
switches.  One panel per series: the worst age (us) against time (ms), the
bound in force dashed; ages above it drawn red, ages no bound applies to
grey; ages above 3x the start-up bound are clipped to the panel's top.  A
description with schedule modes gets its modes as bands behind the panels
and a line at every switch.  Standard library only.
"""
import csv
import json
import re
import sys

W, PANEL_H, GAP, LEFT, RIGHT, TOP = 900, 70, 26, 190, 20, 46


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
    for r in rows[1:]:
        t = int(r[0])
        for k, s in enumerate(series):
            v, b = (r[1 + 2 * k: 3 + 2 * k] + ["", ""])[:2]
            if v:
                s["points"].append((t, int(v), int(b) if b else None))
    return report, series


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


def main():
    if len(sys.argv) != 4:
        fail("usage: plot_ages.py AGES.csv REPORT.json OUT.svg")
    report, series = read(sys.argv[1], sys.argv[2])
    hz = float(report.get("clock_hz", 50e6))
    t_end = max(1, int(report.get("cycles", 1)))
    crash = int(report.get("crash_cycle", 0)) if report.get("crash_board") else 0
    stale = int(report.get("first_stale_cycle", 0)) if report.get("stale_events", 0) else 0
    us = 1e6 / hz
    plot_w = W - LEFT - RIGHT
    height = TOP + len(series) * (PANEL_H + GAP) + 30
    x = lambda t: LEFT + plot_w * min(t, t_end) / t_end
    bands = mode_bands(report, t_end)
    shades = {}
    for _, _, name in bands:
        shades.setdefault(name, ["none", "#e8eefc", "#fcefdc", "#e6f5e6", "#f5e6f5"][len(shades) % 5])
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{height}" '
           f'font-family="sans-serif" font-size="11">',
           f'<rect width="{W}" height="{height}" fill="white"/>',
           f'<text x="{LEFT}" y="18" font-size="14" font-weight="bold">Data age at each consumer '
           f'(worst per time bucket) against the guaranteed bound</text>',
           f'<text x="{LEFT}" y="34" fill="#555">{report.get("label", "")}: '
           f'{t_end * 1e3 / hz:.1f} ms, fault rate {report.get("fault_rate", 0)}, '
           f'{report.get("faults_injected", 0)} faults injected'
           + (f', {report["crash_board"]} crashes at {crash * 1e3 / hz:.2f} ms' if crash else "")
           + (f', {len(bands) - 1} mode switches' if bands else "") + '</text>']
    for i, s in enumerate(series):
        top = TOP + i * (PANEL_H + GAP)
        bottom = top + PANEL_H
        worst = max((v for _, v, _ in s["points"]), default=0)
        ymax = max(1.25 * s["bound"], min(worst, 3 * s["bound"]) * 1.05, 1)
        y = lambda v: bottom - PANEL_H * min(v, ymax) / ymax
        out.append(f'<rect x="{LEFT}" y="{top}" width="{plot_w}" height="{PANEL_H}" fill="#fafafa" stroke="#ccc"/>')
        for t0, t1, name in bands:
            if shades[name] != "none":
                out.append(f'<rect x="{x(t0):.1f}" y="{top}" width="{x(t1) - x(t0):.1f}" height="{PANEL_H}" '
                           f'fill="{shades[name]}"/>')
            if i == 0 and x(t1) - x(t0) > 30:
                out.append(f'<text x="{(x(t0) + x(t1)) / 2:.1f}" y="{top - 4}" text-anchor="middle" '
                           f'fill="#555" font-size="9">{name}</text>')
        for t0, _, _ in bands[1:]:
            out.append(f'<line x1="{x(t0):.1f}" x2="{x(t0):.1f}" y1="{top}" y2="{bottom}" stroke="#73c" '
                       f'stroke-width="0.8"/>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 14}" text-anchor="end" font-weight="bold">'
                   f'{s["channel"]}</text>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 28}" text-anchor="end" fill="#555">at {s["consumer"]}</text>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 42}" text-anchor="end" fill="#555">'
                   f'worst {worst * us:.1f} us</text>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 56}" text-anchor="end" fill="#555">'
                   f'bound {s["bound"] * us:.1f} us</text>')
        out.append(f'<text x="{LEFT + 3}" y="{top + 10}" fill="#999" font-size="9">{ymax * us:.0f} us</text>')
        # the bound in force: a step line over the buckets that had one
        bucket = t_end / max(1, len(s["points"]))
        run = []
        for t, _, b in s["points"] + [(None, None, None)]:
            if b is not None:
                run += [f'{x(t):.1f},{y(b):.1f}', f'{x(t + bucket):.1f},{y(b):.1f}']
            elif run:
                out.append(f'<polyline points="{" ".join(run)}" fill="none" stroke="#2a7" stroke-dasharray="5,3"/>')
                run = []
        if s["points"]:
            pts = " ".join(f'{x(t):.1f},{y(v):.1f}' for t, v, _ in s["points"])
            out.append(f'<polyline points="{pts}" fill="none" stroke="#1f5fb4" stroke-width="1"/>')
            for t, v, b in s["points"]:
                if b is None:
                    out.append(f'<circle cx="{x(t):.1f}" cy="{y(v):.1f}" r="1.2" fill="#999"/>')
                elif v > b:
                    out.append(f'<circle cx="{x(t):.1f}" cy="{y(v):.1f}" r="1.6" fill="#d22"/>')
        for t, colour in ((crash, "#d22"), (stale, "#e90")):
            if t:
                out.append(f'<line x1="{x(t):.1f}" x2="{x(t):.1f}" y1="{top}" y2="{bottom}" stroke="{colour}"/>')
    base = TOP + len(series) * (PANEL_H + GAP) - GAP + 14
    for k in range(6):
        t = t_end * k / 5
        out.append(f'<text x="{x(t):.1f}" y="{base}" text-anchor="middle" fill="#555">{t * 1e3 / hz:.1f} ms</text>')
    legend = ('<tspan fill="#1f5fb4">worst age</tspan>, <tspan fill="#2a7">- - bound in force</tspan>, '
              '<tspan fill="#d22">above it</tspan>')
    if bands:
        legend += (', <tspan fill="#999">no bound (a mode without the channel, or settling after a switch)</tspan>, '
                   '<tspan fill="#73c">| mode switch</tspan> (bands: ' + ", ".join(shades) + ")")
    if crash:
        legend += ', <tspan fill="#d22">| crash</tspan>'
    if stale:
        legend += ', <tspan fill="#e90">| navigation reports RadarMap stale</tspan>'
    out.append(f'<text x="{LEFT}" y="{base + 16}">{legend}</text>')
    out.append("</svg>")
    try:
        with open(sys.argv[3], "w") as f:
            f.write("\n".join(out) + "\n")
    except OSError as e:
        fail(f"cannot write {sys.argv[3]}: {e}")


if __name__ == "__main__":
    main()
