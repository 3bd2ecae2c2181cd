/*
 * test_driver.c -- host unit tests of the ALBATROSS C driver (c-driver/),
 * built against the counting, trapping port layer in tb/unit/port/.
 *
 * Single-threaded and deterministic.  The partner of the side under test is
 * played by writing the control bytes into the RAM array directly, or, for
 * a partner that acts in the middle of a call, by the port's scripted hook.
 * Each check that fails prints what was expected and what was got; the last
 * line is "driver-unit: N checks, F failed" and the exit status is 1 if any
 * check failed.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "albatross.h"
#include "alb_port.h"

struct unit_port unit_port;

/* ------------------------------------------------------------------------ */
/* checks                                                                     */

#define MAX_SHOWN 60

static unsigned long g_checks, g_fails;
static char g_ctx[160];

#define CTX(...) snprintf(g_ctx, sizeof g_ctx, __VA_ARGS__)

static int fail_shown(void)
{
    g_fails++;
    if (g_fails <= MAX_SHOWN)
        return 1;
    if (g_fails == MAX_SHOWN + 1u)
        printf("FAIL ... further failures not shown\n");
    return 0;
}

static int check_int(const char *what, long expected, long got)
{
    g_checks++;
    if (expected == got)
        return 1;
    if (fail_shown())
        printf("FAIL [%s] %s: expected %ld, got %ld\n", g_ctx, what, expected, got);
    return 0;
}

static int check_true(const char *what, int cond, const char *detail)
{
    g_checks++;
    if (cond)
        return 1;
    if (fail_shown())
        printf("FAIL [%s] %s: %s\n", g_ctx, what, detail);
    return 0;
}

static int check_bytes(const char *what, const uint8_t *expected,
                       const uint8_t *got, size_t n)
{
    size_t i;

    g_checks++;
    for (i = 0; i < n; ++i)
        if (expected[i] != got[i])
            break;
    if (i == n)
        return 1;
    if (fail_shown())
        printf("FAIL [%s] %s: byte %lu of %lu: expected 0x%02x, got 0x%02x\n",
               g_ctx, what, (unsigned long)i, (unsigned long)n,
               expected[i], got[i]);
    return 0;
}

