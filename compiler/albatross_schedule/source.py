"""The description's text: reading and decoding the file (encoding faults
located by line and column), and locating an error by table, field and
value (Locator), and collecting the errors of one run (Errors), so that
every message names the file, the line and column, the entity and the
field."""

from __future__ import annotations

import re
import tomllib

from .model import ScheduleError

# Byte-order marks a file may start with, and what they mean.
BOMS = ((b"\xef\xbb\xbf", "a UTF-8 byte-order mark (bytes EF BB BF)"),
        (b"\xff\xfe", "a UTF-16 byte-order mark (bytes FF FE): the file is UTF-16, not UTF-8"),
        (b"\xfe\xff", "a UTF-16 byte-order mark (bytes FE FF): the file is UTF-16, not UTF-8"))


def is_int(v) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)


def describe(v) -> str:
    """A value as the description wrote it (for messages)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return repr(v)
    if isinstance(v, float):
        return f"{v:g}"
    return repr(v) if not isinstance(v, (dict, list)) else type(v).__name__


def out_of_range(v, lo, hi, why="") -> str:
    """The message for an integer v outside [lo, hi] (why: the reason of the bound)."""
    return f"{v} is out of range: an integer from {lo} to {hi}" + (f" ({why})" if why else "")


def load_toml(path: str):
    """Read and decode a TOML file; errors name the file, line and column."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as e:
        raise ScheduleError(f"{path}: cannot read the description: {e.strerror}")
    for mark, what in BOMS:
        if raw.startswith(mark):
            raise ScheduleError(f"{path}:1:1: the file starts with {what}; a description is UTF-8 text without "
                                "a byte-order mark (save it as \"UTF-8\", not \"UTF-8 with BOM\")")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as e:
        line = raw.count(b"\n", 0, e.start) + 1
        start = raw.rfind(b"\n", 0, e.start) + 1
        col = len(raw[start:e.start].decode("utf-8", errors="replace")) + 1
        raise ScheduleError(f"{path}:{line}:{col}: not UTF-8 text: byte 0x{raw[e.start]:02X} at line {line}, "
                            f"column {col} (save the description as UTF-8)")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        msg = str(e)
        m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
        if m:
            base = msg[:m.start()].strip()
            raise ScheduleError(f"{path}:{m.group(1)}:{m.group(2)}: invalid TOML: {base} "
                                f"(line {m.group(1)}, column {m.group(2)})")
        raise ScheduleError(f"{path}: invalid TOML: {msg}")
    return data, text


class Locator:
    """Best-effort line and column of a table ([system], the i-th [[channel]]
    or [[mode]], [board.x]), of a field in it, and of a string value of that
    field (a board in boards = [...], also over several lines)."""

    HEADER_RE = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.\"' -]+?)\s*\]\]?\s*(#.*)?$")
    KEY_RE = re.compile(r"^\s*[\"']?[A-Za-z0-9_-]+[\"']?\s*=")

    def __init__(self, path: str, text: str):
        self.path = path
        self.lines = text.splitlines()
        self.tables = []            # (name, is_array, line index)
        for i, line in enumerate(self.lines):
            m = self.HEADER_RE.match(line)
            if m and not line.lstrip().startswith("#"):
                self.tables.append((m.group(1).strip(), line.lstrip().startswith("[["), i))

    def _header(self, i):
        return bool(self.HEADER_RE.match(self.lines[i])) and not self.lines[i].lstrip().startswith("#")

    def _table_line(self, name, nth=0):
        k = 0
        for tname, _, i in self.tables:
            if tname == name:
                if k == nth:
                    return i
                k += 1
        return None

    def position(self, table, nth=0, field=None, value=None):
        """(line, column), both from 1, or (line, None), or None."""
        start = self._table_line(table, nth)
        if start is None:
            return None
        if field is None:
            return start + 1, len(self.lines[start]) - len(self.lines[start].lstrip()) + 1
        key_re = re.compile(r"^\s*[\"']?" + re.escape(field) + r"[\"']?\s*=\s*")
        for i in range(start + 1, len(self.lines)):
            if self._header(i):
                break
            m = key_re.match(self.lines[i])
            if not m:
                continue
            if isinstance(value, str):      # the value itself, on this line or a continuation line
                for j in range(i, len(self.lines)):
                    if j > i and (self._header(j) or self.KEY_RE.match(self.lines[j])):
                        break
                    k = max((self.lines[j].find(q + value + q, m.end() if j == i else 0) for q in "\"'"))
                    if k >= 0:
                        return j + 1, k + 1
            return i + 1, m.end() + 1
        return start + 1, None

    def line(self, table, nth=0, field=None):
        pos = self.position(table, nth, field)
        return pos[0] if pos else None

    def where(self, table, nth=0, field=None, value=None):
        pos = self.position(table, nth, field, value)
        if not pos:
            return self.path
        return f"{self.path}:{pos[0]}" + (f":{pos[1]}" if pos[1] else "")


class Errors:
    """The errors of one description, each 'FILE:LINE:COL: <entity>, field '<f>': <problem>'."""

    def __init__(self, loc: Locator):
        self.loc = loc
        self.messages = []

    def system(self, field, msg, table="system", value=None):
        where = self.loc.where(table, 0, field, value)
        fld = f", field '{field}'" if field else ""
        self.messages.append(f"{where}: [{table}]{fld}: {msg}")

    def channel(self, i, name, field, msg):
        where = self.loc.where("channel", i, field)
        who = f"channel '{name}'" if isinstance(name, str) and name else f"channel #{i + 1}"
        fld = f", field '{field}'" if field else ""
        self.messages.append(f"{where}: {who}{fld}: {msg}")

    def mode(self, i, name, field, msg):
        where = self.loc.where("mode", i, field)
        who = f"mode '{name}'" if isinstance(name, str) and name else f"mode #{i + 1}"
        fld = f", field '{field}'" if field else ""
        self.messages.append(f"{where}: {who}{fld}: {msg}")

    def general(self, msg):
        self.messages.append(f"{self.loc.path}: {msg}")

    def raise_if_any(self):
        """Raise the errors so far, in the order of their lines (those of the whole file first)."""
        if self.messages:
            at = re.compile(re.escape(self.loc.path) + r":(\d+)(?::(\d+))?: ")

            def key(msg):
                m = at.match(msg)
                return (int(m.group(1)), int(m.group(2) or 0)) if m else (0, 0)
            raise ScheduleError(sorted(self.messages, key=key))
