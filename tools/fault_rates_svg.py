"""The picture of tools/fault_rates.py (bench, svg): delivery and worst age
against the true fault rate, predicted beside measured, as an SVG.
Split out of tools/fault_rates.py, which runs it (fault_rates.py svg)."""

import math

BURST = 2               # the bench's mean burst (fault_rates.BURST_RATES)


# ---- the picture (standard library only: no matplotlib on the machine) ----

COLOURS = {"RadarMap": "#1f77b4", "Status": "#9467bd", "Position": "#2ca02c", "MotorCmd": "#ff7f0e",
           "GlobalTime": "#d62728"}


def _sup(e):
    """10 to the power e as text, e.g. 10⁻⁶."""
    return "10" + str(e).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))


def svg(data, path):
    """Small multiples, one column per channel (its worst consumer):
    top row, the probability that a cycle does not deliver, 1 - p, on a log
    axis (no zero: a run without a miss in N cycles is drawn as a triangle
    pointing down at 1/N, "below this"); bottom row, the worst age against
    the age bound at the plan's target (solid) and the fault-free bound
    (dotted).  Predicted: a line; measured: markers; independent faults in
    the channel's colour, bursts of mean BURST in grey.  A target that lets
    at least one of the run's cycles miss (1 - target >= 1 / cycles: 0.99 at
    50 %) lets ages exceed the bound at target in that share: the band above
    the line is shaded there, its worst age drawn as a ring, and the panel
    gives the measured count above the line against the check's allowance."""
    clk_us = 1e6 / 50e6
    pts = [p for p in data["points"] if p["independent"] and p.get("planned")]
    bpts = [p for p in data["points"] if not p["independent"] and p.get("planned")]
    # a target that lets at least one of the run's cycles miss: ages above the bound at target are allowed
    lenient = lambda p: (1 - p["probability"]) * max(1, p.get("cycles_measured", 1)) >= 1

    def above_target(p, name):
        """The consumer of the channel closest to its allowance: (ages above the bound at
        target, how many the check allows), from the last bound of the family."""
        best = (0, 0)
        for r in p.get("consumers", []):
            if r["channel"] == name and r.get("bounds"):
                b = r["bounds"][-1]
                if best == (0, 0) or b["measured_above"] * max(1, best[1]) > best[0] * max(1, b["allowed_above"]):
                    best = (b["measured_above"], b["allowed_above"])
        return best

    names = []
    for p in pts:
        for c in p["channels"]:
            if c["channel"] not in names:
                names.append(c["channel"])
    ncol = max(1, len(names))
    L, R, T, PW, PH, HG, VG = 64, 16, 108, 150, 190, 26, 74
    W = L + ncol * PW + (ncol - 1) * HG + R
    H = T + 2 * PH + VG + 178
    x_of = lambda x0, r: x0 + PW * r / 0.5
    miss = lambda p: 1.0 - p
    # the log axis: from the smallest value to show, to 1
    vals = [miss(c["predicted_cycle_delivery"]) for p in pts + bpts for c in p["channels"]]
    vals += [miss(c["measured_cycle_delivery"]) for p in pts + bpts for c in p["channels"]]
    vals += [1.0 / max(1, p.get("cycles_measured", 1)) for p in pts + bpts]
    lo = min([v for v in vals if v > 0] + [1e-3])
    e_lo = max(-12, math.floor(math.log10(lo)))
    ylog = lambda y0, v: y0 + PH * (-math.log10(max(v, 10.0 ** e_lo))) / (-e_lo)
    age_top = max([c["worst_age"] for p in pts + bpts for c in p["channels"]] +
                  [c["age_bound_at_target"] for p in pts + bpts for c in p["channels"]]) * clk_us
    age_top = math.ceil(age_top / 50.0) * 50
    ylin = lambda y0, us: y0 + PH - PH * us / age_top
    o = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">'
         % (W, H), '<rect width="100%" height="100%" fill="white"/>',
         '<text x="%d" y="20" font-size="14">The compiler\'s prediction (line) against the measurement (markers), '
         'per channel, as the true fault rate grows</text>' % L,
         '<text x="%d" y="38" fill="#444">Simulated CPUs on the controller\'s RTL, seed %d, a plan made for each '
         'rate; per channel its worst consumer.</text>' % (L, data["seed"]),
         '<text x="%d" y="54" fill="#444">Top: a cycle that delivers nothing, 1 - p (log axis). Bottom: the worst '
         'age seen against the age bound that holds</text>' % L,
         '<text x="%d" y="70" fill="#444">with the plan\'s target probability (solid; the targets: below) and the '
         'fault-free bound (dotted).</text>' % L]
    for col, name in enumerate(names):
        x0 = L + col * (PW + HG)
        colour = COLOURS.get(name, "#333")
        size = next(c["size"] for p in pts for c in p["channels"] if c["channel"] == name)
        o.append('<text x="%.1f" y="%d" text-anchor="middle" font-size="12" font-weight="bold" fill="%s">'
                 '%s (%d B)</text>' % (x0 + PW / 2, T - 14, colour, name, size))
        for row in (0, 1):
            y0 = T + row * (PH + VG)
            o.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#999"/>' % (x0, y0, PW, PH))
            for r in (0, 0.1, 0.2, 0.3, 0.4, 0.5):
                o.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#eee"/>'
                         % (x_of(x0, r), y0, x_of(x0, r), y0 + PH))
                o.append('<text x="%.1f" y="%d" text-anchor="middle" font-size="10">%d</text>'
                         % (x_of(x0, r), y0 + PH + 12, round(r * 100)))
            o.append('<text x="%.1f" y="%d" text-anchor="middle" font-size="10" fill="#444">true fault rate, %%</text>'
                     % (x0 + PW / 2, y0 + PH + 25))
            if row == 0:
                for e in range(e_lo, 1):
                    yy = ylog(y0, 10.0 ** e)
                    if (e - e_lo) % (1 if -e_lo <= 6 else 3) == 0 or e == 0:
                        o.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#eee"/>' % (x0, yy, x0 + PW, yy))
                        if col == 0:
                            o.append('<text x="%d" y="%.1f" text-anchor="end" font-size="10">%s</text>'
                                     % (x0 - 4, yy + 4, "1" if e == 0 else _sup(e)))
                get_p = lambda c: ylog(y0, miss(c["predicted_cycle_delivery"]))
                has_p = lambda c: miss(c["predicted_cycle_delivery"]) >= 10.0 ** e_lo * 0.999
                get_m = lambda c, p: ylog(y0, miss(c["measured_cycle_delivery"]) if
                                          miss(c["measured_cycle_delivery"]) > 0 else 1.0 / max(1, p["cycles_measured"]))
                zero_m = lambda c: miss(c["measured_cycle_delivery"]) <= 0
            else:
                for v in range(0, int(age_top) + 1, 50):
                    o.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#eee"/>'
                             % (x0, ylin(y0, v), x0 + PW, ylin(y0, v)))
                    if col == 0:
                        o.append('<text x="%d" y="%.1f" text-anchor="end" font-size="10">%d</text>'
                                 % (x0 - 4, ylin(y0, v) + 4, v))
                get_p = lambda c: ylin(y0, c["age_bound_at_target"] * clk_us)
                has_p = lambda c: True
                get_m = lambda c, p: ylin(y0, c["worst_age"] * clk_us)
                zero_m = lambda c: False
            if row == 1:
                # the fault-free bound, dotted
                xy = [(x_of(x0, p["rate"]), ylin(y0, c["age_bound_fault_free"] * clk_us)) for p in pts
                      for c in p["channels"] if c["channel"] == name]
                if len(xy) > 1:
                    o.append('<polyline fill="none" stroke="%s" stroke-width="1.2" stroke-dasharray="2,3" '
                             'points="%s"/>' % (colour, " ".join("%.1f,%.1f" % q for q in xy)))
                # where the target lets ages exceed the bound at target: the band above it, and the count
                for p in pts:
                    if not lenient(p):
                        continue
                    c = next(c for c in p["channels"] if c["channel"] == name)
                    xa, xb = x_of(x0, max(0.0, p["rate"] - 0.03)), x_of(x0, min(0.5, p["rate"] + 0.03))
                    yb = ylin(y0, c["age_bound_at_target"] * clk_us)
                    o.append('<rect x="%.1f" y="%d" width="%.1f" height="%.1f" fill="%s" fill-opacity="0.2"/>'
                             % (xa, y0, xb - xa, yb - y0, colour))
                    above, allowed = above_target(p, name)
                    o.append('<text x="%.1f" y="%d" text-anchor="end" font-size="9" fill="#444">%d %%: %d above, '
                             '%d allowed</text>' % (x0 + PW - 3, y0 + 11, round(p["rate"] * 100), above, allowed))
            for series, col_s, width in ((bpts, "#999", 1.2), (pts, colour, 2.0)):
                xy = [(x_of(x0, p["rate"]), get_p(c)) for p in series for c in p["channels"]
                      if c["channel"] == name and has_p(c)]
                if len(xy) > 1:
                    o.append('<polyline fill="none" stroke="%s" stroke-width="%.1f" points="%s"/>'
                             % (col_s, width, " ".join("%.1f,%.1f" % q for q in xy)))
                for p in series:
                    for c in p["channels"]:
                        if c["channel"] != name:
                            continue
                        x, y = x_of(x0, p["rate"]), get_m(c, p)
                        if zero_m(c):      # no miss seen: below 1/N, a triangle pointing down
                            o.append('<path d="M%.1f,%.1f l-4,-6 h8 z" fill="white" stroke="%s" stroke-width="1.3"/>'
                                     % (x, y + 3, col_s))
                        elif series is pts and row == 1 and lenient(p) and c["worst_age"] > c["age_bound_at_target"]:
                            o.append('<circle cx="%.1f" cy="%.1f" r="3.2" fill="white" stroke="%s" stroke-width="1.6"/>'
                                     % (x, y, col_s))
                        elif series is pts:
                            o.append('<circle cx="%.1f" cy="%.1f" r="3.2" fill="%s"/>' % (x, y, col_s))
                        else:
                            o.append('<rect x="%.1f" y="%.1f" width="6" height="6" fill="white" stroke="%s" '
                                     'stroke-width="1.3"/>' % (x - 3, y - 3, col_s))
    o.append('<text x="8" y="%d" font-size="11" transform="rotate(-90 8 %d)" text-anchor="middle">'
             'a cycle delivers nothing (1 - p)</text>' % (T + PH / 2 + 40, T + PH / 2 + 40))
    o.append('<text x="8" y="%d" font-size="11" transform="rotate(-90 8 %d)" text-anchor="middle">'
             'worst age, µs</text>' % (T + PH + VG + PH / 2, T + PH + VG + PH / 2))
    # the plan's target per rate, and the key
    ky = T + 2 * PH + VG + 44
    tg = []
    for p in pts:
        tp = p["probability"]
        tg.append("%d %%: %s" % (round(p["rate"] * 100), "1 - 10⁻%d" % round(-math.log10(1 - tp)) if tp > 0.999
                                 else "%g" % tp))
    o.append('<text x="%d" y="%d" fill="#444">plan target per rate (independent faults): %s</text>'
             % (L, ky, ",  ".join(tg)))
    ky += 16
    o.append('<text x="%d" y="%d" fill="#444">Top: a predicted line starts where 1 - p reaches the axis\' foot, '
             '%s; below it the prediction is smaller still.</text>' % (L, ky, _sup(e_lo)))
    ky += 22
    o.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="#555" stroke-width="2"/>' % (L, ky - 4, L + 22, ky - 4))
    o.append('<text x="%d" y="%d">predicted (independent faults)</text>' % (L + 28, ky))
    o.append('<circle cx="%d" cy="%d" r="3.2" fill="#555"/>' % (L + 230, ky - 4))
    o.append('<text x="%d" y="%d">measured</text>' % (L + 240, ky))
    o.append('<path d="M%d,%d l-4,-6 h8 z" fill="white" stroke="#555" stroke-width="1.3"/>' % (L + 320, ky - 1))
    o.append('<text x="%d" y="%d">no miss in N cycles: drawn at 1/N, the truth is below</text>' % (L + 330, ky))
    ky += 18
    o.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="#999" stroke-width="1.2"/>' % (L, ky - 4, L + 22, ky - 4))
    o.append('<rect x="%d" y="%d" width="6" height="6" fill="white" stroke="#999" stroke-width="1.3"/>'
             % (L + 8, ky - 7))
    o.append('<text x="%d" y="%d">bursts of mean %d: predicted (grey line), measured (squares)</text>'
             % (L + 28, ky, data["burst"]))
    ky += 18
    o.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="#555" stroke-width="1.2" stroke-dasharray="2,3"/>'
             % (L, ky - 4, L + 22, ky - 4))
    o.append('<text x="%d" y="%d">bottom: the fault-free age bound (no fault at all)</text>' % (L + 28, ky))
    ky += 18
    lax = [p for p in pts if lenient(p)]
    if lax:
        o.append('<rect x="%d" y="%d" width="22" height="10" fill="#555" fill-opacity="0.13"/>' % (L, ky - 9))
        o.append('<circle cx="%d" cy="%d" r="3.2" fill="white" stroke="#555" stroke-width="1.6"/>' % (L + 11, ky - 4))
        o.append('<text x="%d" y="%d">allowed (shaded): a plan for %s lets ages exceed its bound at target in up '
                 'to %s of the cycles, so a worst age above</text>'
                 % (L + 28, ky, " and ".join("%g" % p["probability"] for p in lax),
                    " and ".join("%g %%" % round(100 * (1 - p["probability"]), 6) for p in lax)))
        ky += 16
        o.append('<text x="%d" y="%d">the line (ring) is no failure: the ages above it are counted against what the '
                 'check allows (at the top of each panel).</text>' % (L + 28, ky))
    o.append("</svg>")
    with open(path, "w") as fh:
        fh.write("\n".join(o) + "\n")
