#!/usr/bin/env python3
"""Test ROM for tb_sequencer.v in the new format (no per-entry checksum, H3 =
the check word: the CRC of the whole image, H3 included, is 0): three entries (COPY, TIME,
STATUS) in a cycle of 400 clocks.  Usage: make_rom.py OUT.hex [--bad-start0 | --modes | --modes-bad |
--multirate | --multirate-modes]
(--bad-start0: entry 0's start has bit 12 set, above the bench's TIME_BITS = 12:
the entry is invalid and must be skipped every cycle.  --modes: the three
entries are the start-up mode of an image with two modes; a second mode
of two COPY entries (channel ids 3) follows, then the two mode descriptors:
the sequencer must run the three entries only.  --modes-bad: the same with
H2.start_end beyond NE, an invalid header).  --multirate: the image of
tb_sequencer_multirate.v: cluster 8 (256 minor cycles of 400 clocks), entries
of repetitions 1 to 2^8 and several bases, three of them sharing one window
(their due sets disjoint), one with a base not below 2^rep (the controller
reads only base's low rep bits: it runs in the minor cycles n with n mod 2^rep
= base mod 2^rep; verify_rom would refuse the image, the controller does not
check that rule) and one with a rep above the cluster (invalid: never runs,
counted in rom_errors every cycle).
--multirate-modes: the same as mode 0 of an image whose mode 1 has cluster 2
(4 minor cycles of 300 clocks) and two entries sharing a window.  Bit
positions are docs/controller.md's, written here as literals."""
import sys

POLY, SEED = 0x000000AF, 0xFFFFFFFF


def crc(words):
    c = SEED
    for w in words:
        for _ in range(32):
            c = ((c << 1) & 0xFFFFFFFF) ^ (POLY if c >> 31 else 0)
        c ^= w
    return c


def entry(kind, cid, nd, w, start, length, src, dsts, rep=0, base=0):
    e = [(kind << 28) | (cid << 16) | (nd << 12) | w, start, length, src, 0, 0, (rep << 16) | base, 0]
    for i, d in enumerate(dsts):
        e[4 + i // 2] |= d << (16 * (i % 2))
    return e


def multirate(args):
    """(entries, H1, H2) of the --multirate images (E6 = {rep[19:16], base[14:0]}, H2/D2 cluster [23:20])."""
    C, T, S = 1, 2, 3                                   # COPY, TIME, STATUS
    src, d1, d2 = (0 << 12) | 16, (1 << 12) | 16, (2 << 12) | 64
    ents = [entry(C, 0, 1, 4, 10, 100, src, [d1]),                       # every cycle
            entry(T, 1, 1, 1, 120, 60, 0, [d2], rep=1, base=1),          # odd cycles  } one window,
            entry(C, 2, 1, 2, 120, 70, src, [d1], rep=2, base=0),        # 0 mod 4     } due sets
            entry(C, 3, 1, 1, 120, 77, src, [d1], rep=2, base=2),        # 2 mod 4     } disjoint
            entry(S, 2, 1, 9, 200, 80, 0, [d2], rep=3, base=5),          # cycle 5
            entry(C, 0, 1, 1, 290, 40, src, [d1], rep=2, base=5),        # base 5 >= 4: 1 mod 4 (5 mod 4)
            entry(C, 0, 1, 1, 340, 40, src, [d1], rep=9, base=3),        # invalid: rep 9 > cluster 8
            entry(C, 3, 1, 1, 340, 50, src, [d1], rep=8, base=3)]        # cycle 3 of 256, behind the invalid one
    h2 = (8 << 20) | 2                                                   # cluster 8, drop run 2
    if '--multirate-modes' not in args:
        return ents, 400, h2
    n0 = len(ents)
    ents += [entry(C, 3, 1, 1, 20, 60, src, [d1], rep=1, base=0),        # mode 1: even cycles } one
             entry(C, 1, 1, 1, 20, 60, src, [d1], rep=1, base=1),        #   odd cycles        } window
             entry(T, 1, 1, 1, 150, 60, 0, [d2], rep=2, base=3)]         #   3 mod 4
    table = len(ents)
    ents += [[(n0 << 24) | (0 << 16) | 400, (0b10 << 16) | 2, 8 << 20, 0, 0, 0, 0, 0],
             [(table << 24) | (n0 << 16) | 300, (0b01 << 16) | 2, 2 << 20, 0, 0, 0, 0, 0]]
    return ents, 400 | (0b10 << 16), (n0 << 24) | (8 << 20) | (2 << 16) | (table << 8) | 2


ents = [entry(1, 0, 2, 4, 0x100A if '--bad-start0' in sys.argv[2:] else 10, 100, (0 << 12) | 16, [(1 << 12) | 16, (2 << 12) | 16]),
        entry(2, 1, 1, 1, 120, 60, 0, [(3 << 12) | 64]),
        entry(3, 2, 1, 2 * 4 + 1, 200, 150, 0, [(2 << 12) | 128])]
h2 = 0
if '--modes' in sys.argv[2:] or '--modes-bad' in sys.argv[2:]:
    # mode 1: two COPYs of channel 3 in a 300-clock cycle; descriptors D0 = {end, first, cycle}, D1 = {next, K}
    ents += [entry(1, 3, 1, 1, 20, 60, (0 << 12) | 200, [(1 << 12) | 200]),
             entry(1, 3, 1, 1, 150, 60, (0 << 12) | 200, [(1 << 12) | 200])]
    ents += [[(3 << 24) | (0 << 16) | 400, (0b10 << 16) | 2, 0, 0, 0, 0, 0, 0],
             [(5 << 24) | (3 << 16) | 300, (0b01 << 16) | 2, 0, 0, 0, 0, 0, 0]]
    start_end = 8 if '--modes-bad' in sys.argv[2:] else 3         # --modes-bad: beyond NE = 7
    h2 = (start_end << 24) | (2 << 16) | (5 << 8) | 2          # start_end, modes 2, table 5, drop run 2
h1 = 400 | ((0b10 << 16) if h2 else 0)                          # H1.next: mode 0 may switch to mode 1
if '--multirate' in sys.argv[2:] or '--multirate-modes' in sys.argv[2:]:
    ents, h1, h2 = multirate(sys.argv[2:])
rom = [(0xA1BA << 16) | (len(ents) << 8), h1, h2, 0] + sum(ents, [])
# H3: the CRC is linear in it; try each bit's effect and solve (32 unknowns,
# by elimination over GF(2)), so that the image's CRC becomes 0.
def check_word(ws):
    base = crc(ws[:3] + [0] + ws[4:])
    effect = [crc(ws[:3] + [1 << j] + ws[4:]) ^ base for j in range(32)]
    basis = {}                                    # leading bit -> (effect, bits of H3)
    for j, e in enumerate(effect):
        h = 1 << j
        for b in sorted(basis, reverse=True):
            if e >> b & 1:
                e, h = e ^ basis[b][0], h ^ basis[b][1]
        if e:
            basis[e.bit_length() - 1] = (e, h)
    t, h = base, 0
    for b in sorted(basis, reverse=True):
        if t >> b & 1:
            t, h = t ^ basis[b][0], h ^ basis[b][1]
    assert t == 0, "no check word"
    return h


rom[3] = check_word(rom)
assert crc(rom) == 0
open(sys.argv[1], "w").write("".join(f"{w:08x}\n" for w in rom))
