#!/usr/bin/env python3
"""gen_rom.py -- the schedule ROM images of the sequencer proofs (formal/sequencer/sequencer.sby).

    gen_rom.py OUTDIR

Writes, for each image NAME (time, sync, badcrc, rep8), OUTDIR/NAME.hex (the ROM, one word a line,
for $readmemh) and OUTDIR/NAME.vh (the proof's configuration and the image's decoded fields
as Verilog localparams, `include'd by fseq.v).  The images are encoded by the schedule
compiler's own encoder (albatross_schedule.rom.encode_rom: the contract's fields and CRC)
and checked with its verify_rom; nothing is typed as a hex number here.
  time    time-rigid, 2 entries: a COPY (2 destinations) and a TIME, gaps between the slots
          and before the cycle end; cluster 2 (4 minor cycles), the COPY due in the even minor
          cycles (rep 1, base 0), the TIME in those that are 1 mod 4 (rep 2, base 1); the
          sequencer's count CLUSTER_BITS = 2, so that it wraps where the contract's does.
  sync    position-synchronised, 2 entries: the SYNC COPY at 0 (every cycle) and a TIME right
          after it (start = the previous slot's end; rep 1, base 0), H1 = the longest cycle;
          cluster 1, CLUSTER_BITS 1.
  badcrc  the time image with H3 one bit off: the start-up CRC pass must reject it.
  rep8    the time image with cluster 8 and CLUSTER_BITS 8: the COPY due in minor cycle 0
          of 256 (rep 8: a repetition whose top bit is set), the TIME in those that are 5 mod 8.
The due fields (E6: base, rep) and the cluster (H2) are put into the encoder's words here, with
the contract's fields, and the check word recomputed (C.check_word).
The .vh also holds the image itself (F_ROM) and the CRC tables the k-induction invariants use: F_CRCB, the CRC before
each chunk of each word (the ROM check takes CRC_BITS bits of a word a clock: c after words 0..a-1, H3 included, and
after chunks 0..j-1 of word a, at the check's read index {a, j}), and F_PFX, the prefix CRC after each part (header,
entry k) that the start-up pass stores; both padded with 0 to every index.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "compiler"))

from albatross_schedule import contract                        # noqa: E402
from albatross_schedule.model import (MODE_RIGID, MODE_SYNC, Bus, Channel, Plan,  # noqa: E402
                                      Slot, System)
from albatross_schedule.rom import encode_rom, verify_rom      # noqa: E402

C = contract.load()

# The proof's configuration of albatross_sequencer (fseq.v instantiates it with these).
NB, ADDR_WIDTH, N_CHAN, TIME_BITS, TIMEOUT, POLL = 2, 4, 2, 5, 2, 2
FETCH_CYCLES = 7                                    # the sequencer's FETCH_CYCLES
MIN_LEN = FETCH_CYCLES + TIMEOUT + 2                # shortest valid slot
NE = 2
# Per image: (cluster c, the sequencer's CLUSTER_BITS, (rep, base) of entry 0 and 1).
MULTIRATE = {"time": (2, 2, ((1, 0), (2, 1))), "sync": (1, 1, ((0, 0), (1, 0))),
             "badcrc": (2, 2, ((1, 0), (2, 1))), "rep8": (8, 8, ((8, 0), (3, 5)))}
ROM_WORDS = C.entry_address(NE)                     # the image fills the ROM exactly
CRC_BITS = 4                                        # the ROM check's CRC step (albatross_rom_check's default)
CHUNKS = 32 // CRC_BITS                             # clocks of the ROM port per word
CHUNK_BITS = max(1, (CHUNKS - 1).bit_length())      # the chunk field of the check's read index


def system(mode, channels):
    return System(name="fseq", clock_hz=1, boards=["b0", "b1"], ram_bytes=[4 << ADDR_WIDTH] * NB,
                  mode=mode, types_header=None, bus=Bus(n_chan=N_CHAN, time_bits=TIME_BITS,
                                                        timeout_cycles=TIMEOUT, poll_cycles=POLL),
                  channels=channels)


def channels(sync):
    w = C.word_bytes
    copy = Channel(index=0, name="c", kind="copy", ctype=None, size=4, words=1, producer=1,
                   consumers=[0, 1], max_period_us=1, sync=sync, src_base=8 * w, dst_bases=[0, 0])
    time = Channel(index=1, name="t", kind="time", ctype=None, size=4, words=1, producer=None,
                   consumers=[0], max_period_us=1, dst_bases=[8 * w])
    return copy, time


def image_time():
    copy, time = channels(False)
    plan = Plan(cycle=26, capacity=26, limiter=copy,
                slots=[Slot(copy, start=1, length=12, redundant=False),
                       Slot(time, start=14, length=11, redundant=False)])
    return system(MODE_RIGID, [copy, time]), plan


def image_sync():
    copy, time = channels(True)
    plan = Plan(cycle=31, capacity=31, limiter=copy,
                slots=[Slot(copy, start=0, length=12, redundant=False, sync=True),
                       Slot(time, start=12, length=11, redundant=False)])
    return system(MODE_SYNC, [copy, time]), plan


def multirate(words, cluster, _clb, due):
    """The image with H2.cluster and each entry's E6 (rep, base) set, its check word recomputed."""
    words = list(words)
    cl = C.field("H2", "cluster")
    words[cl.index] = (words[cl.index] & ~cl.mask) | cl.put(cluster)
    for k, (rep, base) in enumerate(due):
        for name, v in (("rep", rep), ("base", base)):
            f = C.field("E6", name)
            a = C.entry_address(k) + f.index
            words[a] = (words[a] & ~f.mask) | f.put(v)
    words[C.crc_index] = C.check_word(words)
    return words


