#!/usr/bin/env python3
"""doc_facts.py -- figures typed in the prose are checked against the thing
they describe, so they cannot drift:

  README.md        "One schedule cycle of sim/mobot3.toml: N ROM entries in
                   T µs" (the timeline's caption) against the compiler's
                   build/schedule/mobot3/report.json (--schedule DIR);
  docs/integration.md  "N targets, the board tops included" and
  tools/mk/fusesoc.mk  "N Verilator lints" against the lint targets
                   (flow: lint) of the checkout's *.core files, which
                   make test-fusesoc runs one by one;
  README.md        "ends with `sim: pass`" against the last line of a
                   make sim log (--sim-log FILE, optional), and the make sim
                   excerpt (the block figures:sim-excerpt) against the same
                   log: every line of it but "..." printed by the run, in
                   that order.

  doc_facts.py [--root DIR] [--schedule DIR] [--sim-log FILE]
  doc_facts.py --self-test    the negative: a copy of the tree with each
                              figure changed in turn must fail, naming it

Each line says what the text claims and what the thing is; exit 1 on any
mismatch.
"""
import argparse, json, os, re, shutil, subprocess, sys, tempfile

import yaml

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read(root, rel):
    with open(os.path.join(root, rel), encoding="utf-8") as f:
        return f.read()


def lint_targets(root):
    try:
        files = subprocess.run(["git", "ls-files", "*.core"], cwd=root, capture_output=True,
                               text=True, check=True).stdout.split()
    except (subprocess.CalledProcessError, FileNotFoundError):
        files = []
    if not files:   # not a git checkout (the self-test's copy): walk it
        for d, sub, fs in os.walk(root):
            sub[:] = [s for s in sub if s not in ("build", ".git")]
            files += [os.path.relpath(os.path.join(d, f), root) for f in fs if f.endswith(".core")]
    n = 0
    for f in files:
        with open(os.path.join(root, f)) as fh:
            core = yaml.safe_load(fh) or {}
        n += sum(1 for v in (core.get("targets") or {}).values()
                 if isinstance(v, dict) and v.get("flow") == "lint")
    return n


def check(root, schedule, sim_log):
    bad, ok = [], []
    readme = read(root, "README.md")
    # 1. the timeline's caption
    m = re.search(r"One schedule cycle of sim/mobot3\.toml: (\d+) ROM entries in ([\d.]+) µs", readme)
    rep_path = os.path.join(schedule, "report.json")
    if not m:
        bad.append("README.md: expected the caption 'One schedule cycle of sim/mobot3.toml: "
                   "N ROM entries in T µs', found none")
    elif not os.path.exists(rep_path):
        bad.append(f"{rep_path}: missing (make build/schedule/mobot3/rom.hex writes it)")
    else:
        with open(rep_path) as f:
            rep = json.load(f)
        cyc = rep["cycle"]
        entries = rep["entries"]
        us = cyc["us"] if isinstance(cyc, dict) else cyc * 1e6 / rep["clock_hz"]
        claim = (int(m.group(1)), float(m.group(2)))
        if claim != (entries, us):
            bad.append(f"README.md: the timeline's caption says {claim[0]} ROM entries in "
                       f"{m.group(2)} µs, the compiler's report says {entries} entries in {us:g} µs")
        else:
            ok.append(f"README.md caption: {entries} ROM entries in {us:g} µs, as the compiler reports")
    # 2. the FuseSoC lint targets
    n = lint_targets(root)
    for rel, rx in (("docs/integration.md", r"(\d+) targets, the board tops"),
                    ("tools/mk/fusesoc.mk", r"(\d+) Verilator lints")):
        m = re.search(rx, read(root, rel))
        if not m:
            bad.append(f"{rel}: expected the phrase /{rx}/, found none")
        elif int(m.group(1)) != n:
            bad.append(f"{rel}: says {m.group(1)} lint targets, the core files have {n} (flow: lint)")
        else:
            ok.append(f"{rel}: {n} lint targets, as in the core files")
    # 3. the last line of make sim
    if sim_log:
        claims = "ends with `sim: pass`" in readme
        with open(sim_log) as f:
            lines = [ln.rstrip("\n") for ln in f if ln.strip()]
        last = lines[-1] if lines else "(empty log)"
        if claims and last != "sim: pass":
            bad.append(f"README.md says make sim ends with `sim: pass`; the last line of {sim_log} is {last!r}")
        elif claims:
            ok.append(f"README.md: make sim ends with `sim: pass` ({sim_log})")
        excerpt = sim_excerpt(readme)
        if excerpt is None:
            bad.append("README.md: expected the make sim excerpt (<!-- figures:sim-excerpt --> with a ``` block), "
                       "found none")
        else:
            at = 0
            for line in excerpt:
                try:
                    at = lines.index(line, at) + 1
                except ValueError:
                    bad.append(f"README.md: the make sim excerpt's line {line.strip()[:90]!r} is not printed by the "
                               f"run in {sim_log} (in that order); make figures copies it from the log of "
                               "make test-docs-pictures")
                    break
            else:
                ok.append(f"README.md: the make sim excerpt's {len(excerpt)} lines as {sim_log} prints them")
    return ok, bad


