"""Files generated from the contract definition (rtl/albatross_contract.toml):
the Verilog include of the controller, the C driver's layout header, the
testbenches' C++ header, and markdown tables.  main() writes them or, with
--check, names every one that differs from what the definition gives.

    python -m albatross_schedule.contract_gen [--check]     (the project Python, build/venv)
                                  [--definition FILE] [--root DIR] [FILE.md ...]"""

from __future__ import annotations

import argparse
import os
import re
import sys

from .contract import DEFINITION, REPO, Contract, ContractError, load

GENERATOR = "make contract (compiler/albatross_schedule/contract_gen.py)"
VH_PATH = "rtl/albatross_contract.vh"
C_LAYOUT_PATH = "c-driver/albatross_layout.h"
CXX_PATH = "tb/common/albatross_contract.h"
BLOCKS = ("rom-header", "rom-entry", "rom-mode", "channel-layout", "four-slot-layout")


def _stamp(comment: str) -> str:
    return f"{comment} Generated from {DEFINITION} by {GENERATOR}; do not edit."


def _id(*parts) -> str:
    return "_".join(p.upper() for p in parts)


def _fields(c: Contract):
    """Every named ROM field, places expanded: (name suffix, Field)."""
    out = []
    for w in c.header + c.entry + c.mode:
        for f in w.fields:
            out.append((_id(w.name, f.name), f))
            if f.place:
                for sub in c.place_fields(f):
                    out.append((_id(w.name, sub.name), sub))
    return out


def _control(c: Contract, name: str):
    return c.control[name]


# ---------------------------------------------------------------------------
# Verilog-2005 include: localparams for albatross_controller's module body.

