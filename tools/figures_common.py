"""figures_common.py -- what every table of tools/figures.py shares: the
reports folder, loading a report, the Absent signal (keep the old table), the
old block's text (old_rows, old_lines, old_text; figures.py sets it before it
regenerates a block) and the Markdown table writer."""
import json
import os

REPORTS = "build/reports"


class Absent(Exception):
    """The report a table is made from is absent: keep the table as it is."""


# The text between the markers of the block being regenerated (its old table).
_old = ""


def old_rows(first):
    """The rows of the old table whose first cell is FIRST (cells as strings)."""
    rows = []
    for line in _old.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if line.startswith("| ") and cells[0] == first:
            rows.append(cells)
    return rows


def old_text():
    """The old block's whole text."""
    return _old


def old_lines(prefix):
    """The lines of the old block that start with PREFIX."""
    return [line for line in _old.splitlines() if line.startswith(prefix)]


def load(name):
    path = os.path.join(REPORTS, name)
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def missing(name, target):
    raise Absent(f"_Not measured yet: `{target}` writes `{REPORTS}/{name}`._")


def table(head, rows):
    out = ["| " + " | ".join(head) + " |", "|" + "|".join("---" for _ in head) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def n(v):
    return f"{v:,.0f}"


def viol(rep):
    return n(rep.get("violations_total", 0))
