/*
 * alb_clock.h -- the global time between updates (the paper, section 3.4.1).
 *
 * The controller's global time reaches a board only as the values of its
 * time channel (a TIME entry publishes {time, taken_at = time}, the nominal
 * slot start), exact at the instant taken_at and a little old by the time
 * the board imports it.  "The local tasks need local timers synchronized to
 * this global time": alb_clock_t keeps the board's estimate of
 *     global(local) = g0 + (local - l0) * (1 + skew / 2^32)
 * from samples (taken_at, local timer read right after the Import), where
 * the local timer is the port layer's alb_local_time() (soc/board_memmap.v
 * TIMER on the soft-core boards).  C99, freestanding, no heap, no division
 * on the read path (one 32x32->64 multiply); one 64-bit division per window.
 *
 * Synchronisation (alb_clock_sync, on every New value of the time channel;
 * any channel's taken_at is such a sample too):
 *  - A sample (G, L) says the global time at local L was at least G (the
 *    value is delay d >= 0 old when read).  If the estimate at L is below G,
 *    the anchor moves up to (G, L) at once: the estimate never stays below
 *    a bound it has seen.
 *  - Samples are grouped in windows of ALB_CLOCK_WINDOW local ticks.  Within
 *    a window the sample with the smallest apparent delay (largest G minus
 *    the window's reference line at L) is kept; when the window closes it
 *    becomes the anchor (g0, l0) -- the anchor also moves down if the model
 *    ran ahead -- and joins a ring of the last ALB_CLOCK_RING such samples.
 *  - The rate (skew, Q32 fraction of "global ticks per local tick - 1") is
 *    the slope between the better (smaller delay against the model line) of
 *    the two oldest and the better of the two newest samples of the ring,
 *    taken once ALB_CLOCK_RATE_MIN windows have closed: up to
 *    (ALB_CLOCK_RING - 1) windows apart, so the delays' jitter is divided by
 *    a long span, and no single window of unusual delay (the first, before
 *    a board's loop settles) sets an end of the slope alone.  -DALB_CLOCK_NO_RATE keeps skew at 0 (the negative test of
 *    make test-sim-clock-negative: no rate correction under drift).
 * Error: with d_a the anchor's delay, the estimate's lag is d_a (<= the
 * time channel's delivery bound, and the smallest delay seen in a window in
 * practice) plus the residual rate error times the local time since the
 * anchor (< 2 windows); docs/robot.md derives the bound the robot test checks.
 * Times are 32-bit and wrap: differences are taken modulo 2^32 and must stay
 * below 2^31 ticks (43 s at 50 MHz).
 */
#ifndef ALB_CLOCK_H
#define ALB_CLOCK_H

#include <stdint.h>

#ifndef ALB_CLOCK_WINDOW
#define ALB_CLOCK_WINDOW 65536u  /* local ticks per window (1.3 ms at 50 MHz) */
#endif
#ifndef ALB_CLOCK_RING
#define ALB_CLOCK_RING   16u     /* window samples the rate is taken over */
#endif
#define ALB_CLOCK_RATE_MIN 4u    /* window samples before the rate is taken */
#if ALB_CLOCK_RING < ALB_CLOCK_RATE_MIN
#error "ALB_CLOCK_RING must hold ALB_CLOCK_RATE_MIN window samples"
#endif

/* alb_clock_state() */
#define ALB_CLOCK_EMPTY  0  /* no sample yet: alb_clock_at returns 0 */
#define ALB_CLOCK_OFFSET 1  /* offset known, rate assumed 1 */
#define ALB_CLOCK_RATE   2  /* offset and rate known (ALB_CLOCK_RATE_MIN windows closed) */

typedef struct {
    uint32_t g, l;  /* global time (taken_at) and local time of a sample */
} alb_clock_sample_t;

typedef struct {
    uint32_t g0, l0;         /* anchor: the estimate at local l0 is g0 */
    int32_t  skew;           /* global ticks per local tick - 1, times 2^32 */
    uint32_t rg0, rl0;       /* the open window's reference line (the model */
    int32_t  rskew;          /* when the window opened) */
    uint32_t win_start;      /* local time the open window opened */
    alb_clock_sample_t best; /* the open window's sample of smallest delay */
    int32_t  best_e;         /* its G minus the reference line at its L */
    alb_clock_sample_t ring[ALB_CLOCK_RING];
    uint32_t n_ring, head;   /* samples in the ring, index of the next one */
    uint32_t samples;        /* samples taken */
    int      state;          /* ALB_CLOCK_EMPTY / _OFFSET / _RATE */
} alb_clock_t;

void     alb_clock_init(alb_clock_t *c);
/* One sample: the global time taken_at held at local time local (the local
 * timer read right after the Import that returned it New). */
void     alb_clock_sync(alb_clock_t *c, uint32_t taken_at, uint32_t local);
/* The global-time estimate at local time local (no division). */
uint32_t alb_clock_at(const alb_clock_t *c, uint32_t local);
/* alb_clock_sync with local = alb_local_time() now. */
void     alb_clock_sync_now(alb_clock_t *c, uint32_t taken_at);
/* The current global time: alb_clock_at(c, alb_local_time()). */
uint32_t alb_clock_now(const alb_clock_t *c);
int      alb_clock_state(const alb_clock_t *c);

#endif