/* n bytes at p all equal v */
static int check_fill(const char *what, const uint8_t *p, size_t n, uint8_t v)
{
    size_t i;

    g_checks++;
    for (i = 0; i < n; ++i)
        if (p[i] != v)
            break;
    if (i == n)
        return 1;
    if (fail_shown())
        printf("FAIL [%s] %s: byte %lu of %lu: expected 0x%02x, got 0x%02x\n",
               g_ctx, what, (unsigned long)i, (unsigned long)n, v, p[i]);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* the test port                                                              */

static const char *kind_name[UNIT_KINDS] = { "rd8", "wr8", "rd32", "wr32", "fence" };

void unit_trap(enum unit_kind kind, uintptr_t addr, const char *why)
{
    if (unit_port.traps++ == 0u)
        snprintf(unit_port.trap_msg, sizeof unit_port.trap_msg,
                 "trap: %s at 0x%lx %s (window 0x%lx..0x%lx)", kind_name[kind],
                 (unsigned long)addr, why, (unsigned long)unit_port.win_lo,
                 (unsigned long)unit_port.win_hi);
}

/* The port's watchdog fired: a call that does not return. */
void unit_runaway(unsigned long accesses)
{
    printf("FAIL %s: the driver made %lu RAM accesses since the port was last reset, expected a few per "
           "call (at most %lu in all): a loop that never ends; stopping\n", g_ctx, accesses,
           UNIT_MAX_ACCESSES);
    printf("driver-unit: %lu checks, %lu failed\n", g_checks + 1u, g_fails + 1u);
    exit(1);
}

/* Forget counts, log, traps and hook; the window becomes [lo, hi). */
static void port_reset(uintptr_t lo, uintptr_t hi)
{
    memset(unit_port.count, 0, sizeof unit_port.count);
    unit_port.traps = 0u;
    unit_port.trap_msg[0] = '\0';
    unit_port.nlog = 0u;
    unit_port.hook_at = 0u;
    unit_port.win_lo = lo;
    unit_port.win_hi = hi;
}

static unsigned long ram_accesses(void)
{
    return unit_port.count[UNIT_RD8] + unit_port.count[UNIT_WR8] +
           unit_port.count[UNIT_RD32] + unit_port.count[UNIT_WR32];
}

static uint8_t *ram(uintptr_t addr)
{
    return &unit_port.ram[addr - UNIT_RAM_BASE];
}

static void check_no_trap(void)
{
    check_true("no trapped access", unit_port.traps == 0u, unit_port.trap_msg);
    check_true("access log complete", unit_port.nlog <= UNIT_LOG_MAX,
               "more accesses than the log holds");
}

static void check_counts(const char *call, long rd8, long wr8, long rd32, long wr32)
{
    char what[96];

    snprintf(what, sizeof what, "%s: rd8 accesses", call);
    check_int(what, rd8, (long)unit_port.count[UNIT_RD8]);
    snprintf(what, sizeof what, "%s: wr8 accesses", call);
    check_int(what, wr8, (long)unit_port.count[UNIT_WR8]);
    snprintf(what, sizeof what, "%s: rd32 accesses", call);
    check_int(what, rd32, (long)unit_port.count[UNIT_RD32]);
    snprintf(what, sizeof what, "%s: wr32 accesses", call);
    check_int(what, wr32, (long)unit_port.count[UNIT_WR32]);
    check_no_trap();
}

/*
 * A fence must separate every access of kind a (at addr_a, or any address
 * if addr_a is 0) from every later access of kind b (at addr_b, or any).
 */
static void check_fence_between(const char *rule, enum unit_kind a, uintptr_t addr_a,
                                enum unit_kind b, uintptr_t addr_b)
{
    unsigned long i, n = unit_port.nlog < UNIT_LOG_MAX ? unit_port.nlog : UNIT_LOG_MAX;
    long pending = -1, bad = -1;

    for (i = 0; i < n && bad < 0; ++i) {
        const struct unit_access *e = &unit_port.log[i];
        if (e->kind == UNIT_FENCE)
            pending = -1;
        else if (e->kind == b && (addr_b == 0u || e->addr == addr_b) && pending >= 0)
            bad = (long)i;
        if (e->kind == a && (addr_a == 0u || e->addr == addr_a))
            pending = (long)i;
    }
    g_checks++;
    if (bad >= 0 && fail_shown())
        printf("FAIL [%s] fence missing (%s): %s at log[%ld] is followed by %s at "
               "log[%ld] without a fence between\n", g_ctx, rule, kind_name[a],
               pending, kind_name[b], bad);
}

/* The word accesses of kind k in the log are exactly n, at first, first+4, ... */
static void check_words_at(const char *what, enum unit_kind k, uintptr_t first, long n)
{
    unsigned long i, lim = unit_port.nlog < UNIT_LOG_MAX ? unit_port.nlog : UNIT_LOG_MAX;
    long seen = 0, bad = -1;
    uintptr_t got = 0u;

    for (i = 0; i < lim; ++i) {
        if (unit_port.log[i].kind != k)
            continue;
        if (bad < 0 && unit_port.log[i].addr != first + 4u * (uintptr_t)seen) {
            bad = seen;
            got = unit_port.log[i].addr;
        }
        seen++;
    }
    g_checks++;
    if (bad >= 0 && fail_shown())
        printf("FAIL [%s] %s: %s number %ld at 0x%lx, expected 0x%lx\n", g_ctx, what,
               kind_name[k], bad, (unsigned long)got,
               (unsigned long)(first + 4u * (uintptr_t)bad));
    check_int(what, n, seen);
}

/* ------------------------------------------------------------------------ */
/* channels                                                                   */

#define BIG      67u                       /* largest payload of the sweep  */
#define CH_OFF   64u                       /* channel offset in the RAM     */
#define RAM_FILL 0xc3u

static uintptr_t ch_base = UNIT_RAM_BASE + CH_OFF;
static uint32_t  ch_size;

static uintptr_t a_actual(void) { return ch_base + ALB_OFF_ACTUAL; }
static uintptr_t a_rl(void)     { return ch_base + ALB_OFF_READLOCKED; }
static uintptr_t a_buf(unsigned b) { return ch_base + ALB_OFF_BUFFER(b, ch_size); }
static long words(uint32_t size) { return (long)((size + 3u) / 4u); }

/* Fresh RAM; a channel of the given size; p (producer) and c (consumer) set
 * up, not initialised; the window is the channel. */
static void new_channel(alb_channel_t *p, alb_channel_t *c, uint32_t size)
{
    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    ch_size = size;
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    check_int("alb_channel_setup (producer)", ALB_OK, alb_channel_setup(p, ch_base, size));
    check_int("alb_channel_setup (consumer)", ALB_OK, alb_channel_setup(c, ch_base, size));
}

static void set_control(unsigned actual, unsigned read_locked)
{
    *ram(a_actual()) = (uint8_t)actual;
    *ram(a_rl()) = (uint8_t)read_locked;
}

static void pattern(uint8_t *p, size_t n, unsigned seed)
{
    size_t i;
    for (i = 0; i < n; ++i)
        p[i] = (uint8_t)(seed * 31u + i * 7u + 1u);
}

/* Which buffer (1..3) holds addr, 0 if none. */
static unsigned buffer_of(uintptr_t addr)
{
    unsigned b;
    for (b = 1u; b <= 3u; ++b)
        if (addr >= a_buf(b) && addr < a_buf(b) + ALB_STRIDE(ch_size))
            return b;
    return 0u;
}

/* RAM bytes that changed since snap, other than [lo, hi) and the Actual byte. */
static void check_ram_unchanged(const char *what, const uint8_t *snap,
                                uintptr_t lo, uintptr_t hi, int actual_may_change)
{
    size_t i;
    long first = -1;

    for (i = 0; i < UNIT_RAM_BYTES; ++i) {
        uintptr_t a = UNIT_RAM_BASE + i;
        if (a >= lo && a < hi)
            continue;
        if (actual_may_change && a == a_actual())
            continue;
        if (unit_port.ram[i] != snap[i]) {
            first = (long)i;
            break;
        }
    }
    g_checks++;
    if (first >= 0 && fail_shown())
        printf("FAIL [%s] %s: RAM byte at 0x%lx changed from 0x%02x to 0x%02x\n",
               g_ctx, what, (unsigned long)(UNIT_RAM_BASE + (size_t)first),
               snap[first], unit_port.ram[first]);
}

/* ------------------------------------------------------------------------ */
/* tests                                                                      */

static void test_port_traps(void)
{
    uint8_t snap[UNIT_RAM_BYTES];

    CTX("port self-test");
    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    memcpy(snap, unit_port.ram, sizeof snap);
    port_reset(UNIT_RAM_BASE + 64u, UNIT_RAM_BASE + 128u);
    alb_wr8(UNIT_RAM_BASE + 63u, 1u);
    check_int("write below the window traps", 1, (long)unit_port.traps);
    check_int("trapped load returns 0", 0, alb_rd8(UNIT_RAM_BASE + 128u));
    check_int("read above the window traps", 2, (long)unit_port.traps);
    port_reset(UNIT_RAM_BASE, UNIT_RAM_BASE + UNIT_RAM_BYTES + 8u);
    alb_wr32(UNIT_RAM_BASE + UNIT_RAM_BYTES, 0u);
    alb_wr32(UNIT_RAM_BASE + UNIT_RAM_BYTES - 2u, 0u);
    alb_wr8(UNIT_RAM_BASE - 1u, 0u);
    alb_wr32(0u, 0u);
    check_int("accesses outside the RAM trap", 4, (long)unit_port.traps);
    alb_wr32(UNIT_RAM_BASE + 2u, 0u);
    check_int("misaligned word access traps", 5, (long)unit_port.traps);
    check_bytes("trapped accesses leave the RAM alone", snap, unit_port.ram, sizeof snap);
    check_int("accesses are counted", 5, (long)ram_accesses());
}

static void test_setup_args(void)
{
    alb_channel_t ch;
    unsigned off;

    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    port_reset(0u, 0u);
    for (off = 1u; off <= 3u; ++off) {
        CTX("alb_channel_setup, base offset %u", off);
        check_int("misaligned base", ALB_ERR_ARG, alb_channel_setup(&ch, ch_base + off, 8u));
    }
    CTX("alb_channel_setup");
    check_int("size 0", ALB_ERR_ARG, alb_channel_setup(&ch, ch_base, 0u));
    check_int("null channel", ALB_ERR_ARG, alb_channel_setup(0, ch_base, 8u));
    memset(&ch, 0x55, sizeof ch);
    check_int("aligned base, size 5", ALB_OK, alb_channel_setup(&ch, ch_base, 5u));
    check_true("base kept", ch.base == ch_base, "ch.base differs");
    check_int("size kept", 5, (long)ch.size);
    check_int("no Actual copy yet", 0, ch.actual);
    check_int("no ReadLocked copy yet", 0, ch.read_locked);
    check_int("set-up makes no RAM access", 0, (long)ram_accesses());
    check_no_trap();
}

static void test_uninitialised(void)
{
    alb_channel_t p, c, zero;
    uint8_t v[8], d[8], keep[8];

    CTX("uninitialised sides");
    new_channel(&p, &c, 8u);
    set_control(1u, 1u);
    pattern(v, sizeof v, 1u);
    memset(d, 0x77, sizeof d);
    memcpy(keep, d, sizeof d);
    port_reset(0u, 0u);     /* any access at all traps */
    check_int("alb_import, consumer never initialised", ALB_ERR_ARG, alb_import(&c, d));
    check_int("alb_export, producer never initialised", ALB_ERR_ARG, alb_export(&p, v));
    check_bytes("*dst unchanged", keep, d, sizeof d);

    memset(&zero, 0, sizeof zero);    /* never set up */
    check_int("alb_producer_init, never set up", ALB_ERR_ARG, alb_producer_init(&zero, v));
    check_int("alb_producer_attach, never set up", ALB_ERR_ARG, alb_producer_attach(&zero));
    check_int("alb_consumer_init, never set up", ALB_ERR_ARG, alb_consumer_init(&zero));
    check_int("alb_consumer_attach, never set up", ALB_ERR_ARG, alb_consumer_attach(&zero));
    check_int("alb_import, never set up", ALB_ERR_ARG, alb_import(&zero, d));
    check_int("alb_export, never set up", ALB_ERR_ARG, alb_export(&zero, v));
    check_int("alb_producer_init, null value", ALB_ERR_ARG, alb_producer_init(&p, 0));
    check_int("null channel: producer_init", ALB_ERR_ARG, alb_producer_init(0, v));
    check_int("null channel: consumer_init", ALB_ERR_ARG, alb_consumer_init(0));
    check_int("null channel: import", ALB_ERR_ARG, alb_import(0, d));
    check_int("null channel: export", ALB_ERR_ARG, alb_export(0, v));
    check_int("no RAM access by any rejected call", 0, (long)ram_accesses());
    check_int("no trap", 0, (long)unit_port.traps);

    /* each side's object knows only its own side */
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(8u));
    check_int("alb_producer_init", ALB_OK, alb_producer_init(&p, v));
    check_int("alb_consumer_init", ALB_OK, alb_consumer_init(&c));
    port_reset(0u, 0u);
    check_int("alb_import on the producer's object", ALB_ERR_ARG, alb_import(&p, d));
    check_int("alb_export on the consumer's object", ALB_ERR_ARG, alb_export(&c, v));
    check_int("alb_import, null destination", ALB_ERR_ARG, alb_import(&c, 0));
    check_int("alb_export, null source", ALB_ERR_ARG, alb_export(&p, 0));
    check_bytes("*dst unchanged", keep, d, sizeof d);
    check_int("no RAM access by any rejected call", 0, (long)ram_accesses());
    check_int("no trap", 0, (long)unit_port.traps);
}