def render_vh(c: Contract) -> str:
    L = [_stamp("//"),
         "// The ALBATROSS contract for albatross_controller (`include'd inside its module",
         "// body): the schedule ROM's fields as <WORD>_<FIELD>_LSB / _W (bits [LSB+W-1:LSB]",
         "// of the word), its constants, and the channel layout in bytes from the channel",
         "// base.  See docs/contract.md.",
         "/* verilator lint_off UNUSEDPARAM */",
         f"localparam ALB_ROM_HEADER_WORDS    = {c.header_words};",
         f"localparam ALB_ROM_ENTRY_WORDS     = {c.entry_words};"]
    mw = c.field("H0", "magic").width
    L.append(f"localparam [{mw - 1}:0] ALB_ROM_MAGIC      = {mw}'h{c.magic:0{(mw + 3) // 4}X};")
    L.append(f"localparam [{c.word_bits - 1}:0] ALB_ROM_CRC_POLY = {c.word_bits}'h{c.crc_poly:08X};"
             "  // P = x^32 + POLY; c = (c * x^32 + word) mod P")
    L.append(f"localparam [{c.word_bits - 1}:0] ALB_ROM_CRC_SEED = {c.word_bits}'h{c.crc_seed:08X};")
    L.append(f"localparam ALB_ROM_CRC_WORD        = {c.crc_index};  // the check word: a valid image's CRC is 0")
    L.append(f"localparam ALB_ROM_TIME_BITS       = {c.time_bits};  // widest time within a cycle")
    L.append(f"localparam ALB_ROM_MAX_ENTRIES     = {c.max_entries};")
    L.append(f"localparam ALB_ROM_MAX_DESTS       = {c.max_dests};")
    L.append("// fields")
    width = max(len(n) for n, _ in _fields(c)) + len("ALB_ROM__LSB")
    for n, f in _fields(c):
        L.append(f"localparam {('ALB_ROM_' + n + '_LSB'):<{width}} = {f.lsb:2d}, "
                 f"{('ALB_ROM_' + n + '_W'):<{width - 2}} = {f.width:2d};")
    L.append(f"localparam ALB_ROM_PLACE_BOARD_LSB = {c.place_board.lsb}, ALB_ROM_PLACE_BOARD_W = {c.place_board.width};")
    L.append(f"localparam ALB_ROM_PLACE_BASE_LSB  = {c.place_base.lsb}, ALB_ROM_PLACE_BASE_W  = {c.place_base.width};")
    kw = c.field("E0", "kind").width
    L.append("// E0.kind codes; flag bits within H0.flags and E0.flags")
    for k, v in c.kind.items():
        L.append(f"localparam [{kw - 1}:0] ALB_KIND_{k.upper():<6} = {kw}'d{v};")
    for k, v in c.header_flags.items():
        L.append(f"localparam ALB_ROM_HFLAG_{k.upper()} = {v};")
    for k, v in c.entry_flags.items():
        L.append(f"localparam ALB_ROM_EFLAG_{k.upper()} = {v};")
    L.append("// channel layout: byte offsets from the channel base; buffer index values")
    for cb in c.control.values():
        L.append(f"localparam ALB_CH_OFF_{cb.name.upper():<10} = {cb.offset};")
    L.append(f"localparam ALB_CH_OFF_BUFFERS    = {c.buffers_offset};")
    L.append(f"localparam ALB_CH_WORD_BYTES     = {c.word_bytes};")
    L.append(f"localparam ALB_CH_BUFFERS        = {c.buffers};")
    L.append(f"localparam ALB_CH_BUFFER1        = {c.buffer1};")
    L.append(f"localparam ALB_CH_BUFFER_LAST    = {c.buffer_last};")
    L.append(f"localparam ALB_CH_INITIAL_INDEX  = {c.initial_index};")
    L.append(f"localparam ALB_CH_NOT_STARTED    = {c.not_started};  // a control byte its writer has not set yet")
    L.append(f"localparam ALB_CH_TAKEN_AT_WORDS = {c.taken_at_words};  // destination stride: W + TAKEN_AT_WORDS")
    L.append("// four-slot kind (E0 flag FOUR_SLOT): slot bytes, buffers 1..FS_BUFFERS, buffer b is")
    L.append("// pair (b-1)>>1, slot (b-1)&1")
    for cb in sorted(c.fs_control.values(), key=lambda x: x.offset):
        L.append(f"localparam ALB_CH_OFF_{cb.name.upper():<10} = {cb.offset};")
    L.append(f"localparam ALB_FS_BUFFERS        = {c.fs_buffers};")
    L.append(f"localparam ALB_FS_BUFFER_LAST    = {c.fs_buffer_last};")
    L.append(f"localparam ALB_FS_INITIAL_SLOT   = {c.fs_initial_slot};")
    L.append("/* verilator lint_on UNUSEDPARAM */")
    return "\n".join(L) + "\n"


# ---------------------------------------------------------------------------
# c-driver/albatross_layout.h: self-contained, for users of the driver alone.

def _plain(s: str) -> str:
    return s.replace("`", "")


def layout_rows(c: Contract):
    """(offset, size, contents, writer) of the channel layout, in order."""
    rows = []
    end = 0
    for cb in sorted(c.control.values(), key=lambda x: x.offset):
        if cb.offset > end:
            rows.append((str(end), str(cb.offset - end), "reserved, 0", "—"))
        rows.append((str(cb.offset), str(cb.size), cb.contents, cb.writer))
        end = cb.offset + cb.size
    if c.buffers_offset > end:
        rows.append((str(end), str(c.buffers_offset - end), "reserved, 0", "—"))
    producer = c.control["actual"].writer
    for i in range(c.buffers):
        off = str(c.buffers_offset) + ("" if i == 0 else f" + {'' if i == 1 else i}S")
        rows.append((off, "S", f"Buffer{i + 1}", producer))
    return rows


