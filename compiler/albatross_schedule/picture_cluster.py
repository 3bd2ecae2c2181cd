"""timeline.svg of a multi-rate plan: the cluster drawn as stacked minor
cycles, one row each, as the sequencer runs them (multirate.py's timing
model): the slots of the entries due in that minor cycle, and a thin grey
mark where an entry that is not due costs its skip.  Minor cycles with the
same due entries share a row (its label gives them); when the cluster has
more than MAX_ROWS patterns, the first MAX_ROWS minor cycles are drawn, one
row each, and a note says how many are not.  Under the rows, one line per
channel: its colour, route, entries (repetition and base), fragments and
guaranteed period against the one required."""

from __future__ import annotations

from .model import Plan, System, us
from .picture import _esc, _lighten, _nice_step, _route, channel_colors
from .plan import pub_offset

MAX_ROWS = 32


def _due(slot, n: int) -> bool:
    return n % (1 << slot.rep_log) == slot.base


def row_patterns(plan: Plan) -> tuple:
    """([(minor cycles, due entry indices)], all drawn): the minor cycles
    grouped by their due entries, in order of their first cycle; or, beyond
    MAX_ROWS patterns, the first MAX_ROWS minor cycles alone."""
    groups = {}
    for n in range(plan.cluster):
        key = tuple(k for k, s in enumerate(plan.slots) if _due(s, n))
        groups.setdefault(key, []).append(n)
        if len(groups) > MAX_ROWS:
            return [([n], tuple(k for k, s in enumerate(plan.slots) if _due(s, n))) for n in range(MAX_ROWS)], False
    return sorted(((ns, key) for key, ns in groups.items()), key=lambda g: g[0][0]), True


def cycles_label(ns: list) -> str:
    """Minor cycles in words: "n = 3", "n = 1 mod 4 (8 cycles)", "n = 1, 5, 6 (3 cycles)"."""
    if len(ns) == 1:
        return f"n = {ns[0]}"
    d = ns[1] - ns[0]
    if all(b - a == d for a, b in zip(ns, ns[1:])) and ns[0] < d:
        return f"n = {ns[0]} mod {d} ({len(ns)} cycles)"
    head = ", ".join(map(str, ns[:4]))
    return f"n = {head}{', ...' if len(ns) > 4 else ''} ({len(ns)} cycles)"


def run_row(plan: Plan, n: int, skip: int) -> list:
    """The minor cycle n as the sequencer runs it: [(entry index, begin, end, due)]."""
    out, t = [], 0
    for k, s in enumerate(plan.slots):
        if _due(s, n):
            out.append((k, s.start, s.start + s.length, True))
            t = s.start + s.length
        else:
            b = max(t, s.start)
            out.append((k, b, b + skip, False))
            t = b + skip
    return out


