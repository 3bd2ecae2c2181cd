#!/usr/bin/env python3
"""controller_area.py -- where the controller's logic goes: its LUTs with each
optional feature taken out, against one PicoRV32, per FPGA family.

    tools/controller_area.py --picorv32 FILE [--families ice40,ecp5,xc7]
                             [--out DIR]
                             [--report JSON] [--jobs N]

Each variant is the controller's files (tools/fpga_report.py CTRL_FILES) with
a few source lines tied off (EDITS below: file and exact text, found exactly
once, or the tool stops and names it), synthesised like the controller of `make synth` (NB 4, ADDR_WIDTH 10,
N_CHAN 16, ROM_WORDS 1024; tools/fpga_report.py).  A tie-off lets Yosys drop
the feature's data path; the FSM keeps its states, so a row is an upper bound
of what is left without the feature.  PicoRV32 (as pico_core configures it)
is synthesised in the same run, and every row is also a ratio to it.  The
variants are measurements only: none of them is a supported configuration.

Prints a table and writes JSON (build/reports/controller_area.json).  Exit
status 0; 1 if an edit does not apply or Yosys fails, with the reason; 2 on
a usage error.
"""

import argparse
import concurrent.futures
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fpga_report import CTRL_FILES, design, synth_files  # noqa: E402
from synth_report import FAMILIES, write_json  # noqa: E402

# name: (what is tied off, [(file, exact text, replacement), ...])
EDITS = {
    # Each optional feature is a parameter of albatross_controller (default 1);
    # a variant sets its default to 0.
    "status": ("STATUS entries send zeros: no per-channel counters, no STATUS word 0 (HAS_STATUS = 0)", [
        ("rtl/albatross_controller.v", "parameter HAS_STATUS = 1,", "parameter HAS_STATUS = 0,"),
    ]),
    "sync": ("position-synchronised mode never polls (HAS_SYNC = 0)", [
        ("rtl/albatross_controller.v", "parameter HAS_SYNC   = 1,", "parameter HAS_SYNC   = 0,"),
    ]),
    "background": ("no background re-check of the ROM, the start-up CRC kept (HAS_ROM_RECHECK = 0)", [
        ("rtl/albatross_controller.v", "parameter HAS_ROM_RECHECK = 1,", "parameter HAS_ROM_RECHECK = 0,"),
    ]),
    "rom_checks": ("no field checks of the entries at fetch, the CRC kept (HAS_ENTRY_CHECK = 0)", [
        ("rtl/albatross_controller.v", "parameter HAS_ENTRY_CHECK = 1 ", "parameter HAS_ENTRY_CHECK = 0 "),
    ]),
    "destinations": ("one destination per entry instead of up to four (a measurement: ND read as 1)", [
        ("rtl/albatross_sequencer.v", "nd_q    <= e0_nd;", "nd_q    <= 3'd1;"),
    ]),
}

# name: (description, edits)
VARIANTS = [
    ("full", "the controller as it is", []),
    ("no counters, STATUS", EDITS["status"][0], ["status"]),
    ("no sync mode", EDITS["sync"][0], ["sync"]),
    ("no background check", EDITS["background"][0], ["background"]),
    ("no ROM field checks", EDITS["rom_checks"][0], ["rom_checks"]),
    ("one destination", EDITS["destinations"][0], ["destinations"]),
    ("none of these", "every tie-off above at once: the engines, retries, timing and the start-up CRC",
     ["status", "sync", "background", "rom_checks", "destinations"]),
]


def variant_sources(texts, edits):
    """The controller's files with the edits applied: {path: text}."""
    out = dict(texts)
    for e in edits:
        for path, old, new in EDITS[e][1]:
            n = out[path].count(old)
            if n != 1:
                raise ValueError(f"edit {e!r}: expected the text {old!r} once in {path}, found it {n} times "
                                 f"(update EDITS in tools/controller_area.py)")
            out[path] = out[path].replace(old, new)
    return out


