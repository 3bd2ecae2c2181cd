/*
 * bench.c -- cycles of the real driver on PicoRV32 (tb/pico/pico_bench.v,
 * harness tb/pico/bench_pico.cpp, make bench-pico).  One core is both the
 * producer and the consumer of one channel at the start of the DPRAM window;
 * the other DPRAM port is idle, so every access takes its undisturbed time.
 *
 * For each payload size (4, 16, 64, 256 bytes) it times, with rdcycle around
 * the call, BENCH_REPS calls each of:
 *   M_EXPORT      alb_export
 *   M_IMPORT_NEW  alb_import returning New (an export before each, untimed)
 *   M_IMPORT_OLD  alb_import returning Old
 *   M_COPY_TO     the baseline: a plain volatile word loop copying the same
 *                 size from local RAM into the DPRAM window
 *   M_COPY_FROM   the same loop from the DPRAM window into local RAM
 * Built with -DBENCH_KIND=ALB_FOUR_SLOT the channel is of the four-slot kind
 * (default ALB_THREE_BUFFER).
 * The cost of an empty pair of rdcycle reads (the least of BENCH_REPS) is
 * subtracted from every sample.  Every import is checked against the value
 * exported (outside the timed window).
 *
 * Figures reach the harness as board EVENTs: store ARG (the figure), then
 * EVENT (the key: size << 16 | metric << 8 | field, field F_SUM, F_MIN or
 * F_MAX over the calls; key K_OVERHEAD: the rdcycle pair, K_REPS: calls per
 * figure).  Exit code 0, or 0x40 + size index on a driver error, 0x50 + size
 * index on a wrong imported value.
 */
#include "albatross.h"
#include "board.h"

#define BENCH_EVENT  ((uintptr_t)BOARD_EVENT)     /* board_memmap EVENT */
#define BENCH_ARG    ((uintptr_t)BOARD_EVENT_ARG) /* board_memmap ARG   */
#ifndef BENCH_KIND
#define BENCH_KIND   ALB_THREE_BUFFER                /* the channel kind measured */
#endif
#define BENCH_REPS   64u
#define BENCH_MAXW   64u                       /* words of the largest payload */
#define BENCH_COPY   ((uintptr_t)BOARD_DPRAM_BASE + 0x800u) /* plain-copy area */

enum { M_EXPORT, M_IMPORT_NEW, M_IMPORT_OLD, M_COPY_TO, M_COPY_FROM };
enum { F_SUM, F_MIN, F_MAX };
#define K_OVERHEAD 0xFFFF0000u
#define K_REPS     0xFFFF0001u

typedef struct { uint32_t sum, min, max; } stat_t;

static alb_channel_t prod, cons;
static uint32_t src[BENCH_MAXW], dst[BENCH_MAXW];
static uint32_t overhead;

static void event(uint32_t key, uint32_t value)
{
    *(volatile uint32_t *)BENCH_ARG = value;
    *(volatile uint32_t *)BENCH_EVENT = key;
}

static void stat_add(stat_t *s, uint32_t t0, uint32_t t1)
{
    uint32_t c = t1 - t0 - overhead;

    s->sum += c;
    if (c < s->min)
        s->min = c;
    if (c > s->max)
        s->max = c;
}

static void stat_send(uint32_t size, uint32_t metric, const stat_t *s)
{
    event(size << 16 | metric << 8 | F_SUM, s->sum);
    event(size << 16 | metric << 8 | F_MIN, s->min);
    event(size << 16 | metric << 8 | F_MAX, s->max);
}

/* The baseline, as written without ALBATROSS: a volatile word loop. */
static __attribute__((noinline)) void copy_to(volatile uint32_t *d, const uint32_t *s, uint32_t words)
{
    uint32_t i;

    for (i = 0u; i < words; ++i)
        d[i] = s[i];
}

