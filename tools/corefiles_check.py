#!/usr/bin/env python3
"""corefiles_check.py -- the FuseSoC cores are the one list of the RTL files.

    tools/corefiles_check.py [--root DIR] [--vars FILE]

Checks, each failure naming the file, core or list and what was expected:
  1. every file a core names exists, and every project core it depends on
     (tools/corefiles.py reads them all);
  2. every Verilog file of rtl/, soc/ and fpga/ (*.v, *.vh) is named by
     exactly one core: a file no core names, or that two cores name, fails;
  3. with PyPI's PyYAML installed, the small YAML reader of corefiles.py
     reads every core as PyYAML does (the Makefile uses the small one);
  4. --vars FILE (lines "NAME: files", `make corefiles-print`): each of the
     Makefile's RTL lists holds, of rtl/, soc/ and fpga/, exactly the files
     of the cores it stands for (EXPECT below), in any order (the .v files:
     the include files come with $(RTL_INC)).

Exit status 0; 1 with the reasons; 2 on a usage error.
"""

import argparse
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corefiles  # noqa: E402

# The Makefile's lists and the cores they are made of: [(core, fileset or None = the
# default target with its dependencies)].
EXPECT = {
    "CTRL_RTL": [("controller", None)],
    "FPGA_RTL": [("board:duo", None), ("board:duo", "icebreaker"), ("board:duo", "ulx3s"), ("board:duo", "arty")],
    "PB_RTL": [("soc:system", None)],
    "PICO_RTL": [("soc:system", "board"), ("dpram", None)],
    "PBN_RTL": [("soc:system", "board"), ("dpram", None)],
    "VEX_RTL": [("soc:system", "board"), ("soc:system", "vexriscv"), ("dpram", None)],
    "EP_CORE": [("soc:system", "board")],
    "EP_ENGINES": [("export_endpoint", None), ("import_endpoint", None), ("dpram", None)],
    "CDC_SRC": [("wb_cdc", None), ("dpram", None)],
    "AXIL_SRC": [("dpram_axil", None)],
    "CTRL_SRC": [("soc:system", None)],
}
OWNED_DIRS = ("rtl", "soc", "fpga")


def expected(cores, parts):
    out = set()
    for name, fs in parts:
        vln = cores.find(name)
        out |= set(cores.files(vln, fileset=fs, own=fs is not None))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=corefiles.ROOT)
    ap.add_argument("--vars", help="the Makefile's lists: lines 'NAME: files' (make corefiles-print)")
    a = ap.parse_args()
    errors = []
    try:
        cores = corefiles.Cores(a.root)
        owners = cores.owners()
        for vln in cores.by_name:                       # depends resolve, default targets read
            if "default" in (cores.by_name[vln][1].get("targets") or {}):
                cores.files(vln)
    except corefiles.CoreError as e:
        print(f"corefiles-check: FAIL: {e}")
        return 1
    print(f"corefiles-check: {len(cores.by_name)} cores read, every file they name exists")

    hdl = sorted(os.path.relpath(p, a.root) for d in OWNED_DIRS for ext in ("v", "vh")
                 for p in glob.glob(os.path.join(a.root, d, f"*.{ext}")))
    for f in hdl:
        names = owners.get(f, [])
        if not names:
            errors.append(f"{f}: expected one core to name it, no core does (add it to the core of its "
                          f"folder: {', '.join(cores.rel(p) for p, _ in cores.by_name.values() if cores.rel(p).startswith(os.path.dirname(f) + '/'))})")
        elif len(names) > 1:
            errors.append(f"{f}: expected one core to name it, {len(names)} do: {', '.join(names)}")
    print(f"corefiles-check: {len(hdl)} Verilog files of {', '.join(OWNED_DIRS)}/ checked for one owner each")

    try:
        import yaml  # noqa: PLC0415
    except ImportError:
        yaml = None
        print("corefiles-check: PyYAML not installed: the small reader not compared with it")
    if yaml:
        for vln, (path, _) in sorted(cores.by_name.items()):
            with open(path) as f:
                text = f.read()
            want = yaml.safe_load(text)
            want.pop("CAPI=2", None)
            got = corefiles.mini_yaml(text)
            if got != want:
                keys = sorted(k for k in set(got) | set(want) if got.get(k) != want.get(k))
                errors.append(f"{cores.rel(path)}: expected corefiles.py's small reader to read it as PyYAML "
                              f"does, it differs in {', '.join(keys)}: {[got.get(k) for k in keys]!r} against "
                              f"{[want.get(k) for k in keys]!r}")
        print(f"corefiles-check: the small YAML reader agrees with PyYAML on {len(cores.by_name)} cores")

    if a.vars:
        got = {}
        with open(a.vars) as f:
            for line in f:
                if ":" in line:
                    k, v = line.split(":", 1)
                    got[k.strip()] = set(x for x in v.split() if x.split("/")[0] in OWNED_DIRS and x.endswith(".v"))
        for var, parts in EXPECT.items():
            if var not in got:
                errors.append(f"{var}: expected the Makefile to define it ({a.vars}), it is not there")
                continue
            want = expected(cores, parts)
            if got[var] != want:
                errors.append(f"{var}: expected the files of {', '.join(c + (':' + fs if fs else '') for c, fs in parts)}; "
                              f"not in the cores: {sorted(got[var] - want) or 'none'}, "
                              f"missing: {sorted(want - got[var]) or 'none'}")
        print(f"corefiles-check: {len(EXPECT)} Makefile lists compared with their cores")

    for e in errors:
        print(f"corefiles-check: FAIL: {e}")
    if not errors:
        print("corefiles-check: ok")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
