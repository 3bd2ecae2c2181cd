"""Tests of timeline.svg (compiler/albatross_schedule/picture.py) with schedule
modes: a channel has one colour in every mode's lane group, and a mode keeps
an empty lane for each channel of another mode that it does not carry.  The
negative: the groups drawn each with its own colours (a channel's colour
then follows its place in the mode's list) must be caught by the same check.

    python3 -m unittest discover -s compiler/tests -p test_picture.py -v
"""

import os
import re
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import albatross_schedule as S  # noqa: E402
from albatross_schedule.picture import render_svg  # noqa: E402
from test_modes import TWO_MODES, system_of  # noqa: E402

# One slot box: <g><rect .../>...<rect ... stroke="#colour" .../>...<title>NAME entry slot ...</title></g>
SLOT = re.compile(r'<g>((?:(?!</g>).)*?stroke="(#[0-9a-f]{6})"(?:(?!</g>).)*?)<title>([^<]+?) entry slot', re.S)


def slot_colours(svg: str) -> dict:
    """{channel: set of the colours its slot boxes are drawn in}."""
    out = {}
    for m in SLOT.finditer(svg):
        out.setdefault(m.group(3), set()).add(m.group(2))
    return out


def colour_problems(svg: str) -> list:
    return [f"{name} is drawn in {len(cols)} colours ({', '.join(sorted(cols))}), expected one in every mode"
            for name, cols in sorted(slot_colours(svg).items()) if len(cols) != 1]


class ModesPictureTests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.system, cls.plan, cls.rom, cls.rep = S.compile_system(system_of(TWO_MODES))
        cls.svg = S.generate(cls.system, cls.plan, cls.rom, cls.rep)["timeline.svg"]

    def test_one_colour_per_channel(self):
        colours = slot_colours(self.svg)
        for name in ("Position", "MotorCmd", "GlobalTime", "RadarMap", "Status"):
            self.assertIn(name, colours, f"expected slot boxes of {name} in the picture")
        self.assertEqual(colour_problems(self.svg), [])
        # and two channels never share a colour
        firsts = [next(iter(c)) for c in colours.values()]
        self.assertEqual(len(firsts), len(set(firsts)), f"expected a colour per channel, got {colours}")

    def test_absent_channels_keep_a_lane(self):
        dock = self.svg[self.svg.index("mode dock"):]
        for name in ("RadarMap", "Status"):
            lane = re.search(rf">{name}</text>(?:(?!</svg>|<g>).)*?not carried in this mode", dock, re.S)
            self.assertTrue(lane, f"expected an empty lane for {name} in dock ('not carried in this mode'), "
                                  "found none")
        self.assertNotIn("not carried in this mode", self.svg[:self.svg.index("mode dock")],
                         "cruise carries every channel: expected no empty lane there")

    def test_each_group_coloured_alone_is_caught(self):
        # the negative: every mode drawn with its own default colours
        groups = [render_svg(s, p, r, f"mode {m.name} ") for m, s, p, r in self.system.mode_plans]
        problems = colour_problems("".join(groups))
        self.assertTrue(any(p.startswith("Position is drawn in 2 colours") for p in problems),
                        f"expected Position caught in two colours, got {problems}")


if __name__ == "__main__":
    unittest.main()
