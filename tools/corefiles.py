#!/usr/bin/env python3
"""corefiles.py -- the RTL file lists of the project's FuseSoC cores, the one
place every list is written.

    tools/corefiles.py CORE [--target T | --fileset F] [--own] [--include]
    tools/corefiles.py --make            (the make fragment: CORE_<name> lists)
    tools/corefiles.py --owners          (every file, with the cores naming it)

CORE is a core name (its VLNV "albatross:ip:controller:1.0.0", without the
version, or the last part alone: "controller"; "soc:system" where the last
part is ambiguous) or the path of its .core file.  The cores are the .core
files of rtl/, soc/, fpga/ and constraints/ below the checkout.

Prints the Verilog files, one a line, as paths from the checkout's root: the
filesets of the target (default "default"; filesets with a flag condition,
"flag? (name)", are left out), each fileset's `depend:` cores of the project
first, recursively, in dependency order (a core's files after those of every
core it depends on, each file once).  Cores from elsewhere ("::picorv32") are
left to their owners.  --own: the core's own files only, no dependencies.
--include: also the include files (is_include_file, e.g. the contract .vh).

The cores are read with PyYAML when it is installed (FuseSoC brings it) and
otherwise with the small reader below, which knows the part of YAML the cores
use (block and flow collections, anchors, `<<` merges, comments): the
Makefile reads the lists before `make deps` has installed anything.  The test
(tools/mk/corefiles.mk) checks that both readers agree on every core.

Exit status 0; 1 when a core is unknown, names a missing file or depends on
a project core that does not exist (the message names it); 2 on usage.
"""

import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORE_DIRS = ("rtl", "soc", "fpga", "constraints")
HDL = (".v", ".sv", ".vh", ".svh")


class CoreError(Exception):
    pass


# ---- a small YAML reader (the subset the project's CAPI2 files use) ----------------------------

def _strip_comment(line):
    out, q = [], None
    for i, c in enumerate(line):
        if q:
            if c == q:
                q = None
        elif c in "'\"":
            q = c
        elif c == "#" and (i == 0 or line[i - 1] in " \t"):
            break
        out.append(c)
    return "".join(out).rstrip()


def _split_flow(s):
    """Split the inside of [..] or {..} at top-level commas."""
    parts, depth, q, cur = [], 0, None, []
    for c in s:
        if q:
            q = None if c == q else q
        elif c in "'\"":
            q = c
        elif c in "[{":
            depth += 1
        elif c in "]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append("".join(cur).strip())
            cur = []
            continue
        cur.append(c)
    if "".join(cur).strip():
        parts.append("".join(cur).strip())
    return parts


def _key_value(s):
    """'key: value' -> (key, value) or None when s is not a mapping entry."""
    m = re.match(r"""^("[^"]*"|'[^']*'|[^:'"\[\]{}][^:]*?)\s*:(\s+(.*))?$""", s)
    if not m:
        return None
    return _scalar(m.group(1)), (m.group(3) or "").strip()


def _scalar(s, anchors=None):
    s = s.strip()
    if anchors is not None and s.startswith("*"):
        return anchors[s[1:]]
    if len(s) >= 2 and s[0] == s[-1] and s[0] in "'\"":
        return s[1:-1]
    if anchors is not None and s.startswith("["):
        return [_scalar(x, anchors) for x in _split_flow(s[1:-1])]
    if anchors is not None and s.startswith("{"):
        out = {}
        for x in _split_flow(s[1:-1]):
            kv = _key_value(x)
            out[kv[0]] = _scalar(kv[1], anchors)
        return out
    if s in ("true", "True"):
        return True
    if s in ("false", "False"):
        return False
    if re.fullmatch(r"-?\d+", s):
        return int(s)
    return s


