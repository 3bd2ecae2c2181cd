/*
 * import_pass.c -- one pass of the three-buffer Import loop, measured on the
 * core it runs on (for the compiler's T/V table, compiler/albatross_schedule/
 * termination.py CORE_TIMING; docs/compiler.md "Termination bounds").  The core
 * is both producer and consumer of its own channel at BOARD_DPRAM_BASE + 0x200
 * (clear of the pair test's channel and start flag): alb_import right after an
 * alb_export returns New after exactly one pass of the loop; alb_import again
 * returns Old with none.  One pass = New - Old.  Runs as core 1 of the pair
 * harness (tb/pico/test_pico_pair.cpp, any producer image on core 0), whose
 * report it reuses: STAT 0 = New max, 1 = 1, 2 = Old min, 3 = New min << 16 |
 * Old max (cycles by board_cycles, the empty pair subtracted).  Exit 0 = pass,
 * 0x40 + n = a wrong result.
 */
#include "albatross.h"
#include "alb_port.h"
#include "board.h"

#define REPS 32u
#define CH_BASE ((uintptr_t)BOARD_DPRAM_BASE + 0x200u)

static alb_channel_t prod, cons;

int main(void)
{
    uint32_t v[4], d[4];
    uint32_t k, t0, t1, c, ovh = 0xFFFFFFFFu;
    uint32_t new_min = 0xFFFFFFFFu, new_max = 0u, old_min = 0xFFFFFFFFu, old_max = 0u;
    int r;

    for (k = 0u; k < 4u; ++k)
        v[k] = k + 1u;
    for (k = 0u; k < REPS; ++k) {
        t0 = board_cycles();
        t1 = board_cycles();
        if (t1 - t0 < ovh)
            ovh = t1 - t0;
    }
    if (alb_channel_setup(&prod, CH_BASE, sizeof v) != ALB_OK ||
        alb_channel_setup(&cons, CH_BASE, sizeof v) != ALB_OK ||
        alb_producer_init(&prod, v) != ALB_OK || alb_consumer_init(&cons) != ALB_OK)
        return 0x41;
    for (k = 0u; k < REPS; ++k) {
        v[0] = k;
        if (alb_export(&prod, v) != ALB_OK)
            return 0x42;
        t0 = board_cycles();
        r = alb_import(&cons, d);
        t1 = board_cycles();
        if (r != ALB_NEW || d[0] != k)
            return 0x43;
        c = t1 - t0 - ovh;
        new_min = c < new_min ? c : new_min;
        new_max = c > new_max ? c : new_max;
        t0 = board_cycles();
        r = alb_import(&cons, d);
        t1 = board_cycles();
        if (r != ALB_OLD || d[0] != k)
            return 0x44;
        c = t1 - t0 - ovh;
        old_min = c < old_min ? c : old_min;
        old_max = c > old_max ? c : old_max;
    }
    board_stat(0u, new_max);
    board_stat(1u, 1u);
    board_stat(2u, old_min);
    board_stat(3u, new_min << 16 | old_max);
    return 0;
}