def fs_layout_rows(c: Contract):
    """(offset, size, contents, writer) of the four-slot channel layout."""
    every = list(c.control.values()) + list(c.fs_control.values())
    rows, end = [], 0
    for cb in sorted(every, key=lambda x: x.offset):
        if cb.offset > end:
            rows.append((str(end), str(cb.offset - end), "reserved, 0", "—"))
        contents = cb.contents
        if cb.name == "actual":
            contents = f"`Actual`: {c.buffer1}..{c.fs_buffer_last} (Buffer1..{c.fs_buffers}), the latest buffer"
        elif cb.name == "readlocked":
            contents = (f"`ReadLocked`: {c.buffer1}..{c.fs_buffer_last}, the consumer's pair: the producer "
                        "writes the other one")
        rows.append((str(cb.offset), str(cb.size), contents, cb.writer))
        end = cb.offset + cb.size
    if c.buffers_offset > end:
        rows.append((str(end), str(c.buffers_offset - end), "reserved, 0", "—"))
    producer = c.control["actual"].writer
    for i in range(c.fs_buffers):
        off = str(c.buffers_offset) + ("" if i == 0 else f" + {'' if i == 1 else i}S")
        rows.append((off, "S", f"Buffer{i + 1} (pair {i >> 1}, slot {i & 1})", producer))
    return rows


def render_c_layout(c: Contract) -> str:
    wb = c.word_bytes
    rows = layout_rows(c)
    table = [" *   offset            size  contents                           written only by"]
    for off, size, contents, writer in rows:
        table.append(f" *   {off:<17} {size:<5} {_plain(contents):<34} {writer if writer != '—' else '-'}")
    names = ", ".join(f"{i} = Buffer{i - c.buffer1 + 1}" for i in range(c.buffer1, c.buffer_last + 1))
    L = ["/*",
         " * albatross_layout.h -- memory layout of one ALBATROSS channel in a",
         " * dual-ported RAM (the paper, section 3.1, figure 2).  Shared by the C driver, the",
         " * testbenches and the hardware controller; byte offsets from the channel base.",
         f" * Generated from {DEFINITION} by make contract",
         " * (compiler/albatross_schedule/contract_gen.py); do not edit.",
         " *"] + table + [
         " *",
         f" * S = payload size rounded up to a multiple of {wb}, so every buffer is",
         " * word-aligned when the channel base is.  Buffer indices are stored as",
         f" * {names}; {c.not_started} means that the byte's writer has not set it yet",
         " * (a zeroed RAM: Actual = nothing published yet, ReadLocked = no buffer",
         " * locked); any other value is invalid and reported by the driver.  Channel bases must be",
         f" * {wb}-byte aligned.  Multi-byte payload words are little-endian (byte lane 0 is",
         " * the lowest address).",
         " */",
         "#ifndef ALBATROSS_LAYOUT_H",
         "#define ALBATROSS_LAYOUT_H",
         "",
         f"#define ALB_OFF_ACTUAL      {c.control['actual'].offset}u",
         f"#define ALB_OFF_READLOCKED  {c.control['readlocked'].offset}u",
         f"#define ALB_OFF_BUFFERS     {c.buffers_offset}u",
         f"#define ALB_BUFFER1         {c.buffer1}u",
         f"#define ALB_BUFFER3         {c.buffer_last}u",
         "/* A control byte its writer has not set yet (cold start on a zeroed RAM). */",
         f"#define ALB_NOT_STARTED     {c.not_started}u",
         "",
         "/* Payload size rounded up to whole words: the stride between buffers. */",
         f"#define ALB_STRIDE(size)          (((size) + {wb - 1}u) & ~{wb - 1}u)",
         f"/* Byte offset of buffer b ({c.buffer1}..{c.buffer_last}) of a channel with the given payload size. */",
         "#define ALB_OFF_BUFFER(b, size)   (ALB_OFF_BUFFERS + ((b) - ALB_BUFFER1) * ALB_STRIDE(size))",
         "/* Bytes one channel occupies in the dual-ported RAM. */",
         f"#define ALB_CHANNEL_BYTES(size)   (ALB_OFF_BUFFERS + {c.buffers}u * ALB_STRIDE(size))",
         "/* A control byte value names a buffer. */",
         "#define ALB_VALID_INDEX(v)        ((v) >= ALB_BUFFER1 && (v) <= ALB_BUFFER3)",
         "",
         "/* The four-slot kind (docs/four_slot.md): the same control bytes, the two",
         " * reserved bytes as the producer's slot bytes (Slot0, Slot1: 0 or 1, the",
         " * slot of each pair completed last) and a fourth buffer.  Buffer b",
         f" * ({c.buffer1}..{c.fs_buffer_last}) is pair (b - {c.buffer1}) >> 1, slot (b - {c.buffer1}) & 1. */",
         ] + [f"#define {'ALB_OFF_' + cb.name.upper():<19} {cb.offset}u" for cb in sorted(c.fs_control.values(), key=lambda x: x.offset)] + [
         f"#define ALB_FS_BUFFERS      {c.fs_buffers}u",
         f"#define ALB_BUFFER4         {c.fs_buffer_last}u",
         f"#define ALB_FS_INITIAL_SLOT {c.fs_initial_slot}u",
         "/* Bytes one four-slot channel occupies in the dual-ported RAM. */",
         "#define ALB_FS_CHANNEL_BYTES(size) (ALB_OFF_BUFFERS + ALB_FS_BUFFERS * ALB_STRIDE(size))",
         "/* A control byte value names a buffer of the four-slot kind. */",
         "#define ALB_FS_VALID_INDEX(v)     ((v) >= ALB_BUFFER1 && (v) <= ALB_BUFFER4)",
         "/* A slot byte value names a slot. */",
         "#define ALB_FS_VALID_SLOT(v)      ((v) <= 1u)",
         "/* Pair and slot of buffer b, and the buffer of pair p, slot s. */",
         "#define ALB_FS_PAIR(b)            ((unsigned)((b) - ALB_BUFFER1) >> 1)",
         "#define ALB_FS_SLOT(b)            ((unsigned)((b) - ALB_BUFFER1) & 1u)",
         "#define ALB_FS_BUFFER(p, s)       (ALB_BUFFER1 + 2u * (p) + (s))",
         "/* Byte offset of the slot byte of pair p (0 or 1). */",
         "#define ALB_OFF_SLOT(p)           (ALB_OFF_SLOT0 + (p) * (ALB_OFF_SLOT1 - ALB_OFF_SLOT0))",
         "",
         "#endif"]
    if wb & (wb - 1):
        raise ContractError("layout.word_bytes must be a power of two (ALB_STRIDE masks)")
    return "\n".join(L) + "\n"