def mini_yaml(text):
    """Parse the YAML subset of the cores: block mappings and sequences, flow [..] and {..},
    quoted and plain scalars, &anchors, *aliases and `<<:` merges."""
    lines, depth = [], 0
    for raw in text.splitlines():
        line = _strip_comment(raw)
        if not line.strip() or line.startswith("CAPI=2"):
            continue
        if depth > 0:                            # a flow collection continued on this line
            lines[-1] = (lines[-1][0], lines[-1][1] + " " + line.strip())
        else:
            lines.append((len(line) - len(line.lstrip(" ")), line.strip()))
        depth += sum(line.count(c) for c in "[{") - sum(line.count(c) for c in "]}")
    anchors = {}

    def anchored(value):
        m = re.match(r"^&(\S+)\s*(.*)$", value)
        return (m.group(1), m.group(2)) if m else (None, value)

    def block(i, indent):
        """The collection whose items start at line i with this indent: (value, next i)."""
        if lines[i][1].startswith("- ") or lines[i][1] == "-":
            out = []
            while i < len(lines) and lines[i][0] == indent and lines[i][1].startswith("-"):
                item = lines[i][1][1:].strip()
                kv = _key_value(item)
                if kv is not None and not item.startswith(("'", '"')):
                    # "- key: value" (a mapping in a sequence): key with its {..} options.
                    out.append({kv[0]: _scalar(kv[1], anchors) if kv[1] else None})
                    i += 1
                else:
                    out.append(_scalar(item, anchors))
                    i += 1
            return out, i
        out = {}
        while i < len(lines) and lines[i][0] == indent:
            kv = _key_value(lines[i][1])
            if kv is None:
                raise CoreError(f"cannot read line {lines[i][1]!r}")
            key, value = kv
            anchor, value = anchored(value)
            i += 1
            if value:
                v = _scalar(value, anchors)
            elif i < len(lines) and (lines[i][0] > indent or
                                     (lines[i][0] == indent and lines[i][1].startswith("-"))):
                v, i = block(i, lines[i][0])
            else:
                v = None
            if anchor:
                anchors[anchor] = v
            if key == "<<":
                for k, x in v.items():
                    out.setdefault(k, x)
            else:
                out[key] = v
        return out, i

    value, _ = block(0, lines[0][0]) if lines else ({}, 0)
    return value


def load(path):
    with open(path) as f:
        text = f.read()
    try:
        import yaml  # noqa: PLC0415
    except ImportError:
        return mini_yaml(text)
    return yaml.safe_load(text)


# ---- the cores -------------------------------------------------------------------------------------

def _vln(vlnv):
    """'albatross:ip:controller:1.0.0' -> 'albatross:ip:controller'; '::serv:1.2.0' -> ':serv'."""
    return ":".join(vlnv.split(":")[:3])


class Cores:
    def __init__(self, root=ROOT, reader=load):
        self.root = root
        self.by_name = {}                      # 'albatross:ip:controller' -> (path, data)
        for d in CORE_DIRS:
            folder = os.path.join(root, d)
            for f in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
                if f.endswith(".core"):
                    path = os.path.join(folder, f)
                    data = reader(path)
                    if not isinstance(data, dict) or "name" not in data:
                        raise CoreError(f"{self.rel(path)}: no name: it is not a CAPI2 core")
                    self.by_name[_vln(data["name"])] = (path, data)

    def rel(self, path):
        return os.path.relpath(path, self.root)

    def find(self, spec):
        """A core by name, VLN, last name part or .core path: its VLN."""
        if spec.endswith(".core"):
            want = os.path.abspath(spec)
            for name, (path, _) in self.by_name.items():
                if os.path.abspath(path) == want:
                    return name
            raise CoreError(f"{spec}: not a core of this checkout ({', '.join(CORE_DIRS)})")
        spec = _vln(spec) if spec.count(":") >= 2 else spec
        hits = [n for n in self.by_name if n == spec or n.endswith(":" + spec)]
        if len(hits) != 1:
            known = ", ".join(sorted(self.by_name))
            raise CoreError(f"core {spec!r}: {'ambiguous' if hits else 'unknown'} (known: {known})")
        return hits[0]

    def filesets(self, name, target=None, fileset=None):
        path, data = self.by_name[name]
        sets = data.get("filesets") or {}
        if fileset is not None:
            names = [fileset]
        else:
            targets = data.get("targets") or {}
            t = target or "default"
            if t not in targets:
                raise CoreError(f"{self.rel(path)}: no target {t!r} (has {', '.join(targets)})")
            names = [f for f in (targets[t] or {}).get("filesets", []) if "?" not in f]
        for f in names:
            if f not in sets:
                raise CoreError(f"{self.rel(path)}: no fileset {f!r}")
        return [(f, sets[f]) for f in names]

    def own(self, name, target=None, fileset=None, include=False, any_type=False):
        """The files the core's filesets name (paths from the root), checked to exist."""
        path, _ = self.by_name[name]
        out = []
        for fs_name, fs in self.filesets(name, target, fileset):
            for item in fs.get("files") or []:
                fname, opts = (next(iter(item.items())) if isinstance(item, dict) else (item, None))
                opts = opts or {}
                full = os.path.join(os.path.dirname(path), fname)
                if not os.path.isfile(full):
                    raise CoreError(f"{self.rel(path)}: fileset {fs_name} names {fname}, which does not exist "
                                    f"({self.rel(full)})")
                if not any_type and not fname.endswith(HDL):
                    continue
                if opts.get("is_include_file") and not include:
                    continue
                out.append(self.rel(full))
        return out

    def depends(self, name, target=None, fileset=None):
        path, _ = self.by_name[name]
        out = []
        for _, fs in self.filesets(name, target, fileset):
            for dep in fs.get("depend") or []:
                vln = _vln(dep)
                if vln.startswith(":"):              # a core from elsewhere (::picorv32)
                    continue
                if vln not in self.by_name:
                    raise CoreError(f"{self.rel(path)}: depends on {dep}, which is no core of this checkout")
                out.append(vln)
        return out

    def files(self, name, target=None, fileset=None, include=False, own=False):
        """The files in dependency order: every depended-on core's (default target) first."""
        seen, order = set(), []

        def visit(n, tgt, fs, stack):
            if n in stack:
                raise CoreError(f"dependency cycle: {' -> '.join(stack + [n])}")
            if not own:
                for d in self.depends(n, tgt, fs):
                    visit(d, None, None, stack + [n])
            for f in self.own(n, tgt, fs, include):
                if f not in seen:
                    seen.add(f)
                    order.append(f)
        visit(name, target, fileset, [])
        return order

    def owners(self):
        """{file: [core, ...]}: every file any fileset of any core names (any target)."""
        out = {}
        for name, (path, data) in sorted(self.by_name.items()):
            for fs_name in data.get("filesets") or {}:
                for f in self.own(name, fileset=fs_name, include=True, any_type=True):
                    if name not in out.setdefault(f, []):
                        out[f].append(name)
        return out