static void test_init_attach(void)
{
    alb_channel_t p, c;
    uint8_t v[13], d[13];
    unsigned a, r;

    CTX("init, size 13");
    new_channel(&p, &c, 13u);
    pattern(v, sizeof v, 2u);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
    check_int("alb_producer_init", ALB_OK, alb_producer_init(&p, v));
    check_counts("alb_producer_init", 0, 1, 0, words(13u));
    check_words_at("alb_producer_init writes Buffer1", UNIT_WR32, a_buf(1u), words(13u));
    check_fence_between("initial value before Actual", UNIT_WR32, 0u, UNIT_WR8, a_actual());
    check_int("Actual in RAM", 1, *ram(a_actual()));
    check_int("producer's copy of Actual", 1, p.actual);
    check_bytes("Buffer1 holds the initial value", v, ram(a_buf(1u)), sizeof v);
    check_int("ReadLocked untouched", RAM_FILL, *ram(a_rl()));

    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
    check_int("alb_consumer_init", ALB_OK, alb_consumer_init(&c));
    check_counts("alb_consumer_init", 0, 1, 0, 0);
    check_int("ReadLocked in RAM", 1, *ram(a_rl()));
    check_int("consumer's copy of ReadLocked", 1, c.read_locked);
    check_int("Actual untouched", 1, *ram(a_actual()));

    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
    memset(d, 0x77, sizeof d);
    check_int("alb_import right after init: Old", ALB_OLD, alb_import(&c, d));
    check_counts("alb_import after init", 1, 0, words(13u), 0);
    check_bytes("alb_import after init returns the initial value", v, d, sizeof d);

    for (a = 1u; a <= 3u; ++a)
        for (r = 1u; r <= 3u; ++r) {
            CTX("attach, Actual=%u ReadLocked=%u", a, r);
            new_channel(&p, &c, 13u);
            set_control(a, r);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
            check_int("alb_producer_attach", ALB_OK, alb_producer_attach(&p));
            check_int("producer's copy of Actual", (long)a, p.actual);
            check_counts("alb_producer_attach", 1, 0, 0, 0);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
            check_int("alb_consumer_attach", ALB_OK, alb_consumer_attach(&c));
            check_int("consumer's copy of ReadLocked", (long)r, c.read_locked);
            check_counts("alb_consumer_attach", 1, 0, 0, 0);
            check_int("Actual untouched", (long)a, *ram(a_actual()));
            check_int("ReadLocked untouched", (long)r, *ram(a_rl()));
        }
}

