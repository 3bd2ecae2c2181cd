"""timeline.svg: one schedule cycle, a lane for the bus and one per channel;
with [[mode]], one such lane group per mode, the start-up mode first.  A
channel keeps its colour in every mode, and a mode's group keeps an empty
lane for each channel of another mode that it does not carry."""

from __future__ import annotations

import math

from .model import Plan, System, us
from .plan import pub_offset


PALETTE = ["#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948", "#b07aa1",
           "#ff9da7", "#9c755f", "#bab0ac"]


def _esc(s: str) -> str:
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")


def _nice_step(span: float, target: int = 10) -> float:
    raw = span / target
    mag = 10 ** math.floor(math.log10(raw)) if raw > 0 else 1
    for m in (1, 2, 2.5, 5, 10):
        if raw <= m * mag:
            return m * mag
    return 10 * mag


def _lighten(hex_color: str, f: float) -> str:
    r, g, b = (int(hex_color[i:i + 2], 16) for i in (1, 3, 5))
    r, g, b = (round(v + (255 - v) * f) for v in (r, g, b))
    return f"#{r:02x}{g:02x}{b:02x}"


def _route(system: System, ch) -> str:
    """producer -> consumers; the controller where a side is no board."""
    return (f"{system.boards[ch.producer] if ch.producer is not None else 'controller'} "
            f"\u2192 {', '.join(system.boards[c] for c in ch.consumers) or 'controller'}")


def channel_colors(names) -> dict:
    """One colour per channel name, in the order given."""
    return {name: PALETTE[i % len(PALETTE)] for i, name in enumerate(names)}


