#!/usr/bin/env python3
"""fusesoc_check.py --root DIR --work DIR [--sim VLNV] [--library DIR] [--picorv32 FILE]

Checks the FuseSoC (CAPI2) core files of the library DIR the way a user of
the IP meets them (tools/mk/fusesoc.mk, docs/integration.md):

 1. A FuseSoC configuration of its own in WORK (WORK/fusesoc.conf, written by
    `fusesoc library add --sync-type local --no-auto-sync`; build and cache
    roots in WORK): FuseSoC never fetches (a local library, and no core may
    have a `provider:` section), and no user or global fusesoc.conf is read.
 1b. The CPUs' cores for albatross:soc:system: --library DIR adds a folder
    as one more local library (pythondata-cpu-serv's, which holds ::serv);
    --picorv32 FILE writes WORK/deps/picorv32.core, ::picorv32:0-r1 naming
    FILE (pythondata-cpu-picorv32's picorv32.v: the package's own
    picorv32.core has an empty depend: list that FuseSoC 2.4 refuses).
 2. Every *.core file under DIR (folders holding a FUSESOC_IGNORE file are
    skipped, as FuseSoC does: build/ gets one) is valid YAML with CAPI=2
    and a name, every file its filesets name exists, and FuseSoC loaded it
    (FuseSoC only warns about a core file it cannot parse and goes on
    without it; this check fails instead).
 3. Every core of Verilog sources has a target whose flow is `lint`, and
    every such target passes (Verilator -Wall through FuseSoC and Edalize):
    each core with its dependencies, checked alone.  No target uses the
    deprecated default_tool: form.
 4. Cores of C files (the driver, no flow): the C files of target default
    compile with the project's flags (C99, -Wall -Wextra -Werror -pedantic),
    the include path made of the folders of the core's include files.
 5. --sim VLNV: `fusesoc run --target sim VLNV` prints a line starting with
    PASS and no line starting with FAIL.

Ends with "fusesoc-check: N cores ..., ok" or the first failure, named with
the core file and what was expected.  Everything FuseSoC writes stays in WORK.
"""
import argparse
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import traceback

import yaml

C_FLAGS = ['-std=c99', '-Wall', '-Wextra', '-Werror', '-pedantic', '-ffreestanding',
           '-DALB_LOCAL_TIMER_ADDR=0x20000040u']


def fail(msg):
    print('fusesoc-check: FAIL ' + msg)
    sys.exit(1)


TIMEOUT = 600   # seconds for one FuseSoC call or compile: the check ends on its own


def run(cmd, log, env):
    """Run cmd, its output to log; returns (exit status, output).  A `fusesoc`
    command runs as FuseSoC's own main() in a forked child (run_fusesoc)."""
    if cmd[0] == 'fusesoc' and hasattr(os, 'fork') and hasattr(os, 'pidfd_open'):
        return run_fusesoc(cmd, log, env)
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env,
                           timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        fail('expected %s to end within %d s, it did not (log %s)' % (' '.join(cmd[:6]), TIMEOUT, log))
    with open(log, 'w') as f:
        f.write(' '.join(cmd) + '\n' + p.stdout)
    return p.returncode, p.stdout