def render_cluster_svg(system: System, plan: Plan, rep: dict, heading: str = "", colors: dict | None = None,
                       absent: tuple = ()) -> str:
    hz = system.clock_hz
    C = plan.cycle
    skip = getattr(plan, "skip_cost", 0)
    rows, whole = row_patterns(plan)
    label_w, plot_w, right_w = 230, 1000, 150
    width = label_w + plot_w + right_w
    top, row_h, box_h = 84, 30, 20
    axis_y = top + len(rows) * row_h + 6
    legend_y = axis_y + (58 if whole else 74)
    n_ch = len(system.channels) + len(absent)
    height = legend_y + 22 * n_ch + 44
    sx = plot_w / C
    by_name = colors or channel_colors([ch.name for ch in system.channels] + [n for n, _ in absent])
    font = "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\""

    def X(clk):
        return label_w + clk * sx

    o = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
         f'viewBox="0 0 {width} {height}" {font}>',
         '<defs><pattern id="hatch" patternUnits="userSpaceOnUse" width="6" height="6" '
         'patternTransform="rotate(45)"><rect width="2.2" height="6" fill="#ffffff" fill-opacity="0.55"/>'
         '</pattern></defs>',
         f'<rect width="{width}" height="{height}" fill="#ffffff"/>']
    span = C * plan.cluster
    title = (f"{heading}{system.name}: multi-rate, minor cycle {C} clocks = {us(C, hz):g} \u00b5s, cluster of "
             f"{plan.cluster} minor cycles = {us(span, hz) / 1000:g} ms ({system.mode}, {hz / 1e6:g} MHz)")
    # a long title (a mode's heading before it) gets a smaller font to fit the width (about 0.6 em a character)
    fs = min(16.0, round((width - 32) / (0.6 * len(title)), 1))
    o.append(f'<text x="16" y="24" font-size="{fs:g}" font-weight="bold" fill="#222">{_esc(title)}</text>')
    sub = (f"{len(plan.slots)} ROM entries \u00b7 bus utilisation {100 * rep['bus_utilisation']:.1f} % over the "
           f"cluster \u00b7 busiest minor cycle ends at {rep.get('busiest_minor_cycle_clocks', '?')} of "
           f"{plan.capacity} usable clocks \u00b7 an entry not due costs {skip} clocks (grey)")
    o.append(f'<text x="16" y="44" font-size="12" fill="#555">{_esc(sub)}</text>')
    o.append(f'<text x="16" y="{top - 10}" font-size="11" fill="#555">minor cycles (n = 0 .. {plan.cluster - 1}), '
             'each row one or more with the same entries due</text>')
    o.append(f'<text x="{label_w + plot_w + 10}" y="{top - 10}" font-size="11" fill="#555">ends at (clocks)</text>')

    # grid and axis: time within a minor cycle
    step = _nice_step(us(C, hz), 10)
    tick = 0.0
    while tick <= us(C, hz) + 1e-9:
        x = X(tick * hz / 1e6)
        o.append(f'<line x1="{x:.1f}" y1="{top - 4}" x2="{x:.1f}" y2="{axis_y}" stroke="#e6e6e6" stroke-width="1"/>')
        o.append(f'<text x="{x:.1f}" y="{axis_y + 16}" font-size="11" fill="#444" text-anchor="middle">{tick:g}</text>')
        tick += step
    o.append(f'<line x1="{X(0)}" y1="{axis_y}" x2="{X(C):.1f}" y2="{axis_y}" stroke="#444" stroke-width="1"/>')
    o.append(f'<text x="{X(C):.1f}" y="{axis_y + 32}" font-size="11" fill="#444" text-anchor="end">'
             'time from the minor cycle\'s start (\u00b5s)</text>')
    if plan.capacity < C:
        x0 = X(plan.capacity)
        o.append(f'<rect x="{x0:.1f}" y="{top}" width="{X(C) - x0:.1f}" height="{len(rows) * row_h}" fill="#999" '
                 'fill-opacity="0.15"/>')
        o.append(f'<text x="{X(C) - 3:.1f}" y="{top - 22}" font-size="10" fill="#777" text-anchor="end">'
                 'kept idle (mode switch)</text>')
    if not whole:
        o.append(f'<text x="16" y="{axis_y + 50}" font-size="12" fill="#a33">The cluster has more than {MAX_ROWS} '
                 f'patterns of due entries: minor cycles 0 .. {MAX_ROWS - 1} are drawn, {plan.cluster - MAX_ROWS} '
                 'more are not (report.txt lists every entry\'s repetition and base).</text>')

    for r, (ns, _) in enumerate(rows):
        y = top + r * row_h
        if r % 2:
            o.append(f'<rect x="0" y="{y}" width="{width}" height="{row_h}" fill="#f6f7f9"/>')
        o.append(f'<text x="{label_w - 10}" y="{y + row_h / 2 + 4}" font-size="11" text-anchor="end" '
                 f'fill="#222">{_esc(cycles_label(ns))}</text>')
        by = y + (row_h - box_h) // 2
        end = 0
        for k, b, e, due in run_row(plan, ns[0], skip):
            s = plan.slots[k]
            ch = s.channel
            end = e
            if not due:
                if skip:
                    o.append(f'<rect x="{X(b):.2f}" y="{by + box_h - 4}" width="{max(skip * sx, 0.6):.2f}" '
                             f'height="4" fill="#999"><title>{_esc(ch.name)} entry {k}: not due, skipped '
                             f'{b}..{e}</title></rect>')
                continue
            col = by_name.get(ch.name, "#4e79a7")
            w = max((e - b) * sx, 1.0)
            busy = min(pub_offset(ch, system.bus, False) * sx, w)
            o.append(f'<rect x="{X(b):.2f}" y="{by}" width="{w:.2f}" height="{box_h}" fill="{_lighten(col, 0.65)}"/>')
            o.append(f'<rect x="{X(b):.2f}" y="{by}" width="{busy:.2f}" height="{box_h}" fill="{col}"/>')
            if s.redundant:
                o.append(f'<rect x="{X(b):.2f}" y="{by}" width="{w:.2f}" height="{box_h}" fill="url(#hatch)"/>')
            frag = f", fragment of {s.frag} words" if s.frag else ""
            dash = ' stroke-dasharray="3,2"' if s.redundant else ""
            o.append(f'<rect x="{X(b):.2f}" y="{by}" width="{w:.2f}" height="{box_h}" fill="none" stroke="{col}" '
                     f'stroke-width="1"{dash}>'
                     f'<title>{_esc(ch.name)} entry {k}: slot {b}..{e} clocks, repetition {1 << s.rep_log}, base '
                     f'{s.base}{frag}{" (redundant)" if s.redundant else ""}</title></rect>')
            text = next((t for t in (ch.name, ch.name[:3]) if 6.1 * len(t) + 3 <= w), "")
            if text:
                o.append(f'<text x="{X(b) + w / 2:.2f}" y="{by + box_h / 2 + 4}" font-size="10" text-anchor="middle" '
                         f'fill="#111">{_esc(text)}</text>')
        o.append(f'<text x="{label_w + plot_w + 10}" y="{y + row_h / 2 + 4}" font-size="11" fill="#444">'
                 f'{end}</text>')

    # one line per channel
    o.append(f'<text x="16" y="{legend_y - 12}" font-size="12" font-weight="bold" fill="#222">channels: colour, '
             'route, entries (repetition r, base b: due in the minor cycles n mod r = b), fragments, guaranteed '
             'period / required</text>')
    for i, ch in enumerate(system.channels):
        y = legend_y + 22 * i
        col = by_name.get(ch.name, "#4e79a7")
        c = next(c for c in rep["channels"] if c["id"] == ch.id)
        ents = ", ".join(f"r {x['repetition']} b {x['base']}" for x in c["slots"][:6])
        more = f" + {len(c['slots']) - 6} more" if len(c["slots"]) > 6 else ""
        frag = f", {ch.fragments} fragments of {ch.frag_words} words" if ch.fragments > 1 else ""
        o.append(f'<rect x="16" y="{y - 11}" width="22" height="14" fill="{col}"/>')
        o.append(f'<text x="46" y="{y}" font-size="12" fill="#222"><tspan font-weight="bold">{_esc(ch.name)}'
                 f'</tspan> ({_esc(_route(system, ch))}): {_esc(ents + more)}{_esc(frag)}; '
                 f'{c["guaranteed_period"]["us"]:g} / {ch.max_period_us} \u00b5s</text>')
    for j, (name, route) in enumerate(absent):
        y = legend_y + 22 * (len(system.channels) + j)
        o.append(f'<rect x="16" y="{y - 11}" width="22" height="14" fill="{_lighten(by_name[name], 0.35)}"/>')
        o.append(f'<text x="46" y="{y}" font-size="12" fill="#999">{_esc(name)} ({_esc(route)}): not carried in '
                 'this mode</text>')
    ly = legend_y + 22 * n_ch + 16
    o.append(f'<text x="16" y="{ly}" font-size="11" fill="#666">dark: the transfer fault-free; light: retry reserve '
             '+ guard; hatched, dashed: a redundant entry; grey mark: an entry not due, skipped</text>')
    o.append("</svg>")
    return "\n".join(o) + "\n"
