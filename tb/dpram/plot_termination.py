#!/usr/bin/env python3
"""plot_termination.py REPORT.json OUT.svg -- the termination figure as a picture.

Reads the "termination_by_speed_ratio" table that tb_dpram random writes
(Import loop iterations per writer/reader speed-ratio bucket) and draws the
mean and worst iterations on a log scale: the paper's reader loop is
lock-free, not wait-free, so the worst case grows with the writer's lead.
Standard library only.
"""
import json
import math
import sys


def fail(msg):
    sys.exit(f"plot_termination: {msg}")


def ratio_label(log10):
    r = 10 ** abs(log10)
    text = f"{r:.0f}" if r >= 9.5 else f"{r:.2g}"
    return f"1:{text}" if log10 < 0 else f"{text}:1"


def main():
    if len(sys.argv) != 3:
        fail("usage: plot_termination.py REPORT.json OUT.svg")
    try:
        with open(sys.argv[1]) as f:
            report = json.load(f)
    except (OSError, ValueError) as e:
        fail(f"cannot read {sys.argv[1]}: {e}")
    rows = report.get("termination_by_speed_ratio")
    if not rows:
        fail(f"{sys.argv[1]} has no termination_by_speed_ratio table")
    rows = [r for r in rows if r["imports"] > 0]
    if not rows:
        fail("no Import was checked: nothing to plot")

    w, h, left, right, top, bottom = 720, 420, 70, 20, 50, 70
    pw, ph = w - left - right, h - top - bottom
    ymin, ymax = 0.01, 100.0
    ytop = max(r["worst_iterations"] for r in rows)
    while ymax < ytop * 1.5:
        ymax *= 10

    def x_of(i):
        return left + pw * (i + 0.5) / len(rows)

    def y_of(v):
        v = max(v, ymin)
        return top + ph * (1 - (math.log10(v) - math.log10(ymin)) / (math.log10(ymax) - math.log10(ymin)))

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{w / 2}" y="22" text-anchor="middle" font-size="15">'
           f'Import loop iterations against writer:reader speed ratio</text>',
           f'<text x="{w / 2}" y="39" text-anchor="middle" fill="#555">'
           f'{report.get("imports_checked", 0):,.0f} Imports checked, '
           f'{report.get("violations_total", 0):.0f} violations</text>']
    decade = ymin
    while decade <= ymax * 1.001:
        y = y_of(decade)
        out.append(f'<line x1="{left}" y1="{y:.1f}" x2="{left + pw}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end">{decade:g}</text>')
        decade *= 10
    out.append(f'<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="#888"/>')
    for i, r in enumerate(rows):
        mid = (r["log10_ratio_from"] + r["log10_ratio_to"]) / 2
        out.append(f'<text x="{x_of(i):.1f}" y="{top + ph + 18}" text-anchor="middle">'
                   f'{ratio_label(mid)}</text>')
        out.append(f'<text x="{x_of(i):.1f}" y="{top + ph + 32}" text-anchor="middle" fill="#777" '
                   f'font-size="10">{r["imports"]:,} imp.</text>')
    out.append(f'<text x="{left + pw / 2}" y="{h - 12}" text-anchor="middle">'
               f'writer speed : reader speed (bucket centre)</text>')
    out.append(f'<text transform="translate(18,{top + ph / 2}) rotate(-90)" text-anchor="middle">'
               f'loop iterations per Import (log)</text>')
    for key, colour, name in (("worst_iterations", "#c0392b", "worst"),
                              ("mean_iterations", "#2471a3", "mean")):
        pts = " ".join(f"{x_of(i):.1f},{y_of(r[key]):.1f}" for i, r in enumerate(rows))
        out.append(f'<polyline points="{pts}" fill="none" stroke="{colour}" stroke-width="2"/>')
        for i, r in enumerate(rows):
            out.append(f'<circle cx="{x_of(i):.1f}" cy="{y_of(r[key]):.1f}" r="3.5" fill="{colour}">'
                       f'<title>{name}: {r[key]:g}</title></circle>')
    lx = left + 12
    for n, (colour, name) in enumerate((("#c0392b", "worst iterations"), ("#2471a3", "mean iterations"))):
        y = top + 16 + 16 * n
        out.append(f'<line x1="{lx}" y1="{y - 4}" x2="{lx + 22}" y2="{y - 4}" stroke="{colour}" stroke-width="2"/>')
        out.append(f'<text x="{lx + 28}" y="{y}">{name}</text>')
    out.append("</svg>")
    try:
        with open(sys.argv[2], "w") as f:
            f.write("\n".join(out) + "\n")
    except OSError as e:
        fail(f"cannot write {sys.argv[2]}: {e}")
    print(f"picture: {sys.argv[2]}")


if __name__ == "__main__":
    main()
