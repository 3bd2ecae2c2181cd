"""The names of the generated C (albatross_schedule/cnames.py).

    build/venv/bin/python -m unittest compiler/tests/test_names.py -v      (make test-compiler-names)

The names check works on an enumeration, cnames.generated_names(), of every
identifier and macro the generated headers and sources may declare.  These
tests prove

  - that the enumeration is complete: every #define, typedef, function and
    channel macro (ALB_CHANNEL, ALB_SAMPLING, ALB_CHANNEL_DEFINE, expanded by
    their ## patterns read from c-driver/albatross.h) in the generated files
    of every example and every accepted description here is in it, and the
    descriptions exercise every template of it;
  - that the generated C of all of them compiles with gcc -std=c99 -Wall
    -Wextra -Werror -pedantic (one gcc call a description);
  - that a name generated twice is rejected, naming both sources, and that
    without the check the C of such a description does not compile;
  - that the faults of a description are all reported, before any planning.

The bad descriptions themselves (compiler/tests/bad/mode_name*.toml, ...)
and their messages are checked by test_schedule.py.  Outputs go to
build/compiler-tests/names/.
"""

import glob
import os
import re
import shutil
import subprocess
import sys
import tomllib
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from oracle import BAD, CFLAGS, CINC, OUT, REPO  # noqa: E402
import test_four_slot_time  # noqa: E402  (its description)
import test_modes  # noqa: E402  (the robot with two modes)
import albatross_schedule as S  # noqa: E402
import albatross_schedule.description as D  # noqa: E402
from albatross_schedule import cnames  # noqa: E402

NAMES_OUT = os.path.join(OUT, "names")
# Where the descriptions' types headers (types_header) are: sim/mobot3_types.h, soc/firmware/board.h, ...
TYPES_DIRS = [os.path.join(REPO, d) for d in ("sim", "compiler/examples", "soc/firmware")]
HAVE_GCC = shutil.which("gcc") is not None

# A description whose names come close to each other without colliding: a board
# MODE_Z (ALB_MODE_Z_BOARD) beside a mode Z (ALB_MODE_Z), a channel MODE_Y
# (ALB_MODE_Y_ID, ...) beside a mode Y, and a channel of every kind.
EDGE = """
[system]
name = "edge"
clock_hz = 50_000_000
boards = ["a", "b", "MODE_Z"]

[board.b]
core = "picorv32"

[[channel]]
name = "MODE_Y"
size = 6
producer = "a"
consumers = ["b", "MODE_Z"]
max_period_us = 1000

[[channel]]
name = "Word"
type = "uint32_t"
kind = "four_slot"
size = 4
producer = "b"
consumers = ["a"]
max_period_us = 1000

[[channel]]
name = "Stat"
kind = "status"
consumers = ["a"]
max_period_us = 2000

[[channel]]
name = "Clock"
kind = "time"
consumers = ["a", "b"]
max_period_us = 1000

[[channel]]
name = "Running"
kind = "mode"
consumers = ["b"]
max_period_us = 1000

[[channel]]
name = "Request"
kind = "mode_request"
producer = "a"
size = 4
max_period_us = 1000

[[mode]]
name = "Run"

[[mode]]
name = "Y"
channels = ["MODE_Y", "Clock", "Stat", "Word"]
periods = { MODE_Y = 500 }

[[mode]]
name = "Z"
channels = ["MODE_Y", "Word", "Stat", "Clock"]
"""

# The descriptions of the three faults (compiler/tests/bad/), each
# with the macro it would define twice.
DOUBLE_DEFINED = {"mode_names_case.toml": "ALB_MODE_RUN", "mode_name_board_macro.toml": "ALB_MODE_X_BOARD",
                  "mode_name_channel_macro.toml": "ALB_MODE_X_ID"}


def repository_descriptions() -> list:
    """Every description of the repository (the robot's, the compiler's examples, the FPGA's)."""
    out = []
    for pattern in ("sim/*.toml", "compiler/examples/*.toml", "fpga/*.toml"):
        for path in sorted(glob.glob(os.path.join(REPO, pattern))):
            with open(path, encoding="utf-8") as f:
                if re.search(r"(?m)^\[system\]", f.read()):
                    out.append(path)
    return out


