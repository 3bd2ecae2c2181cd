/*
 * test_clock.c -- host unit test of the local-time estimator
 * c-driver/alb_clock.c (make test-clock-unit).  A model controller publishes
 * its time every PERIOD clocks (value = taken_at = the publish instant); a
 * model board whose local timer runs at 1 + ppm/10^6 ticks per controller
 * clock imports each value a random delay later (uniform in [D_MIN, D_MAX])
 * and synchronises; the test then asks alb_clock_now at random instants
 * between updates and compares with the controller's time.  Checks, per
 * drift in {0, +300, -1000, +5000, -20000} ppm and with the 32-bit times
 * wrapping during the run:
 *   - before the first sample the state is EMPTY; after one it is OFFSET and
 *     the estimate is the sample's time at its local time;
 *   - after warm-up (ALB_CLOCK_RING windows) the state is RATE, the rate is
 *     within RATE_TOL_PPM of the truth, and every estimate lies in
 *     [true - D_MAX - SLACK, true + SLACK] (lag at most the delivery delay,
 *     never ahead by more than the rate residual);
 *   - the mean lag is below D_MIN + (D_MAX - D_MIN) / 8 (the window minimum
 *     works: far below the mean delay).
 * And the read path's short multiply: alb_clock_at within 3 ticks of the
 * exact line for random spans up to 2^22 ticks and skews up to +-2^31.
 * Built with -DALB_CLOCK_NO_RATE (the estimator without rate correction)
 * the drifting cases must fail (make test-clock-unit-negative).
 * Last line: "clock-unit: N checks, F failed"; exit 1 if F > 0.
 */
#include <stdint.h>
#include <stdio.h>
#include "alb_clock.h"

uint32_t unit_local_now;

#define PERIOD        2500u   /* controller clocks between time updates */
#define D_MIN         40u     /* delivery delay range (controller clocks) */
#define D_MAX         1500u
#define SLACK         40      /* clocks: rate residual over two windows, rounding */
#define RATE_TOL_PPM  250.0  /* statistical (window minima of this delay spread, fixed seed); also kClockRho of sim/mobot_sim.cpp */

static unsigned long checks, failed;
static uint64_t rng = 0x9E3779B97F4A7C15ull;

static uint32_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)(rng >> 11);
}

static void check(int ok, const char *what, long ppm, double a, double b)
{
    ++checks;
    if (!ok) {
        if (failed < 10)
            printf("FAIL drift %+ld ppm: %s (%.1f, %.1f)\n", ppm, what, a, b);
        ++failed;
    }
}

/* The board's local timer at controller time t (t counted from t0, 64-bit). */
static uint32_t local_at(uint64_t t, long ppm, uint32_t l_offset)
{
    return l_offset + (uint32_t)(uint64_t)((double)t * (1.0 + (double)ppm * 1e-6));
}

