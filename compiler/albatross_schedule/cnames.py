"""C names: every identifier and macro that the generated C declares, made
by the templates of this module (cgen.py writes its names through them), and
the check that rejects a description whose names would break that C.

The names of a description (system, boards, channels, modes, channel types)
become parts of the identifiers, macros and file names of the generated board
headers and sources (cgen.py) and of the driver's channel macros
(c-driver/albatross.h: ALB_CHANNEL, ALB_SAMPLING).  generated_names()
enumerates all of them, with the fixed names of the generated files, before
anything is planned or written; check_names() rejects

  - a generated name (or a system, board or channel name itself) that is a C
    keyword (C99, C11, and the C23 ones that C11 headers define as macros), a
    name of <stdint.h>, <stddef.h> or <stdbool.h> (a channel `uint32` would
    declare `uint32_t`), an identifier of the driver (DRIVER_IDENTIFIERS:
    c-driver/*.h and its ports; compiler/tests checks this list against the
    headers) or a fixed name of the generated files (FIXED_NAMES);
  - any name generated twice: the message names both sources (modes `Run`
    and `run` both give ALB_MODE_RUN; a mode `X_BOARD` beside a board
    `MODE_X` gives ALB_MODE_X_BOARD twice);
  - a board whose header and source would take the name of a C standard
    header or a driver header (a board `stdint` would write a stdint.h that
    hides the system's <stdint.h>), compared without case (the outputs may
    land on a case-insensitive file system);
  - a channel `type` that is not a type: a keyword other than a type keyword,
    a name the generated files declare, a driver or standard name that is no
    type.

Names are checked as one name space over all the generated files, although
a program includes one board header: that is stricter than C, and it keeps a
name from meaning two things in two boards' headers.  compiler/tests/
test_names.py parses every #define, typedef and function of the generated
files of many descriptions and checks that each is in generated_names().

The generated names, for a channel N (upper case U), a board B (upper case
V) of system S (upper case T), and a mode M (upper case K):
  channel  N_t (its value type, unless `type` names one)  N_msg
           ALB_U_<suffix> (CHANNEL_MACROS)  alb_ch_N  alb_check_N_size
           alb_check_N_taken_at  LookForNewN  MakeNAvailable  ReadN
  board    ALB_V_BOARD  ALB_V_RAM_BYTES  ALB_T_V_H  alb_B_init_all
           alb_B_attach_all; files B.h  B.c  B_ram.hex
  mode     ALB_MODE_K
  fixed    FIXED_NAMES (alb_mode_t, ALB_MODE_T_DEFINED, ALB_STATUS_*, alb_first_error)
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
alb_consumer_attach alb_consumer_init alb_export alb_fence alb_import alb_local_time alb_port
alb_producer_attach alb_producer_init alb_rd32 alb_rd8 alb_read alb_sample alb_sample_t alb_wr32 alb_wr8 alb_port_impl
""".split())

# C standard header names (C11, and C23's new ones) and the driver's headers:
# no board may write <name>.h.
STD_HEADERS = frozenset("""assert complex ctype errno fenv float inttypes iso646 limits locale math setjmp signal
stdalign stdarg stdatomic stdbit stdbool stdckdint stddef stdint stdio stdlib stdnoreturn string tgmath threads
time uchar wchar wctype""".split())
DRIVER_HEADERS = frozenset("albatross albatross_layout alb_port alb_port_impl alb_clock".split())



# ---------------------------------------------------------------------------
# The templates: cgen.py makes every name it declares with these.

# Macros of a channel: ALB_<NAME>_<suffix>.
CHANNEL_MACROS = ("ID", "BASE", "SIZE", "WORDS", "KIND", "PERIOD_CLOCKS", "LATENCY_CLOCKS", "AGE_CLOCKS",
                  "LATENCY_AT_TARGET_CLOCKS", "AGE_AT_TARGET_CLOCKS", "IMPORT_MAX_PASSES",
                  "IMPORT_MAX_ACCESSES", "MAX_AGE_CLOCKS")
# Macros of a board: ALB_<BOARD>_<suffix>.
BOARD_MACROS = ("BOARD", "RAM_BYTES")
# Set-up functions of a board: alb_<board>_<what>_all.
SETUP_FUNCTIONS = ("init", "attach")
# The names the driver's channel macros declare for a channel (c-driver/albatross.h;
# compiler/tests/test_names.py reads them from the macros' ## patterns).
DRIVER_MACRO_NAMES = {"ALB_CHANNEL": (("alb_ch_{}", "channel object"), ("LookForNew{}", "Import function"),
                                      ("Make{}Available", "Export function")),
                      "ALB_CHANNEL_DEFINE": (("alb_ch_{}", "channel object"),),
                      "ALB_SAMPLING": (("Read{}", "read function"),)}