# ---------------------------------------------------------------------------
# C++ header for the testbenches.

def render_cxx(c: Contract) -> str:
    L = [_stamp("//"),
         "// The ALBATROSS contract for the C++ testbenches: schedule ROM fields (word index",
         "// in the header or entry, lsb, width), constants, the CRC, and the channel",
         "// layout.  See docs/contract.md.",
         "#pragma once",
         "#include <cstdint>",
         "",
         "namespace alb_contract {",
         "",
         "struct Field {",
         "    unsigned word, lsb, width;  // word: index within the header, an entry or a mode descriptor",
         "    constexpr uint32_t max() const { return width >= 32 ? 0xFFFFFFFFu : (1u << width) - 1u; }",
         "    constexpr uint32_t put(uint32_t v) const { return (v & max()) << lsb; }",
         "    constexpr uint32_t get(uint32_t w) const { return (w >> lsb) & max(); }",
         "};",
         "",
         f"constexpr unsigned ROM_HEADER_WORDS = {c.header_words}, ROM_ENTRY_WORDS = {c.entry_words};",
         f"constexpr unsigned ROM_MAX_ENTRIES = {c.max_entries}, ROM_MAX_DESTS = {c.max_dests};",
         f"constexpr uint32_t ROM_MAGIC = 0x{c.magic:04X}u;",
         f"constexpr uint32_t ROM_CRC_POLY = 0x{c.crc_poly:08X}u, ROM_CRC_SEED = 0x{c.crc_seed:08X}u;",
         f"constexpr unsigned ROM_CRC_WORD = {c.crc_index}, ROM_TIME_BITS = {c.time_bits};",
         ""]
    for n, f in _fields(c):
        L.append(f"constexpr Field {n}{{{f.index}, {f.lsb}, {f.width}}};")
    L.append(f"constexpr Field PLACE_BOARD{{0, {c.place_board.lsb}, {c.place_board.width}}};")
    L.append(f"constexpr Field PLACE_BASE{{0, {c.place_base.lsb}, {c.place_base.width}}};")
    L.append("// destination places of an entry, in order")
    L.append("constexpr Field DST[] = {" + ", ".join(_id(f.word, f.name) for f in c.dest_fields) + "};")
    L.append("")
    for k, v in c.kind.items():
        L.append(f"constexpr unsigned KIND_{k.upper()} = {v};")
    for k, v in c.header_flags.items():
        L.append(f"constexpr unsigned HFLAG_{k.upper()} = 1u << {v};  // in H0.flags")
    for k, v in c.entry_flags.items():
        L.append(f"constexpr unsigned EFLAG_{k.upper()} = 1u << {v};  // in E0.flags")
    L += ["",
          "// CRC of n ROM words (the check word ROM_CRC_WORD too): 0 for a valid image.",
          "inline uint32_t rom_crc(const uint32_t *w, int n) {",
          "    uint32_t c = ROM_CRC_SEED;",
          "    for (int i = 0; i < n; ++i) {",
          "        for (int b = 0; b < 32; ++b) c = (c << 1) ^ ((c >> 31) ? ROM_CRC_POLY : 0u);",
          "        c ^= w[i];",
          "    }",
          "    return c;",
          "}",
          "// The check word of an image of n words: the word ROM_CRC_WORD that makes its",
          "// CRC 0 (the word it holds plus the CRC times x^-(32 (n - 1 - ROM_CRC_WORD)) mod P).",
          "inline uint32_t rom_check_word(const uint32_t *w, int n) {",
          "    uint32_t c = rom_crc(w, n);",
          "    for (int b = 0; b < 32 * (n - 1 - (int)ROM_CRC_WORD); ++b)",
          "        c = (c & 1u) ? ((c ^ ROM_CRC_POLY) >> 1) | 0x80000000u : c >> 1;",
          "    return w[ROM_CRC_WORD] ^ c;",
          "}",
          "constexpr uint32_t place(uint32_t board, uint32_t base_word) {",
          "    return PLACE_BOARD.put(board) | PLACE_BASE.put(base_word);",
          "}",
          "",
          "// channel layout: byte offsets from the channel base",
          f"constexpr uint32_t OFF_ACTUAL = {c.control['actual'].offset}, "
          f"OFF_READLOCKED = {c.control['readlocked'].offset}, OFF_BUFFERS = {c.buffers_offset};",
          f"constexpr uint32_t WORD_BYTES = {c.word_bytes}, BUFFERS = {c.buffers}, BUFFER1 = {c.buffer1}, "
          f"INITIAL_INDEX = {c.initial_index};",
          f"constexpr uint32_t TAKEN_AT_WORDS = {c.taken_at_words};",
          "// four-slot kind: slot bytes, four buffers; buffer b is pair (b-1)>>1, slot (b-1)&1",
          f"constexpr uint32_t OFF_SLOT0 = {c.fs_control['slot0'].offset}, OFF_SLOT1 = {c.fs_control['slot1'].offset};",
          f"constexpr uint32_t FS_BUFFERS = {c.fs_buffers}, FS_INITIAL_SLOT = {c.fs_initial_slot};",
          "// Bytes of a destination payload: the value's words, then taken_at.",
          "constexpr uint32_t dest_bytes(uint32_t words) { return WORD_BYTES * (words + TAKEN_AT_WORDS); }",
          "// Byte offset of taken_at in a destination payload.",
          "constexpr uint32_t taken_at_offset(uint32_t words) { return WORD_BYTES * words; }",
          "",
          "}  // namespace alb_contract"]
    return "\n".join(L) + "\n"