static void test_export_import(void)
{
    alb_channel_t p, c;
    uint8_t v[3][24], d[24];
    unsigned i;

    CTX("export/import, size 24");
    new_channel(&p, &c, 24u);
    pattern(v[0], sizeof v[0], 10u);
    pattern(v[1], sizeof v[1], 11u);
    pattern(v[2], sizeof v[2], 12u);
    alb_producer_init(&p, v[0]);
    alb_consumer_init(&c);
    for (i = 0; i < 6u; ++i) {
        CTX("export/import, size 24, round %u", i);
        check_int("alb_export", ALB_OK, alb_export(&p, v[1 + i % 2u]));
        memset(d, 0, sizeof d);
        check_int("first alb_import: New", ALB_NEW, alb_import(&c, d));
        check_bytes("first alb_import: the exported bytes", v[1 + i % 2u], d, sizeof d);
        memset(d, 0, sizeof d);
        check_int("second alb_import: Old", ALB_OLD, alb_import(&c, d));
        check_bytes("second alb_import: the same bytes", v[1 + i % 2u], d, sizeof d);
    }
    CTX("export/import, size 24, two exports then import");
    check_int("alb_export", ALB_OK, alb_export(&p, v[0]));
    check_int("alb_export", ALB_OK, alb_export(&p, v[2]));
    check_int("alb_import: New", ALB_NEW, alb_import(&c, d));
    check_bytes("alb_import: the newest value", v[2], d, sizeof d);
    check_int("alb_import: Old", ALB_OLD, alb_import(&c, d));
    check_no_trap();
}