static void run(long ppm, uint32_t g_offset, uint32_t l_offset)
{
    alb_clock_t c;
    uint64_t t, warm = (uint64_t)(ALB_CLOCK_RING + 1u) * ALB_CLOCK_WINDOW * 11u / 10u;
    uint64_t end = warm + 40u * ALB_CLOCK_WINDOW;
    double worst_lag = 0, worst_lead = 0, sum_lag = 0;
    unsigned long n = 0;
    alb_clock_init(&c);
    check(alb_clock_state(&c) == ALB_CLOCK_EMPTY, "state EMPTY before a sample", ppm, 0, 0);
    for (t = PERIOD; t < end; t += PERIOD) {
        uint32_t d = D_MIN + next() % (D_MAX - D_MIN + 1u), q, k;
        uint32_t g = g_offset + (uint32_t)t;
        unit_local_now = local_at(t + d, ppm, l_offset);
        alb_clock_sync_now(&c, g);
        if (t == PERIOD) {
            check(alb_clock_state(&c) == ALB_CLOCK_OFFSET, "state OFFSET after one sample", ppm, 0, 0);
            check(alb_clock_now(&c) == g, "first estimate = the sample's time", ppm, alb_clock_now(&c), g);
        }
        /* a few queries between this import and the next update's */
        for (k = 0u; k < 3u; ++k) {
            uint64_t tq = t + d + next() % PERIOD;
            int32_t err;
            unit_local_now = local_at(tq, ppm, l_offset);
            err = (int32_t)(alb_clock_now(&c) - (g_offset + (uint32_t)tq));
            if (tq < warm)
                continue;
            q = err < 0 ? (uint32_t)-err : 0u;
            sum_lag += q;
            ++n;
            if (-err > worst_lag) worst_lag = -err;
            if (err > worst_lead) worst_lead = err;
        }
    }
    {
        double rate_ppm = (double)c.skew / 4294967296.0 * 1e6;
        double true_ppm = (1.0 / (1.0 + (double)ppm * 1e-6) - 1.0) * 1e6;  /* global per local - 1 */
        double diff = rate_ppm - true_ppm;
        check(alb_clock_state(&c) == ALB_CLOCK_RATE, "state RATE after warm-up", ppm, c.state, 0);
        check(diff < RATE_TOL_PPM && diff > -RATE_TOL_PPM, "rate within tolerance (est ppm, true ppm)", ppm,
              rate_ppm, true_ppm);
        check(worst_lag <= D_MAX + SLACK, "lag <= D_MAX + SLACK (worst lag, bound)", ppm, worst_lag, D_MAX + SLACK);
        check(worst_lead <= SLACK, "lead <= SLACK (worst lead, bound)", ppm, worst_lead, SLACK);
        check(n && sum_lag / (double)n < D_MIN + (D_MAX - D_MIN) / 8.0, "mean lag small (mean, bound)", ppm,
              n ? sum_lag / (double)n : 0, D_MIN + (D_MAX - D_MIN) / 8.0);
        printf("drift %+6ld ppm: rate %+9.2f ppm (true %+9.2f), worst lag %5.0f, worst lead %4.0f, mean lag %6.1f "
               "clocks over %lu estimates\n", ppm, rate_ppm, true_ppm, worst_lag, worst_lead,
               n ? sum_lag / (double)n : 0, n);
    }
}

/* alb_clock_at against the exact line (double) on a hand-set state. */
static void scale_check(void)
{
    alb_clock_t c;
    unsigned k, bad = 0u;
    double worst = 0;
    alb_clock_init(&c);
    c.state = ALB_CLOCK_RATE;
    c.g0 = 1000000u;
    c.l0 = 5000000u;
    for (k = 0u; k < 200000u; ++k) {
        int32_t d = (int32_t)(next() % (1u << 23)) - (1 << 22);
        double x, diff;
        c.skew = (int32_t)(next() << 1 ^ next());
        x = (double)c.g0 + d + (double)d * (double)c.skew / 4294967296.0;
        diff = (double)(int32_t)(alb_clock_at(&c, c.l0 + (uint32_t)d) - c.g0) - (x - (double)c.g0);
        if (diff < 0) diff = -diff;
        if (diff > worst) worst = diff;
        bad += diff > 3.0;
    }
    check(bad == 0u, "alb_clock_at within 3 ticks of the exact line (worst, bound)", 0, worst, 3.0);
    printf("read path: worst deviation from the exact line %.2f ticks over %u spans\n", worst, k);
}

int main(void)
{
    static const long drifts[] = {0, 300, -1000, 5000, -20000};
    unsigned k;
    scale_check();
    for (k = 0u; k < sizeof drifts / sizeof drifts[0]; ++k)
        run(drifts[k], 0xFFF00000u + 977u * k, 0xFFFF0000u - 12345u * k);  /* both wrap early */
    printf("clock-unit: %lu checks, %lu failed\n", checks, failed);
    return failed ? 1 : 0;
}