def written_descriptions() -> list:
    """The accepted descriptions the tests build (test_modes, test_four_slot_time, EDGE),
    written to build/compiler-tests/names/ next to sim/ (their types header)."""
    texts = {"robot_modes": test_modes.ROBOT_TEXT + test_modes.TWO_MODES,
             "four_slot_time": test_four_slot_time.DESC.replace("{time_extra}", "four_slot = true")
             .replace("{status_extra}", "four_slot = true"),
             "edge": EDGE}
    os.makedirs(NAMES_OUT, exist_ok=True)
    out = []
    for name, text in texts.items():
        path = os.path.join(NAMES_OUT, name + ".toml")
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        out.append(path)
    return out


def driver_macro_patterns() -> dict:
    """{macro: {template}} of the driver's channel macros: each Prefix##Name##Suffix
    of the macro's body (c-driver/albatross.h) as 'Prefix{}Suffix'."""
    with open(os.path.join(REPO, "c-driver", "albatross.h")) as f:
        text = f.read()
    out = {}
    for m in re.finditer(r"(?m)^#define\s+(ALB_\w+)\((\w+)[^)]*\)((?:.*\\\n)*.*)$", text):
        macro, param, body = m.groups()
        found = {f"{a}{{}}{b or ''}" for a, b in re.findall(r"(\w*)##" + param + r"(?:##(\w+))?", body)}
        if found:
            out[macro] = found
    return out


DRIVER_MACROS = driver_macro_patterns()


def declared_names(text: str) -> set:
    """Every file-scope name a generated header or source declares: the macros
    (#define), typedefs, functions, and the names of the driver's channel macros
    it invokes.  Indented lines (function bodies) and comments are skipped."""
    names = set()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    for line in text.splitlines():
        if not line or line[0].isspace() or line[0] in "{}":
            continue
        m = re.match(r"#\s*define\s+(\w+)", line)
        if m:
            names.add(m.group(1))
            continue
        if line.startswith("#"):
            continue
        m = re.match(r"(ALB_\w+)\((\w+)", line)
        if m and m.group(1) in DRIVER_MACROS:
            names |= {t.format(m.group(2)) for t in DRIVER_MACROS[m.group(1)]}
            continue
        if line.startswith("typedef"):
            m = re.match(r"typedef\s+[\w\s*]*?\b(\w+)\s*(\[.*\])?\s*;$", re.sub(r"\{.*\}", "", line))
        else:               # a function's declaration or definition (or anything else at file scope)
            m = re.match(r"[\w\s*]*?\b(\w+)\s*\(", line)
        if m:
            names.add(m.group(1))
        else:
            names.add(line)         # not understood: reported as a name of its own
    return names


def compile_into(path: str, out: str):
    """The description's System (as parsed) and its generated files, written to out."""
    shutil.rmtree(out, ignore_errors=True)
    S.compile_file(path, out)
    return S.load_description(path)


def gcc_all(out: str, include: str):
    """One gcc call: every generated header (alone) and source of a description."""
    files = sorted(glob.glob(os.path.join(out, "*.h")) + glob.glob(os.path.join(out, "*.c")))
    return subprocess.run(["gcc"] + CFLAGS + CINC + ["-I" + out, "-I" + include]
                          + ["-I" + d for d in TYPES_DIRS] + ["-fsyntax-only", "-x", "c"] + files,
                          capture_output=True, text=True)