def crc_chunks(c, w):
    """The CRC after c takes word w's CHUNKS chunks: one per entry, most significant first."""
    out = []
    for j in range(CHUNKS):
        for i in range(32 - CRC_BITS * j - 1, 32 - CRC_BITS * (j + 1) - 1, -1):
            c = (((c << 1) & 0xFFFFFFFF) | ((w >> i) & 1)) ^ (C.crc_poly if c >> 31 else 0)
        out.append(c)
    return out


def crc_tables(words):
    """CRC before each chunk of each word (F_CRCB, at the check's read index
    {word, chunk}) and after each part (F_PFX), H3 included.  The chunk steps
    end where the contract's word step does (checked here)."""
    before = [C.crc(words[:a]) for a in range(len(words) + 1)]
    chunked = []
    for a, w in enumerate(words):
        after = crc_chunks(before[a], w)
        if after[-1] != before[a + 1]:
            raise SystemExit(f"gen_rom: the {CRC_BITS}-bit CRC step disagrees with the contract's CRC at word {a}")
        chunked += [before[a]] + after[:-1] + [0] * ((1 << CHUNK_BITS) - CHUNKS)
    ends = [C.header_words - 1] + [C.entry_address(k + 1) - 1 for k in range(NE)]
    return chunked, [before[a + 1] for a in ends]


def check_plan(system_, plan):
    for s in plan.slots:
        if s.length < MIN_LEN:
            raise SystemExit(f"gen_rom: slot at {s.start} shorter than MIN_LEN {MIN_LEN}")
    if plan.cycle >= 1 << TIME_BITS:
        raise SystemExit("gen_rom: the cycle does not fit TIME_BITS")
    if len(plan.slots) != NE:
        raise SystemExit(f"gen_rom: fseq.v models {NE} entries")