/* Access counts, exact bytes and guard bytes for one size and alignment. */
static void sweep_one(uint32_t size, unsigned so, unsigned dof)
{
    static union { uint32_t align; uint8_t b[BIG + 16u]; } sbuf, dbuf;
    alb_channel_t p, c;
    uint8_t init[BIG], snap[UNIT_RAM_BYTES], keep[BIG];
    uint8_t *src = sbuf.b + so, *dst = dbuf.b + 4u + dof;
    const uint8_t guard = 0x5a;
    unsigned b;

    CTX("size %u, source offset %u, destination offset %u", (unsigned)size, so, dof);
    new_channel(&p, &c, size);
    pattern(init, size, 3u);
    alb_producer_init(&p, init);
    alb_consumer_init(&c);
    memset(sbuf.b, 0xee, sizeof sbuf.b);
    pattern(src, size, 100u + size + so);
    memcpy(keep, src, size);

    /* Export: 2 accesses beyond the payload */
    memcpy(snap, unit_port.ram, sizeof snap);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    check_int("alb_export", ALB_OK, alb_export(&p, src));
    check_counts("alb_export", 1, 1, 0, words(size));
    check_int("alb_export: accesses beyond the payload", 2,
              (long)(unit_port.count[UNIT_RD8] + unit_port.count[UNIT_WR8]));
    b = *ram(a_actual());
    check_int("alb_export: published buffer (Actual=1, ReadLocked=1)", 3, (long)b);
    check_int("producer's copy of Actual", 3, p.actual);
    if (b >= 1u && b <= 3u) {
        check_words_at("alb_export: payload words", UNIT_WR32, a_buf(b), words(size));
        check_bytes("alb_export: payload in the RAM", src, ram(a_buf(b)), size);
        check_ram_unchanged("alb_export writes only its buffer and Actual", snap,
                            a_buf(b), a_buf(b) + ALB_STRIDE(size), 1);
    }
    check_bytes("alb_export leaves the source alone", keep, src, size);
    check_fence_between("release: data before Actual", UNIT_WR32, 0u, UNIT_WR8, a_actual());
    check_int("alb_export: last access stores Actual", (long)a_actual(),
              unit_port.nlog ? (long)unit_port.log[(unit_port.nlog - 1u) % UNIT_LOG_MAX].addr : -1);

    /* Import, new data: 3 accesses beyond the payload */
    memset(dbuf.b, guard, sizeof dbuf.b);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    check_int("alb_import: New", ALB_NEW, alb_import(&c, dst));
    check_counts("alb_import (new)", 2, 1, words(size), 0);
    check_int("alb_import (new): accesses beyond the payload", 3,
              (long)(unit_port.count[UNIT_RD8] + unit_port.count[UNIT_WR8]));
    check_words_at("alb_import (new): payload words", UNIT_RD32, a_buf(3u), words(size));
    check_bytes("alb_import (new): exact bytes", keep, dst, size);
    check_fill("alb_import (new): guard bytes before *dst", dbuf.b, 4u + dof, guard);
    check_fill("alb_import (new): guard bytes after *dst", dst + size,
               sizeof dbuf.b - (4u + dof + size), guard);
    check_int("ReadLocked in RAM", 3, *ram(a_rl()));
    check_int("consumer's copy of ReadLocked", 3, c.read_locked);
    check_fence_between("ReadLocked store before Actual load", UNIT_WR8, a_rl(),
                        UNIT_RD8, a_actual());
    check_fence_between("acquire: Actual before data", UNIT_RD8, a_actual(), UNIT_RD32, 0u);

    /* Import, no new data: 1 access beyond the payload */
    memset(dbuf.b, guard, sizeof dbuf.b);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    check_int("alb_import: Old", ALB_OLD, alb_import(&c, dst));
    check_counts("alb_import (no new)", 1, 0, words(size), 0);
    check_words_at("alb_import (no new): payload words", UNIT_RD32, a_buf(3u), words(size));
    check_bytes("alb_import (no new): exact bytes", keep, dst, size);
    check_fill("alb_import (no new): guard bytes before *dst", dbuf.b, 4u + dof, guard);
    check_fill("alb_import (no new): guard bytes after *dst", dst + size,
               sizeof dbuf.b - (4u + dof + size), guard);
    check_fence_between("acquire: Actual before data", UNIT_RD8, a_actual(), UNIT_RD32, 0u);

    /* Two exports in a row: store of Actual, fence, load of ReadLocked */
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    alb_export(&p, src);
    alb_export(&p, init);
    check_counts("two alb_exports", 2, 2, 0, 2 * words(size));
    check_fence_between("Actual store before ReadLocked load", UNIT_WR8, a_actual(),
                        UNIT_RD8, a_rl());
}

