"""figures_area.py -- the controller's size tables of tools/figures.py, from `make area`
(build/reports/controller_area.json, controller_growth.json): the configurations
against one PicoRV32, the growth with boards and channels, Fmax, the parts."""
from figures_common import REPORTS, load, missing, n, table


def _cells(e):
    """LUTs, FFs, block RAMs of a row, or why there are none."""
    if "not_supported" in e:
        return ["not supported by this controller"] * 3
    if "luts" not in e:
        return ["error"] * 3
    return [n(e["luts"]), n(e["ffs"]), n(e["brams"])]


def controller_area():
    r = load("controller_area.json")
    if not r or "fmax" not in r:
        missing("controller_area.json", "make area")
    fams = list(r["picorv32_luts"])
    head = ["configuration", "what is off"] + [f"{fam} LUTs / FFs / BRAMs (LUTs / PicoRV32)" for fam in fams]
    pico = r["picorv32"]
    rows = [["one PicoRV32 (as pico_core)", "-"] + [" / ".join(_cells(pico[f])) for f in fams]]
    for name in dict.fromkeys(e["config"] for e in r["rows"]):
        cells, why = [], None
        for fam in fams:
            e = next(x for x in r["rows"] if x["config"] == name and x["family"] == fam)
            if "not_supported" in e:
                cells.append("not supported by this controller")
                why = e["not_supported"]
            elif "luts" in e:
                cells.append(" / ".join(_cells(e)) + (f" ({e['over_picorv32']:.2f})" if "over_picorv32" in e else ""))
            else:
                cells.append("error")
        desc = next(x["description"] for x in r["rows"] if x["config"] == name)
        rows.append([name, desc + (f" ({why})" if why else "")] + cells)
    goals = r["goals_over_picorv32"]
    out = table(head, rows)
    out += ("\n\nTargets, LUTs / one PicoRV32: full function at most " +
            ", ".join(f"{v:.2f} on {f}" for f, v in goals["full"].items()) +
            f" (aim {r['aims_over_picorv32']['full']:.2f}); core configuration at most " +
            ", ".join(f"{v:.2f} on {f}" for f, v in goals["core"].items()) +
            f" (aim {r['aims_over_picorv32']['core']:.2f}) (`{REPORTS}/controller_area.json`).")
    parts = r.get("parts_ice40")
    if parts:
        out += ("\n\nWhere the full controller's LUTs go on iCE40 (synthesised without flattening, so a part's "
                "LUTs are its own; the sum is above the flattened figure):\n\n"
                + table(["part", "ice40 LUTs"], [[f"`{k}`", n(v)] for k, v in sorted(parts.items(), key=lambda kv: -kv[1])]
                        + [["sum", n(sum(parts.values()))]]))
    cones = r.get("cones_ice40")
    if cones:
        cfgs = list(cones)
        depth = max(len(v) for v in cones.values())
        out += ("\n\nThe same on iCE40 flattened, by register: each LUT counted toward the registers, block RAMs "
                "and ports its output reaches through LUTs and carries, split evenly where it reaches several "
                "(`tools/lut_cones.py`; a share is what a register's logic costs, not what removing it would "
                "save):\n\n"
                + table([x for c in cfgs for x in (f"{c}: register", "LUTs")],
                        [[x for c in cfgs for x in ((_reg(cones[c][i][0]), f"{cones[c][i][1]:.0f}")
                                                     if i < len(cones[c]) else ("", ""))]
                         for i in range(depth)]))
    return out


def _reg(name):
    return name if name.startswith("(") else f"`{name}`"


def controller_growth():
    r = load("controller_growth.json")
    if not r:
        missing("controller_growth.json", "make area")
    fams = list(dict.fromkeys(e["family"] for e in r["rows"]))
    head = ["boards (NB)", "channels (N_CHAN)"] + [f"{fam} LUTs / FFs / BRAMs" for fam in fams]
    rows = []
    for key in dict.fromkeys((e["vary"], e["value"]) for e in r["rows"]):
        es = [next(x for x in r["rows"] if (x["vary"], x["value"]) == key and x["family"] == f) for f in fams]
        p = es[0]["parameters"]
        rows.append([str(p["NB"]), str(p["N_CHAN"])] + [" / ".join(_cells(e)) if "not_supported" not in e
                                                      else "not supported by this controller" for e in es])
    out = table(head, rows)
    why = sorted({e["not_supported"] for e in r["rows"] if "not_supported" in e})
    if why:
        out += "\n\nNot supported by this controller: " + "; ".join(why) + "."
    return out + f" (`{REPORTS}/controller_growth.json`)"


def controller_fmax():
    r = load("controller_area.json")
    if not r or "fmax" not in r:
        missing("controller_area.json", "make area")
    rows = []
    for fam, f in r["fmax"].items():
        if f["controller_mhz"] is None and f["picorv32_mhz"] is None:
            rows.append([fam, "not placed here", "not placed here", f["part"]])
            continue
        c, p = f["controller_mhz"], f["picorv32_mhz"]
        rows.append([fam, f"{c:.1f}" if c is not None else "error", f"{p:.1f}" if p is not None else "error",
                     f["part"] + (f"; controller / PicoRV32 {c / p:.2f}" if c and p else "")])
    return table(["family", "controller alone, MHz", "PicoRV32 alone, MHz", "placed on"], rows) + \
        f"\n\n(`{REPORTS}/controller_area.json`; each placed out of context, seed 1.)"


def controller_ladder():
    r = load("controller_ladder.json")
    if not r or "rows" not in r:
        missing("controller_ladder.json", "make area")
    fams = r["families"]
    head = ["rung", "taken out (with every rung above)"] + \
        [f"{fam} LUTs (saved; LUTs / PicoRV32)" for fam in fams]
    rows = []
    for e in r["rows"]:
        cells = []
        for fam in fams:
            if fam not in e["luts"]:
                cells.append("error")
                continue
            extra = [f"{n(e['saved'][fam])} saved"] if fam in e["saved"] else []
            if fam in e["over_picorv32"]:
                extra.append(f"{e['over_picorv32'][fam]:.2f}")
            cells.append(n(e["luts"][fam]) + (f" ({'; '.join(extra)})" if extra else ""))
        rows.append([str(e["rung"]), f"{e['name']}: {e['taken_out']}"] + cells)
    goals = r.get("core_goals_over_picorv32", {})
    pico = r.get("picorv32_luts", {})
    out = table(head, rows)
    if goals and pico:
        out += ("\n\nThe core configuration's target: " + ", ".join(
            f"{n(goals[f] * pico[f])} LUTs on {f} ({goals[f]:.2f} of one PicoRV32)" for f in goals if f in pico) + ".")
    return out + f" (`{REPORTS}/controller_ladder.json`)"


SECTIONS = {"controller-area": controller_area, "controller-growth": controller_growth,
            "controller-fmax": controller_fmax, "controller-ladder": controller_ladder}
