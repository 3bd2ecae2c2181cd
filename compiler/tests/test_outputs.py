"""Tests of the output folder (-o DIR, pipeline.write_outputs): every output
is written to a new folder beside the target, which then replaces it whole;
a failed run leaves the earlier outputs as they were and no temporary
files; files of an earlier run that the new one does not write are gone;
files the compiler did not write are kept, or the folder is refused.

    python3 -m unittest discover -s compiler/tests -p test_outputs.py -v
"""

import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from oracle import OUT, TOOL, TOOL_ENV  # noqa: E402
import albatross_schedule as S  # noqa: E402
import albatross_schedule.pipeline as P  # noqa: E402

# Two boards, two small channels: compiled in a fraction of a second.
DESC = """
[system]
name      = "pair"
clock_hz  = 50_000_000
boards    = ["left", "right"]
ram_bytes = 4096

[[channel]]
name          = "Ping"
size          = 4
producer      = "left"
consumers     = ["right"]
max_period_us = {period}

[[channel]]
name          = "Pong"
size          = 8
producer      = "right"
consumers     = ["left"]
max_period_us = 100
"""
MANIFEST = "manifest.txt"


def outputs_of(boards):
    return {"rom.hex", "report.json", "report.txt", "timeline.svg", MANIFEST} | \
        {f"{b}{x}" for b in boards for x in (".h", ".c", "_ram.hex")}


def snapshot(folder):
    """{relative path: bytes} of every file under folder (folders end in /)."""
    out = {}
    for root, dirs, files in os.walk(folder):
        for d in dirs:
            out[os.path.relpath(os.path.join(root, d), folder) + "/"] = None
        for f in files:
            with open(os.path.join(root, f), "rb") as fh:
                out[os.path.relpath(os.path.join(root, f), folder)] = fh.read()
    return out