def vh(name, words, system_, plan, valid):
    def lp(n, v, w=32, doc=""):
        return f"localparam [{w - 1}:0] {n} = {w}'d{v};" + (f"  // {doc}" if doc else "")
    fld = C.field
    hdr = words[:C.header_words]
    out = [f"// {name}.vh -- generated by formal/sequencer/gen_rom.py; do not edit.",
           f"// The proof's configuration and the decoded image {name}.hex.",
           f"localparam F_NB = {NB}, F_AW = {ADDR_WIDTH}, F_NCHAN = {N_CHAN}, F_TB = {TIME_BITS},",
           f"           F_TIMEOUT = {TIMEOUT}, F_POLL = {POLL}, F_ROM_WORDS = {ROM_WORDS}, F_NE = {NE},",
           f"           F_CRC_BITS = {CRC_BITS}, F_CHUNKS = {CHUNKS}, F_CB = {CHUNK_BITS};"
           "  // the ROM check's CRC step, chunks of a word, chunk-index bits",
           f"localparam F_VALID = {int(valid)};  // the image is valid (else: the start-up must reject it)",
           f"localparam F_CL = {fld('H2', 'cluster').get(hdr[2])};  // the cluster c: 2^c minor cycles",
           f"localparam F_CLB = {MULTIRATE[name][1]};  // the sequencer's CLUSTER_BITS",
           f"localparam F_SMODE = {int(system_.sync_mode)};  // position-synchronised",
           lp("F_H1", fld("H1", "cycle").get(hdr[1]), 32, "cycle length"),
           lp("F_DROP", fld("H2", "drop_run").get(hdr[2]), 8, "the drop run K"),
           lp("F_CRC_ALL", C.crc(words), 32, "the CRC of the whole image, H3 included (0: valid)")]
    aw = ADDR_WIDTH
    for k in range(NE):
        e = words[C.entry_address(k): C.entry_address(k + 1)]
        g = lambda w, f: fld(w, f).get(e[fld(w, f).index])          # noqa: E731
        places = [C.unplace(f.get(e[f.index])) for f in C.dest_fields]
        src = C.unplace(C.src_field.get(e[C.src_field.index]))
        out += [f"// entry {k}",
                lp(f"F_S{k}", g("E1", "start"), 32, "start"),
                lp(f"F_L{k}", g("E2", "length"), 32, "length"),
                lp(f"F_R{k}", g("E6", "rep"), 32, "rep: due every 2^rep minor cycles"),
                lp(f"F_B{k}", g("E6", "base"), 32, "base: due when n mod 2^rep = base"),
                lp(f"F_KIND{k}", g("E0", "kind") & 3, 2),
                lp(f"F_SYNC{k}", int(bool(g("E0", "flags") & C.flag("entry", "sync"))), 1),
                lp(f"F_CHAN{k}", g("E0", "id") & 31, 5),
                lp(f"F_ND{k}", g("E0", "nd") & 7, 3),
                lp(f"F_W{k}", g("E0", "w"), 12),
                lp(f"F_SRCB{k}", src[0], 4),
                lp(f"F_SRCA{k}", src[1] & ((1 << aw) - 1), aw),
                lp(f"F_DSTB{k}", sum(b << (4 * d) for d, (b, _) in enumerate(places)), 16),
                lp(f"F_DSTA{k}", sum((a & ((1 << aw) - 1)) << (aw * d) for d, (_, a) in enumerate(places)),
                   4 * aw)]
    before, pfx = crc_tables(words)
    aw = (ROM_WORDS - 1).bit_length()                 # ROM address bits: pad the tables to
    before += [0] * ((1 << (aw + CHUNK_BITS)) - len(before))   # every index, so that none is
    pfx += [0] * ((1 << (aw - 3)) - len(pfx))         # out of range (no x in the model)
    rom = list(words) + [0] * ((1 << aw) - len(words))
    out.append(f"localparam [{32 * len(rom) - 1}:0] F_ROM = {{" +
               ", ".join(f"32'h{w:08x}" for w in reversed(rom)) + "};  // the image, word a at [32a +: 32]")
    out.append(f"localparam [{32 * len(before) - 1}:0] F_CRCB = {{" +
               ", ".join(f"32'h{c:08x}" for c in reversed(before)) + "};  // chunk j of word a at [32({a, j}) +: 32]")
    out.append(f"localparam [{32 * len(pfx) - 1}:0] F_PFX = {{" +
               ", ".join(f"32'h{c:08x}" for c in reversed(pfx)) + "};  // part r at [32r +: 32]")
    return "\n".join(out) + "\n"


def main():
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    for name, make in (("time", image_time), ("sync", image_sync), ("badcrc", image_time), ("rep8", image_time)):
        sys_, plan = make()
        check_plan(sys_, plan)
        words = multirate(encode_rom(sys_, plan), *MULTIRATE[name])
        problems, _ = verify_rom(words, n_chan=N_CHAN, n_boards=NB, ram_words=1 << ADDR_WIDTH,
                                 sync_expected=sys_.sync_mode)
        if problems:
            raise SystemExit(f"gen_rom: image {name} invalid: " + "; ".join(problems))
        valid = name != "badcrc"
        if not valid:
            words[C.crc_index] ^= 1                          # one CRC bit off
        with open(os.path.join(outdir, name + ".hex"), "w") as f:
            f.write("".join(f"{w:08x}\n" for w in words))
        with open(os.path.join(outdir, name + ".vh"), "w") as f:
            f.write(vh(name, words, sys_, plan, valid))


if __name__ == "__main__":
    main()
