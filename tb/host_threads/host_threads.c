/*
 * host_threads.c -- the real driver (c-driver/albatross.c) on two host
 * threads over ordinary shared memory.
 *
 * A producer thread exports a continuous stream of values, a consumer thread
 * imports continuously, each pinned to its own core, on one or more channels
 * of one kind (three-buffer or four-slot) in a plain static array.  On
 * x86-64 each core has a store buffer, so the store-buffering pattern the
 * driver's fences guard against (albatross.c, "Memory ordering") really
 * happens when a fence is missing.  Built with the unchanged mmio port
 * (c-driver/port/mmio/) every Import must check out; built with
 * tb/host_threads/port/ (no fence, or none at one site) it is expected to
 * fail, and says how often.
 *
 * Every Import is checked:
 *   torn          the payload's words name different sequence numbers (word
 *                 i holds seq XOR a salt of i: a mix of two values shows)
 *   back in time  older than the value the previous Import returned
 *   stale         older than the newest value whose alb_export had returned
 *                 before the Import began (the producer's count `exported`,
 *                 a release store after each Export, loaded before it)
 *   wrong New     ALB_NEW but not newer than the previous value
 *   wrong Old     ALB_OLD but a different value than the previous one
 * The bookkeeping uses release stores and acquire loads, which are plain
 * moves on x86-64: they add no fence that could hide the race.
 *
 * Bounds: the consumer makes --imports Imports, and goes on until the
 * producer has overtaken --min-overtaken of them (an Export completed during
 * the Import), but not past --soft-seconds: on a busy machine the two threads
 * run side by side only part of the time, and an Import no Export overtakes
 * races with nothing.  The producer runs until the consumer is done.  The main thread is a watchdog: a three-buffer Import is
 * lock-free, not wait-free (its loop repeats while the producer publishes
 * again), so if no Import completes for --stall-ms the watchdog pauses the
 * producer (counted as a starvation event, a finding, not a hang) and lets it
 * go on once the Import is done; if even a paused producer does not let the
 * Import finish within 20 such periods, or the run exceeds --seconds, it
 * fails with a message.
 *
 * --stop-after V ends the run at the V-th Import with a violation (the
 * negatives: caught, no need to go on).
 *
 * Exit status: 0 no violation, 1 violations (the last line counts them),
 * 2 bad arguments or set-up, 3 watchdog, 4 the threads did not overlap (the
 * producer overtook fewer than --min-overtaken Imports within --soft-seconds:
 * a pass would prove nothing).  --json FILE writes the figures.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <pthread.h>
#include <sched.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "albatross.h"
#include "ht_check.h"

#define MAX_WORDS    16u
#define MAX_CHANNELS 8u
#define CH_SPAN      320u     /* bytes per channel: a four-slot channel of 16 words, 64-aligned */
#define LINE         64

#ifndef HT_VARIANT
#define HT_VARIANT "mmio"     /* the port layer this binary was built with */
#endif

/* The "dual-ported RAM": ordinary memory shared by the two threads. */
static unsigned char ram[MAX_CHANNELS * CH_SPAN] __attribute__((aligned(LINE)));

/* Shared bookkeeping, each written by one thread, on lines of their own. */
static struct {
    uint32_t exported[MAX_CHANNELS];           /* producer: last seq exported per channel */
    unsigned char pad0[LINE];
    uint64_t exports;                          /* producer: Exports done */
    int      producer_error;                   /* producer: an Export result not ALB_OK */
    unsigned char pad1[LINE];
    uint64_t imports;                          /* consumer: Imports done */
    int      consumer_done;
    unsigned char pad2[LINE];
    int      stop;                             /* main: producer, stop */
    int      pause;                            /* main: producer, wait */
    int      paused;                           /* producer: it is waiting */
} sh __attribute__((aligned(LINE)));

