#!/usr/bin/env python3
"""plot_import_accesses.py THREE.json FOUR.json OUT.json OUT.svg -- the figure
of the termination bound: RAM accesses per Import beyond the payload against the
writer:reader speed ratio, both channel kinds in one plot.

Reads the reports of `tb_dpram ratio --kind three_buffer` and `--kind
four_slot` (fixed speed ratios, checkers on), writes them combined as JSON
and draws mean and worst per kind on a log10 ratio axis: the four-slot
Import is wait-free (worst flat at its bound, 3 accesses), the three-buffer
loop grows as the writer gets faster.  Fails if the four-slot worst is not
at most 3 at every point, or if either run had a violation.
Standard library only.
"""
import json
import sys

FS_BOUND = 3


def fail(msg):
    sys.exit(f"plot_import_accesses: {msg}")


def load(path, kind):
    try:
        with open(path) as f:
            r = json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{path}: {e}")
    if r.get("kind") != kind:
        fail(f"{path}: kind {r.get('kind')!r}, expected {kind!r}")
    if r.get("violations_total", 1):
        fail(f"{path}: {r.get('violations_total')} violations in the {kind} run")
    return r


def ratio_label(log10):
    r = 10 ** abs(log10)
    text = f"{r:.0f}" if r >= 9.5 else f"{r:.2g}"
    return f"1:{text}" if log10 < 0 else f"{text}:1"


def svg(three, four):
    W, H, L, R, T, B = 640, 400, 64, 170, 40, 56
    pw, ph = W - L - R, H - T - B
    xs = [p["log10_ratio"] for p in three["points"] + four["points"]]
    x0, x1 = min(xs), max(xs)
    ymax = max(p["worst_control_accesses"] for p in three["points"] + four["points"])
    step = 10 if ymax > 40 else 5
    ymax = (ymax // step + 1) * step

    def X(v):
        return L + (v - x0) / ((x1 - x0) or 1) * pw

    def Y(v):
        return T + ph - v / ymax * ph

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<text x="{L}" y="22" font-size="13">RAM accesses per Import beyond the payload, against writer:reader speed</text>']
    for y in range(0, ymax + 1, step):
        out.append(f'<line x1="{L}" y1="{Y(y):.1f}" x2="{L + pw}" y2="{Y(y):.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{L - 6}" y="{Y(y) + 4:.1f}" text-anchor="end">{y}</text>')
    for p in four["points"]:
        v = p["log10_ratio"]
        out.append(f'<line x1="{X(v):.1f}" y1="{T}" x2="{X(v):.1f}" y2="{T + ph}" stroke="#eee"/>')
        out.append(f'<text x="{X(v):.1f}" y="{T + ph + 16}" text-anchor="middle">{ratio_label(v)}</text>')
    out.append(f'<text x="{L + pw / 2}" y="{H - 12}" text-anchor="middle">writer:reader speed ratio (held fixed per point)</text>')
    out.append(f'<rect x="{L}" y="{T}" width="{pw}" height="{ph}" fill="none" stroke="black"/>')
    series = [(three, "worst_control_accesses", "#c0392b", "", "three-buffer, worst"),
              (three, "mean_control_accesses", "#c0392b", ' stroke-dasharray="5,3"', "three-buffer, mean"),
              (four, "worst_control_accesses", "#2471a3", "", "four-slot, worst"),
              (four, "mean_control_accesses", "#2471a3", ' stroke-dasharray="5,3"', "four-slot, mean")]
    for i, (rep, key, colour, dash, name) in enumerate(series):
        pts = " ".join(f"{X(p['log10_ratio']):.1f},{Y(p[key]):.1f}" for p in rep["points"])
        out.append(f'<polyline points="{pts}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>')
        for p in rep["points"]:
            out.append(f'<circle cx="{X(p["log10_ratio"]):.1f}" cy="{Y(p[key]):.1f}" r="2.5" fill="{colour}"/>')
        ly = T + 14 + 18 * i
        out.append(f'<line x1="{L + pw + 10}" y1="{ly}" x2="{L + pw + 34}" y2="{ly}" stroke="{colour}" stroke-width="2"{dash}/>')
        out.append(f'<text x="{L + pw + 40}" y="{ly + 4}">{name}</text>')
    ly = T + 14 + 18 * len(series)
    out.append(f'<line x1="{L}" y1="{Y(FS_BOUND):.1f}" x2="{L + pw}" y2="{Y(FS_BOUND):.1f}" stroke="#2471a3" stroke-width="0.8" stroke-dasharray="2,2"/>')
    out.append(f'<text x="{L + pw + 10}" y="{ly + 4}">four-slot bound: {FS_BOUND}</text>')
    out.append(f'<text x="{L + pw + 10}" y="{ly + 22}">{four["imports_per_point"]} Imports per point</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 5:
        fail("usage: plot_import_accesses.py THREE.json FOUR.json OUT.json OUT.svg")
    three, four = load(sys.argv[1], "three-buffer"), load(sys.argv[2], "four-slot")
    worst4 = max(p["worst_control_accesses"] for p in four["points"])
    if worst4 > FS_BOUND:
        fail(f"four-slot worst {worst4} accesses beyond the payload, expected at most {FS_BOUND} (wait-free)")
    combined = {"three_buffer": three, "four_slot": four, "four_slot_bound": FS_BOUND,
                "four_slot_worst": worst4,
                "three_buffer_worst": max(p["worst_control_accesses"] for p in three["points"])}
    with open(sys.argv[3], "w") as f:
        json.dump(combined, f, indent=1)
    with open(sys.argv[4], "w") as f:
        f.write(svg(three, four))
    print(f"plot_import_accesses: wrote {sys.argv[3]} and {sys.argv[4]} (four-slot worst {worst4}, "
          f"three-buffer worst {combined['three_buffer_worst']} accesses beyond the payload)")


if __name__ == "__main__":
    main()