# Fixed names of the generated files: the running mode's type and its guard, the
# STATUS word accessors, the set-up sources' helper.
MODE_TYPE = "alb_mode_t"
MODE_TYPE_GUARD = "ALB_MODE_T_DEFINED"
STATUS_FIELDS = ("CYCLES", "ROM_ERRORS", "RETRIES", "TRANSFERS", "CORRUPT", "ABANDONED")
FIRST_ERROR = "alb_first_error"
FIXED_NAMES = dict([(MODE_TYPE, "type"), (MODE_TYPE_GUARD, "macro"), (FIRST_ERROR, "function")]
                   + [(f"ALB_STATUS_{f}", "macro") for f in STATUS_FIELDS])


def status_macro(field: str) -> str:
    assert field in STATUS_FIELDS, field
    return f"ALB_STATUS_{field}"


def channel_macro(channel: str, suffix: str) -> str:
    assert suffix in CHANNEL_MACROS, f"ALB_<NAME>_{suffix} is not in cnames.CHANNEL_MACROS"
    return f"ALB_{channel.upper()}_{suffix}"


def value_type(channel: str) -> str:
    return f"{channel}_t"


def message_type(channel: str) -> str:
    return f"{channel}_msg"


def size_check(channel: str) -> str:
    return f"alb_check_{channel}_size"


def taken_at_check(channel: str) -> str:
    return f"alb_check_{channel}_taken_at"


def channel_object(channel: str) -> str:
    return DRIVER_MACRO_NAMES["ALB_CHANNEL_DEFINE"][0][0].format(channel)


def declares_value_type(ch) -> bool:
    """The headers declare ch's value type <name>_t: a copy or STATUS channel without
    `type` (a TIME channel's value is uint32_t, a mode channel's alb_mode_t)."""
    return ch.ctype is None and (ch.kind == "copy" or (ch.kind == "status" and not ch.mode_info))


def board_macro(board: str, suffix: str) -> str:
    assert suffix in BOARD_MACROS, suffix
    return f"ALB_{board.upper()}_{suffix}"


def header_guard(system: str, board: str) -> str:
    return f"ALB_{system.upper()}_{board.upper()}_H"


def setup_function(board: str, what: str) -> str:
    assert what in SETUP_FUNCTIONS, what
    return f"alb_{board}_{what}_all"


def mode_macro(mode: str) -> str:
    return f"ALB_MODE_{mode.upper()}"


# ---------------------------------------------------------------------------
# The enumeration.

class Source:
    """Where a name comes from: the system, a board, channel or mode (its index in
    the description), or the generated files themselves (kind "fixed")."""

    def __init__(self, kind: str, index: int = 0, name: str = ""):
        self.kind, self.index, self.name = kind, index, name

    @property
    def label(self) -> str:
        return "the generated files (a fixed name)" if self.kind == "fixed" else f"{self.kind} '{self.name}'"

    def __eq__(self, other):
        return isinstance(other, Source) and (self.kind, self.index) == (other.kind, other.index)

    def __hash__(self):
        return hash((self.kind, self.index))


FIXED = Source("fixed")


def channel_names(ch) -> list:
    """(identifier, what it is) generated for channel ch (any of its roles)."""
    n = ch.name
    out = [(message_type(n), "message type")]
    if declares_value_type(ch):
        out.append((value_type(n), "value type"))
    out += [(channel_macro(n, s), "macro") for s in CHANNEL_MACROS]
    out += [(size_check(n), "size check"), (taken_at_check(n), "layout check")]
    for names in DRIVER_MACRO_NAMES.values():
        out += [(t.format(n), what) for t, what in names if (t.format(n), what) not in out]
    return out


def board_names(system_name: str, board: str) -> list:
    return ([(board_macro(board, s), "macro") for s in BOARD_MACROS]
            + [(header_guard(system_name, board), "header guard")]
            + [(setup_function(board, w), "set-up function") for w in SETUP_FUNCTIONS])


def generated_names(system_name: str, boards: list, channels: list, modes: list) -> list:
    """Every identifier and macro the generated C may declare, as (identifier,
    what it is, Source), in the order fixed names, boards, channels, modes.
    boards: names (a None entry is skipped, its index kept); channels: objects
    with name, index, ctype, kind, mode_info; modes: names (None skipped)."""
    out = [(ident, what, FIXED) for ident, what in FIXED_NAMES.items()]
    for i, b in enumerate(boards):
        if b is not None:
            out += [(ident, what, Source("board", i, b)) for ident, what in board_names(system_name, b)]
    for ch in channels:
        out += [(ident, what, Source("channel", ch.index, ch.name)) for ident, what in channel_names(ch)]
    for i, m in enumerate(modes):
        if m is not None:
            out.append((mode_macro(m), "macro", Source("mode", i, m)))
    return out