# ---------------------------------------------------------------------------
# Markdown tables.

def _md_rom(c: Contract, words) -> list:
    L = ["| word | bits | meaning |", "|---|---|---|"]
    for w in words:
        if not w.fields:
            L.append(f"| {w.name} | [{c.word_bits - 1}:0] | {w.doc} |")
            continue
        for i, f in enumerate(w.fields):
            meaning = f.doc
            if f.place:
                b, s = c.place_board, c.place_base
                meaning += f": `{{board{b.bits}, base word{s.bits}}}`"
            L.append((f"| {w.name} |" if i == 0 else "| |") + f" {f.bits} | {meaning} |")
    return L


def render_markdown_block(c: Contract, name: str) -> str:
    if name == "rom-header":
        L = _md_rom(c, c.header)
    elif name == "rom-entry":
        L = _md_rom(c, c.entry)
    elif name == "rom-mode":
        L = _md_rom(c, c.mode)
    elif name == "channel-layout":
        L = ["| offset | size | contents | written only by |", "|---|---|---|---|"]
        L += [f"| {o} | {s} | {t} | {w} |" for o, s, t, w in layout_rows(c)]
    elif name == "four-slot-layout":
        L = ["| offset | size | contents | written only by |", "|---|---|---|---|"]
        L += [f"| {o} | {s} | {t} | {w} |" for o, s, t, w in fs_layout_rows(c)]
    else:
        raise ContractError(f"unknown contract block '{name}' (known: {', '.join(BLOCKS)})")
    return "\n".join([f"<!-- {_stamp('').strip()} -->"] + L)