static struct {
    unsigned kind, channels, words, cpu_consumer, cpu_producer;
    uint64_t imports, stop_after, min_overtaken;
    double seconds, soft_seconds;
    unsigned stall_ms;
    const char *json, *label;
} opt = {ALB_THREE_BUFFER, 1u, 2u, 0u, 1u, 1000000u, 0u, 1000u, 60.0, 40.0, 1000u, 0, "run"};

static alb_channel_t prod_ch[MAX_CHANNELS], cons_ch[MAX_CHANNELS];

/* Results of the consumer (the tally of ht_check.h, and the overlap). */
static struct {
    struct ht_tally t;
    uint64_t overtaken, max_overtake;
    int error;                    /* an Import result neither New nor Old */
} res;

static void fill(uint32_t *w, uint32_t seq)
{
    ht_fill(w, opt.words, seq);
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int pin(unsigned cpu)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    return pthread_setaffinity_np(pthread_self(), sizeof set, &set);
}

static void *producer(void *arg)
{
    uint32_t w[MAX_WORDS], seq[MAX_CHANNELS];
    unsigned c;
    int rc;

    (void)arg;
    if (pin(opt.cpu_producer) != 0) {
        fprintf(stderr, "host-threads: cannot pin the producer to CPU %u\n", opt.cpu_producer);
        __atomic_store_n(&sh.producer_error, 1, __ATOMIC_RELAXED);
        return 0;
    }
    memset(seq, 0, sizeof seq);
    while (!__atomic_load_n(&sh.stop, __ATOMIC_RELAXED)) {
        if (__atomic_load_n(&sh.pause, __ATOMIC_RELAXED)) {
            __atomic_store_n(&sh.paused, 1, __ATOMIC_RELAXED);
            while (__atomic_load_n(&sh.pause, __ATOMIC_RELAXED) && !__atomic_load_n(&sh.stop, __ATOMIC_RELAXED))
                sched_yield();
            __atomic_store_n(&sh.paused, 0, __ATOMIC_RELAXED);
            continue;
        }
        for (c = 0; c < opt.channels; ++c) {
            fill(w, ++seq[c]);
            rc = alb_export(&prod_ch[c], w);
            if (rc != ALB_OK) {
                fprintf(stderr, "host-threads: alb_export on channel %u: expected ALB_OK, got %d\n", c, rc);
                __atomic_store_n(&sh.producer_error, 1, __ATOMIC_RELAXED);
                return 0;
            }
            __atomic_store_n(&sh.exported[c], seq[c], __ATOMIC_RELEASE);
        }
        __atomic_store_n(&sh.exports, sh.exports + opt.channels, __ATOMIC_RELAXED);
    }
    return 0;
}

static void report_violation(uint64_t i, unsigned c, int r, const uint32_t *w, uint32_t last,
                             uint32_t fresh, const char *what)
{
    if (res.t.violations > 5u)
        return;
    fprintf(stderr, "host-threads: Import %llu, channel %u: %s (result %s, words %08x %08x -> seq %u / %u, "
            "previous %u, exported before the Import %u)\n", (unsigned long long)i, c, what,
            r == ALB_NEW ? "New" : "Old", (unsigned)w[0], (unsigned)w[opt.words - 1u],
            (unsigned)(w[0] ^ ht_salt(0)), (unsigned)(w[opt.words - 1u] ^ ht_salt(opt.words - 1u)),
            (unsigned)last, (unsigned)fresh);
}

