/*
 * alb_clock.c -- the global time between updates of the time channel: the
 * estimator of alb_clock.h (read its head comment for the rules).
 */
#include "alb_clock.h"
#include "alb_port.h"

#ifndef ALB_PORT_HAS_LOCAL_TIME
#error "alb_clock.c needs the port's alb_local_time() (alb_port.h): with c-driver/port/mmio, define ALB_LOCAL_TIMER_ADDR, the address of the board's free-running 32-bit local timer (e.g. -DALB_LOCAL_TIMER_ADDR=0x20000040u); a port of your own defines alb_local_time() and ALB_PORT_HAS_LOCAL_TIME"
static inline uint32_t alb_local_time(void) { return 0u; }   /* the #error is the only message */
#endif

/* a * b mod 2^32 by shift and add over the bits of b (rv32i has no multiply
 * instruction; b is the short factor, so few steps). */
static uint32_t alb_clock_mul(uint32_t a, uint32_t b)
{
    uint32_t r = 0u;
    while (b != 0u) {
        if (b & 1u)
            r += a;
        a <<= 1;
        b >>= 1;
    }
    return r;
}

/* d * skew / 2^32 for a signed tick difference d, rounded towards zero,
 * within 3 ticks.  For |d| < 2^18 (four windows) and |skew| < 2^28 (a
 * drift under 6 %) one short product: (|d| / 4) * (|skew| / 2^14) / 2^16,
 * where the second factor is the drift in units of 2^-18 (a 1000 ppm drift:
 * 262, nine steps); the dropped low bits cost < 1 tick each.  Otherwise the
 * 64-bit product (libgcc). */
static int32_t alb_clock_scale(int32_t d, int32_t skew)
{
    uint32_t ud = d < 0 ? 0u - (uint32_t)d : (uint32_t)d;
    uint32_t us = skew < 0 ? 0u - (uint32_t)skew : (uint32_t)skew;
    uint32_t p;
    if (ud < (1u << 18) && us < (1u << 28))
        p = alb_clock_mul(ud >> 2, us >> 14) >> 16;
    else
        p = (uint32_t)(((uint64_t)ud * us) >> 32);
    return (d < 0) != (skew < 0) ? -(int32_t)p : (int32_t)p;
}

/* The line through (g, l) with slope 1 + skew / 2^32, at local. */
static uint32_t alb_clock_line(uint32_t g, uint32_t l, int32_t skew, uint32_t local)
{
    int32_t d = (int32_t)(local - l);
    return g + (uint32_t)d + (uint32_t)alb_clock_scale(d, skew);
}

void alb_clock_init(alb_clock_t *c)
{
    uint32_t k;
    c->g0 = c->l0 = c->rg0 = c->rl0 = c->win_start = 0u;
    c->skew = c->rskew = c->best_e = 0;
    c->best.g = c->best.l = 0u;
    for (k = 0u; k < ALB_CLOCK_RING; ++k)
        c->ring[k].g = c->ring[k].l = 0u;
    c->n_ring = c->head = c->samples = 0u;
    c->state = ALB_CLOCK_EMPTY;
}

uint32_t alb_clock_at(const alb_clock_t *c, uint32_t local)
{
    if (c->state == ALB_CLOCK_EMPTY)
        return 0u;
    return alb_clock_line(c->g0, c->l0, c->skew, local);
}

#ifndef ALB_CLOCK_NO_RATE
/* floor(n * 2^32 / d) for n < d < 2^31: 32 steps of shift-and-subtract
 * (rv32i has no divide instruction; libgcc's 64-bit division costs some ten
 * thousand cycles on PicoRV32, one such pause per window was enough to
 * stretch a robot board's loop past its budget). */
static uint32_t alb_clock_frac(uint32_t n, uint32_t d)
{
    uint32_t q = 0u, k;
    for (k = 0u; k < 32u; ++k) {
        n <<= 1;  /* n < d < 2^31: no overflow */
        q <<= 1;
        if (n >= d) {
            n -= d;
            q |= 1u;
        }
    }
    return q;
}

/* The ring sample of smallest apparent delay among ring ages [from, to)
 * (0 the newest): the largest G above the model line.  The line's rate term
 * is taken coarsely, (|d| / 2^6) * (|skew| / 2^16) / 2^10: within 20 ticks
 * over the ring's span (2^20 ticks), enough to rank delays, in one short
 * product per sample whose steps are the bits of the rate estimate (the
 * drift) in units of 15 ppm (3 at a crystal's 100 ppm, 9 at 5000 ppm), never libgcc's 64-bit
 * one (a window close must not stall the board's loop). */