def run_fusesoc(cmd, log, env):
    """The `fusesoc` command as a child process forked from this one, which has
    imported FuseSoC once: the child sets its environment and argv, sends its
    output (and that of the tools Edalize starts) to log and calls FuseSoC's
    main(), as the command does.  Each call is still a process of its own;
    only the half second of Python imports per call (about 20 calls) is
    saved.  Same timeout as run(): the child's process group is killed."""
    import fusesoc.main
    with open(log, 'w') as f:
        f.write(' '.join(cmd) + '\n')
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:
        code = 1
        try:
            os.setpgid(0, 0)
            fd = os.open(log, os.O_WRONLY | os.O_APPEND)
            os.dup2(fd, 1)
            os.dup2(fd, 2)
            os.environ.clear()
            os.environ.update(env)
            sys.argv = cmd
            fusesoc.main.main()
            code = 0
        except SystemExit as e:
            code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
        except BaseException:
            traceback.print_exc()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(code)
    pidfd = os.pidfd_open(pid)
    ready, _, _ = select.select([pidfd], [], [], TIMEOUT)
    os.close(pidfd)
    if not ready:
        os.killpg(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        fail('expected %s to end within %d s, it did not (log %s)' % (' '.join(cmd[:6]), TIMEOUT, log))
    _, status = os.waitpid(pid, 0)
    with open(log) as f:
        out = f.read().split('\n', 1)[1]
    return os.waitstatus_to_exitcode(status), out


def tail(text, n=12):
    """The error lines of a tool's output (Verilator's %Error, FuseSoC's
    ERROR), else its last n lines, indented."""
    lines = text.rstrip().splitlines()
    errors = [ln for ln in lines if re.match(r'\s*(%Error|ERROR)', ln)]
    return '\n'.join('    ' + ln for ln in (errors[:n] if errors else lines[-n:]))


def picorv32_core(path):
    """A CAPI2 core for the PicoRV32 of the PyPI package, by absolute path."""
    return ('CAPI=2:\n# Written by tools/fusesoc_check.py: the PicoRV32 of pythondata-cpu-picorv32.\n'
            'name: ::picorv32:0-r1\ndescription: PicoRV32 (pythondata-cpu-picorv32)\n'
            'filesets:\n  rtl:\n    files: [%s]\n    file_type: verilogSource\n'
            'targets:\n  default:\n    filesets: [rtl]\n' % path)


def find_cores(root):
    cores = []
    for d, subdirs, files in os.walk(root):
        if 'FUSESOC_IGNORE' in files:
            subdirs[:] = []
            continue
        subdirs[:] = sorted(s for s in subdirs if not s.startswith('.'))
        cores += [os.path.join(d, f) for f in sorted(files) if f.endswith('.core')]
    return cores


def load_core(path):
    with open(path) as f:
        text = f.read()
    if not text.startswith('CAPI=2:'):
        fail('%s: expected a CAPI2 core file (first line "CAPI=2:"), got %r' % (path, text.split('\n')[0]))
    try:
        core = yaml.safe_load(text)
    except yaml.YAMLError as e:
        fail('%s: expected valid YAML, got a parse error:\n%s' % (path, e))
    if not isinstance(core, dict) or not core.get('name'):
        fail('%s: expected a core with a name, got none' % path)
    if 'provider' in core:
        fail('%s: expected no provider section (the check must never fetch), got one' % path)
    return core


def fileset_files(core, fs_name, path):
    fs = (core.get('filesets') or {}).get(fs_name)
    if fs is None:
        fail('%s: expected a fileset %s (named by a target), got none' % (path, fs_name))
    out = []
    for entry in fs.get('files') or []:
        if isinstance(entry, dict):
            (name, attrs), = entry.items()
        else:
            name, attrs = entry, {}
        out.append((name, attrs or {}, attrs.get('file_type', fs.get('file_type', ''))))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--root', required=True, help='library folder (the checkout)')
    ap.add_argument('--work', required=True, help='folder for the config, builds and logs')
    ap.add_argument('--sim', action='append', default=[], help='core whose sim target must print PASS')
    ap.add_argument('--library', action='append', default=[], help='one more library folder (read only)')
    ap.add_argument('--picorv32', help='picorv32.v, for a ::picorv32:0-r1 core written into WORK')
    args = ap.parse_args()
    root = os.path.abspath(args.root)
    work = os.path.abspath(args.work)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, 'logs'))
    conf = os.path.join(work, 'fusesoc.conf')
    with open(conf, 'w') as f:
        f.write('[main]\nbuild_root = %s\ncache_root = %s\n' % (os.path.join(work, 'build'),
                                                              os.path.join(work, 'cache')))
    env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, 'xdg', 'config'),
               XDG_DATA_HOME=os.path.join(work, 'xdg', 'data'), XDG_CACHE_HOME=os.path.join(work, 'xdg', 'cache'))
    fsoc = ['fusesoc', '--config', conf, '--monochrome']
    log = os.path.join(work, 'logs')
    libs = [('albatross', root)] + [('lib%d' % i, os.path.abspath(d)) for i, d in enumerate(args.library)]
    if args.picorv32:
        deps = os.path.join(work, 'deps')
        os.makedirs(deps)
        with open(os.path.join(deps, 'picorv32.core'), 'w') as f:
            f.write(picorv32_core(os.path.abspath(args.picorv32)))
        libs.append(('picorv32', deps))
    for lib_name, d in libs:
        rc, out = run(fsoc + ['library', 'add', '--sync-type', 'local', '--no-auto-sync', lib_name, d],
                      os.path.join(log, 'library_add_%s.log' % lib_name), env)
        if rc:
            fail('fusesoc library add %s: expected exit 0, got %d:\n%s' % (d, rc, tail(out)))

    # 2. the core files: YAML, names, files; all loaded by FuseSoC
    paths = find_cores(root)
    if not paths:
        fail('expected core files under %s, got none' % root)
    cores = {}
    for p in paths:
        c = load_core(p)
        if c['name'] in cores:
            fail('%s: expected one core file per name, %s is also in %s' % (p, c['name'], cores[c['name']][0]))
        cores[c['name']] = (p, c)
        for fs_name in c.get('filesets') or {}:
            for name, _, _ in fileset_files(c, fs_name, p):
                if not os.path.isfile(os.path.join(os.path.dirname(p), name)):
                    fail('%s: fileset %s names %s, expected the file %s, it does not exist'
                         % (p, fs_name, name, os.path.join(os.path.dirname(p), name)))
    rc, out = run(fsoc + ['core', 'list'], os.path.join(log, 'core_list.log'), env)
    listed = set(re.findall(r'^(\S+)[ \t]*:', out, re.M))   # [ \t]: a name may start with ':'
    if rc:
        fail('fusesoc core list: expected exit 0, got %d:\n%s' % (rc, tail(out)))
    for name, (p, _) in sorted(cores.items()):
        if name not in listed:
            warn = [ln for ln in out.splitlines() if os.path.basename(p) in ln]
            fail('%s: expected FuseSoC to load core %s, it did not%s' % (p, name, (':\n' + tail('\n'.join(warn))) if warn else ''))
    print('fusesoc-check: %d core files, every file they name exists, all loaded by FuseSoC' % len(cores))

    # 3. lint targets, 4. C cores
    n_lint = n_c = 0
    for name, (p, c) in sorted(cores.items()):
        targets = c.get('targets') or {}
        flows = [t for t, v in targets.items() if isinstance(v, dict) and v.get('flow') == 'lint']
        hdl = [n for fs_name in c.get('filesets') or {} for n, a, ft in fileset_files(c, fs_name, p)
               if ft.startswith('verilogSource') and not a.get('is_include_file')]
        if hdl and not flows:
            fail('%s: expected a lint target (flow: lint) in a core of Verilog sources, got none' % p)
        for t, v in targets.items():
            if isinstance(v, dict) and 'default_tool' in v:
                fail('%s: target %s: expected the flow: form, got default_tool: (deprecated)' % (p, t))
        for t in flows:
            lg = os.path.join(log, '%s.%s.log' % (name.replace(':', '_'), t))
            rc, out = run(fsoc + ['run', '--target', t, name], lg, env)
            deprecated = [ln for ln in out.splitlines() if 'deprecat' in ln.lower()]
            if deprecated and not rc:
                fail('%s: expected target %s of %s to run without a deprecation warning, got:\n%s'
                     % (p, t, name, tail('\n'.join(deprecated))))
            if rc:
                fail('%s: expected target %s of %s to pass, got exit %d (log %s):\n%s' % (p, t, name, rc, lg, tail(out)))
            print('fusesoc-check: lint ok  %s (target %s)' % (name, t))
            n_lint += 1
        cfiles = []
        for fs_name in (targets.get('default') or {}).get('filesets') or []:
            if '?' in fs_name:   # a conditional fileset ("flag? (name)"): not part of a plain build
                continue
            cfiles += [(n, a) for n, a, ft in fileset_files(c, fs_name, p) if ft.startswith('cSource')]
        if cfiles:
            d = os.path.dirname(p)
            incs = sorted({'-I' + os.path.join(d, os.path.dirname(n)) for n, a in cfiles if a.get('is_include_file')})
            srcs = [os.path.join(d, n) for n, a in cfiles if not a.get('is_include_file')]
            cc = os.environ.get('CC', 'gcc')
            for s in srcs:
                lg = os.path.join(log, '%s.%s.cc.log' % (name.replace(':', '_'), os.path.basename(s)))
                rc, out = run([cc] + C_FLAGS + incs + ['-c', '-o', os.devnull, s], lg, env)
                if rc:
                    fail('%s: expected %s to compile with the core\'s include files (%s), got exit %d:\n%s'
                         % (p, s, ' '.join(incs), rc, tail(out)))
            print('fusesoc-check: C ok     %s (%d sources, include path from the core)' % (name, len(srcs)))
            n_c += 1

    # 5. simulation
    for name in args.sim:
        if name not in cores:
            fail('expected a core %s for the simulation, got none in %s' % (name, root))
        lg = os.path.join(log, '%s.sim.log' % name.replace(':', '_'))
        rc, out = run(fsoc + ['run', '--target', 'sim', name], lg, env)
        deprecated = [ln for ln in out.splitlines() if 'deprecat' in ln.lower()]
        if deprecated:
            fail('%s: expected target sim of %s to run without a deprecation warning, got:\n%s'
                 % (cores[name][0], name, tail('\n'.join(deprecated))))
        passed = [ln for ln in out.splitlines() if ln.startswith('PASS')]
        failed = [ln for ln in out.splitlines() if ln.startswith('FAIL')]
        if rc or failed or not passed:
            fail('%s: expected target sim of %s to print PASS and no FAIL, got exit %d, %d FAIL lines (log %s):\n%s'
                 % (cores[name][0], name, rc, len(failed), lg, tail('\n'.join(failed) if failed else out)))
        print('fusesoc-check: sim ok   %s: %s' % (name, passed[-1]))
    print('fusesoc-check: %d cores, %d lint targets, %d C cores, %d simulations, ok' % (len(cores), n_lint, n_c, len(args.sim)))


if __name__ == '__main__':
    main()
