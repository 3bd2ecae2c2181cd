"""Tests of the schedule compiler (the package compiler/albatross_schedule/).

    python3 -m unittest discover -s compiler/tests -v      (from the repository root)

The checkers of oracle.py re-implement the ROM contract (docs/controller.md) independently of the
compiler (ROM format, checksum, validation rules, memory map) and are
themselves checked on deliberately corrupted ROMs and plans.  The
end-to-end test runs the generated C (board headers, set-up functions, RAM
images) with the real driver on the host, and moves the values between the
boards' RAM images with a small Python model of the controller executing
rom.hex.  Outputs go to build/compiler-tests/ only.
"""

import glob
import json
import os
import re
import shutil
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from oracle import (  # noqa: E402  (the oracles, the controller model, the paths)
    BAD, CFLAGS, CINC, COMPILER_DIR, ControllerModel, EXAMPLES, EXAMPLE_FILES,
    OUT, REPO, RamImage, TOOL, TOOL_ENV, check_word, compile_example,
    decode, harness_source, layout_problems, pattern, plan_problems, read_hex, rom_problems)
import albatross_schedule as S  # noqa: E402


# ---------------------------------------------------------------------------

class ExampleTests(unittest.TestCase):
    """The two MOBOT-III examples: outputs, ROM, plan, layout, headers."""

    @classmethod
    def setUpClass(cls):
        cls.out = {}
        cls.rep = {}
        for name in EXAMPLE_FILES:
            out = os.path.join(OUT, name[:-5])
            cls.rep[name] = compile_example(name, out)
            cls.out[name] = out

    def each(self):
        for name in EXAMPLE_FILES:
            with self.subTest(example=name):
                yield name, self.out[name], self.rep[name]

    def test_outputs_exist(self):
        for name, out, rep in self.each():
            files = ["rom.hex", "report.json", "report.txt", "timeline.svg"]
            for b in rep["boards"]:
                files += [f"{b['name']}.h", f"{b['name']}.c", f"{b['name']}_ram.hex"]
            for f in files:
                self.assertTrue(os.path.getsize(os.path.join(out, f)) > 0, f)
            with open(os.path.join(out, "timeline.svg")) as f:
                svg = f.read()
            self.assertTrue(svg.startswith("<svg") and svg.rstrip().endswith("</svg>"))
            for c in rep["channels"]:
                self.assertIn(c["name"], svg)

    def test_rom_valid(self):
        for name, out, rep in self.each():
            words = read_hex(os.path.join(out, "rom.hex"))
            ram_words = [b["ram_bytes"] // 4 for b in rep["boards"]]
            self.assertEqual(rom_problems(words, rep["bus"]["n_chan"], ram_words), [])
            hdr, entries = decode(words)
            self.assertEqual(hdr["cycle"], rep["cycle"]["clocks"])
            self.assertEqual(hdr["ne"], rep["entries"])
            self.assertEqual(hdr["flags"], 1 if rep["mode"] == "position-synchronised" else 0)
            # the compiler's own verifier agrees
            self.assertEqual(S.verify_rom(words, rep["bus"]["n_chan"], len(rep["boards"]), ram_words)[0], [])

    def test_rom_matches_report(self):
        kinds = {"copy": 1, "time": 2, "status": 3}
        for name, out, rep in self.each():
            _, entries = decode(read_hex(os.path.join(out, "rom.hex")))
            by_id = {c["id"]: c for c in rep["channels"]}
            seen = {i: [] for i in by_id}
            for e in entries:
                c = by_id[e["id"]]
                seen[e["id"]].append((e["start"], e["length"]))
                self.assertEqual(e["kind"], kinds[c["kind"]])
                self.assertEqual(e["w"], c["words"])
                self.assertEqual(e["nd"], len(c["consumers"]))
                self.assertEqual(e["length"], c["slot_length"])
                if c["producer"]:
                    self.assertEqual((e["src_board"], 4 * e["src_word"]),
                                     (c["producer"]["board_index"], c["producer"]["base"]))
                self.assertEqual([(b, 4 * w) for b, w in e["dst"]],
                                 [(d["board_index"], d["base"]) for d in c["consumers"]])
            for i, c in by_id.items():
                self.assertEqual(seen[i], [(s["start"], s["length"]) for s in c["slots"]])

    def test_plan(self):
        for name, out, rep in self.each():
            self.assertEqual(plan_problems(rep), [])
            self.assertEqual(rep["cycle"]["clocks"], min(c["max_period"]["clocks"] for c in rep["channels"]))
            self.assertLessEqual(rep["entries"], 255)
            self.assertTrue(0 < rep["bus_utilisation"] <= rep["controller_busy"] <= rep["schedule_fill"] <= 1)
            # spare capacity is used: no channel's slot would still fit
            cap = rep["capacity_clocks"]
            used = sum(c["slot_length"] * c["redundancy"] for c in rep["channels"])
            self.assertLessEqual(used, cap)
            room = [c for c in rep["channels"] if used + c["slot_length"] <= cap and
                    c["name"] != "Status" and       # Status is capped by max_slots = 2
                    not c["spaced_for_termination"]]  # capped for its consumers' Import bound
            self.assertEqual(room, [], "spare capacity left unused")
            if rep["mode"] == "position-synchronised":
                last = max(s["start"] + s["length"] for c in rep["channels"] for s in c["slots"])
                self.assertLessEqual(last + rep["bus"]["poll_cycles"], rep["cycle"]["clocks"])
                first = rep["entries_list"][0]
                self.assertTrue(first["sync"] and first["start"] == 0 and first["channel"] == "Position")

    def test_slot_lengths_and_bounds(self):
        """Recompute A, L, the latency and age bounds from the formulas of docs/compiler.md "Plan"."""
        for name, out, rep in self.each():
            bus = rep["bus"]
            cycle = rep["cycle"]["clocks"]
            for c in rep["channels"]:
                # the slot's retry budget: [bus] retries_per_slot, or sized from [faults] (test_faults.py)
                if rep["fault_hypothesis"] is None:
                    self.assertEqual(c["retries_per_slot"], bus["retries_per_slot"], c["name"])
                budget = c["retries_per_slot"] * (bus["timeout_cycles"] + bus["access_cycles"] + 1)
                W, ND = c["words"], len(c["consumers"])
                # per destination W + 3 accesses (three-buffer) or W + 4 (four-slot: the Slot store)
                per = W + (4 if c["channel_kind"] == "four_slot" else 3)
                A = (3 + W + ND * per) if c["kind"] == "copy" else ND * per
                self.assertEqual(c["accesses"], A, c["name"])
                pub = bus["fetch_cycles"] + bus["first_access_extra"] + bus["access_cycles"] * A
                self.assertEqual(c["slot_length"], pub + budget + bus["guard_cycles"], c["name"])
                starts = sorted(s["start"] for s in c["slots"])
                nxt = starts[1:] + [starts[0] + cycle]
                sample = bus["fetch_cycles"] + bus["access_cycles"]
                if c["kind"] == "copy":
                    # E extra Import passes (a source value published during the
                    # Import): the producer's Actual stores are >= 2 (W + 2) clocks
                    # apart, a pass is 2 accesses; E = max(1, m // (m - 2 access)).
                    m, p2 = 2 * (W + 2), 2 * bus["access_cycles"]
                    extra = max(1, m // (m - p2)) * p2
                    ff = max(n + pub + extra - (s + sample) for s, n in zip(starts, nxt))
                    self.assertEqual(c["latency"]["fault_free"]["clocks"], ff, c["name"])
                    self.assertEqual(c["latency"]["with_retries"]["clocks"], ff + budget, c["name"])
                    self.assertIsNone(c["age_bound"])
                else:
                    per = c["guaranteed_period"]["clocks"]
                    self.assertEqual(c["age_bound"]["fault_free"]["clocks"], per + pub)
                    self.assertEqual(c["age_bound"]["with_retries"]["clocks"], per + pub + budget)
                    self.assertIsNone(c["latency"])
                us = c["guaranteed_period"]["clocks"] * 1e6 / rep["clock_hz"]
                self.assertAlmostEqual(c["guaranteed_period"]["us"], us, places=3)

    def test_example_plan_is_spread(self):
        """Redundancy: every channel of mobot3 gets several slots, evenly:
        no gap of a channel is larger than twice its ideal C / n."""
        rep = self.rep["mobot3.toml"]
        cycle = rep["cycle"]["clocks"]
        for c in rep["channels"]:
            n = c["redundancy"]
            self.assertGreaterEqual(n, 2, c["name"])
            self.assertLessEqual(c["guaranteed_period"]["clocks"], 2 * cycle / n, c["name"])
        by = {c["name"]: c["redundancy"] for c in rep["channels"]}
        self.assertEqual(by["Status"], 2)                       # max_slots
        self.assertGreaterEqual(by["Position"], by["RadarMap"])  # priority

    def test_ram_layout_and_images(self):
        for name, out, rep in self.each():
            self.assertEqual(layout_problems(rep), [])
            for b in rep["boards"]:
                words = read_hex(os.path.join(out, f"{b['name']}_ram.hex"))
                self.assertEqual(len(words), b["ram_bytes"] // 4)
                ctl = {i["base"] // 4 for i in b["instances"]}
                for k, w in enumerate(words):
                    self.assertEqual(w, 0x00000101 if k in ctl else 0, f"{b['name']} word {k}")
            # every instance the ROM names is in a board's layout
            inst = {(b["index"], i["base"], i["channel"]) for b in rep["boards"] for i in b["instances"]}
            for c in rep["channels"]:
                if c["producer"]:
                    self.assertIn((c["producer"]["board_index"], c["producer"]["base"], c["name"]), inst)
                for d in c["consumers"]:
                    self.assertIn((d["board_index"], d["base"], c["name"]), inst)

    def test_headers(self):
        for name, out, rep in self.each():
            chans = {c["name"]: c for c in rep["channels"]}
            for b in rep["boards"]:
                with open(os.path.join(out, b["name"] + ".h")) as f:
                    h = f.read()
                self.assertIn('#include "albatross.h"', h)
                self.assertIn('#include "mobot3_types.h"', h)
                self.assertIn(f"int alb_{b['name']}_attach_all(uintptr_t dpram_base);", h)
                self.assertIn(f"int alb_{b['name']}_init_all(uintptr_t dpram_base);", h)
                macros = dict(re.findall(r"#define (ALB_\w+)\s+(\w+)", h))
                for i in b["instances"]:
                    c = chans[i["channel"]]
                    N = c["name"].upper()
                    self.assertEqual(int(macros[f"ALB_{N}_BASE"].rstrip("u"), 16), i["base"])
                    size = c["size"] if i["role"] == "source" else 4 * c["words"] + 4
                    self.assertEqual(int(macros[f"ALB_{N}_SIZE"].rstrip("u")), size)
                    nbuf = 4 if c["channel_kind"] == "four_slot" else 3   # 4 + 4*S or 4 + 3*S bytes
                    self.assertEqual(i["bytes"], 4 + nbuf * ((size + 3) & ~3))
                    self.assertEqual(int(macros[f"ALB_{N}_WORDS"].rstrip("u")), c["words"])
                    if i["role"] == "source":
                        self.assertIn(f"ALB_CHANNEL({c['name']}, {c['type']})", h)
                    else:
                        self.assertIn(f"typedef struct {{ {c['type']} value; uint32_t taken_at; }} "
                                      f"{c['name']}_msg;", h)
                        self.assertIn(f"ALB_CHANNEL({c['name']}, {c['name']}_msg)", h)
                        self.assertIn(f"ALB_SAMPLING({c['name']}, {c['name']}_msg)", h)
                        # the sampling read's refresh bound: latency + producer period
                        # for a copy, the age bound for time and status
                        bound = (f"((producer_period_clocks) + ALB_{N}_LATENCY_CLOCKS)"
                                 if c["kind"] == "copy" else f"(ALB_{N}_AGE_CLOCKS)")
                        self.assertIn(f"#define ALB_{N}_MAX_AGE_CLOCKS(producer_period_clocks) {bound}", h)
                for c in rep["channels"]:
                    self.assertEqual(int(macros[f"ALB_{c['name'].upper()}_ID"].rstrip("u")), c["id"])

    def test_deterministic(self):
        out2 = os.path.join(OUT, "mobot3-again")
        compile_example("mobot3.toml", out2)
        for f in sorted(os.listdir(out2)):
            with open(os.path.join(out2, f)) as a, open(os.path.join(self.out["mobot3.toml"], f)) as b:
                self.assertEqual(a.read(), b.read(), f)


@unittest.skipUnless(shutil.which("gcc"), "gcc not found: the generated C is not compiled (apt-get install gcc)")
class GeneratedCTests(unittest.TestCase):
    """gcc -std=c99 -Wall -Wextra -Werror -pedantic on every generated file,
    and an end-to-end run of the generated C with the real driver."""

    @classmethod
    def setUpClass(cls):
        cls.out = {}
        cls.rep = {}
        for name in EXAMPLE_FILES:
            out = os.path.join(OUT, "c-" + name[:-5])
            cls.rep[name] = compile_example(name, out)
            cls.out[name] = out

    def gcc(self, args):
        r = subprocess.run(["gcc"] + CFLAGS + CINC + args, capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, " ".join(args) + "\n" + r.stderr)

    def test_compile_board_files(self):
        for name in EXAMPLE_FILES:
            out, rep = self.out[name], self.rep[name]
            for b in rep["boards"]:
                with self.subTest(example=name, board=b["name"]):
                    self.gcc(["-I" + out, "-I" + EXAMPLES, "-c", os.path.join(out, b["name"] + ".c"),
                              "-o", os.path.join(out, b["name"] + ".o")])
                    # the header alone is a complete translation unit too
                    self.gcc(["-I" + out, "-I" + EXAMPLES, "-x", "c", "-c", os.path.join(out, b["name"] + ".h"),
                              "-o", os.path.join(out, b["name"] + "_h.o")])

    def test_static_assertion_catches_a_wrong_type(self):
        """Negative test of the generated check: a type of the wrong size
        must not compile."""
        out = self.out["mobot3.toml"]
        bad = os.path.join(out, "wrong_types")
        os.makedirs(bad, exist_ok=True)
        with open(os.path.join(EXAMPLES, "mobot3_types.h")) as f:
            text = f.read()
        with open(os.path.join(bad, "mobot3_types.h"), "w") as f:
            f.write(text.replace("int32_t heading_urad;", "int32_t heading_urad;\n    int32_t extra;"))
        r = subprocess.run(["gcc"] + CFLAGS + CINC + ["-I" + out, "-I" + bad, "-c",
                           os.path.join(out, "navigation.c"), "-o", os.path.join(bad, "nav.o")],
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0, "a 16-byte RobotPosition compiled against size = 12")
        self.assertIn("alb_check_Position_size", r.stderr)

    def build_harness(self, name, board):
        out, rep = self.out[name], self.rep[name]
        src = os.path.join(out, f"harness_{board}.c")
        with open(src, "w") as f:
            f.write(harness_source(board, rep))
        exe = os.path.join(out, f"harness_{board}")
        self.gcc(["-O1", "-I" + out, "-I" + EXAMPLES, src, os.path.join(out, board + ".c"),
                  os.path.join(REPO, "c-driver", "albatross.c"), "-o", exe])
        return exe

    def run_harness(self, exe, ram_in, ram_out, mode, *ops):
        r = subprocess.run([exe, ram_in, ram_out, mode] + list(ops), capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        return r.stdout.splitlines()

    def test_end_to_end(self):
        """Producers export through the generated interface into their RAM
        images; the controller model executes rom.hex; every consumer then
        imports exactly the exported bytes with the model's taken_at, once."""
        for name in EXAMPLE_FILES:
            with self.subTest(example=name):
                self.end_to_end(name)

    def end_to_end(self, name):
        out, rep = self.out[name], self.rep[name]
        boards = [b["name"] for b in rep["boards"]]
        exe = {b: self.build_harness(name, b) for b in boards}
        state = os.path.join(out, "e2e")
        os.makedirs(state, exist_ok=True)
        ram = {b: os.path.join(state, f"{b}.hex") for b in boards}
        chans = {c["name"]: c for c in rep["channels"]}
        seeds = {}
        # producers publish (RAM images loaded: attach)
        for bi, b in enumerate(boards):
            ops = []
            for i in rep["boards"][bi]["instances"]:
                if i["role"] == "source":
                    seeds[i["channel"]] = len(seeds) + 3
                    ops.append(f"export:{i['channel']}:{seeds[i['channel']]}")
            lines = self.run_harness(exe[b], os.path.join(out, f"{b}_ram.hex"), ram[b], "attach", *ops)
            self.assertEqual(lines[0], "setup 0")
            self.assertEqual(lines[1:], ["export 0"] * len(ops))
        # the controller runs two cycles
        model = ControllerModel(read_hex(os.path.join(out, "rom.hex")),
                                [RamImage(read_hex(ram[b])) for b in boards], rep["bus"]["n_chan"])
        model.run_cycle()
        taken = {i: st["taken_at"] for i, st in model.state.items()}
        model.run_cycle()
        for bi, b in enumerate(boards):
            with open(ram[b], "w") as f:
                f.write("".join(f"{w:08x}\n" for w in model.rams[bi].words()))
        # consumers read (attach: a restart with the controller running)
        for bi, b in enumerate(boards):
            ops = [f"import:{i['channel']}" for i in rep["boards"][bi]["instances"] if i["role"] == "destination"]
            lines = self.run_harness(exe[b], ram[b], ram[b] + ".after", "attach", *ops)
            self.assertEqual(lines[0], "setup 0")
            for k, op in enumerate(ops):
                c = chans[op.split(":")[1]]
                head, r, data = lines[1 + 3 * k].rsplit(" ", 2)
                taken_at = int(lines[2 + 3 * k].split()[1])
                self.assertEqual((head, r), (f"import {c['name']}", "1"), f"{b}: {c['name']} not New")
                self.assertEqual(lines[3 + 3 * k], "typed 0", f"{b}: {c['name']} New twice")
                value = bytes.fromhex(data)
                if c["kind"] == "copy":
                    self.assertEqual(value[:c["size"]], pattern(seeds[c["name"]], c["size"]), f"{b}: {c['name']}")
                    self.assertEqual(taken_at, taken[c["id"]], f"{b}: {c['name']} taken_at")
                elif c["kind"] == "time":
                    self.assertEqual(int.from_bytes(value, "little"), taken_at)
                    self.assertGreaterEqual(taken_at, rep["cycle"]["clocks"])   # second cycle
                else:
                    self.assertEqual(int.from_bytes(value[:4], "little") & 0xFFFF, 1)   # cycles
        # cold start on an all-zero RAM: init_all sets the CPU's own bytes;
        # before the controller's first transfer every Make<Name>Available
        # returns ALB_OK (ReadLocked 0: the controller has not started) and
        # every Import ALB_OLD, reading nothing (Actual 0: nothing published)
        zero = os.path.join(state, "zero.hex")
        for bi, b in enumerate(boards):
            with open(zero, "w") as f:
                f.write("00000000\n" * (rep["boards"][bi]["ram_bytes"] // 4))
            insts = rep["boards"][bi]["instances"]
            ops = [f"export:{i['channel']}:7" for i in insts if i["role"] == "source"]
            imps = [f"import:{i['channel']}" for i in insts if i["role"] == "destination"]
            lines = self.run_harness(exe[b], zero, zero + ".out", "init", *ops, *imps)
            self.assertEqual(lines[0], "setup 0")
            self.assertEqual(lines[1:1 + len(ops)], ["export 0"] * len(ops),
                             f"{b}: Make<Name>Available on a zeroed RAM after init_all")
            for k, op in enumerate(imps):
                head, r, data = lines[1 + len(ops) + 3 * k].rsplit(" ", 2)
                self.assertEqual((head, r), (f"import {op.split(':')[1]}", "0"),
                                 f"{b}: Import before anything was published")
                self.assertEqual(set(data), {"e"}, f"{b}: *dst changed though nothing was published")
            lines = self.run_harness(exe[b], zero, zero + ".out", "init")
            self.assertEqual(lines[0], "setup 0")
            words = read_hex(zero + ".out")
            for i in rep["boards"][bi]["instances"]:
                w = words[i["base"] // 4]
                self.assertEqual(w, 0x001 if i["role"] == "source" else 0x100, f"{b}: {i['channel']}")


class BadDescriptionTests(unittest.TestCase):
    """compiler/tests/bad/*.toml: exit status 2, the expected message, no
    traceback, nothing written.  The command's own main() runs each one in
    this process (a Python start-up per file cost 10 s); test_missing_file and
    PackageTests run the installed command itself."""

    def test_bad_descriptions(self):
        import contextlib
        import io
        from albatross_schedule import cli

        files = sorted(f for f in os.listdir(BAD) if f.endswith(".toml"))
        self.assertGreater(len(files), 40)
        for f in files:
            with self.subTest(file=f):
                path = os.path.join(BAD, f)
                with open(path, "rb") as fh:    # bom.toml, not_utf8.toml: the bytes are the fault
                    head = fh.read().removeprefix(b"\xef\xbb\xbf").decode("utf-8", errors="replace")
                expects = re.findall(r"\A(?:# expect: .+\n)+", head)
                self.assertTrue(expects, f"{f}: the first line must be '# expect: <message>' (one line a fault)")
                out = os.path.join(OUT, "bad", f[:-5])
                shutil.rmtree(out, ignore_errors=True)
                stdout, stderr = io.StringIO(), io.StringIO()
                with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
                    try:
                        rc = cli.main([path, "--out", out])
                    except SystemExit as e:     # argparse: a usage error
                        rc = e.code
                err = stderr.getvalue()
                self.assertEqual(rc, 2, f"{f}: exit {rc}\n{stdout.getvalue()}{err}")
                for expect in re.findall(r"# expect: (.+)", expects[0]):
                    self.assertIn(expect, err)
                self.assertNotIn("Traceback", err)
                self.assertTrue(err.startswith("error: " + path), err)
                self.assertFalse(os.path.exists(out), f"{f}: outputs written for a bad description")

    def test_missing_file(self):
        r = subprocess.run(TOOL + [os.path.join(BAD, "no-such.toml"), "--out",
                            os.path.join(OUT, "none")], capture_output=True, text=True, env=TOOL_ENV)
        self.assertEqual(r.returncode, 2)
        self.assertIn("cannot read the description", r.stderr)


class PackageTests(unittest.TestCase):
    """The compiler is a small package, installed by make deps as the albatross-schedule command."""

    def test_modules_are_small(self):
        pkg = os.path.join(COMPILER_DIR, "albatross_schedule")
        for f in sorted(os.listdir(pkg)):
            if f.endswith(".py"):
                with open(os.path.join(pkg, f)) as fh:
                    n = sum(1 for _ in fh)
                self.assertLessEqual(n, 500, f"albatross_schedule/{f} has {n} lines (at most about 500)")

    def test_command_line(self):
        r = subprocess.run(TOOL + ["--help"], capture_output=True, text=True, env=TOOL_ENV)
        self.assertEqual(r.returncode, 0, r.stderr)
        for flag in ("-o DIR, --out DIR", "--quiet", "--no-redundancy", "description"):
            self.assertIn(flag, r.stdout)
        r = subprocess.run(TOOL, capture_output=True, text=True, env=TOOL_ENV)
        self.assertEqual(r.returncode, 2)
        self.assertIn("usage: albatross-schedule", r.stderr)

    def test_installed_from_the_checkout(self):
        """make deps installs the package editable: the command runs this checkout's
        modules (an edit takes effect at once) and reads this checkout's contract."""
        r = subprocess.run([sys.executable, "-c", "import albatross_schedule as s, albatross_schedule.contract as c; "
                            "print(s.__file__); print(c.DEFAULT_PATH)"], capture_output=True, text=True,
                           cwd="/", env=TOOL_ENV)
        self.assertEqual(r.returncode, 0, r.stderr)
        mod, contract = r.stdout.split()
        self.assertEqual(os.path.realpath(mod), os.path.realpath(os.path.join(COMPILER_DIR, "albatross_schedule",
                                                                              "__init__.py")))
        self.assertEqual(contract, os.path.realpath(os.path.join(REPO, "rtl", "albatross_contract.toml")))

    def test_output_folder_option(self):
        out = os.path.join(OUT, "short-o")
        shutil.rmtree(out, ignore_errors=True)
        r = subprocess.run(TOOL + [os.path.join(EXAMPLES, "mobot3.toml"), "-o", out, "-q"], capture_output=True,
                           text=True, env=TOOL_ENV)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.isfile(os.path.join(out, "rom.hex")), f"expected {out}/rom.hex")


def description(channels, boards=("a", "b", "c"), extra_system="", bus=""):
    text = (f'[system]\nname = "gen"\nclock_hz = 50_000_000\nboards = {json.dumps(list(boards))}\n'
            f'{extra_system}\n{bus}\n')
    for c in channels:
        text += "\n[[channel]]\n" + "".join(f"{k} = {json.dumps(v)}\n" for k, v in c.items())
    return text


class PlanTests(unittest.TestCase):
    """The planner through the Python API on generated descriptions."""

    def compile_text(self, text, name="gen.toml"):
        os.makedirs(OUT, exist_ok=True)
        path = os.path.join(OUT, name)
        with open(path, "w") as f:
            f.write(text)
        system = S.load_description(path)
        _, plan, rom, rep = S.compile_system(system)
        return system, plan, rom, rep

    def test_entry_cap(self):
        """Huge spare capacity: redundancy stops at 255 entries, ROM valid."""
        chans = [{"name": f"C{i}", "size": 4, "producer": "a", "consumers": ["b"], "max_period_us": 1000}
                 for i in range(3)]
        system, plan, rom, rep = self.compile_text(description(chans))
        self.assertEqual(len(plan.slots), 255)
        self.assertEqual(rom_problems(rom, 16, [1024] * 3), [])
        self.assertEqual(plan_problems(rep), [])
        self.assertEqual(sorted(c["redundancy"] for c in rep["channels"]), [85, 85, 85])

    def test_too_many_entries(self):
        chans = [{"name": f"C{i}", "size": 4, "producer": "a", "consumers": ["b"], "max_period_us": 10000}
                 for i in range(256)]
        with self.assertRaises(S.ScheduleError) as cm:
            self.compile_text(description(chans, bus="[bus]\nn_chan = 256\n"))
        self.assertIn("256 channels need 256 ROM entries, at most 255", str(cm.exception))

    def test_exactly_full(self):
        """A plan that needs the whole cycle: one slot each, back to back."""
        bus = S.Bus()
        ch = {"name": "X", "size": 8, "producer": "a", "consumers": ["b"], "max_period_us": 1}
        # W = 2, ND = 1: A = 3 + 2 + 5 = 10
        L = bus.fetch_cycles + bus.first_access_extra + 2 * 10 + bus.retry_budget + bus.guard_cycles
        text = description([ch]).replace("50_000_000", str(L * 1_000_000))
        system, plan, rom, rep = self.compile_text(text)
        self.assertEqual([(s.start, s.length) for s in plan.slots], [(0, L)])
        text = description([ch]).replace("50_000_000", str((L - 1) * 1_000_000))
        with self.assertRaises(S.ScheduleError) as cm:
            self.compile_text(text)
        self.assertIn(f"needs {L} clocks per cycle but only {L - 1} are available", str(cm.exception))

    def test_priority_and_max_slots(self):
        chans = [{"name": "Low", "size": 64, "producer": "a", "consumers": ["b"], "max_period_us": 20},
                 {"name": "High", "size": 64, "producer": "a", "consumers": ["b"], "max_period_us": 20,
                  "priority": 5},
                 {"name": "Capped", "size": 4, "producer": "b", "consumers": ["c"], "max_period_us": 20,
                  "max_slots": 1}]
        system, plan, rom, rep = self.compile_text(description(chans))
        n = {c["name"]: c["redundancy"] for c in rep["channels"]}
        self.assertEqual(n["Capped"], 1)
        self.assertGreaterEqual(n["High"], n["Low"])
        self.assertEqual(plan_problems(rep), [])

    def test_sync_plan(self):
        chans = [{"name": "Map", "size": 40, "producer": "a", "consumers": ["b", "c"], "max_period_us": 40},
                 {"name": "Pos", "size": 12, "producer": "b", "consumers": ["a", "c"], "max_period_us": 20,
                  "sync": True},
                 {"name": "T", "kind": "time", "consumers": "all", "max_period_us": 20}]
        system, plan, rom, rep = self.compile_text(description(chans, extra_system='mode = "position-synchronised"'))
        self.assertEqual(rom_problems(rom, 16, [1024] * 3), [])
        self.assertTrue(plan.slots[0].sync and plan.slots[0].start == 0 and plan.slots[0].channel.name == "Pos")
        self.assertEqual(sum(s.sync for s in plan.slots), 1)
        self.assertEqual(rom[0] & 1, 1)
        self.assertLessEqual(plan.slots[-1].start + plan.slots[-1].length + system.bus.poll_cycles, plan.cycle)

    def test_types_and_layout(self):
        chans = [{"name": "Odd", "size": 5, "producer": "a", "consumers": ["b", "c"], "max_period_us": 100},
                 {"name": "St", "kind": "status", "consumers": ["a"], "max_period_us": 100}]
        system, plan, rom, rep = self.compile_text(description(chans, bus="[bus]\nn_chan = 4\n"))
        odd, st = rep["channels"]
        self.assertEqual((odd["words"], odd["type"]), (2, "Odd_t"))
        self.assertEqual((st["words"], st["size"]), (9, 36))
        self.assertEqual(layout_problems(rep), [])
        self.assertEqual(rom_problems(rom, 4, [1024] * 3), [])
        b = {x["name"]: x for x in rep["boards"]}
        # a: Odd source (4 + 3*8 = 28 bytes) then St destination (4 + 3*40)
        self.assertEqual([(i["base"], i["bytes"]) for i in b["a"]["instances"]], [(0, 28), (28, 124)])


class CheckerNegativeTests(unittest.TestCase):
    """The test's own checkers must report deliberately broken ROMs and plans."""

    @classmethod
    def setUpClass(cls):
        cls.rep = compile_example("mobot3.toml", os.path.join(OUT, "neg-mobot3"))
        cls.rom = read_hex(os.path.join(OUT, "neg-mobot3", "rom.hex"))
        cls.ram_words = [b["ram_bytes"] // 4 for b in cls.rep["boards"]]

    def problems(self, rom):
        return rom_problems(rom, 16, self.ram_words)

    def reseal(self, rom, k):
        rom[3] = check_word(rom)

    def test_flipped_bit_fails_crc(self):
        for word in (1, 4 + 8 * 3 + 1, 4 + 8 * 7 + 4):
            rom = list(self.rom)
            rom[word] ^= 1 << 9
            self.assertTrue(self.problems(rom), f"bit flip in word {word} not caught")
            self.assertTrue(S.verify_rom(rom, 16, 4, self.ram_words)[0])

    def test_overlapping_slot(self):
        rom = list(self.rom)
        rom[4 + 8 * 5 + 1] = rom[4 + 8 * 4 + 1]   # entry 5 starts where entry 4 starts
        self.reseal(rom, 5)
        self.assertIn("entry 5: overlaps or precedes the previous slot", self.problems(rom))
        self.assertTrue(any("before the previous slot" in p for p in S.verify_rom(rom, 16, 4, self.ram_words)[0]))

    def test_slot_after_cycle(self):
        rom = list(self.rom)
        k = self.rep["entries"] - 1
        rom[4 + 8 * k + 2] += 100
        self.reseal(rom, k)
        self.assertIn(f"entry {k}: ends after the cycle", self.problems(rom))

    def test_extent_outside_ram(self):
        rom = list(self.rom)
        rom[4 + 4] = (rom[4 + 4] & 0xFFFF0000) | (2 << 12) | 1020     # destination 0 near the top
        self.reseal(rom, 0)
        self.assertTrue(any("outside the RAM" in p for p in self.problems(rom)))

    def test_period_and_layout_violations(self):
        rep = json.loads(json.dumps(self.rep))
        rep["channels"][1]["slots"] = rep["channels"][1]["slots"][:1]
        self.assertTrue(plan_problems(rep))
        rep = json.loads(json.dumps(self.rep))
        rep["channels"][0]["slots"] = []
        self.assertIn("RadarMap: no slot", plan_problems(rep))
        rep = json.loads(json.dumps(self.rep))
        rep["boards"][2]["instances"][1]["base"] -= 4
        self.assertTrue(any("overlaps" in p for p in layout_problems(rep)))
        self.assertTrue(S.verify_ram_layout([("a", 0, 40), ("b", 36, 8)], 4096))

    def test_model_detects_a_wrong_destination(self):
        """The end-to-end path depends on the ROM: a destination moved by one
        word (CRC resealed) gives the consumer no new value."""
        rom = list(self.rom)
        ch = next(c for c in self.rep["channels"] if c["name"] == "MotorCmd")
        k = ch["slots"][0]["entry"]
        rams = [RamImage([0x101 if w == 0 else 0 for w in range(1024)]) for _ in range(4)]
        src = RamImage([0] * 1024)
        base = ch["producer"]["base"]
        src.wr8(base, 2)                      # a published value in Buffer2
        src.wr8(base + 1, 1)
        rams[ch["producer"]["board_index"]] = src
        rom[4 + 8 * k + 4] += 1               # destination base word + 1
        self.reseal(rom, k)
        model = ControllerModel(rom, rams, 16)
        model.entries = [model.entries[k]]
        model.run_cycle()
        d = ch["consumers"][0]
        self.assertEqual(rams[d["board_index"]].rd8(d["base"]), 1, "value landed at the right place anyway")


if __name__ == "__main__":
    unittest.main()


class CNameTests(unittest.TestCase):
    """The names check (albatross_schedule/cnames.py) knows the driver's identifiers, and
    what it rejects really breaks the generated C (compiler/tests/bad/cname_*.toml and
    board_*.toml give its messages)."""

    def test_driver_identifiers_listed(self):
        from albatross_schedule.cnames import DRIVER_IDENTIFIERS
        found = set()
        for pattern in ("c-driver/*.h", "c-driver/port/*/*.h"):
            for path in glob.glob(os.path.join(REPO, pattern)):
                with open(path) as f:
                    text = f.read()
                text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
                text = re.sub(r"//[^\n]*", "", text)
                # alb_ch_##Name and the like are prefixes of generated names, not identifiers
                found |= set(re.findall(r"\b((?:alb|ALB|ALBATROSS)_\w*[A-Za-z0-9])\b(?!\s*##)", text))
        self.assertGreater(len(found), 40)
        self.assertEqual(sorted(found - DRIVER_IDENTIFIERS), [],
                         "identifiers of the driver headers missing from cnames.DRIVER_IDENTIFIERS")

    @unittest.skipUnless(shutil.which("gcc"), "gcc not found")
    def test_rejected_names_break_c(self):
        """Without the check, a channel uint32 declares uint32_t again and gcc stops: the
        check guards a real fault (the header is generated with the check switched off)."""
        import albatross_schedule.description as D
        desc = os.path.join(BAD, "cname_stdint_type.toml")
        out = os.path.join(OUT, "cname-unchecked")
        shutil.rmtree(out, ignore_errors=True)
        saved = D.check_c_names
        D.check_c_names = lambda *a: None
        try:
            S.compile_file(desc, out)
        finally:
            D.check_c_names = saved
        src = os.path.join(out, "use.c")
        with open(src, "w") as f:
            f.write('#include "a.h"\nint main(void) { return 0; }\n')
        r = subprocess.run(["gcc"] + CFLAGS + CINC + ["-I" + out, "-fsyntax-only", src], capture_output=True,
                           text=True)
        self.assertNotEqual(r.returncode, 0, "expected gcc to reject the header of a channel named uint32")
        self.assertIn("uint32_t", r.stderr)
