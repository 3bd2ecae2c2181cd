#!/usr/bin/env python3
"""code_size.py -- code size of the ALBATROSS driver per optimisation level.

usage: code_size.py [--prefix riscv64-unknown-elf-] [--flags "..."]
                    [--out build/reports/driver_size.json] LEVEL=OBJECT ...

For each object (e.g. Os=build/rv32i/albatross-Os.o) it reads
`<prefix>nm -S --size-sort` (per-symbol sizes), `<prefix>size -A` (.text of
the object) and the call relocations of `<prefix>objdump -dr` (which static
helpers and libgcc routines alb_import and alb_export call; a helper the
compiler inlined is simply not there).  Sizes of libgcc routines (e.g.
__mulsi3 on rv32i, which has no multiply) are looked up in the multilib's
libgcc.a and reported apart: they are linked once per program.
Writes the JSON report and prints a table; standard library only.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

ENTRY_POINTS = ("alb_import", "alb_export")
TOOLS = ("gcc", "nm", "size", "objdump")


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def nm_sizes(nm, path):
    """{symbol: (size, type)} of the sized symbols in nm -S --size-sort output."""
    syms = {}
    for line in run([nm, "-S", "--size-sort", path]).splitlines():
        fields = line.split()
        if len(fields) == 4:
            _addr, size, kind, name = fields
            syms[name] = (int(size, 16), kind)
    return syms


def text_size(size_tool, path):
    for line in run([size_tool, "-A", path]).splitlines():
        fields = line.split()
        if len(fields) >= 2 and fields[0] == ".text":
            return int(fields[1])
    return 0


def call_graph(objdump, path):
    """{function: set of called symbols}, from R_RISCV_CALL*/JAL relocations."""
    calls, current = {}, None
    head = re.compile(r"^[0-9a-f]+ <([^>]+)>:$")
    reloc = re.compile(r"R_RISCV_(?:CALL|CALL_PLT|JAL)\s+(\S+)")
    for line in run([objdump, "-dr", path]).splitlines():
        m = head.match(line)
        if m:
            if not m.group(1).startswith(".L"):   # local labels stay in the function
                current = m.group(1)
                calls.setdefault(current, set())
            continue
        m = reloc.search(line)
        if m and current and not m.group(1).startswith(".L"):
            calls[current].add(m.group(1).split("+")[0])
    return calls


def libgcc_sizes(gcc, nm, flags):
    """{routine: size} from the libgcc.a of the multilib selected by flags."""
    arch = [f for f in flags if f.startswith(("-march=", "-mabi="))]
    try:
        lib = run([gcc] + arch + ["-print-libgcc-file-name"]).strip()
    except (OSError, subprocess.CalledProcessError):
        return {}
    if not os.path.isfile(lib):
        return {}
    sizes = {}
    for line in run([nm, "-S", "--size-sort", lib]).splitlines():
        fields = line.split()
        if len(fields) == 4 and fields[2] in "Tt":
            sizes.setdefault(fields[3], int(fields[1], 16))
    return sizes


def measure(prefix, level, path, flags):
    tool = {t: prefix + t for t in TOOLS}
    syms = nm_sizes(tool["nm"], path)
    text_syms = {n: s for n, (s, k) in syms.items() if k in "Tt"}
    graph = call_graph(tool["objdump"], path)
    lib = None
    functions = {}
    for entry in ENTRY_POINTS:
        helpers, external, todo = {}, {}, list(graph.get(entry, ()))
        while todo:
            callee = todo.pop()
            if callee in text_syms:
                if callee not in helpers and callee != entry:
                    helpers[callee] = text_syms[callee]
                    todo.extend(graph.get(callee, ()))
            elif callee not in external:
                if lib is None:
                    lib = libgcc_sizes(tool["gcc"], tool["nm"], flags)
                external[callee] = lib.get(callee)
        own = text_syms.get(entry, 0)
        with_helpers = own + sum(helpers.values())
        functions[entry] = {
            "own": own,
            "helpers": helpers,
            "with_helpers": with_helpers,
            "libgcc": external,
            "with_libgcc": with_helpers + sum(v or 0 for v in external.values()),
        }
    return {
        "object": path,
        "text_bytes": text_size(tool["size"], path),
        "symbols": dict(sorted(text_syms.items(), key=lambda kv: (kv[1], kv[0]))),
        "functions": functions,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--prefix", default="riscv64-unknown-elf-")
    ap.add_argument("--flags", default="", help="compiler flags, recorded in the report")
    ap.add_argument("--out", default="build/reports/driver_size.json")
    ap.add_argument("objects", nargs="+", metavar="LEVEL=OBJECT")
    args = ap.parse_args()

    missing = [args.prefix + t for t in TOOLS if shutil.which(args.prefix + t) is None]
    if missing:
        print("driver-size: %s not found: run make deps (installs gcc-riscv64-unknown-elf)"
              % ", ".join(missing))
        return 1
    flags = args.flags.split()
    report = {
        "target": " ".join(f for f in flags if f.startswith(("-march=", "-mabi="))),
        "compiler": run([args.prefix + "gcc", "--version"]).splitlines()[0],
        "flags": args.flags,
        "note": "bytes of .text; with_helpers adds the out-of-line static helpers "
                "the function calls (inlined ones are in 'own'); libgcc routines "
                "are linked once per program",
        "levels": {},
    }
    for spec in args.objects:
        level, _, path = spec.partition("=")
        if not path or not os.path.isfile(path):
            print("driver-size: no object for %s (%s)" % (level, path or "missing path"))
            return 1
        report["levels"]["-" + level.lstrip("-")] = measure(args.prefix, level, path, flags)

    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    with open(args.out, "w") as f:
        json.dump(report, f, indent=2)
        f.write("\n")

    print("ALBATROSS driver code size, %s (%s)" % (report["target"], report["compiler"]))
    for level, r in report["levels"].items():
        print("%s  %s: .text %d bytes" % (level, r["object"], r["text_bytes"]))
        for name, size in sorted(r["symbols"].items(), key=lambda kv: -kv[1]):
            print("    %-22s %5d" % (name, size))
        for name, fn in r["functions"].items():
            parts = ["own %d" % fn["own"]]
            parts += ["+ %s %d" % kv for kv in fn["helpers"].items()]
            line = "    %-10s %s = %d" % (name, " ".join(parts), fn["with_helpers"])
            if fn["libgcc"]:
                line += "  (+ libgcc %s)" % ", ".join(
                    "%s %s" % (k, v if v is not None else "?") for k, v in fn["libgcc"].items())
            print(line)
    summary = "; ".join(
        "%s alb_import %d B, alb_export %d B, .text %d B" % (
            level, r["functions"]["alb_import"]["with_helpers"],
            r["functions"]["alb_export"]["with_helpers"], r["text_bytes"])
        for level, r in report["levels"].items())
    print("wrote %s" % args.out)
    print("driver-size: %s" % summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
