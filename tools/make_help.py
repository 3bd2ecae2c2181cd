#!/usr/bin/env python3
"""make_help.py MAKEFILE... -- make help: every target whose rule line carries
a "## description" comment, grouped and aligned.

A description may name its group first, in brackets:
    sim: ... ## [sim] the robot ...
Without one, the group comes from the target's name (GUESS below).  Groups
print in the order of GROUPS; a group not in it prints last, under its own
name.  Standard library only, so that make help works before make deps.

  make_help.py --check-docs MAKEFILE... [--targets FILE] [DOC...]
      every `make X` in the docs (code spans and code blocks of README.md,
      docs/*.md, compiler/README.md) must be listed by make help; a test
      target make test-NAME named there must be a rule (--targets: the
      targets of make's database, one per line).  Exit 1 naming each miss.
"""
import os, re, sys

GROUPS = [("start", "Start"), ("test", "Tests"), ("sim", "Simulation"), ("fpga", "FPGA"),
          ("formal", "Formal"), ("bench", "Benchmarks and figures"), ("docs", "Docs and generated files")]
# name pattern -> group, for a description without [group]; first match wins
GUESS = [(r"^(help|deps|schedule|clean)$", "start"),
         (r"^(test|check|list-tests|lint)$|^test-", "test"),
         (r"^sim", "sim"),
         (r"^(synth|pnr|bitstream|area|fusesoc-boards)$|^fpga", "fpga"),
         (r"^formal", "formal"),
         (r"^(bench|soak)|-size$|^endpoint-report$", "bench"),
         (r"^(figures|contract)$|^docs", "docs")]
RULE = re.compile(r"^([a-zA-Z0-9_.-]+):[^=]*?##\s+(.*)$")


def targets(files):
    seen = {}
    for f in files:
        if not os.path.isfile(f):
            continue
        with open(f) as fh:
            lines = re.sub(r"\\\n", " ", fh.read()).split("\n")   # join continued lines
            for line in lines:
                m = RULE.match(line)
                if not m or m.group(1) in seen:
                    continue
                name, text = m.group(1), m.group(2).strip()
                g = re.match(r"\[([a-z]+)\]\s*(.*)$", text)
                if g:
                    group, text = g.group(1), g.group(2)
                else:
                    group = next((grp for rx, grp in GUESS if re.search(rx, name)), "other")
                seen[name] = (group, text)
    return seen


def render(ts):
    w = max(len(n) for n in ts) + 2
    order = [g for g, _ in GROUPS] + sorted({g for g, _ in ts.values()} - {g for g, _ in GROUPS})
    title = dict(GROUPS)
    out = ["ALBATROSS -- make targets (make test-NAME runs one test of make test)"]
    for g in order:
        rows = [(n, t) for n, (gg, t) in ts.items() if gg == g]
        if not rows:
            continue
        out.append("")
        out.append(title.get(g, g.capitalize()) + ":")
        out += [f"  {n:<{w}}{t}" for n, t in rows]
    return "\n".join(out)


def doc_makes(docs):
    """(file, line, target) of every `make X` in code spans and code blocks."""
    found = []
    for d in docs:
        with open(d) as fh:
            text = fh.read()
        spans = []
        for m in re.finditer(r"^```.*?\n(.*?)^```", text, re.M | re.S):
            spans.append((m.start(1), m.group(1)))
        for m in re.finditer(r"`([^`\n]+)`", text):
            spans.append((m.start(1), m.group(1)))
        for start, code in spans:
            for m in re.finditer(r"(?:^|[\s;(&|])make((?:\s+-[CsjkB]\s*\S*|\s+-[a-z]+)*)((?:\s+[A-Z_]+=\S*)*)\s+([a-z][a-zA-Z0-9_.-]*)(?![/\w.-])", code, re.M):
                name = m.group(3)
                if name.endswith(("-", "_", ".")) or "/" in name or name in ("the", "this"):
                    continue   # a family (test-foo-<kind>), a file, or prose
                line = text.count("\n", 0, start + m.start(3)) + 1
                found.append((d, line, name))
    return found


def main(argv):
    if argv and argv[0] == "--check-docs":
        argv = argv[1:]
        tfile = None
        if "--targets" in argv:
            i = argv.index("--targets")
            tfile = argv[i + 1]
            argv = argv[:i] + argv[i + 2:]
        makefiles = [a for a in argv if not a.endswith(".md")]
        docs = [a for a in argv if a.endswith(".md")]
        helped = targets(makefiles)
        rules = set()
        if tfile:
            with open(tfile) as fh:
                rules = {ln.strip() for ln in fh if ln.strip()}
        miss = []
        for d, line, name in doc_makes(docs):
            if name in helped:
                continue
            if name.startswith("test-") and name in rules:
                continue
            if name == "test-NAME":     # the placeholder of "run one test", not a target
                continue
            miss.append(f"{d}:{line}: make {name}: expected it in make help"
                        + (" (or, for a test, a rule test-NAME)" if name.startswith("test-") else "")
                        + ", it is not")
        for m in miss:
            print(m)
        n = len({x[2] for x in doc_makes(docs)})
        print(f"help-docs: {len(miss)} target(s) named in the docs but missing from make help" if miss
              else f"help-docs: all {n} targets the docs name are in make help (tests: a rule)")
        return 1 if miss else 0
    try:
        print(render(targets(argv)))
    except BrokenPipeError:        # make help | head
        sys.stderr.close()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