static void *consumer(void *arg)
{
    uint32_t w[MAX_WORDS], last[MAX_CHANNELS], prev, fresh, after;
    uint64_t i;
    unsigned c = 0;
    int r, bad, time_up = 0;
    double t0 = now_s();

    (void)arg;
    if (pin(opt.cpu_consumer) != 0) {
        fprintf(stderr, "host-threads: cannot pin the consumer to CPU %u\n", opt.cpu_consumer);
        res.error = 1;
        __atomic_store_n(&sh.consumer_done, 1, __ATOMIC_RELEASE);
        return 0;
    }
    memset(last, 0, sizeof last);
    for (i = 0; i < opt.imports || (res.overtaken < opt.min_overtaken && !time_up); ++i) {
        if (i >= opt.imports && (i & 0xFFFFu) == 0u && now_s() - t0 > opt.soft_seconds)
            time_up = 1;             /* past the budget, still too few overtaken: give up */
        fresh = __atomic_load_n(&sh.exported[c], __ATOMIC_ACQUIRE);
        r = alb_import(&cons_ch[c], w);
        after = __atomic_load_n(&sh.exported[c], __ATOMIC_ACQUIRE);
        if (r != ALB_NEW && r != ALB_OLD) {
            fprintf(stderr, "host-threads: alb_import on channel %u: expected ALB_NEW or ALB_OLD, got %d\n", c, r);
            res.error = 1;
            break;
        }
        if (after != fresh) {
            ++res.overtaken;
            if ((uint64_t)(after - fresh) > res.max_overtake)
                res.max_overtake = after - fresh;
        }
        prev = last[c];
        bad = ht_judge(&res.t, opt.words, r, w, &last[c], fresh, i);
        if (bad) {
            report_violation(i, c, r, w, prev, fresh, ht_violation_name((unsigned)bad));
            if (res.t.violations == opt.stop_after) {
                ++i;
                __atomic_store_n(&sh.imports, i, __ATOMIC_RELAXED);
                break;
            }
        }
        __atomic_store_n(&sh.imports, i + 1u, __ATOMIC_RELAXED);
        if (++c == opt.channels)
            c = 0;
    }
    __atomic_store_n(&sh.consumer_done, 1, __ATOMIC_RELEASE);
    return 0;
}

static int parse(int argc, char **argv)
{
    int i;
    for (i = 1; i + 1 < argc; i += 2) {
        const char *k = argv[i], *v = argv[i + 1];
        if (!strcmp(k, "--kind"))
            opt.kind = !strcmp(v, "four-slot") ? ALB_FOUR_SLOT : !strcmp(v, "three-buffer") ? ALB_THREE_BUFFER : 99u;
        else if (!strcmp(k, "--imports"))
            opt.imports = strtoull(v, 0, 10);
        else if (!strcmp(k, "--stop-after"))
            opt.stop_after = strtoull(v, 0, 10);
        else if (!strcmp(k, "--words"))
            opt.words = (unsigned)strtoul(v, 0, 10);
        else if (!strcmp(k, "--channels"))
            opt.channels = (unsigned)strtoul(v, 0, 10);
        else if (!strcmp(k, "--seconds"))
            opt.seconds = strtod(v, 0);
        else if (!strcmp(k, "--stall-ms"))
            opt.stall_ms = (unsigned)strtoul(v, 0, 10);
        else if (!strcmp(k, "--min-overtaken"))
            opt.min_overtaken = strtoull(v, 0, 10);
        else if (!strcmp(k, "--soft-seconds"))
            opt.soft_seconds = strtod(v, 0);
        else if (!strcmp(k, "--cpus"))
            sscanf(v, "%u,%u", &opt.cpu_consumer, &opt.cpu_producer);
        else if (!strcmp(k, "--json"))
            opt.json = v;
        else if (!strcmp(k, "--label"))
            opt.label = v;
        else
            return -1;
    }
    if (i != argc || opt.kind > ALB_FOUR_SLOT || opt.words < 2u || opt.words > MAX_WORDS ||
        opt.channels < 1u || opt.channels > MAX_CHANNELS || opt.imports == 0u)
        return -1;
    return 0;
}