def sim_excerpt(readme):
    """The lines of README.md's make sim excerpt, without the "..." lines; None without one."""
    m = re.search(r"^<!-- figures:sim-excerpt -->\n```\n(.*?)\n```\n<!-- /figures:sim-excerpt -->$", readme,
                  re.S | re.M)
    if not m:
        return None
    return [ln for ln in m.group(1).split("\n") if ln.strip() != "..."]


def self_test(schedule):
    """Each figure changed in a copy of the texts must be caught."""
    cases = [("README.md", r"(sim/mobot3\.toml: )(\d+)( ROM entries)", "caption"),
             ("docs/integration.md", r"()(\d+)( targets, the board tops)", "integration.md"),
             ("tools/mk/fusesoc.mk", r"()(\d+)( Verilator lints)", "fusesoc.mk")]
    good = True
    with tempfile.TemporaryDirectory() as d:
        for rel in ("README.md", "docs/integration.md", "tools/mk/fusesoc.mk"):
            os.makedirs(os.path.dirname(os.path.join(d, rel)) or d, exist_ok=True)
            shutil.copy(os.path.join(HERE, rel), os.path.join(d, rel))
        for d0, sub, fs in os.walk(HERE):
            sub[:] = [s for s in sub if s not in ("build", ".git")]
            for f in fs:
                if f.endswith(".core"):
                    rel = os.path.relpath(os.path.join(d0, f), HERE)
                    os.makedirs(os.path.join(d, os.path.dirname(rel)), exist_ok=True)
                    shutil.copy(os.path.join(d0, f), os.path.join(d, rel))
        ok, bad = check(d, schedule, None)
        if bad:
            print(f"self-test: the unchanged copy must pass, got: {bad}")
            good = False
        for rel, rx, what in cases:
            p = os.path.join(d, rel)
            orig = open(p).read()
            changed = re.sub(rx, lambda m: m.group(1) + str(int(m.group(2)) + 1) + m.group(3), orig, count=1)
            open(p, "w").write(changed)
            _, bad = check(d, schedule, None)
            hit = [b for b in bad if b.startswith(rel)]
            print(("caught: " + hit[0]) if hit else f"NOT CAUGHT: {what} changed by one")
            good &= bool(hit)
            open(p, "w").write(orig)
        log = os.path.join(d, "sim.log")
        open(log, "w").write("sim: pass\nsim: report build/reports/sim.json\n")
        _, bad = check(d, schedule, log)
        hit = [b for b in bad if "sim: pass" in b]
        print(("caught: " + hit[0]) if hit else "NOT CAUGHT: a make sim log that does not end with sim: pass")
        good &= bool(hit)
        # the excerpt: a log that prints it passes; one figure of it changed by one must be caught
        readme = os.path.join(d, "README.md")
        excerpt = sim_excerpt(open(readme).read()) or []
        open(log, "w").write("\n".join(["progress"] + excerpt + ["sim: pass"]) + "\n")
        _, bad = check(d, schedule, log)
        if [b for b in bad if "excerpt" in b] or not excerpt:
            print(f"self-test: a log that prints the excerpt must pass, got: {bad}")
            good = False
        orig = open(readme).read()
        row = next((ln for ln in excerpt if re.search(r"\d{3,}", ln)), "")
        changed = orig.replace(row, re.sub(r"\d{3,}", lambda m: str(int(m.group()) + 1), row, count=1), 1)
        open(readme, "w").write(changed)
        _, bad = check(d, schedule, log)
        hit = [b for b in bad if "excerpt" in b]
        print(("caught: " + hit[0]) if hit and changed != orig else "NOT CAUGHT: a figure of the make sim excerpt "
              "changed by one")
        good &= bool(hit) and changed != orig
        open(readme, "w").write(orig)
    print("doc-facts self-test: " + ("every changed figure caught" if good else "FAILED"))
    return 0 if good else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--root", default=HERE)
    ap.add_argument("--schedule", default=os.path.join(HERE, "build", "schedule", "mobot3"))
    ap.add_argument("--sim-log")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    if a.self_test:
        return self_test(a.schedule)
    ok, bad = check(a.root, a.schedule, a.sim_log)
    for x in ok:
        print("ok   " + x)
    for x in bad:
        print("FAIL " + x)
    print(f"doc-facts: {len(bad)} figure(s) of the text disagree with the thing" if bad
          else f"doc-facts: all {len(ok)} figures agree")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
