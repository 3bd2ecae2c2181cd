#!/usr/bin/env python3
"""figures.py [FILE.md ...] -- regenerate the manual's figure tables from
build/reports/*.json (written by make test and make bench).  Without
arguments: README.md and docs/*.md.

Each table sits between the markers
    <!-- figures:NAME -->   and   <!-- /figures:NAME -->
in any of the files, and is replaced whole.  Every NAME below must appear in
exactly one block of the files given, and every block must name a table this
script knows, so a table can move between pages but never get lost or
doubled.  A table whose report is absent is kept as it is (a row whose own
report is absent is kept from the old table); only a block that is still
empty says which make target produces it.  No measured number is ever typed
into the manual by hand.  Standard library only.  The tables themselves are
in figures_core.py and figures_integration.py, their shared helpers in
figures_common.py.
"""
import glob
import re
import sys

import figures_area
import figures_common
import figures_core
import figures_integration
from figures_common import REPORTS, Absent

# Every table by its block name; a name made twice is an error.
SECTIONS = dict(figures_core.SECTIONS)
for _name, _make in list(figures_integration.SECTIONS.items()) + list(figures_area.SECTIONS.items()):
    assert _name not in SECTIONS, f"table '{_name}' is made twice"
    SECTIONS[_name] = _make


# A marker is a line of its own (a marker quoted inside a sentence is text).
BLOCK = re.compile(r"^<!-- figures:([A-Za-z0-9_-]+) -->\n(.*?)^<!-- /figures:\1 -->$", re.S | re.M)


def main():
    paths = sys.argv[1:] or ["README.md"] + sorted(glob.glob("docs/*.md"))
    texts = {}
    for path in paths:
        with open(path) as f:
            texts[path] = f.read()
    # Every table in exactly one block, every block a known table.
    where = {}
    for path, text in texts.items():
        for m in BLOCK.finditer(text):
            name = m.group(1)
            if name not in SECTIONS:
                sys.exit(f"figures.py: {path} has a block for an unknown table '{name}'")
            if name in where:
                sys.exit(f"figures.py: table '{name}' is in two blocks ({where[name]} and {path})")
            where[name] = path
        opened = set(re.findall(r"^<!-- figures:([A-Za-z0-9_-]+) -->$", text, re.M))
        for name in opened - {m.group(1) for m in BLOCK.finditer(text)}:
            sys.exit(f"figures.py: {path}: <!-- figures:{name} --> has no matching <!-- /figures:{name} -->")
    lost = sorted(set(SECTIONS) - set(where))
    if lost:
        sys.exit(f"figures.py: no <!-- figures:NAME --> ... <!-- /figures:NAME --> block for "
                 f"{', '.join(lost)} in {', '.join(paths)}")
    made, kept = [], []

    def regenerate(m):
        name = m.group(1)
        figures_common._old = old = m.group(2)
        try:
            body = SECTIONS[name]()
            made.append(name)
        except Absent as e:
            kept.append(name)
            body = old.strip("\n") or str(e)   # an empty block says how to fill it
        return f"<!-- figures:{name} -->\n{body}\n<!-- /figures:{name} -->"

    for path, text in texts.items():
        new = BLOCK.sub(regenerate, text)
        if new != text:
            with open(path, "w") as f:
                f.write(new)
    print(f"figures: {len(made)} tables regenerated from {REPORTS}/"
          + (f", {len(kept)} kept as they were (report absent: {', '.join(kept)})" if kept else "")
          + f" in {', '.join(sorted(set(where.values())))}")


if __name__ == "__main__":
    main()
