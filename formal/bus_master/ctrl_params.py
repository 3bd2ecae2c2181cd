#!/usr/bin/env python3
"""ctrl_params.py -- the bus master's parameters in the controller, for the
proof (formal/bus_master/bus_master.sby, tasks with the tag ctrl).

    ctrl_params.py OUT.ys [--at default|min|max]
                          [--controller rtl/albatross_controller.v]
                          [--master rtl/albatross_bus_master.v]
                          [--harness formal/bus_master/fbus_master.v]

Reads the one instantiation of albatross_bus_master in the controller and
resolves each parameter it sets to a number: a literal, or a name of the
controller's (a parameter's default or a localparam, followed through other
names).  A parameter the instantiation leaves out takes the bus master's own
default.  Writes a Yosys script with one `chparam` that sets them all on the
harness fbus_master, so the proof runs at the controller's configuration,
whatever it becomes (nothing to keep in step by hand).  --at min / max: a
value that comes from a parameter of the controller takes instead the lower /
upper end of the range its declaration's comment states ("..., 3..60"), so
the proof also runs at both ends of what the controller accepts.  Stops with
status 2 and a message naming the parameter when the controller has no such
instantiation or more than one, when a value is an expression it cannot
resolve, when --at finds no range, or when the harness has no parameter of
that name.
"""
import argparse
import os
import re
import sys

NUM = re.compile(r"^(?:(\d+)?'([sS]?)([dDhHbBoO])([0-9a-fA-F_xXzZ]+)|(\d[\d_]*))$")


def fail(msg):
    print(f"ctrl_params: {msg}", file=sys.stderr)
    sys.exit(2)


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def declared(text, kinds=("parameter", "localparam")):
    """name -> value text of every parameter (its default) and localparam (of KINDS)."""
    out = {}
    for kind, name, value in re.findall(
            r"\b(parameter|localparam)\s+(?:integer\s+|signed\s+)?(?:\[[^\]]*\]\s*)?(\w+)\s*=\s*([^,;]+?)\s*(?=[,;)]|$)",
            text, flags=re.M):
        if kind in kinds:
            out.setdefault(name, value.strip())
    return out


def number(value):
    m = NUM.match(value.strip())
    if not m:
        return None
    if m.group(5) is not None:
        return int(m.group(5).replace("_", ""))
    base = {"d": 10, "h": 16, "b": 2, "o": 8}[m.group(3).lower()]
    digits = m.group(4).replace("_", "")
    if re.search(r"[xXzZ]", digits):
        return None
    return int(digits, base)


def ranges(raw):
    """parameter name -> (lo, hi) from a "lo..hi" in its declaration's comment."""
    out = {}
    for name, comment in re.findall(r"^\s*parameter\s+(\w+)\s*=[^\n]*?//([^\n]*)$", raw, flags=re.M):
        m = re.search(r"\b(\d+)\s*\.\.\s*(\d+)\b", comment)
        if m:
            out[name] = (int(m.group(1)), int(m.group(2)))
    return out


def resolve(param, value, names, seen=()):
    """(number, the names followed to it)"""
    n = number(value)
    if n is not None:
        return n, seen
    v = value.strip()
    if re.fullmatch(r"\w+", v) and v in names and v not in seen:
        return resolve(param, names[v], names, seen + (v,))
    fail(f"the controller sets the bus master's {param} to '{value}', which is neither a number nor a "
         f"name of a controller parameter or localparam with a number (resolve it here or set it plainly)")


def instantiations(text, module):
    """The parameter lists (text inside #( ... )) of every instance of MODULE."""
    out = []
    for m in re.finditer(r"\b" + module + r"\s*#\s*\(", text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
        if depth:
            fail(f"unbalanced parameter list of {module}")
        out.append(text[m.end():i - 1])
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--at", choices=("default", "min", "max"), default="default")
    ap.add_argument("--controller", default="rtl/albatross_controller.v")
    ap.add_argument("--master", default="rtl/albatross_bus_master.v")
    ap.add_argument("--harness", default="formal/bus_master/fbus_master.v")
    a = ap.parse_args()
    raw = open(a.controller).read()
    ctrl = strip_comments(raw)
    master = declared(strip_comments(open(a.master).read()), ("parameter",))
    harness = declared(strip_comments(open(a.harness).read()), ("parameter",))
    lists = instantiations(ctrl, "albatross_bus_master")
    if len(lists) != 1:
        fail(f"{a.controller} has {len(lists)} instances of albatross_bus_master with parameters, not one")
    given = dict(re.findall(r"\.(\w+)\s*\(\s*([^()]*?)\s*\)", lists[0]))
    names = declared(ctrl)
    cparams = declared(ctrl, ("parameter",))
    bounds = ranges(raw)
    params, notes = {}, []
    for p in sorted(set(given) | {k for k in master if k in harness}):
        if p not in harness:
            fail(f"the controller sets the bus master's {p}, but the harness {a.harness} has no parameter {p}")
        if p in given:
            params[p], via = resolve(p, given[p], names)
            via = [n for n in via if n in cparams]
            if a.at != "default" and via:
                if via[0] not in bounds:
                    fail(f"--at {a.at}: the bus master's {p} comes from the controller's parameter {via[0]}, "
                         f"whose declaration's comment gives no range lo..hi")
                params[p] = bounds[via[0]][0 if a.at == "min" else 1]
                notes.append(f"{p}: the controller's {via[0]} at its {a.at}imum")
        elif p in master:
            params[p] = resolve(p, master[p], master)[0]
    missing = [p for p in ("REQS", "HOLD_FIELDS", "TIMEOUT", "ADDR_WIDTH", "BOARD_BITS") if p not in params]
    if missing:
        fail(f"no value for {', '.join(missing)} (neither the controller's instance nor the bus master's defaults)")
    sets = " ".join(f"-set {p} {v}" for p, v in sorted(params.items()))
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    with open(a.out, "w") as f:
        f.write(f"# generated by formal/bus_master/ctrl_params.py --at {a.at} from {a.controller}: the bus\n"
                f"# master as the controller instantiates it\nchparam {sets} fbus_master\n")
    print(f"ctrl_params: the controller's bus master ({a.at}): "
          + ", ".join(f"{p} = {v}" for p, v in sorted(params.items()))
          + (f" ({'; '.join(notes)})" if notes else ""))


if __name__ == "__main__":
    main()