def render_svg(system: System, plan: Plan, rep: dict, heading: str = "", colors: dict | None = None,
               absent: tuple = ()) -> str:
    """colors: the colour of each channel by name (default: by its place in
    system.channels); absent: (name, route) of channels this schedule does
    not carry, each given an empty lane (another mode's channels).  A
    multi-rate plan: its cluster (picture_cluster.py)."""
    if plan.multirate:
        from .picture_cluster import render_cluster_svg
        return render_cluster_svg(system, plan, rep, heading, colors, absent)
    hz = system.clock_hz
    C = plan.cycle
    routes = {ch.index: _route(system, ch) for ch in system.channels}
    label_w = int(max([200] + [5.6 * len(r) + 24 for r in list(routes.values()) + [r for _, r in absent]]
                      + [7.4 * len(n) + 70 for n in [ch.name for ch in system.channels] + [n for n, _ in absent]]))
    right_w, plot_w = 190, 1000
    width = label_w + plot_w + right_w
    top, lane_h, box_h = 74, 34, 22
    n_lanes = 1 + len(system.channels) + len(absent)
    axis_y = top + n_lanes * lane_h + 6
    legend_y = axis_y + 40
    height = legend_y + 38
    sx = plot_w / C

    def X(clk):
        return label_w + clk * sx

    by_name = colors or channel_colors([ch.name for ch in system.channels] + [n for n, _ in absent])
    colors = {ch.index: by_name[ch.name] for ch in system.channels}
    font = "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\""
    o = []
    o.append(f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
             f'viewBox="0 0 {width} {height}" {font}>')
    o.append('<defs><pattern id="hatch" patternUnits="userSpaceOnUse" width="6" height="6" '
             'patternTransform="rotate(45)"><rect width="2.2" height="6" fill="#ffffff" '
             'fill-opacity="0.55"/></pattern></defs>')
    o.append(f'<rect width="{width}" height="{height}" fill="#ffffff"/>')
    title = (f"{heading}{system.name}: one schedule cycle = {C} clocks = {us(C, hz):g} \u00b5s "
             f"({system.mode}, {hz / 1e6:g} MHz)")
    o.append(f'<text x="{label_w}" y="24" font-size="16" font-weight="bold" fill="#222">{_esc(title)}</text>')
    sub = (f"{len(plan.slots)} ROM entries \u00b7 bus utilisation {100 * rep['bus_utilisation']:.1f} % "
           f"(fault-free accesses) \u00b7 slots fill {100 * rep['schedule_fill']:.1f} % of the cycle")
    o.append(f'<text x="{label_w}" y="44" font-size="12" fill="#555">{_esc(sub)}</text>')
    o.append(f'<text x="{label_w + plot_w + 12}" y="{top - 8}" font-size="11" fill="#555">'
             'guaranteed period / required</text>')

    # grid + axis
    step_us = _nice_step(us(C, hz), 10)
    tick = 0.0
    ticks = []
    while tick <= us(C, hz) + 1e-9:
        ticks.append(tick)
        tick += step_us
    for tu in ticks:
        x = X(tu * hz / 1e6)
        o.append(f'<line x1="{x:.1f}" y1="{top - 4}" x2="{x:.1f}" y2="{axis_y}" stroke="#e6e6e6" stroke-width="1"/>')
        o.append(f'<text x="{x:.1f}" y="{axis_y + 16}" font-size="11" fill="#444" text-anchor="middle">{tu:g}</text>')
    o.append(f'<line x1="{X(0)}" y1="{axis_y}" x2="{X(C):.1f}" y2="{axis_y}" stroke="#444" stroke-width="1"/>')
    o.append(f'<text x="{X(C):.1f}" y="{axis_y + 32}" font-size="11" fill="#444" text-anchor="end">'
             'time from cycle start (\u00b5s)</text>')
    o.append(f'<line x1="{X(C):.1f}" y1="{top - 4}" x2="{X(C):.1f}" y2="{axis_y}" stroke="#444" '
             'stroke-width="1" stroke-dasharray="4,3"/>')
    if system.sync_mode:
        x0 = X(plan.capacity)
        o.append(f'<rect x="{x0:.1f}" y="{top}" width="{X(C) - x0:.1f}" height="{n_lanes * lane_h}" '
                 'fill="#999" fill-opacity="0.12"/>')
        o.append(f'<text x="{X(C) - 3:.1f}" y="{top - 8}" font-size="10" fill="#777" text-anchor="end">'
                 'poll for next position</text>')

    short = {}
    for ch in system.channels:
        caps = "".join(c for c in ch.name if c.isupper() or c.isdigit()) or ch.name[:2]
        cand = caps if len(caps) >= 2 else ch.name[:2]
        while cand in short.values() and len(cand) < len(ch.name):
            cand = ch.name[:len(cand) + 1]
        short[ch.index] = cand

    def box(ch, s, y, label_mode):
        x, w = X(s.start), max(s.length * sx, 1.0)
        col = colors[ch.index]
        busy = pub_offset(ch, system.bus, False) * sx
        parts = []
        parts.append(f'<rect x="{x:.2f}" y="{y}" width="{w:.2f}" height="{box_h}" fill="{_lighten(col, 0.65)}"/>')
        parts.append(f'<rect x="{x:.2f}" y="{y}" width="{min(busy, w):.2f}" height="{box_h}" fill="{col}"/>')
        if s.redundant:
            parts.append(f'<rect x="{x:.2f}" y="{y}" width="{w:.2f}" height="{box_h}" fill="url(#hatch)"/>')
        dash = ' stroke-dasharray="3,2"' if s.redundant else ""
        parts.append(f'<rect x="{x:.2f}" y="{y}" width="{w:.2f}" height="{box_h}" fill="none" '
                     f'stroke="{col}" stroke-width="1"{dash}/>')
        if s.sync:
            parts.append(f'<text x="{x + 2:.2f}" y="{y - 2}" font-size="9" font-weight="bold" fill="#222">SYNC</text>')
        # label: the channel name, shortened to what fits
        fits = int((w - 3) / 6.1)
        if label_mode == "name":
            text = next((t for t in (ch.name, short[ch.index]) if len(t) <= fits), "")
        else:
            text = label_mode if len(label_mode) <= fits else ""
        if text:
            parts.append(f'<text x="{x + w / 2:.2f}" y="{y + box_h / 2 + 4}" font-size="10.5" '
                         f'text-anchor="middle" fill="#111" style="paint-order:stroke" stroke="#ffffff" '
                         f'stroke-width="2.5" stroke-opacity="0.75">{_esc(text)}</text>')
        parts.append(f'<title>{_esc(ch.name)} entry slot {s.start}..{s.start + s.length} clocks'
                     f'{" (redundant)" if s.redundant else ""}</title>')
        return "<g>" + "".join(parts) + "</g>"

    # lane 0: the bus, all slots
    y0 = top
    o.append(f'<rect x="0" y="{y0}" width="{width}" height="{lane_h}" fill="#f4f6f8"/>')
    o.append(f'<text x="{label_w - 10}" y="{y0 + lane_h / 2 + 4}" font-size="12" font-weight="bold" '
             f'text-anchor="end" fill="#222">system bus (all slots)</text>')
    for s in plan.slots:
        o.append(box(s.channel, s, y0 + (lane_h - box_h) // 2, "name"))
    # one lane per channel
    for li, ch in enumerate(system.channels, 1):
        y = top + li * lane_h
        if li % 2 == 0:
            o.append(f'<rect x="0" y="{y}" width="{width}" height="{lane_h}" fill="#fafafa"/>')
        route = routes[ch.index]
        o.append(f'<text x="{label_w - 10}" y="{y + 15}" font-size="12" font-weight="bold" text-anchor="end" '
                 f'fill="{colors[ch.index]}">{_esc(ch.name)}{" (sync)" if ch.sync else ""}</text>')
        o.append(f'<text x="{label_w - 10}" y="{y + 28}" font-size="9.5" text-anchor="end" fill="#666">'
                 f'{_esc(route)}</text>')
        for e, s in enumerate(plan.slots):
            if s.channel is ch:
                o.append(box(ch, s, y + (lane_h - box_h) // 2, f"#{e}"))
        c = next(c for c in rep["channels"] if c["id"] == ch.id)
        o.append(f'<text x="{label_w + plot_w + 12}" y="{y + 15}" font-size="11" fill="#222">'
                 f'{c["guaranteed_period"]["us"]:g} / {ch.max_period_us} \u00b5s</text>')
        o.append(f'<text x="{label_w + plot_w + 12}" y="{y + 28}" font-size="9.5" fill="#666">'
                 f'\u00d7{len(ch.slots)} per cycle, L = {ch.slot_len} clk</text>')

    # the channels of other modes that this one does not carry: an empty lane each
    for li, (name, route) in enumerate(absent, 1 + len(system.channels)):
        y = top + li * lane_h
        if li % 2 == 0:
            o.append(f'<rect x="0" y="{y}" width="{width}" height="{lane_h}" fill="#fafafa"/>')
        o.append(f'<text x="{label_w - 10}" y="{y + 15}" font-size="12" font-weight="bold" text-anchor="end" '
                 f'fill="{_lighten(by_name[name], 0.35)}">{_esc(name)}</text>')
        o.append(f'<text x="{label_w - 10}" y="{y + 28}" font-size="9.5" text-anchor="end" fill="#999">'
                 f'{_esc(route)}</text>')
        o.append(f'<text x="{label_w + 8}" y="{y + 21}" font-size="11" fill="#999">'
                 'not carried in this mode</text>')

    # legend
    lx, ly = label_w, legend_y
    col = "#4e79a7"
    items = [("transfer, fault-free", col, False, False), ("retry reserve + guard", _lighten(col, 0.65), False, False),
             ("redundant slot", col, True, False)]
    for text, fill, hatched, _ in items:
        o.append(f'<rect x="{lx}" y="{ly}" width="26" height="14" fill="{fill}"/>')
        if hatched:
            o.append(f'<rect x="{lx}" y="{ly}" width="26" height="14" fill="url(#hatch)"/>')
            o.append(f'<rect x="{lx}" y="{ly}" width="26" height="14" fill="none" stroke="{col}" stroke-dasharray="3,2"/>')
        o.append(f'<text x="{lx + 32}" y="{ly + 11}" font-size="11" fill="#333">{_esc(text)}</text>')
        lx += 40 + 6.5 * len(text)
    o.append(f'<text x="{lx}" y="{ly + 11}" font-size="11" fill="#666">'
             '#n: ROM entry n \u00b7 first slot of a channel solid, redundant slots hatched</text>')
    o.append("</svg>")
    return "\n".join(o) + "\n"


def render_modes_svg(system: System, plan: Plan, rep: dict) -> str:
    """The timeline of every mode, one lane group (render_svg) under the other;
    a system without modes: render_svg."""
    plans = getattr(system, "mode_plans", None)
    if not plans:
        return render_svg(system, plan, rep)
    # every channel of any mode, the start-up mode's first: one colour each in every group
    names, routes = [], {}
    for _, s, _, _ in plans:
        for ch in s.channels:
            if ch.name not in routes:
                names.append(ch.name)
                routes[ch.name] = _route(s, ch)
    colors = channel_colors(names)
    groups = []
    for i, (m, s, p, r) in enumerate(plans):
        nxt = ", ".join(plans[j][0].name for j in m.next) or "none"
        heading = f"mode {m.name}{' (start-up)' if i == 0 else ''}, switches to {nxt} \u2014 "
        here = {ch.name for ch in s.channels}
        groups.append(render_svg(s, p, r, heading, colors, tuple((n, routes[n]) for n in names if n not in here)))
    sizes = []
    for g in groups:
        head = g[:g.index(">")]
        sizes.append((int(head.split(' width="')[1].split('"')[0]), int(head.split(' height="')[1].split('"')[0])))
    width, height = max(w for w, _ in sizes), sum(h for _, h in sizes)
    o = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}">',
         f'<rect width="{width}" height="{height}" fill="#ffffff"/>']
    y = 0
    for g, (_, h) in zip(groups, sizes):
        # each group's own <svg>, placed at its offset (its hatch pattern id made its own)
        body = g.replace('id="hatch"', f'id="hatch{y}"').replace("url(#hatch)", f"url(#hatch{y})")
        o.append(body.replace("<svg ", f'<svg y="{y}" ', 1).rstrip("\n"))
        if y:
            o.append(f'<line x1="0" y1="{y}" x2="{width}" y2="{y}" stroke="#888" stroke-width="1.5"/>')
        y += h
    o.append("</svg>")
    return "\n".join(o) + "\n"