static void test_sweep(void)
{
    uint32_t size;
    unsigned so, dof;

    for (size = 1u; size <= BIG; ++size)
        for (so = 0u; so < 4u; ++so)
            for (dof = 0u; dof < 4u; ++dof)
                sweep_one(size, so, dof);
}

/* Figure 4: the buffer written for every valid (Actual, ReadLocked). */
static void test_selection(void)
{
    alb_channel_t p, c;
    uint8_t v[10], snap[UNIT_RAM_BYTES];
    unsigned a, r, want;

    pattern(v, sizeof v, 7u);
    for (a = 1u; a <= 3u; ++a)
        for (r = 1u; r <= 3u; ++r) {
            CTX("selection, Actual=%u ReadLocked=%u", a, r);
            want = a != r ? 6u - a - r : (a == 3u ? 2u : 3u);
            new_channel(&p, &c, 10u);
            set_control(a, r);
            alb_producer_attach(&p);
            memcpy(snap, unit_port.ram, sizeof snap);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(10u));
            check_int("alb_export", ALB_OK, alb_export(&p, v));
            check_counts("alb_export", 1, 1, 0, words(10u));
            check_int("buffer published in Actual", (long)want, *ram(a_actual()));
            check_int("producer's copy of Actual", (long)want, p.actual);
            check_words_at("payload written to the selected buffer", UNIT_WR32,
                           a_buf(want), words(10u));
            check_bytes("payload", v, ram(a_buf(want)), sizeof v);
            check_ram_unchanged("nothing else written", snap, a_buf(want),
                                a_buf(want) + ALB_STRIDE(10u), 1);
        }
}

/* Actual out of range: alb_import reports it and reads no buffer. */
static void test_corrupt_actual(void)
{
    alb_channel_t p, c;
    uint8_t d[9], keep[9], v[9];
    unsigned bad, r;

    for (r = 1u; r <= 3u; ++r)
        for (bad = 0u; bad < 256u; ++bad) {
            if (bad >= 1u && bad <= 3u)
                continue;
            CTX("Actual=%u, ReadLocked=%u", bad, r);
            new_channel(&p, &c, 9u);
            set_control(bad, r);
            alb_consumer_attach(&c);
            memset(d, 0x77, sizeof d);
            memcpy(keep, d, sizeof d);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(9u));
            check_int("alb_import", ALB_ERR_CORRUPT, alb_import(&c, d));
            check_int("no buffer read", 0, (long)unit_port.count[UNIT_RD32]);
            check_int("no write", 0, (long)(unit_port.count[UNIT_WR8] + unit_port.count[UNIT_WR32]));
            check_bytes("*dst unchanged", keep, d, sizeof d);
            check_int("ReadLocked kept", (long)r, *ram(a_rl()));
            check_int("consumer's copy of ReadLocked kept", (long)r, c.read_locked);
            check_no_trap();
        }

    /* The producer publishes a corrupt value between the two loads of Actual */
    for (bad = 0u; bad < 256u; ++bad) {
        if (bad >= 1u && bad <= 3u)
            continue;
        CTX("Actual 2 then %u during the import, ReadLocked=1", bad);
        new_channel(&p, &c, 9u);
        set_control(2u, 1u);
        alb_consumer_attach(&c);
        memset(d, 0x77, sizeof d);
        memcpy(keep, d, sizeof d);
        port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(9u));
        unit_port.hook_at = 3u;     /* rd8 Actual, wr8 ReadLocked, rd8 Actual */
        unit_port.hook_addr = a_actual();
        unit_port.hook_value = (uint8_t)bad;
        check_int("alb_import", ALB_ERR_CORRUPT, alb_import(&c, d));
        check_int("no buffer read", 0, (long)unit_port.count[UNIT_RD32]);
        check_bytes("*dst unchanged", keep, d, sizeof d);
        check_no_trap();
    }

    /* After a repair the consumer goes on */
    CTX("Actual repaired after corruption");
    new_channel(&p, &c, 9u);
    pattern(v, sizeof v, 5u);
    alb_producer_init(&p, v);
    alb_consumer_init(&c);
    *ram(a_actual()) = 0xffu;
    check_int("alb_import, corrupt", ALB_ERR_CORRUPT, alb_import(&c, d));
    *ram(a_actual()) = 1u;
    check_int("alb_import, repaired", ALB_OLD, alb_import(&c, d));
    check_bytes("alb_import, repaired: value", v, d, sizeof v);
}

