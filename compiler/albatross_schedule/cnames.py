"""C names: the names of a description (system, boards, channels, channel
types) become parts of the identifiers, macros and file names of the generated
board headers and sources (cgen.py) and the driver's channel macros
(c-driver/albatross.h: ALB_CHANNEL, ALB_SAMPLING).  A name is rejected when
the name itself, or anything generated from it, collides with

  - a C keyword (C99, C11, and the C23 ones that C11 headers define as macros),
  - a name of <stdint.h>, <stddef.h> or <stdbool.h> (the generated files and
    the driver include them; a channel `uint32` would declare `uint32_t`),
  - an identifier of the driver (DRIVER_IDENTIFIERS: c-driver/*.h and its
    ports; compiler/tests checks this list against the headers),
  - something generated from another name of the description,

or when a board's header and source would take the name of a C standard
header or a driver header (a board `stdint` would write a stdint.h that hides
the system's <stdint.h>).  File names are compared without case (the outputs
may land on a case-insensitive file system).

The generated names, for a channel N (upper case U) and a board B (upper
case V) of system S (upper case T):
  channel  N_t (its value type, unless `type` names one)  N_msg
           ALB_U_<suffix> (CHANNEL_MACROS)  alb_ch_N  alb_check_N_size
           alb_check_N_taken_at  LookForNewN  MakeNAvailable  ReadN
  board    ALB_V_BOARD  ALB_V_RAM_BYTES  ALB_T_V_H  alb_B_init_all
           alb_B_attach_all; files B.h  B.c  B_ram.hex
"""

from __future__ import annotations

# C99 and C11 keywords, and the C23 keywords that C11 headers define as macros.
C_KEYWORDS = frozenset("""
auto break case char const continue default do double else enum extern float for goto if inline int long
register restrict return short signed sizeof static struct switch typedef union unsigned void volatile while
_Bool _Complex _Imaginary _Alignas _Alignof _Atomic _Generic _Noreturn _Static_assert _Thread_local
alignas alignof bool constexpr false nullptr static_assert thread_local true typeof typeof_unqual
_BitInt _Decimal32 _Decimal64 _Decimal128 noreturn complex imaginary
""".split())
# Keywords that name a type on their own (a channel's `type` may be one).
C_TYPE_KEYWORDS = frozenset("char short int long float double _Bool bool".split())


def _stdint_names() -> set:
    names = {"intptr_t", "uintptr_t", "intmax_t", "uintmax_t", "INTPTR_MIN", "INTPTR_MAX", "UINTPTR_MAX",
             "INTMAX_MIN", "INTMAX_MAX", "UINTMAX_MAX", "INTMAX_C", "UINTMAX_C", "PTRDIFF_MIN", "PTRDIFF_MAX",
             "SIG_ATOMIC_MIN", "SIG_ATOMIC_MAX", "SIZE_MAX", "WCHAR_MIN", "WCHAR_MAX", "WINT_MIN", "WINT_MAX"}
    for n in (8, 16, 32, 64):
        for kind in ("", "_least", "_fast"):
            names |= {f"int{kind}{n}_t", f"uint{kind}{n}_t", f"INT{kind.upper()}{n}_MIN",
                      f"INT{kind.upper()}{n}_MAX", f"UINT{kind.upper()}{n}_MAX"}
        names |= {f"INT{n}_C", f"UINT{n}_C"}
    return names


# Names of the standard headers the generated files and the driver include.
STD_NAMES = {"<stdint.h>": frozenset(_stdint_names()),
             "<stddef.h>": frozenset("NULL offsetof ptrdiff_t size_t wchar_t max_align_t".split()),
             "<stdbool.h>": frozenset("bool true false __bool_true_false_are_defined".split())}