def var_name(vln):
    """'albatross:ip:controller' -> 'controller', 'albatross:soc:system' -> 'soc_system'."""
    parts = vln.split(":")
    return parts[2] if parts[1] in ("ip",) else "_".join(parts[1:3])


def make_fragment(cores):
    lines = ["# Generated by tools/corefiles.py --make from the FuseSoC cores (rtl/, soc/, fpga/,",
             "# constraints/): do not edit.  CORE_<name>: the Verilog files of core <name>'s default",
             "# target with its project dependencies, in dependency order; CORE_OWN_<name>: its own;",
             "# CORE_FS_<name>_<fileset>: the Verilog files of one fileset (no dependencies).",
             "CORE_FILES_MK_CORES := " + " ".join(cores.rel(p) for p, _ in sorted(cores.by_name.values()))]
    for vln in sorted(cores.by_name):
        if "default" not in (cores.by_name[vln][1].get("targets") or {}):
            continue
        v = var_name(vln)
        lines.append(f"CORE_{v} := {' '.join(cores.files(vln))}")
        lines.append(f"CORE_OWN_{v} := {' '.join(cores.files(vln, own=True))}")
        for fs in cores.by_name[vln][1].get("filesets") or {}:
            lines.append(f"CORE_FS_{v}_{fs} := {' '.join(cores.own(vln, fileset=fs))}")
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("core", nargs="?")
    ap.add_argument("--target")
    ap.add_argument("--fileset")
    ap.add_argument("--own", action="store_true", help="the core's own files only")
    ap.add_argument("--include", action="store_true", help="also include files (.vh)")
    ap.add_argument("--make", action="store_true", help="print the make fragment of every core")
    ap.add_argument("--owners", action="store_true", help="print every file with the cores naming it")
    ap.add_argument("--root", default=ROOT, help="the checkout (default: this tool's)")
    ap.add_argument("--mini", action="store_true", help="read with the small reader even when PyYAML is there")
    a = ap.parse_args(argv)
    if sum(map(bool, (a.core, a.make, a.owners))) != 1:
        ap.error("give one of CORE, --make, --owners")
    if a.target and a.fileset:
        ap.error("--target or --fileset, not both")
    try:
        cores = Cores(a.root, reader=(lambda p: mini_yaml(open(p).read())) if a.mini else load)
        if a.make:
            sys.stdout.write(make_fragment(cores))
        elif a.owners:
            for f, names in sorted(cores.owners().items()):
                print(f, " ".join(names))
        else:
            print("\n".join(cores.files(cores.find(a.core), a.target, a.fileset, a.include, a.own)))
    except (CoreError, OSError) as e:
        print(f"corefiles: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