static void write_json(double secs, int status, unsigned stalls)
{
    FILE *f;
    if (!opt.json)
        return;
    f = fopen(opt.json, "w");
    if (!f) {
        fprintf(stderr, "host-threads: cannot write %s\n", opt.json);
        return;
    }
    fprintf(f, "{\n  \"label\": \"%s\",\n  \"kind\": \"%s\",\n  \"port\": \"%s\",\n"
            "  \"payload_words\": %u,\n  \"channels\": %u,\n  \"imports\": %llu,\n  \"exports\": %llu,\n"
            "  \"new\": %llu,\n  \"old\": %llu,\n  \"torn\": %llu,\n  \"back_in_time\": %llu,\n"
            "  \"stale\": %llu,\n  \"wrong_new\": %llu,\n  \"wrong_old\": %llu,\n"
            "  \"violations\": %llu,\n  \"first_violation_at\": %llu,\n"
            "  \"overtaken\": %llu,\n  \"max_exports_during_one_import\": %llu,\n"
            "  \"starvation_events\": %u,\n  \"seconds\": %.3f,\n  \"ns_per_import\": %.1f,\n  \"exit\": %d\n}\n",
            opt.label, opt.kind == ALB_FOUR_SLOT ? "four-slot" : "three-buffer", HT_VARIANT, opt.words,
            opt.channels, (unsigned long long)sh.imports, (unsigned long long)sh.exports,
            (unsigned long long)res.t.news, (unsigned long long)res.t.olds, (unsigned long long)res.t.torn,
            (unsigned long long)res.t.back, (unsigned long long)res.t.stale, (unsigned long long)res.t.wrong_new,
            (unsigned long long)res.t.wrong_old, (unsigned long long)res.t.violations,
            (unsigned long long)res.t.first_violation, (unsigned long long)res.overtaken,
            (unsigned long long)res.max_overtake, stalls, secs, sh.imports ? 1e9 * secs / (double)sh.imports : 0.0,
            status);
    fclose(f);
}