class OutputFolderTests(unittest.TestCase):
    def setUp(self):
        os.makedirs(OUT, exist_ok=True)
        self.root = tempfile.mkdtemp(prefix="outputs-", dir=OUT)
        self.out = os.path.join(self.root, "out")

    def tearDown(self):
        shutil.rmtree(self.root, ignore_errors=True)

    def desc(self, name="pair.toml", period=50, boards=("left", "right"), where=None):
        text = DESC.format(period=period)
        if boards != ("left", "right"):
            text = text.replace('boards    = ["left", "right"]', f"boards    = {json.dumps(list(boards))}")
            text = text.replace('"right"', json.dumps(boards[1]))
        path = os.path.join(where or self.root, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def run_tool(self, desc, out=None, cwd=None):
        return subprocess.run(TOOL + [desc, "-o", out or self.out, "-q"], capture_output=True, text=True,
                              env=TOOL_ENV, cwd=cwd, timeout=120)

    def no_temporaries(self):
        """Nothing of a run left beside the folder or in it."""
        beside = sorted(n for n in os.listdir(self.root) if n.startswith("out."))
        self.assertEqual(beside, [], f"expected no temporary folder beside {self.out}, found {beside}")
        if os.path.isdir(self.out):
            inside = sorted(n for n in os.listdir(self.out) if ".tmp" in n)
            self.assertEqual(inside, [], f"expected no temporary file in {self.out}, found {inside}")

    def test_first_run_writes_the_outputs_and_a_manifest(self):
        r = self.run_tool(self.desc())
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(set(os.listdir(self.out)), outputs_of(["left", "right"]))
        with open(os.path.join(self.out, MANIFEST)) as f:
            listed = {l.strip() for l in f if l.strip() and not l.startswith("#")}
        self.assertEqual(listed, outputs_of(["left", "right"]) - {MANIFEST},
                         "the manifest lists every output it wrote")
        mode = stat.S_IMODE(os.stat(self.out).st_mode)
        um = os.umask(0)
        os.umask(um)
        self.assertEqual(mode, 0o777 & ~um, f"a new folder's mode: expected {oct(0o777 & ~um)}, got {oct(mode)}")
        self.no_temporaries()
        # rom.hex is the newest output (make's target)
        times = {n: os.stat(os.path.join(self.out, n)).st_mtime_ns for n in os.listdir(self.out)}
        self.assertEqual(max(times.values()), times["rom.hex"])

    def test_unwritable_target_keeps_the_earlier_run(self):
        """A folder where report.json goes, inside an earlier run: the run fails naming
        the file, and the earlier outputs stay as they were, with no temporary file."""
        self.assertEqual(self.run_tool(self.desc(period=50)).returncode, 0)
        os.remove(os.path.join(self.out, "report.json"))
        os.makedirs(os.path.join(self.out, "report.json"))
        with open(os.path.join(self.out, "report.json", "mine.txt"), "w") as f:
            f.write("a file of the user\n")
        before = snapshot(self.out)
        r = self.run_tool(self.desc(period=60))       # another plan: every output would change
        self.assertEqual(r.returncode, 2, f"expected the run to fail, got {r.returncode}: {r.stderr}")
        target = os.path.join(self.out, "report.json")
        self.assertIn(target, r.stderr, f"expected the error to name {target}, got: {r.stderr}")
        self.assertEqual(snapshot(self.out), before, "the earlier outputs changed")
        self.no_temporaries()

    def test_failed_write_keeps_the_earlier_run(self):
        """A write that fails midway (disk full): the earlier outputs as they were,
        no temporary files, the error names the file."""
        P.compile_file(self.desc(period=50), self.out)
        with open(os.path.join(self.out, "notes.txt"), "w") as f:
            f.write("kept\n")
        before = snapshot(self.out)
        real = P._write_file
        written, failed = [], []

        def failing(path, text):
            if len(written) == 3:
                failed.append(os.path.basename(path))
                raise OSError(28, "No space left on device")
            written.append(path)
            real(path, text)

        P._write_file = failing
        try:
            with self.assertRaises(S.ScheduleError) as cm:
                P.compile_file(self.desc(period=60), self.out)
        finally:
            P._write_file = real
        msg = cm.exception.messages[0]
        self.assertEqual(len(failed), 1, "the fourth write did not happen")
        target = os.path.join(self.out, failed[0])
        self.assertTrue(msg.startswith(target + ":"), f"expected the error to name {target}, got: {msg}")
        self.assertIn("No space left on device", msg)
        self.assertEqual(snapshot(self.out), before, "the earlier outputs changed")
        self.no_temporaries()

    def test_renamed_board_leaves_no_stale_files(self):
        self.assertEqual(self.run_tool(self.desc(boards=("left", "right"))).returncode, 0)
        r = self.run_tool(self.desc(boards=("left", "middle")))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(set(os.listdir(self.out)), outputs_of(["left", "middle"]),
                         "expected the outputs of the second run only (no right.h, right.c, right_ram.hex)")
        self.no_temporaries()

    def test_earlier_compiler_run_is_recognised(self):
        """A folder written before the manifest (its report.json names the boards), with
        the leftover of a failed write: replaced, the stale files gone."""
        self.assertEqual(self.run_tool(self.desc(boards=("left", "right"))).returncode, 0)
        os.remove(os.path.join(self.out, MANIFEST))
        with open(os.path.join(self.out, "report.json.tmp"), "w") as f:
            f.write("{")
        r = self.run_tool(self.desc(boards=("left", "middle")))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(set(os.listdir(self.out)), outputs_of(["left", "middle"]))

    def test_files_of_others_in_a_run_folder_are_kept(self):
        """Files the compiler did not write (make's tb_plan.txt, a folder of the user,
        the description itself) stay, unchanged, beside the new outputs."""
        desc = self.desc()
        self.assertEqual(self.run_tool(desc).returncode, 0)
        keep = {"tb_plan.txt": b"plan\n", "mine/deep.txt": b"deep\n"}
        os.makedirs(os.path.join(self.out, "mine"))
        for n, data in keep.items():
            with open(os.path.join(self.out, n), "wb") as f:
                f.write(data)
        inside = self.desc(name="inside.toml", where=self.out, boards=("left", "middle"))
        r = self.run_tool(inside)
        self.assertEqual(r.returncode, 0, r.stderr)
        snap = snapshot(self.out)
        for n, data in keep.items():
            self.assertEqual(snap.get(n), data, f"{n} was not kept as it was")
        self.assertIn("inside.toml", snap, "the description compiled from the folder was not kept")
        self.assertEqual(set(os.listdir(self.out)),
                         outputs_of(["left", "middle"]) | {"tb_plan.txt", "mine", "inside.toml"})
        self.no_temporaries()

    def test_folder_of_others_is_refused(self):
        """A folder that is not empty and not a run of the compiler is never replaced."""
        os.makedirs(os.path.join(self.out, "photos"))
        with open(os.path.join(self.out, "thesis.tex"), "w") as f:
            f.write("\\begin{document}\n")
        before = snapshot(self.out)
        r = self.run_tool(self.desc())
        self.assertEqual(r.returncode, 2, r.stderr)
        for w in (self.out, "thesis.tex", "photos", MANIFEST):
            self.assertIn(w, r.stderr, f"expected the error to name {w}: {r.stderr}")
        self.assertEqual(snapshot(self.out), before)
        self.no_temporaries()

    def test_description_alone_in_a_new_folder(self):
        """make's rule for the robot's modes writes the joined description into the
        output folder first: that folder is accepted, the description kept."""
        os.makedirs(self.out)
        inside = self.desc(name="joined.toml", where=self.out)
        r = self.run_tool(inside)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(set(os.listdir(self.out)), outputs_of(["left", "right"]) | {"joined.toml"})

    def test_output_name_taken_by_a_file_of_others(self):
        """A run folder where a file the compiler did not write has the name of a new
        output: refused, naming the file; nothing changed."""
        self.assertEqual(self.run_tool(self.desc(boards=("left", "right"))).returncode, 0)
        with open(os.path.join(self.out, "middle.h"), "w") as f:
            f.write("/* mine */\n")
        before = snapshot(self.out)
        r = self.run_tool(self.desc(boards=("left", "middle")))
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn(os.path.join(self.out, "middle.h"), r.stderr)
        self.assertEqual(snapshot(self.out), before)
        self.no_temporaries()

    def test_target_that_is_a_file_or_the_current_folder(self):
        with open(self.out, "w") as f:
            f.write("x\n")
        r = self.run_tool(self.desc())
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn(f"{self.out}: not a folder", r.stderr)
        os.remove(self.out)
        os.makedirs(self.out)
        r = self.run_tool(self.desc(), out=".", cwd=self.out)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("the current folder", r.stderr)
        self.assertEqual(os.listdir(self.out), [])

    def test_link_to_the_folder_stays_a_link(self):
        real = os.path.join(self.root, "real")
        os.makedirs(real)
        os.symlink(real, self.out)
        self.assertEqual(self.run_tool(self.desc()).returncode, 0)
        self.assertTrue(os.path.islink(self.out), "the link to the output folder was replaced")
        self.assertIn("rom.hex", os.listdir(real))
        self.assertEqual(sorted(n for n in os.listdir(self.root) if n.startswith("real.")), [])


if __name__ == "__main__":
    unittest.main()