# The driver's identifiers (c-driver/albatross.h, albatross_layout.h, alb_port.h,
# alb_clock.h, port/*/alb_port_impl.h), outside comments.
DRIVER_IDENTIFIERS = frozenset("""
ALBATROSS_H ALBATROSS_LAYOUT_H ALB_PORT_H ALB_PORT_IMPL_H ALB_CLOCK_H
ALB_BUFFER1 ALB_BUFFER3 ALB_BUFFER4 ALB_CHANNEL ALB_CHANNEL_BYTES ALB_CHANNEL_DEFINE ALB_CLOCK_EMPTY
ALB_CLOCK_OFFSET ALB_CLOCK_RATE ALB_CLOCK_RATE_MIN ALB_CLOCK_RING ALB_CLOCK_WINDOW ALB_ERR_ARG ALB_ERR_CORRUPT
ALB_FOUR_SLOT ALB_FOUR_SLOT_EXPORT ALB_FOUR_SLOT_IMPORT ALB_FS_BUFFER ALB_FS_BUFFERS ALB_FS_CHANNEL_BYTES
ALB_FS_INITIAL_SLOT ALB_FS_PAIR ALB_FS_SLOT ALB_FS_VALID_INDEX ALB_FS_VALID_SLOT ALB_NEW ALB_OFF_ACTUAL
ALB_OFF_BUFFER ALB_OFF_BUFFERS ALB_OFF_READLOCKED ALB_OFF_SLOT ALB_OFF_SLOT0 ALB_OFF_SLOT1 ALB_OK ALB_OLD
ALB_SAMPLE_NEVER ALB_SAMPLE_NEW ALB_SAMPLE_OLD ALB_SAMPLE_STALE ALB_SAMPLING ALB_STRIDE ALB_THREE_BUFFER
ALB_THREE_BUFFER_EXPORT ALB_THREE_BUFFER_IMPORT ALB_VALID_INDEX ALB_LOCAL_TIMER_ADDR ALB_NOT_STARTED
ALB_PORT_HAS_LOCAL_TIME
alb_channel alb_channel_setup alb_channel_setup_kind alb_channel_t alb_clock alb_clock_at alb_clock_init
alb_clock_now alb_clock_sample_t alb_clock_state alb_clock_sync alb_clock_sync_now alb_clock_t
alb_consumer_attach alb_consumer_init alb_export alb_fence alb_first_error alb_import alb_local_time alb_port
alb_producer_attach alb_producer_init alb_rd32 alb_rd8 alb_read alb_sample alb_sample_t alb_wr32 alb_wr8 alb_port_impl
""".split())

# Macros generated per channel: ALB_<NAME>_<suffix> (cgen.render_board_header).
CHANNEL_MACROS = ("ID", "BASE", "SIZE", "WORDS", "KIND", "PERIOD_CLOCKS", "LATENCY_CLOCKS", "AGE_CLOCKS",
                  "LATENCY_AT_TARGET_CLOCKS", "AGE_AT_TARGET_CLOCKS", "IMPORT_MAX_PASSES",
                  "IMPORT_MAX_ACCESSES", "MAX_AGE_CLOCKS")
# Fixed macros of a header with a STATUS channel.
FIXED_MACROS = frozenset("ALB_STATUS_CYCLES ALB_STATUS_ROM_ERRORS ALB_STATUS_RETRIES ALB_STATUS_TRANSFERS "
                         "ALB_STATUS_CORRUPT ALB_STATUS_ABANDONED".split())

# C standard header names (C11, and C23's new ones) and the driver's headers:
# no board may write <name>.h.
STD_HEADERS = frozenset("""assert complex ctype errno fenv float inttypes iso646 limits locale math setjmp signal
stdalign stdarg stdatomic stdbit stdbool stdckdint stddef stdint stdio stdlib stdnoreturn string tgmath threads
time uchar wchar wctype""".split())
DRIVER_HEADERS = frozenset("albatross albatross_layout alb_port alb_port_impl alb_clock".split())