def parts_ice40(paths, top, chparam, stem):
    """The full controller on iCE40 without flattening: {module: LUT4} of each part's own cells
    (a part's count excludes the parts it instantiates)."""
    import re
    import subprocess
    script = (f"read_verilog -DSYNTHESIS -Irtl {' '.join(paths)}; {chparam}; synth_ice40 -noflatten -top {top}; "
              f"tee -q -o {stem}_stat.txt stat")
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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--picorv32", required=True, help="picorv32.v of the PyPI package")
    ap.add_argument("--families", default="ice40,ecp5,xc7")
    ap.add_argument("--out", default="build/fpga/area")
    ap.add_argument("--report", default="build/reports/controller_area.json")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    a = ap.parse_args()
    fams = [f for f in a.families.split(",") if f]
    bad = [f for f in fams if f not in FAMILIES]
    if bad or not fams:
        ap.error(f"unknown family: {', '.join(bad) or '(none)'}; known: {', '.join(FAMILIES)}")
    if not os.path.isfile(a.picorv32):
        ap.error(f"--picorv32 {a.picorv32}: no such file (run make deps)")
    if a.jobs < 1:
        ap.error("--jobs must be at least 1")
    try:
        texts = {}
        for path in CTRL_FILES:
            with open(path) as f:
                texts[path] = f.read()
    except OSError as e:
        ap.error(f"{e.filename}: {e.strerror}")
    os.makedirs(a.out, exist_ok=True)

    _, ctop, chparam = design("controller", "ice40", a.picorv32, [])
    jobs = []                                    # (key, files, top, chparam, family, stem)
    for fam in fams:
        pfiles, ptop, pchp = design("picorv32", fam, a.picorv32, [])
        jobs.append((("PicoRV32", fam), pfiles, ptop, pchp, fam, os.path.join(a.out, f"picorv32_{fam}")))
    for name, _, edits in VARIANTS:
        try:
            srcs = variant_sources(texts, edits)
        except ValueError as e:
            print(f"controller_area: FAIL: {e}")
            return 1
        vdir = os.path.join(a.out, slug(name))
        os.makedirs(vdir, exist_ok=True)
        paths = []
        for path in CTRL_FILES:
            out = os.path.join(vdir, os.path.basename(path))
            with open(out, "w") as f:
                f.write(srcs[path])
            paths.append(out)
        for fam in fams:
            jobs.append(((name, fam), paths, ctop, chparam, fam, os.path.join(a.out, f"{slug(name)}_{fam}")))

    res = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futs = {pool.submit(synth_files, *j[1:]): j[0] for j in jobs}
        for i, fut in enumerate(concurrent.futures.as_completed(futs), 1):
            key = futs[fut]
            res[key] = fut.result()
            r = res[key]
            print(f"controller_area: [{i}/{len(jobs)}] {key[0]} on {key[1]}: "
                  f"{r.get('luts', 'ERROR')} LUTs ({r['yosys_seconds']} s)", flush=True)

    parts = {}
    if "ice40" in fams:
        parts = parts_ice40([os.path.join(a.out, "full", os.path.basename(p)) for p in CTRL_FILES], ctop, chparam,
                            os.path.join(a.out, "parts_ice40"))
        if "error" in parts:
            res[("parts", "ice40")] = {"error": parts.pop("error")}
        print("controller_area: parts on ice40 (not flattened): "
              + ", ".join(f"{k} {v}" for k, v in sorted(parts.items(), key=lambda kv: -kv[1])), flush=True)
    errors = [f"{k[0]} on {k[1]}: {r['error']}" for k, r in res.items() if "error" in r]
    pico = {fam: res[("PicoRV32", fam)].get("luts") for fam in fams}
    rows = []
    for name, desc, edits in VARIANTS:
        for fam in fams:
            r = res[(name, fam)]
            row = {"variant": name, "description": desc, "edits": edits, "family": fam}
            if "luts" in r:
                row.update({k: r[k] for k in ("luts", "ffs", "carries", "brams", "lutrams")})
                if pico[fam]:
                    row["over_picorv32"] = round(r["luts"] / pico[fam], 3)
            rows.append(row)

    print(f"\n{'variant':<22}" + "".join(f"{fam + ' LUTs':>12}{'/ Pico':>8}" for fam in fams))
    print(f"{'one PicoRV32':<22}" + "".join(f"{pico[fam] if pico[fam] else 'ERROR':>12}{'':>8}" for fam in fams))
    for name, _, _ in VARIANTS:
        line = f"{name:<22}"
        for fam in fams:
            row = next(x for x in rows if x["variant"] == name and x["family"] == fam)
            line += f"{row.get('luts', 'ERROR'):>12}" + (f"{row['over_picorv32']:>8.2f}" if "over_picorv32" in row
                                                        else f"{'-':>8}")
        print(line)
    write_json(a.report, {"picorv32_luts": pico, "rows": rows, "parts_ice40": parts, "goal_over_picorv32": 0.35, "aim_over_picorv32": 0.25,
                          "note": "LUTs: SB_LUT4 / LUT4 / LUT1-6; variants are tie-offs of "
                                  "the controller's files (tools/controller_area.py), measurements only"})
    print(f"controller_area: {a.report}")
    if errors:
        print("controller_area: FAIL: " + "; ".join(errors))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
