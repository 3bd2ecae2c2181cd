/*
 * unit_helpers.c -- the shared part of the host unit tests of the ALBATROSS
 * C driver (see test_driver.c): the checks, the test port's callbacks and
 * log inspection, and the channel under test.  Declared in unit_test.h.
 */
#include "unit_test.h"

struct unit_port unit_port;

/* ------------------------------------------------------------------------ */
/* checks                                                                     */

unsigned long g_checks, g_fails;
char g_ctx[160];

int fail_shown(void)
{
    g_fails++;
    if (g_fails <= MAX_SHOWN)
        return 1;
    if (g_fails == MAX_SHOWN + 1u)
        printf("FAIL ... further failures not shown\n");
    return 0;
}

int check_int(const char *what, long expected, long got)
{
    g_checks++;
    if (expected == got)
        return 1;
    if (fail_shown())
        printf("FAIL [%s] %s: expected %ld, got %ld\n", g_ctx, what, expected, got);
    return 0;
}

int check_true(const char *what, int cond, const char *detail)
{
    g_checks++;
    if (cond)
        return 1;
    if (fail_shown())
        printf("FAIL [%s] %s: %s\n", g_ctx, what, detail);
    return 0;
}

int check_bytes(const char *what, const uint8_t *expected,
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
int check_fill(const char *what, const uint8_t *p, size_t n, uint8_t v)
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

const char *kind_name[UNIT_KINDS] = { "rd8", "wr8", "rd32", "wr32", "fence" };

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
void port_reset(uintptr_t lo, uintptr_t hi)
{
    memset(unit_port.count, 0, sizeof unit_port.count);
    unit_port.traps = 0u;
    unit_port.trap_msg[0] = '\0';
    unit_port.nlog = 0u;
    unit_port.hook_at = 0u;
    unit_port.win_lo = lo;
    unit_port.win_hi = hi;
}

unsigned long ram_accesses(void)
{
    return unit_port.count[UNIT_RD8] + unit_port.count[UNIT_WR8] +
           unit_port.count[UNIT_RD32] + unit_port.count[UNIT_WR32];
}

uint8_t *ram(uintptr_t addr)
{
    return &unit_port.ram[addr - UNIT_RAM_BASE];
}

void check_no_trap(void)
{
    check_true("no trapped access", unit_port.traps == 0u, unit_port.trap_msg);
    check_true("access log complete", unit_port.nlog <= UNIT_LOG_MAX,
               "more accesses than the log holds");
}

void check_counts(const char *call, long rd8, long wr8, long rd32, long wr32)
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
void check_fence_between(const char *rule, enum unit_kind a, uintptr_t addr_a,
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
void check_words_at(const char *what, enum unit_kind k, uintptr_t first, long n)
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

uintptr_t ch_base = UNIT_RAM_BASE + CH_OFF;
uint32_t  ch_size;

uintptr_t a_actual(void) { return ch_base + ALB_OFF_ACTUAL; }
uintptr_t a_rl(void)     { return ch_base + ALB_OFF_READLOCKED; }
uintptr_t a_buf(unsigned b) { return ch_base + ALB_OFF_BUFFER(b, ch_size); }
long words(uint32_t size) { return (long)((size + 3u) / 4u); }

/* Fresh RAM; a channel of the given size; p (producer) and c (consumer) set
 * up, not initialised; the window is the channel. */
void new_channel(alb_channel_t *p, alb_channel_t *c, uint32_t size)
{
    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    ch_size = size;
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    check_int("alb_channel_setup (producer)", ALB_OK, alb_channel_setup(p, ch_base, size));
    check_int("alb_channel_setup (consumer)", ALB_OK, alb_channel_setup(c, ch_base, size));
}

void set_control(unsigned actual, unsigned read_locked)
{
    *ram(a_actual()) = (uint8_t)actual;
    *ram(a_rl()) = (uint8_t)read_locked;
}

void pattern(uint8_t *p, size_t n, unsigned seed)
{
    size_t i;
    for (i = 0; i < n; ++i)
        p[i] = (uint8_t)(seed * 31u + i * 7u + 1u);
}

/* Which buffer (1..3) holds addr, 0 if none. */
unsigned buffer_of(uintptr_t addr)
{
    unsigned b;
    for (b = 1u; b <= 3u; ++b)
        if (addr >= a_buf(b) && addr < a_buf(b) + ALB_STRIDE(ch_size))
            return b;
    return 0u;
}

/* RAM bytes that changed since snap, other than [lo, hi) and the Actual byte. */
void check_ram_unchanged(const char *what, const uint8_t *snap,
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