def reserved_why(ident: str):
    """Why ident may not be declared by generated code, or None."""
    if ident in C_KEYWORDS:
        return "a C keyword"
    for header, names in STD_NAMES.items():
        if ident in names:
            return f"a {header} name"
    if ident in DRIVER_IDENTIFIERS or ident in FIXED_MACROS:
        return "an identifier of the driver (c-driver/) or of every generated file"
    return None


def channel_generated(name: str, has_value_type: bool) -> list:
    """(identifier, what it is) generated for a channel."""
    u = name.upper()
    out = [(f"{name}_msg", "message type")]
    if has_value_type:
        out.append((f"{name}_t", "value type"))
    out += [(f"ALB_{u}_{s}", "macro") for s in CHANNEL_MACROS]
    out += [(f"alb_ch_{name}", "channel object"), (f"alb_check_{name}_size", "size check"),
            (f"alb_check_{name}_taken_at", "layout check"), (f"LookForNew{name}", "Import function"),
            (f"Make{name}Available", "Export function"), (f"Read{name}", "read function")]
    return out


def board_generated(system_name: str, board: str) -> list:
    v = board.upper()
    return [(f"ALB_{v}_BOARD", "macro"), (f"ALB_{v}_RAM_BYTES", "macro"),
            (f"ALB_{system_name.upper()}_{v}_H", "header guard"),
            (f"alb_{board}_init_all", "set-up function"), (f"alb_{board}_attach_all", "set-up function")]


def check_names(system_name: str, boards: list, channels: list, err) -> None:
    """Report every name whose C identifiers or files collide (err: description.Errors).
    channels: the parsed Channel objects (name, ctype, kind, index)."""
    owner = {}          # generated identifier -> (entity, what it is there)

    def claim(ident, who, what, report):
        why = reserved_why(ident)
        if why:
            report(f"its {what} {ident} is {why}" if what else f"'{ident}' is {why}")
        elif what and ident in owner and owner[ident][0] != who:
            report(f"its {what} {ident} is also generated for {owner[ident][0]} ({owner[ident][1]})")
        elif what:
            owner.setdefault(ident, (who, what))

    claim(system_name, f"system '{system_name}'", "",
          lambda msg: err.system("name", f"system name '{system_name}': {msg}"))
    for b in boards:
        def report_board(msg, b=b):
            err.system("boards", f"board '{b}': {msg}")
        low = b.lower()
        if low in STD_HEADERS:
            report_board(f"its header {b}.h would hide the C standard header <{low}.h>")
        elif low in DRIVER_HEADERS:
            report_board(f"its header {b}.h would overwrite the driver header {low}.h")
        else:
            claim(b, f"board '{b}'", "", report_board)
            for ident, what in board_generated(system_name, b):
                claim(ident, f"board '{b}'", what, report_board)
    for ch in channels:
        def report_channel(msg, ch=ch):
            err.channel(ch.index, ch.name, "name", msg)
        claim(ch.name, f"channel '{ch.name}'", "", report_channel)
        for ident, what in channel_generated(ch.name, ch.ctype is None and ch.kind != "time"):
            claim(ident, f"channel '{ch.name}'", what, report_channel)
    for ch in channels:     # a named type: a type name, not one the headers declare for a channel
        if not ch.ctype:
            continue
        words = ch.ctype.split()
        tag = words[-1]
        if tag in C_KEYWORDS and not (len(words) == 1 and tag in C_TYPE_KEYWORDS):
            err.channel(ch.index, ch.name, "type", f"'{ch.ctype}': '{tag}' is a C keyword, not a type name")
        elif len(words) == 1 and tag in owner and owner[tag][1] in ("value type", "message type") \
                and owner[tag][0] != f"channel '{ch.name}'":
            err.channel(ch.index, ch.name, "type", f"'{ch.ctype}' is the {owner[tag][1]} that the "
                        f"generated headers declare for {owner[tag][0]}")