/* The selection loop repeats while the producer publishes again. */
static void test_import_loop(void)
{
    alb_channel_t p, c;
    uint8_t d[8];

    CTX("Actual 2 then 3 during the import, ReadLocked=1");
    new_channel(&p, &c, 8u);
    set_control(2u, 1u);
    pattern(ram(a_buf(2u)), 8u, 20u);
    pattern(ram(a_buf(3u)), 8u, 30u);
    alb_consumer_attach(&c);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(8u));
    unit_port.hook_at = 3u;
    unit_port.hook_addr = a_actual();
    unit_port.hook_value = 3u;
    check_int("alb_import", ALB_NEW, alb_import(&c, d));
    check_counts("alb_import, loop taken twice", 3, 2, words(8u), 0);
    check_int("ReadLocked in RAM", 3, *ram(a_rl()));
    check_int("consumer's copy of ReadLocked", 3, c.read_locked);
    check_words_at("reads Buffer3", UNIT_RD32, a_buf(3u), words(8u));
    check_bytes("value of Buffer3", ram(a_buf(3u)), d, sizeof d);
}

/* ReadLocked out of range: alb_export reports it and publishes anyway. */
static void test_corrupt_read_locked(void)
{
    alb_channel_t p, c;
    uint8_t v[11], w[11], snap[UNIT_RAM_BYTES];
    unsigned bad, a, b, b2;

    pattern(v, sizeof v, 8u);
    pattern(w, sizeof w, 9u);
    for (a = 1u; a <= 3u; ++a)
        for (bad = 0u; bad < 256u; ++bad) {
            if (bad >= 1u && bad <= 3u)
                continue;
            CTX("Actual=%u, ReadLocked=%u", a, bad);
            new_channel(&p, &c, 11u);
            set_control(a, bad);
            alb_producer_attach(&p);
            memcpy(snap, unit_port.ram, sizeof snap);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(11u));
            check_int("alb_export", ALB_ERR_CORRUPT, alb_export(&p, v));
            check_counts("alb_export", 1, 1, 0, words(11u));
            b = *ram(a_actual());
            check_true("published into a buffer 1..3", b >= 1u && b <= 3u,
                       "Actual is not a buffer index");
            check_true("published into a buffer other than Actual", b != a,
                       "the buffer the consumer may be reading was overwritten");
            check_int("producer's copy of Actual", (long)b, p.actual);
            if (b < 1u || b > 3u)
                continue;
            check_words_at("payload written to the published buffer", UNIT_WR32,
                           a_buf(b), words(11u));
            check_bytes("payload", v, ram(a_buf(b)), sizeof v);
            check_ram_unchanged("nothing else written", snap, a_buf(b),
                                a_buf(b) + ALB_STRIDE(11u), 1);
            /* and again: the producer is never stopped */
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(11u));
            check_int("second alb_export", ALB_ERR_CORRUPT, alb_export(&p, w));
            b2 = *ram(a_actual());
            check_true("second export: a buffer other than the last Actual",
                       b2 >= 1u && b2 <= 3u && b2 != b, "wrong buffer");
            if (b2 >= 1u && b2 <= 3u)
                check_bytes("second export: payload", w, ram(a_buf(b2)), sizeof w);
            check_no_trap();
        }
}

/* Attach to corrupt control bytes. */
static void test_corrupt_attach(void)
{
    alb_channel_t p, c;
    uint8_t v[4] = { 1, 2, 3, 4 }, d[4];
    unsigned bad;

    for (bad = 0u; bad < 256u; ++bad) {
        if (bad >= 1u && bad <= 3u)
            continue;
        CTX("attach, control bytes %u", bad);
        new_channel(&p, &c, 4u);
        set_control(bad, bad);
        port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(4u));
        check_int("alb_producer_attach", ALB_ERR_CORRUPT, alb_producer_attach(&p));
        check_int("alb_consumer_attach", ALB_ERR_CORRUPT, alb_consumer_attach(&c));
        check_counts("two attaches", 2, 0, 0, 0);
        check_int("producer still has no copy", 0, p.actual);
        check_int("consumer still has no copy", 0, c.read_locked);
        port_reset(0u, 0u);
        check_int("alb_export after a failed attach", ALB_ERR_ARG, alb_export(&p, v));
        check_int("alb_import after a failed attach", ALB_ERR_ARG, alb_import(&c, d));
        check_int("no RAM access", 0, (long)ram_accesses());
    }
}

/*
 * A deterministic mixed sequence of exports and imports: no export writes
 * into the buffer the consumer holds or the one last published, and every
 * import returns the newest value, New exactly once per new value.
 */