class GeneratedNamesTests(unittest.TestCase):
    """The enumeration of cnames is complete, and the generated C compiles."""

    @classmethod
    def setUpClass(cls):
        cls.results = {}            # description path -> (System, output folder)
        for path in repository_descriptions() + written_descriptions():
            out = os.path.join(NAMES_OUT, "out-" + os.path.basename(path)[:-5])
            cls.results[path] = (compile_into(path, out), out)

    def test_corpus(self):
        self.assertGreaterEqual(len(self.results), 9, sorted(self.results))

    def test_every_declared_name_is_enumerated(self):
        seen = set()
        for path, (system, out) in self.results.items():
            listed = cnames.system_names(system)
            for f in sorted(os.listdir(out)):
                if f.endswith((".h", ".c")):
                    with self.subTest(description=os.path.basename(path), file=f):
                        with open(os.path.join(out, f)) as fh:
                            declared = declared_names(fh.read())
                        self.assertEqual(sorted(declared - listed), [],
                                         "declared by the generated file but not in cnames.generated_names()")
                        seen |= declared
        # the descriptions exercise every template of the enumeration
        suffixes = {s for s in cnames.CHANNEL_MACROS if any(n.endswith("_" + s) for n in seen)}
        self.assertEqual(sorted(set(cnames.CHANNEL_MACROS) - suffixes), [], "channel macros never generated")
        self.assertEqual(sorted(set(cnames.FIXED_NAMES) - seen), [], "fixed names never generated")
        for prefix in ("alb_ch_", "LookForNew", "Read", "alb_check_"):
            self.assertTrue(any(n.startswith(prefix) for n in seen), prefix)
        self.assertTrue(any(n.startswith("ALB_MODE_") and n != cnames.MODE_TYPE_GUARD for n in seen))

    @unittest.skipUnless(HAVE_GCC, "gcc not found: the generated C is not compiled (apt-get install gcc)")
    def test_generated_c_compiles(self):
        for path, (_, out) in self.results.items():
            with self.subTest(description=os.path.basename(path)):
                r = gcc_all(out, os.path.dirname(path))
                self.assertEqual(r.returncode, 0, f"gcc on the files of {path} ({out}):\n{r.stderr}")

    def test_parser_sees_a_name_without_template(self):
        """Negative test of the completeness check: names a generator would add
        without cnames' templates are found as not enumerated."""
        system, out = self.results[os.path.join(REPO, "sim", "mobot3.toml")]
        with open(os.path.join(out, "navigation.h")) as f:
            text = f.read()
        extra = ("#define ALB_SOMETHING_NEW 1u\ntypedef struct { uint32_t w; } alb_new_t;\n"
                 "typedef char alb_new_check[1];\nint alb_new_function(void);\nALB_CHANNEL(Extra, uint32_t)\n")
        missing = declared_names(text + extra) - cnames.system_names(system)
        self.assertEqual(sorted(missing), sorted(["ALB_SOMETHING_NEW", "alb_new_t", "alb_new_check",
                                                  "alb_new_function", "alb_ch_Extra", "LookForNewExtra",
                                                  "MakeExtraAvailable"]))

    def test_driver_macro_names(self):
        """cnames.DRIVER_MACRO_NAMES are the names the driver's channel macros make
        (ALB_SAMPLING's alb_ch_##Name refers to ALB_CHANNEL's object)."""
        self.assertEqual(sorted(cnames.DRIVER_MACRO_NAMES), sorted(DRIVER_MACROS))
        listed = {t for names in cnames.DRIVER_MACRO_NAMES.values() for t, _ in names}
        self.assertEqual(listed, set().union(*DRIVER_MACROS.values()))

    def test_generator_uses_the_templates(self):
        """A channel macro outside cnames.CHANNEL_MACROS cannot be generated."""
        with self.assertRaises(AssertionError):
            cnames.channel_macro("X", "NOT_LISTED")