def system_names(system) -> set:
    """The identifiers of generated_names() for a parsed System."""
    return {ident for ident, _, _ in generated_names(system.name, system.boards, system.channels,
                                                     [m.name for m in system.modes])}


def reserved_why(ident: str):
    """Why ident may not be declared by generated code, or None."""
    if ident in C_KEYWORDS:
        return "a C keyword"
    for header, names in STD_NAMES.items():
        if ident in names:
            return f"a {header} name"
    if ident in DRIVER_IDENTIFIERS:
        return "an identifier of the driver (c-driver/)"
    return None


def check_names(system_name: str, boards: list, channels: list, modes: list, err) -> None:
    """Report every name whose C identifiers or files collide (err: source.Errors).
    boards: the valid board names (None for an invalid one); channels: the parsed
    Channel objects with a valid, unique name; modes: the [[mode]] names (None for
    an invalid one).  Each message names the entity and field, and for a name
    generated twice the other source and its line."""

    def report(src, msg, value=None):
        if src.kind == "board":
            err.system("boards", f"board '{src.name}': {msg}", value=src.name)
        elif src.kind == "channel":
            err.channel(src.index, src.name, "name", msg)
        elif src.kind == "mode":
            err.mode(src.index, src.name, "name", msg)
        else:
            err.system("name", f"system name '{src.name}': {msg}")

    def line_of(src):
        if src.kind == "fixed":
            return None
        if src.kind == "mode":
            return err.loc.line("mode", src.index, "name")
        if src.kind == "channel":
            return err.loc.line("channel", src.index, "name")
        pos = err.loc.position("system", 0, "boards" if src.kind == "board" else "name", src.name)
        return pos[0] if pos else None

    system = Source("system", 0, system_name)
    why = reserved_why(system_name)
    if why:
        report(system, f"'{system_name}' is {why}")
    for i, b in enumerate(boards):
        if b is None:
            continue
        low = b.lower()
        if low in STD_HEADERS:
            report(Source("board", i, b), f"its header {b}.h would hide the C standard header <{low}.h>")
        elif low in DRIVER_HEADERS:
            report(Source("board", i, b), f"its header {b}.h would overwrite the driver header {low}.h")
        elif reserved_why(b):
            report(Source("board", i, b), f"'{b}' is {reserved_why(b)}")
    bad = set()                     # sources already reported: one message each
    for ch in channels:
        why = reserved_why(ch.name)
        if why:
            report(Source("channel", ch.index, ch.name), f"'{ch.name}' is {why}")
            bad.add(Source("channel", ch.index, ch.name))

    owner = {}                      # identifier -> (what, Source)
    for ident, what, src in generated_names(system_name, boards, channels, modes):
        if src in bad:
            continue
        why = reserved_why(ident) if src is not FIXED else None
        if why is None and ident in FIXED_NAMES and src is not FIXED:
            why = "a fixed name of the generated files"
        if why:
            report(src, f"its {what} {ident} is {why}")
            bad.add(src)
        elif ident in owner:
            other_what, other = owner[ident]
            line = line_of(other)
            report(src, f"its {what} {ident} is also generated for {other.label} ({other_what}"
                   + (f", line {line}" if line else "") + ")")
            bad.add(src)
        else:
            owner[ident] = (what, src)

    for ch in channels:             # a named type: a type name, not one the generated files declare
        if not ch.ctype:
            continue
        words = ch.ctype.split()
        tag = words[-1]
        if tag in C_KEYWORDS and not (len(words) == 1 and tag in C_TYPE_KEYWORDS):
            err.channel(ch.index, ch.name, "type", f"'{ch.ctype}': '{tag}' is a C keyword, not a type name")
        elif len(words) > 1:
            continue
        elif tag in owner and owner[tag][1] is FIXED:
            err.channel(ch.index, ch.name, "type", f"'{ch.ctype}' is a {owner[tag][0]} that the generated "
                        "headers declare themselves")
        elif tag in owner:
            err.channel(ch.index, ch.name, "type", f"'{ch.ctype}' is the {owner[tag][0]} that the generated "
                        f"headers declare for {owner[tag][1].label}")
        elif tag not in C_KEYWORDS and reserved_why(tag) and (tag in DRIVER_IDENTIFIERS or not tag.endswith("_t")):
            err.channel(ch.index, ch.name, "type", f"'{ch.ctype}' is {reserved_why(tag)}, not a type name")