static void test_sequence(void)
{
    alb_channel_t p, c;
    uint8_t v[4][19], d[19];
    uint32_t lcg = 12345u;
    unsigned i, k, latest = 0u, unread = 0u, held, act;
    unsigned long j;

    new_channel(&p, &c, 19u);
    for (k = 0; k < 4u; ++k)
        pattern(v[k], sizeof v[k], 40u + k);
    alb_producer_init(&p, v[0]);
    alb_consumer_init(&c);
    for (i = 0; i < 3000u; ++i) {
        lcg = lcg * 1103515245u + 12345u;
        CTX("sequence step %u", i);
        port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(19u));
        if ((lcg >> 16) & 1u) {
            k = (lcg >> 20) & 3u;
            held = *ram(a_rl());
            act = *ram(a_actual());
            check_int("alb_export", ALB_OK, alb_export(&p, v[k]));
            for (j = 0; j < unit_port.nlog && j < UNIT_LOG_MAX; ++j)
                if (unit_port.log[j].kind == UNIT_WR32) {
                    unsigned b = buffer_of(unit_port.log[j].addr);
                    check_true("export avoids the buffer held by the consumer",
                               b != held, "wrote into ReadLocked's buffer");
                    check_true("export avoids the last published buffer",
                               b != act, "wrote into Actual's buffer");
                }
            latest = k;
            unread = 1u;
        } else {
            memset(d, 0, sizeof d);
            check_int("alb_import", unread ? ALB_NEW : ALB_OLD, alb_import(&c, d));
            check_bytes("alb_import: newest value", v[latest], d, sizeof d);
            unread = 0u;
        }
        check_no_trap();
    }
}

/* The typed interface of seed 3.1. */
typedef struct {
    int16_t  range[5];
    uint8_t  quality;
    double   heading;
    char     tag[3];
} RadarShot;

ALB_CHANNEL(RadarMap, RadarShot)
ALB_CHANNEL_DEFINE(RadarMap);

static void test_typed(void)
{
    RadarShot shot, got, keep;
    alb_channel_t *prod = &alb_ch_RadarMap;
    int i;

    CTX("typed interface, RadarMap of RadarShot (%lu bytes)", (unsigned long)sizeof(RadarShot));
    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    ch_size = (uint32_t)sizeof(RadarShot);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(ch_size));
    memset(&shot, 0, sizeof shot);
    check_int("alb_channel_setup", ALB_OK, alb_channel_setup(prod, ch_base, ch_size));
    check_int("alb_producer_init", ALB_OK, alb_producer_init(prod, &shot));

    /* one object plays both sides here (on two CPUs each has its own) */
    check_int("alb_consumer_init", ALB_OK, alb_consumer_init(prod));

    for (i = 0; i < 5; ++i)
        shot.range[i] = (int16_t)(1000 * i - 1234);
    shot.quality = 200u;
    shot.heading = 271.25;
    memcpy(shot.tag, "RM", 3);
    check_int("MakeRadarMapAvailable", ALB_OK, MakeRadarMapAvailable(&shot));
    memset(&got, 0xa5, sizeof got);
    check_true("LookForNewRadarMap: true", LookForNewRadarMap(&got), "returned false");
    check_bytes("LookForNewRadarMap: the value", (const uint8_t *)&shot,
                (const uint8_t *)&got, sizeof shot);
    check_true("fields", got.heading == 271.25 && got.range[4] == 2766 &&
               got.quality == 200u && strcmp(got.tag, "RM") == 0, "field values differ");
    memset(&got, 0xa5, sizeof got);
    check_true("LookForNewRadarMap again: false", !LookForNewRadarMap(&got), "returned true");
    check_bytes("LookForNewRadarMap again: the same value", (const uint8_t *)&shot,
                (const uint8_t *)&got, sizeof shot);
    shot.quality = 7u;
    check_int("MakeRadarMapAvailable", ALB_OK, MakeRadarMapAvailable(&shot));
    check_true("LookForNewRadarMap after a new export: true", LookForNewRadarMap(&got),
               "returned false");
    check_int("new field value", 7, got.quality);

    /* errors: false and *v unchanged */
    *ram(a_actual()) = 0u;
    memcpy(&keep, &got, sizeof got);
    check_true("LookForNewRadarMap, corrupt Actual: false", !LookForNewRadarMap(&got),
               "returned true");
    check_bytes("LookForNewRadarMap, corrupt Actual: *v unchanged", (const uint8_t *)&keep,
                (const uint8_t *)&got, sizeof got);
    check_no_trap();
}

int main(void)
{
    test_port_traps();
    test_setup_args();
    test_uninitialised();
    test_init_attach();
    test_export_import();
    test_sweep();
    test_selection();
    test_corrupt_actual();
    test_import_loop();
    test_corrupt_read_locked();
    test_corrupt_attach();
    test_sequence();
    test_typed();
    printf("driver-unit: %lu checks, %lu failed\n", g_checks, g_fails);
    return g_fails == 0u ? EXIT_SUCCESS : EXIT_FAILURE;
}