static __attribute__((noinline)) void copy_from(uint32_t *d, const volatile uint32_t *s, uint32_t words)
{
    uint32_t i;

    for (i = 0u; i < words; ++i)
        d[i] = s[i];
}

static int same(uint32_t words)
{
    uint32_t i;

    for (i = 0u; i < words; ++i)
        if (dst[i] != src[i])
            return 0;
    return 1;
}

static void fill(uint32_t seed, uint32_t words)
{
    uint32_t i;

    for (i = 0u; i < words; ++i)
        src[i] = seed * 0x9E3779B9u + i;
}

static int bench_size(uint32_t k, uint32_t size)
{
    stat_t st[5];
    uint32_t words = size / 4u, rep, m, t0, t1;
    volatile uint32_t *win = (volatile uint32_t *)BENCH_COPY;
    int r;

    for (m = 0u; m < 5u; ++m) {
        st[m].sum = 0u;
        st[m].min = 0xFFFFFFFFu;
        st[m].max = 0u;
    }
    fill(0u, words);
    if (alb_channel_setup_kind(&prod, BOARD_CHANNEL, size, BENCH_KIND) != ALB_OK ||
        alb_channel_setup_kind(&cons, BOARD_CHANNEL, size, BENCH_KIND) != ALB_OK ||
        alb_producer_init(&prod, src) != ALB_OK || alb_consumer_init(&cons) != ALB_OK)
        return 0x40 + (int)k;

    for (rep = 1u; rep <= BENCH_REPS; ++rep) {
        fill(rep, words);
        t0 = board_cycles();
        r = alb_export(&prod, src);
        t1 = board_cycles();
        stat_add(&st[M_EXPORT], t0, t1);
        if (r != ALB_OK)
            return 0x40 + (int)k;
    }
    for (rep = 1u; rep <= BENCH_REPS; ++rep) {
        fill(rep + 1000u, words);
        if (alb_export(&prod, src) != ALB_OK)
            return 0x40 + (int)k;
        t0 = board_cycles();
        r = alb_import(&cons, dst);
        t1 = board_cycles();
        stat_add(&st[M_IMPORT_NEW], t0, t1);
        if (r != ALB_NEW || !same(words))
            return 0x50 + (int)k;
    }
    for (rep = 1u; rep <= BENCH_REPS; ++rep) {
        dst[0] = ~src[0];
        t0 = board_cycles();
        r = alb_import(&cons, dst);
        t1 = board_cycles();
        stat_add(&st[M_IMPORT_OLD], t0, t1);
        if (r != ALB_OLD || !same(words))
            return 0x50 + (int)k;
    }
    for (rep = 1u; rep <= BENCH_REPS; ++rep) {
        fill(rep + 2000u, words);
        t0 = board_cycles();
        copy_to(win, src, words);
        t1 = board_cycles();
        stat_add(&st[M_COPY_TO], t0, t1);
    }
    for (rep = 1u; rep <= BENCH_REPS; ++rep) {
        dst[0] = ~src[0];
        t0 = board_cycles();
        copy_from(dst, win, words);
        t1 = board_cycles();
        stat_add(&st[M_COPY_FROM], t0, t1);
        if (!same(words))
            return 0x50 + (int)k;
    }
    for (m = 0u; m < 5u; ++m)
        stat_send(size, m, &st[m]);
    return 0;
}

int main(void)
{
    static const uint32_t sizes[] = {4u, 16u, 64u, 256u};
    uint32_t k, t0, t1;
    int r;

    overhead = 0xFFFFFFFFu;
    for (k = 0u; k < BENCH_REPS; ++k) {
        t0 = board_cycles();
        t1 = board_cycles();
        if (t1 - t0 < overhead)
            overhead = t1 - t0;
    }
    event(K_OVERHEAD, overhead);
    event(K_REPS, BENCH_REPS);
    for (k = 0u; k < sizeof sizes / sizeof sizes[0]; ++k) {
        r = bench_size(k, sizes[k]);
        if (r != 0)
            return r;
    }
    return 0;
}