BLOCK_RE = re.compile(r"(<!-- contract:([a-z-]+) -->\n)(.*?)(<!-- /contract:\2 -->)", re.S)


def render_markdown(c: Contract, text: str) -> str:
    """text with every contract block's contents replaced by the generated table."""
    return BLOCK_RE.sub(lambda m: m.group(1) + render_markdown_block(c, m.group(2)) + "\n" + m.group(4), text)


# ---------------------------------------------------------------------------
# Command line.

def generated(c: Contract) -> dict:
    return {VH_PATH: render_vh(c), C_LAYOUT_PATH: render_c_layout(c), CXX_PATH: render_cxx(c)}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="albatross_schedule.contract_gen",
                                 description="Generate (or --check) the files derived from the contract "
                                 f"definition {DEFINITION}.")
    ap.add_argument("markdown", nargs="*", help="markdown files whose <!-- contract:NAME --> blocks to rewrite")
    ap.add_argument("--definition", help=f"the definition (default: {DEFINITION})")
    ap.add_argument("--root", default=REPO, help="where the generated files go (default: the repository)")
    ap.add_argument("--check", action="store_true",
                    help="write nothing; fail naming every file that differs from what the definition gives")
    a = ap.parse_args(argv)
    try:
        c = load(a.definition)
        files = {os.path.join(a.root, p): t for p, t in generated(c).items()}
        for md in a.markdown:
            with open(md) as f:
                text = f.read()
            files[md] = render_markdown(c, text)
    except (ContractError, OSError) as e:
        print(f"contract: error: {e}", file=sys.stderr)
        return 2
    stale = []
    for path, text in files.items():
        try:
            with open(path) as f:
                old = f.read()
        except OSError:
            old = None
        if old == text:
            continue
        if a.check:
            stale.append(path)
            continue
        os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
        with open(path, "w", newline="\n") as f:
            f.write(text)
        print(f"contract: wrote {os.path.relpath(path)}")
    if stale:
        for p in stale:
            print(f"contract: {os.path.relpath(p)} is stale: it differs from what {c.path} gives "
                  "(run make contract)", file=sys.stderr)
        return 1
    if a.check:
        print(f"contract: {len(files)} files match {os.path.relpath(c.path)}: " +
              ", ".join(os.path.relpath(p) for p in files))
    return 0


if __name__ == "__main__":
    sys.exit(main())
