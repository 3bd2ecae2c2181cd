#!/usr/bin/env python3
"""plot_ages.py AGES.csv REPORT.json OUT.svg -- each channel's data age over time.

AGES.csv (sim/mobot_sim.cpp --ages) has one row per time bucket: its first
cycle, then per series (a channel at one consumer) the worst age seen by an
Import in that bucket, in controller clocks (empty: no Import).  The header
names each series "Channel@consumer(bound=N)".  REPORT.json gives the clock,
the crash and the first stale report.  One panel per series: the worst age
(us) against time (ms), the guaranteed bound dashed; ages above 3x the bound
are clipped to the panel's top and drawn red.  Standard library only.
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
    for name in rows[0][1:]:
        m = re.fullmatch(r"(.+)@(.+)\(bound=(\d+)\)", name)
        if not m:
            fail(f"{ages_path}: cannot read series name {name!r}")
        series.append({"channel": m[1], "consumer": m[2], "bound": int(m[3]), "points": []})
    for r in rows[1:]:
        t = int(r[0])
        for s, v in zip(series, r[1:]):
            if v:
                s["points"].append((t, int(v)))
    return report, series


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
    x = lambda t: LEFT + plot_w * t / t_end
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{height}" '
           f'font-family="sans-serif" font-size="11">',
           f'<rect width="{W}" height="{height}" fill="white"/>',
           f'<text x="{LEFT}" y="18" font-size="14" font-weight="bold">Data age at each consumer '
           f'(worst per time bucket) against the guaranteed bound</text>',
           f'<text x="{LEFT}" y="34" fill="#555">{report.get("label", "")}: '
           f'{t_end * 1e3 / hz:.1f} ms, fault rate {report.get("fault_rate", 0)}, '
           f'{report.get("faults_injected", 0)} faults injected'
           + (f', {report["crash_board"]} crashes at {crash * 1e3 / hz:.2f} ms' if crash else "")
           + '; dashed: bound</text>']
    for i, s in enumerate(series):
        top = TOP + i * (PANEL_H + GAP)
        bottom = top + PANEL_H
        worst = max((v for _, v in s["points"]), default=0)
        ymax = max(1.25 * s["bound"], min(worst, 3 * s["bound"]) * 1.05, 1)
        y = lambda v: bottom - PANEL_H * min(v, ymax) / ymax
        out.append(f'<rect x="{LEFT}" y="{top}" width="{plot_w}" height="{PANEL_H}" fill="#fafafa" stroke="#ccc"/>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 14}" text-anchor="end" font-weight="bold">'
                   f'{s["channel"]}</text>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 28}" text-anchor="end" fill="#555">at {s["consumer"]}</text>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 42}" text-anchor="end" fill="#555">'
                   f'worst {worst * us:.1f} us</text>')
        out.append(f'<text x="{LEFT - 8}" y="{top + 56}" text-anchor="end" fill="#555">'
                   f'bound {s["bound"] * us:.1f} us</text>')
        out.append(f'<text x="{LEFT + 3}" y="{top + 10}" fill="#999" font-size="9">{ymax * us:.0f} us</text>')
        out.append(f'<line x1="{LEFT}" x2="{LEFT + plot_w}" y1="{y(s["bound"]):.1f}" y2="{y(s["bound"]):.1f}" '
                   f'stroke="#2a7" stroke-dasharray="5,3"/>')
        if s["points"]:
            pts = " ".join(f'{x(t):.1f},{y(v):.1f}' for t, v in s["points"])
            out.append(f'<polyline points="{pts}" fill="none" stroke="#1f5fb4" stroke-width="1"/>')
            for t, v in s["points"]:
                if v > s["bound"]:
                    out.append(f'<circle cx="{x(t):.1f}" cy="{y(v):.1f}" r="1.6" fill="#d22"/>')
        for t, colour in ((crash, "#d22"), (stale, "#e90")):
            if t:
                out.append(f'<line x1="{x(t):.1f}" x2="{x(t):.1f}" y1="{top}" y2="{bottom}" stroke="{colour}"/>')
    base = TOP + len(series) * (PANEL_H + GAP) - GAP + 14
    for k in range(6):
        t = t_end * k / 5
        out.append(f'<text x="{x(t):.1f}" y="{base}" text-anchor="middle" fill="#555">{t * 1e3 / hz:.1f} ms</text>')
    legend = '<tspan fill="#1f5fb4">worst age</tspan>, <tspan fill="#d22">above the bound</tspan>'
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
