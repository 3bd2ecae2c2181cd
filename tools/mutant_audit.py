#!/usr/bin/env python3
"""mutant_audit.py -- every mutant's every edit still lands.

The negative tests break a source file with a sed script (tb/mutants/,
formal/*/mutants/, sim/mutants/, ...) and expect a check to catch the fault.
The recipes that apply a script fail when it changes nothing at all, but a
script of several edits can go stale one edit at a time when the file it
edits is reworded: the mutant then plants a different (or a partial) fault
and its negative test proves less than its name says.

For every *.sed script this audit runs each command alone (GNU sed, -s -n,
with F to name the files it changes) and requires:
  * a script with a '# target: PATH' line: every command changes PATH;
  * any other script: some one tracked source file is changed by every
    command (the file the script is written for).
It prints one line per stale command (the script, its line, the command)
and exits 1 if there is any.  Scripts are single-line commands ('s', 'd'
with an address or range), as every mutant of this project is; any other
command is reported as unsupported.

  python3 tools/mutant_audit.py [--root DIR] [--scripts DIR ...]
"""
import argparse
import os
import re
import subprocess
import sys

SOURCE_DIRS = ("rtl", "c-driver", "sim", "soc", "fpga", "tb", "formal")
SOURCE_EXT = (".v", ".vh", ".sv", ".c", ".h", ".cpp", ".py", ".sby")


def tracked_sources(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "--", *SOURCE_DIRS], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"mutant_audit: git ls-files failed in {root}: {out.stderr.strip()}")
    return sorted(f for f in out.stdout.split() if f.endswith(SOURCE_EXT))


def find_scripts(root, dirs):
    found = []
    for d in dirs:
        for base, _, files in os.walk(os.path.join(root, d)):
            if "/build" in base[len(root):]:
                continue
            found += [os.path.relpath(os.path.join(base, f), root) for f in files if f.endswith(".sed")]
    return sorted(found)


# An address: /re/ (with \/ inside), a line number or $; optionally a range.
ADDR = r"(?:/(?:[^/\\]|\\.)*/|\d+|\$)"
S_CMD = re.compile(rf"^((?:{ADDR}(?:,{ADDR})?)?)\s*s(.)")
D_CMD = re.compile(rf"^({ADDR}(?:,{ADDR})?)\s*d\s*$")


def probe(cmd):
    """A sed script that prints (F) the file name for every line cmd changes, or None."""
    m = S_CMD.match(cmd)
    if m:
        sep = re.escape(m.group(2))
        # drop a p or w flag: only F may print
        body = re.sub(rf"({sep}[gIi0-9]*)[pw][^{sep}]*$", r"\1", cmd)
        return body + "\nT\nF"
    m = D_CMD.match(cmd)
    if m:
        return m.group(1) + "F"
    return None


def changed_files(root, script, files):
    if not files:
        return set()
    r = subprocess.run(["sed", "-s", "-n", script, *files], cwd=root, capture_output=True, text=True)
    if r.returncode != 0:
        return None
    return {ln for ln in r.stdout.splitlines() if ln}


def audit(root, scripts, sources):
    problems = []
    for path in scripts:
        with open(os.path.join(root, path), errors="replace") as f:
            lines = f.read().splitlines()
        target = next((ln.split(":", 1)[1].strip() for ln in lines if ln.startswith("# target:")), None)
        cmds = [(i + 1, ln) for i, ln in enumerate(lines) if ln.strip() and not ln.lstrip().startswith("#")]
        if not cmds:
            problems.append(f"{path}: no command (a mutant must edit something)")
            continue
        if target is not None and not os.path.isfile(os.path.join(root, target)):
            problems.append(f"{path}: its target {target} does not exist")
            continue
        candidates = [target] if target else sources
        hits = []
        for no, cmd in cmds:
            script = probe(cmd)
            if script is None:
                problems.append(f"{path}:{no}: unsupported command (expected s or an addressed d): {cmd[:80]}")
                hits.append(None)
                continue
            got = changed_files(root, script, candidates)
            if got is None:
                problems.append(f"{path}:{no}: sed rejects the command: {cmd[:80]}")
            hits.append(got)
        if target:
            for (no, cmd), got in zip(cmds, hits):
                if got is not None and target not in got:
                    problems.append(f"{path}:{no}: expected this edit to change {target}, it changes nothing there: {cmd[:100]}")
            continue
        valid = [h for h in hits if h is not None]
        common = set.intersection(*valid) if valid else set()
        if not common:
            # name the file most edits land in, and the edits that miss it
            tally = {}
            for h in valid:
                for f in h:
                    tally[f] = tally.get(f, 0) + 1
            best = max(tally, key=lambda f: (tally[f], f)) if tally else None
            if best is None:
                problems.append(f"{path}: no edit changes any tracked source file")
            for (no, cmd), got in zip(cmds, hits):
                if got is not None and best is not None and best not in got:
                    problems.append(f"{path}:{no}: expected this edit to change {best} (the file its other "
                                    f"edits change), it changes nothing there: {cmd[:100]}")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--root", default=".")
    ap.add_argument("--scripts", nargs="*", default=list(SOURCE_DIRS), help="folders searched for *.sed")
    a = ap.parse_args()
    root = os.path.abspath(a.root)
    scripts = find_scripts(root, a.scripts)
    if not scripts:
        sys.exit(f"mutant_audit: no *.sed script under {', '.join(a.scripts)} in {root}")
    problems = audit(root, scripts, tracked_sources(root))
    for p in problems:
        print(f"mutant_audit: STALE {p}")
    print(f"mutant_audit: {len(scripts)} mutants, {len(problems)} stale edit(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