class DuplicateNameTests(unittest.TestCase):
    """A name generated twice is rejected with both sources; unchecked, its C breaks."""

    def errors(self, path):
        with self.assertRaises(S.ScheduleError) as cm:
            S.load_description(path)
        return cm.exception.messages

    def test_both_sources_named(self):
        for f, macro in DOUBLE_DEFINED.items():
            with self.subTest(file=f):
                msgs = self.errors(os.path.join(BAD, f))
                hits = [m for m in msgs if macro in m]
                self.assertEqual(len(hits), 1, msgs)
                self.assertRegex(hits[0], r"\.toml:\d+:\d+: mode '\w+', field 'name': its macro " + macro
                                 + r" is also generated for (mode|board|channel) '\w+' \(macro, line \d+\)")

    @unittest.skipUnless(HAVE_GCC, "gcc not found")
    def test_unchecked_names_break_c(self):
        """Without the names check the three descriptions compile into headers that
        define a macro twice, which gcc -Werror rejects: the check guards a real fault."""
        saved = D.check_c_names
        D.check_c_names = lambda *a: None
        try:
            for f, macro in DOUBLE_DEFINED.items():
                with self.subTest(file=f):
                    out = os.path.join(NAMES_OUT, "unchecked-" + f[:-5])
                    shutil.rmtree(out, ignore_errors=True)
                    S.compile_file(os.path.join(BAD, f), out)
                    r = gcc_all(out, BAD)
                    self.assertNotEqual(r.returncode, 0, f"expected gcc to reject the C of {f}")
                    self.assertIn(f'"{macro}" redefined', r.stderr)
        finally:
            D.check_c_names = saved

    def test_enumeration_finds_every_pair(self):
        """generated_names() over the three descriptions holds the colliding macro twice."""
        for f, macro in DOUBLE_DEFINED.items():
            with self.subTest(file=f):
                with open(os.path.join(BAD, f), "rb") as fh:
                    data = tomllib.load(fh)
                saved = D.check_c_names
                D.check_c_names = lambda *a: None
                try:
                    system = S.parse_description(data, f)
                finally:
                    D.check_c_names = saved
                names = cnames.generated_names(system.name, system.boards, system.channels,
                                               [m.name for m in system.modes])
                self.assertEqual(len([n for n, _, _ in names if n == macro]), 2)


class DescriptionFaultsFirstTests(unittest.TestCase):
    """Every fault of the description itself is reported, before any planning."""

    ROBOT = test_modes.ROBOT_TEXT

    def errors_of(self, text):
        try:
            S.compile_system(S.parse_description(tomllib.loads(text), "d.toml", text))
        except S.ScheduleError as e:
            return e.messages
        return []

    def test_names_before_an_unplannable_cycle(self):
        """Modes Run and run beside a channel no cycle can carry: the names fault
        is reported, and the plan is never tried."""
        text = self.ROBOT + test_modes.REQ_CHANNEL + """
[[channel]]
name          = "Huge"
size          = 1000
producer      = "radar"
consumers     = ["motor"]
max_period_us = 10

[[mode]]
name = "Run"

[[mode]]
name = "run"
"""
        msgs = self.errors_of(text)
        self.assertTrue(any("ALB_MODE_RUN" in m for m in msgs), msgs)
        self.assertFalse(any("infeasible" in m for m in msgs), msgs)
        # the same channel alone is a planning fault
        msgs = self.errors_of(text.replace('name = "run"', 'name = "walk"'))
        self.assertTrue(any("infeasible" in m for m in msgs), msgs)

    def test_independent_faults_in_one_run(self):
        text = self.ROBOT.replace("[[channel]]", "[[channel]]\nmax_slots = 18_446_744_073_709_551_616", 1)
        text = text.replace("[board.motor]", "[board.motor]\nimport_t_clocks = 100_000_000_000_000_000_000", 1)
        msgs = self.errors_of(text)
        self.assertEqual(len(msgs), 2, msgs)
        self.assertIn("[board.motor], field 'import_t_clocks': 100000000000000000000 is out of range", msgs[0])
        self.assertIn("field 'max_slots': 18446744073709551616 is out of range", msgs[1])   # in line order

    def test_mode_period_out_of_range(self):
        text = self.ROBOT + test_modes.TWO_MODES.replace("Position = 25", "Position = 100_000_000_000_000_000_000")
        msgs = self.errors_of(text)
        self.assertEqual(len(msgs), 1, msgs)
        self.assertRegex(msgs[0], r"d\.toml:\d+:\d+: mode 'dock', field 'periods': Position: 100000000000000000000 "
                         r"is out of range")

    def test_faulty_channel_still_known_to_modes(self):
        """A channel with a fault of its own is no 'unknown channel' to the modes."""
        text = self.ROBOT.replace('size          = 12', 'size          = 0', 1) + test_modes.TWO_MODES
        msgs = self.errors_of(text)
        self.assertTrue(any("field 'size': 0 is not a positive integer" in m for m in msgs), msgs)
        self.assertFalse(any("no channel" in m for m in msgs), msgs)


if __name__ == "__main__":
    unittest.main()
