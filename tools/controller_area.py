#!/usr/bin/env python3
"""controller_area.py -- where the controller's logic goes: its LUTs with each
optional feature taken out, against one PicoRV32, per FPGA family.

    tools/controller_area.py --picorv32 FILE [--families ice40,ecp5,xc7]
                             [--rtl rtl/albatross_controller.v] [--out DIR]
                             [--report JSON] [--jobs N]

Each variant is rtl/albatross_controller.v with a few source lines tied off
(EDITS below: exact text, found exactly once, or the tool stops and names
it), synthesised like the controller of `make synth` (NB 4, ADDR_WIDTH 10,
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
from fpga_report import design, synth_files  # noqa: E402
from synth_report import FAMILIES, write_json  # noqa: E402

# name: (what is tied off, [(exact text, replacement), ...])
EDITS = {
    # The counters are read only through STATUS words, so Yosys drops them too.
    "status": ("STATUS entries send zeros: no per-channel counters, no STATUS word 0", [
        ("DS_ST0:    dat_n = {rerr_q, cycles_q};", "DS_ST0:    dat_n = 32'd0;"),
        ("DS_CTRB:   dat_n = ctrb_q;", "DS_CTRB:   dat_n = 32'd0;"),
    ]),
    "sync": ("position-synchronised mode never starts (no polling)", [
        ("if (sync_set) sync_ok_q <= 1'b1;", ""),
    ]),
    "fetch_check": ("a fetched entry's checksum is not checked again at run time", [
        ("((state_q == S_SCAN || state_q == S_FETCH) && M_FC_E7[fc_q8]);", "(state_q == S_SCAN && M_FC_E7[fc_q8]);"),
        ("((state_q == S_SCAN || state_q == S_FETCH) && fc_q == 8);", "(state_q == S_SCAN && fc_q == 8);"),
    ]),
    "rom_checks": ("no field checks of the header and entries at start-up (checksums kept)", [
        ("else if (bad_now)                                         bad_q <= 1'b1;", ""),
    ]),
    "destinations": ("one destination per entry instead of up to four", [
        ("nd_q    <= e0_nd[2:0];", "nd_q    <= 3'd1;"),
    ]),
}

# name: (description, edits)
VARIANTS = [
    ("full", "the controller as it is", []),
    ("no counters, STATUS", EDITS["status"][0], ["status"]),
    ("no sync mode", EDITS["sync"][0], ["sync"]),
    ("no run-time checksum", EDITS["fetch_check"][0], ["fetch_check"]),
    ("no ROM field checks", EDITS["rom_checks"][0], ["rom_checks"]),
    ("one destination", EDITS["destinations"][0], ["destinations"]),
    ("none of these", "every tie-off above at once: the Import/Export engine, retries and timing",
     ["status", "sync", "fetch_check", "rom_checks", "destinations"]),
]


def variant_source(text, edits, rtl):
    for e in edits:
        for old, new in EDITS[e][1]:
            n = text.count(old)
            if n != 1:
                raise ValueError(f"edit {e!r}: expected the text {old!r} once in {rtl}, found it {n} times "
                                 f"(update EDITS in tools/controller_area.py)")
            text = text.replace(old, new)
    return text


def slug(name):
    return "".join(c if c.isalnum() else "_" for c in name.lower()).strip("_")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--picorv32", required=True, help="picorv32.v of the PyPI package")
    ap.add_argument("--families", default="ice40,ecp5,xc7")
    ap.add_argument("--rtl", default="rtl/albatross_controller.v")
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
        with open(a.rtl) as f:
            text = f.read()
    except OSError as e:
        ap.error(f"--rtl {a.rtl}: {e.strerror}")
    os.makedirs(a.out, exist_ok=True)

    _, ctop, chparam = design("controller", "ice40", a.picorv32, [])
    jobs = []                                    # (key, files, top, chparam, family, stem)
    for fam in fams:
        pfiles, ptop, pchp = design("picorv32", fam, a.picorv32, [])
        jobs.append((("PicoRV32", fam), pfiles, ptop, pchp, fam, os.path.join(a.out, f"picorv32_{fam}")))
    for name, _, edits in VARIANTS:
        try:
            src = variant_source(text, edits, a.rtl)
        except ValueError as e:
            print(f"controller_area: FAIL: {e}")
            return 1
        path = os.path.join(a.out, f"{slug(name)}.v")
        with open(path, "w") as f:
            f.write(src)
        for fam in fams:
            jobs.append(((name, fam), [path], ctop, chparam, fam, os.path.join(a.out, f"{slug(name)}_{fam}")))

    res = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futs = {pool.submit(synth_files, *j[1:]): j[0] for j in jobs}
        for i, fut in enumerate(concurrent.futures.as_completed(futs), 1):
            key = futs[fut]
            res[key] = fut.result()
            r = res[key]
            print(f"controller_area: [{i}/{len(jobs)}] {key[0]} on {key[1]}: "
                  f"{r.get('luts', 'ERROR')} LUTs ({r['yosys_seconds']} s)", flush=True)

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
    write_json(a.report, {"picorv32_luts": pico, "rows": rows, "goal_over_picorv32": 0.25,
                          "note": "LUTs: SB_LUT4 / LUT4 / LUT1-6; variants are tie-offs of "
                                  "rtl/albatross_controller.v (tools/controller_area.py), measurements only"})
    print(f"controller_area: {a.report}")
    if errors:
        print("controller_area: FAIL: " + "; ".join(errors))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