static const alb_clock_sample_t *alb_clock_best(const alb_clock_t *c, uint32_t from, uint32_t to)
{
    const alb_clock_sample_t *b = 0;
    uint32_t us = c->skew < 0 ? 0u - (uint32_t)c->skew : (uint32_t)c->skew;
    int32_t be = 0;
    uint32_t k;
    for (k = from; k < to; ++k) {
        const alb_clock_sample_t *s = &c->ring[(c->head + ALB_CLOCK_RING - 1u - k) % ALB_CLOCK_RING];
        int32_t d = (int32_t)(s->l - c->l0), e = (int32_t)(s->g - c->g0) - d, r = 0;
        uint32_t ud = d < 0 ? 0u - (uint32_t)d : (uint32_t)d;
        if (ud < (1u << 22) && us < (1u << 28))
            r = (int32_t)(alb_clock_mul(ud >> 6, us >> 16) >> 10);
        e -= (d < 0) != (c->skew < 0) ? -r : r;
        if (!b || e > be) {
            b = s;
            be = e;
        }
    }
    return b;
}
#endif

/* The rate between the better (smaller-delay) of the two newest and of the
 * two oldest ring samples (ALB_CLOCK_RATE_MIN windows closed: no two are
 * shared): one window of unusual delay, e.g. the first, can set neither end
 * alone (its delay spread over a short span was the rate error, and the
 * rate error is the only way the estimate can lead). */
static void alb_clock_rate(alb_clock_t *c)
{
#ifndef ALB_CLOCK_NO_RATE
    const alb_clock_sample_t *n = alb_clock_best(c, 0u, 2u);
    const alb_clock_sample_t *o = alb_clock_best(c, c->n_ring - 2u, c->n_ring);
    uint32_t dl = n->l - o->l, q;
    int32_t diff = (int32_t)((n->g - o->g) - dl);
    uint32_t ud = diff < 0 ? 0u - (uint32_t)diff : (uint32_t)diff;
    if (dl == 0u || dl >= 0x80000000u)
        return;
    /* |skew| = |diff| / dl in Q32, saturating below 1/2 (a 50 % drift) */
    q = ud >= dl / 2u ? 0x7FFFFFFFu : alb_clock_frac(ud, dl);
    if (q > 0x7FFFFFFFu)
        q = 0x7FFFFFFFu;
    c->skew = diff < 0 ? -(int32_t)q : (int32_t)q;
    c->state = ALB_CLOCK_RATE;
#else
    c->state = ALB_CLOCK_RATE;  /* claims a rate, keeps 1: the negative test's estimator */
#endif
}

/* Open a window at sample (g, l): the model is its reference line. */
static void alb_clock_open(alb_clock_t *c, uint32_t g, uint32_t l)
{
    c->rg0 = c->g0;
    c->rl0 = c->l0;
    c->rskew = c->skew;
    c->win_start = l;
    c->best.g = g;
    c->best.l = l;
    c->best_e = (int32_t)(g - alb_clock_line(c->rg0, c->rl0, c->rskew, l));
}

void alb_clock_sync(alb_clock_t *c, uint32_t taken_at, uint32_t local)
{
    int32_t e;
    if (c->state == ALB_CLOCK_EMPTY) {
        c->g0 = taken_at;
        c->l0 = local;
        c->skew = 0;
        c->state = ALB_CLOCK_OFFSET;
        c->samples = 1u;
        alb_clock_open(c, taken_at, local);
        return;
    }
    ++c->samples;
    /* a lower bound the estimate is below: move up to it now */
    if ((int32_t)(taken_at - alb_clock_at(c, local)) > 0) {
        c->g0 = taken_at;
        c->l0 = local;
    }
    /* the window's sample of smallest delay, against the fixed reference line */
    e = (int32_t)(taken_at - alb_clock_line(c->rg0, c->rl0, c->rskew, local));
    if (e > c->best_e) {
        c->best.g = taken_at;
        c->best.l = local;
        c->best_e = e;
    }
    if (local - c->win_start < ALB_CLOCK_WINDOW)
        return;
    /* close the window: its best sample is the anchor and joins the ring */
    c->ring[c->head] = c->best;
    c->head = (c->head + 1u) % ALB_CLOCK_RING;
    if (c->n_ring < ALB_CLOCK_RING)
        ++c->n_ring;
    c->g0 = c->best.g;
    c->l0 = c->best.l;
    if (c->n_ring >= ALB_CLOCK_RATE_MIN)
        alb_clock_rate(c);
    if ((int32_t)(taken_at - alb_clock_at(c, local)) > 0) {
        c->g0 = taken_at;
        c->l0 = local;
    }
    alb_clock_open(c, taken_at, local);
}

void alb_clock_sync_now(alb_clock_t *c, uint32_t taken_at)
{
    alb_clock_sync(c, taken_at, alb_local_time());
}

uint32_t alb_clock_now(const alb_clock_t *c)
{
    return alb_clock_at(c, alb_local_time());
}

int alb_clock_state(const alb_clock_t *c)
{
    return c->state;
}