int main(int argc, char **argv)
{
    uint32_t w[MAX_WORDS];
    pthread_t tp, tc;
    struct timespec tick = {0, 20 * 1000 * 1000};
    double t0, t_progress, t, secs;
    uint64_t seen = 0, n;
    unsigned c, stalls = 0;
    int status = 0;
    const char *kind;

    if (parse(argc, argv) != 0) {
        fprintf(stderr, "usage: %s [--kind three-buffer|four-slot] [--imports N] [--words 2..%u] "
                "[--channels 1..%u] [--stop-after V] [--seconds S] [--stall-ms MS] [--min-overtaken N] [--soft-seconds S] [--cpus C,P] "
                "[--json FILE] [--label NAME]\n", argv[0], MAX_WORDS, MAX_CHANNELS);
        return 2;
    }
    kind = opt.kind == ALB_FOUR_SLOT ? "four-slot" : "three-buffer";
    fill(w, 0u);
    for (c = 0; c < opt.channels; ++c) {
        uintptr_t base = (uintptr_t)&ram[c * CH_SPAN];
        if (alb_channel_setup_kind(&prod_ch[c], base, 4u * opt.words, opt.kind) != ALB_OK ||
            alb_channel_setup_kind(&cons_ch[c], base, 4u * opt.words, opt.kind) != ALB_OK ||
            alb_producer_init(&prod_ch[c], w) != ALB_OK || alb_consumer_init(&cons_ch[c]) != ALB_OK) {
            fprintf(stderr, "host-threads: channel %u set-up failed\n", c);
            return 2;
        }
    }
    t0 = t_progress = now_s();
    if (pthread_create(&tc, 0, consumer, 0) != 0 || pthread_create(&tp, 0, producer, 0) != 0) {
        fprintf(stderr, "host-threads: pthread_create failed\n");
        return 2;
    }
    /* The watchdog. */
    while (!__atomic_load_n(&sh.consumer_done, __ATOMIC_ACQUIRE)) {
        nanosleep(&tick, 0);
        t = now_s();
        n = __atomic_load_n(&sh.imports, __ATOMIC_RELAXED);
        if (n != seen) {
            seen = n;
            t_progress = t;
            if (__atomic_load_n(&sh.pause, __ATOMIC_RELAXED))
                __atomic_store_n(&sh.pause, 0, __ATOMIC_RELAXED);
        } else if (!__atomic_load_n(&sh.pause, __ATOMIC_RELAXED) && t - t_progress > 1e-3 * opt.stall_ms) {
            ++stalls;   /* starvation (or the consumer descheduled): stop the producer */
            fprintf(stderr, "host-threads: no Import completed for %u ms (Import %llu): producer paused "
                    "(starvation event %u)\n", opt.stall_ms, (unsigned long long)n, stalls);
            __atomic_store_n(&sh.pause, 1, __ATOMIC_RELAXED);
            t_progress = t;
        } else if (__atomic_load_n(&sh.pause, __ATOMIC_RELAXED) && t - t_progress > 20e-3 * opt.stall_ms) {
            /* 20 stall periods: a busy machine may leave the consumer unscheduled
             * for a while; an Import that loops for ever never completes. */
            fprintf(stderr, "host-threads: watchdog: Import %llu did not complete with the producer paused "
                    "for %u ms: a hang, not starvation\n", (unsigned long long)n, 20u * opt.stall_ms);
            status = 3;
            break;
        }
        if (t - t0 > opt.seconds) {
            fprintf(stderr, "host-threads: watchdog: %.0f s elapsed, expected %llu Imports, got %llu\n",
                    opt.seconds, (unsigned long long)opt.imports, (unsigned long long)n);
            status = 3;
            break;
        }
        if (__atomic_load_n(&sh.producer_error, __ATOMIC_RELAXED)) {
            status = 2;
            break;
        }
    }
    secs = now_s() - t0;
    if (status == 3) {      /* the threads may be stuck: report and leave without joining */
        write_json(secs, status, stalls);
        printf("host-threads %s %s (%s): watchdog fired\n", opt.label, kind, HT_VARIANT);
        fflush(stdout);
        _Exit(3);
    }
    pthread_join(tc, 0);
    __atomic_store_n(&sh.stop, 1, __ATOMIC_RELAXED);
    pthread_join(tp, 0);
    if (res.error || sh.producer_error)
        status = 2;
    else if (res.t.violations != 0u)
        status = 1;
    else if (res.overtaken < opt.min_overtaken)
        status = 4;
    write_json(secs, status, stalls);
    printf("host-threads %s %s (%s port, %u words, %u channel%s): %llu Imports checked (New %llu, Old %llu), "
           "%llu Exports, %.1f s, %.0f ns per Import; producer overtook %llu Imports (max %llu Exports in one); "
           "%u starvation events\n",
           opt.label, kind, HT_VARIANT, opt.words, opt.channels, opt.channels > 1u ? "s" : "",
           (unsigned long long)sh.imports, (unsigned long long)res.t.news, (unsigned long long)res.t.olds,
           (unsigned long long)sh.exports, secs, sh.imports ? 1e9 * secs / (double)sh.imports : 0.0,
           (unsigned long long)res.overtaken, (unsigned long long)res.max_overtake, stalls);
    if (status == 4)
        printf("host-threads: expected the producer to overtake at least %llu Imports, got %llu of %llu in %.0f s: "
               "the threads did not run side by side enough\n", (unsigned long long)opt.min_overtaken,
               (unsigned long long)res.overtaken, (unsigned long long)sh.imports, opt.soft_seconds);
    printf("host-threads: %llu violations (%llu torn, %llu back in time, %llu stale, %llu wrong New, "
           "%llu wrong Old)%s\n", (unsigned long long)res.t.violations, (unsigned long long)res.t.torn,
           (unsigned long long)res.t.back, (unsigned long long)res.t.stale, (unsigned long long)res.t.wrong_new,
           (unsigned long long)res.t.wrong_old, res.t.violations ? "; expected 0" : "");
    return status;
}
