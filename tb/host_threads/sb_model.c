/*
 * sb_model.c -- the real driver (c-driver/albatross.c) run by two simulated
 * CPUs over a software model of a memory system with store buffers, under a
 * seeded scheduler: the deterministic proof that the host thread checker
 * (ht_check.h) catches what a missing fence does, the same way on every
 * machine.  tools/mk/host_threads.mk builds it with the port layer
 * tb/host_threads/sbport/ and tools/host_threads.py judges it.
 *
 * The model.  Two simulated CPUs, the consumer (0) and the producer (1),
 * each a coroutine (its own stack) running the driver's code.  Every RAM access
 * of the driver (the port layer) is a scheduling point: the access happens
 * when the scheduler next runs that CPU.  Each CPU has a store buffer of up
 * to SB_CAP entries:
 *   - a store goes to the end of its CPU's buffer, not to memory;
 *   - a load takes each byte from the newest entry of its own buffer that
 *     covers it (store forwarding), else from memory;
 *   - the scheduler drains entries to memory at random steps; --mode tso
 *     drains each buffer in order, oldest first (x86-TSO: only a store
 *     followed by a load of another address can be reordered); --mode pso
 *     drains any entry that no older entry of the same buffer overlaps (a
 *     weaker model that also reorders stores to different addresses, as
 *     SPARC PSO or, for stores, Arm and RISC-V RVWMO do);
 *   - a kept alb_fence() is a scheduling point too, and then drains its
 *     CPU's whole buffer (one entry per step, the other CPU may run in
 *     between) before the CPU goes on; a dropped one (--drop) does nothing.
 * Loads are performed in program order: load-load and load-store reordering
 * (which Arm and RISC-V also allow, and which the acquire and release fences
 * of the consumer guard against) are outside this model.
 *
 * The scheduler (xorshift64*, --seed) runs, at each step, either a drain of
 * one entry of a non-empty buffer or the current CPU up to its next access,
 * switching CPU at random; every --epoch steps it draws new probabilities
 * of draining and of switching (from rare to frequent), so one run covers
 * both long-buffered stores and fine interleavings.  Same seed, same run.
 *
 * The producer exports 1, 2, 3, ... and after each Export stores its count
 * with release order (in tso that is any store; in pso it drains only after
 * every older entry); the consumer loads it before and after each Import
 * and judges each Import with ht_judge (torn, back in time, stale, wrong
 * New, wrong Old) against the count loaded before.
 *
 * Exit status: 0 no violation, 1 violations (the last line counts them),
 * 2 bad arguments or an Import/Export error, 3 the step bound hit first.
 */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <setjmp.h>
#include <ucontext.h>

#include "albatross.h"
#include "ht_check.h"

#define MAX_WORDS 16u
#define CH_SPAN   320u          /* a four-slot channel of 16 words fits */
#define BOOK_OFF  CH_SPAN       /* the producer's count `exported` */
#define SB_CAP    16u
#define STACK     (256u * 1024u)
#define MAX_DROP  4

static unsigned char mem[CH_SPAN + 64u] __attribute__((aligned(64)));

struct sb_entry { uintptr_t addr; unsigned n; uint32_t v; int release; };
static struct { struct sb_entry e[SB_CAP]; unsigned n; } sb[2];

static struct {
    unsigned kind, words, pso, epoch;
    uint64_t imports, stop_after, seed, max_steps;
    int drop[MAX_DROP], ndrop, drop_all;
    const char *json, *label, *drop_text;
} opt = {ALB_THREE_BUFFER, 2u, 0u, 4000u, 20000u, 0u, 1u, 0u, {0}, 0, 0, 0, "run", "none"};

/* Each CPU's stack is set up by makecontext and entered once by setcontext;
 * after that every switch is _setjmp/_longjmp (no signal-mask system call:
 * about ten times faster than swapcontext). */
static ucontext_t cpu_ctx[2];
static jmp_buf sched_jb, cpu_jb[2];
static int started[2];
static int cur = -1;                  /* the CPU running, -1 outside the coroutines */
static uint64_t rng, steps, drains, exports, imports, overtaken, max_overtake, fences, fences_dropped;
static int consumer_done, error;
static struct ht_tally tally;
static alb_channel_t prod_ch, cons_ch;

static uint64_t rnd(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return rng * 0x2545F4914F6CDD1Dull;
}

/* True with probability 1 / 2^k. */
static int one_in(unsigned k)
{
    return (rnd() >> 40 & ((1u << k) - 1u)) == 0u;
}

/* Back to the scheduler: the coroutine goes on when next run. */
static void yield(void)
{
    if (cur >= 0 && !_setjmp(cpu_jb[cur]))
        _longjmp(sched_jb, 1);
}

/* Run CPU t up to its next scheduling point. */
static void run_cpu(int t)
{
    if (_setjmp(sched_jb))
        return;
    if (!started[t]) {
        started[t] = 1;
        setcontext(&cpu_ctx[t]);
    }
    _longjmp(cpu_jb[t], 1);
}

static int overlap(const struct sb_entry *a, const struct sb_entry *b)
{
    return a->addr < b->addr + b->n && b->addr < a->addr + a->n;
}

static void drain_entry(int t, unsigned i)
{
    struct sb_entry *e = &sb[t].e[i];
    unsigned k;
    for (k = 0; k < e->n; ++k)
        *(unsigned char *)(e->addr + k) = (unsigned char)(e->v >> (8u * k));
    memmove(&sb[t].e[i], &sb[t].e[i + 1u], (sb[t].n - i - 1u) * sizeof sb[t].e[0]);
    --sb[t].n;
    ++drains;
}

/* One entry of CPU t's buffer that may reach memory now: the oldest (tso);
 * in pso a random one no older entry overlaps (a release one only when it
 * is the oldest). */
static unsigned pick(int t)
{
    unsigned cand[SB_CAP], nc = 0, i, j;
    if (!opt.pso)
        return 0u;
    for (i = 0; i < sb[t].n; ++i) {
        int ok = !(sb[t].e[i].release && i != 0u);
        for (j = 0; ok && j < i; ++j)
            ok = !overlap(&sb[t].e[j], &sb[t].e[i]);
        if (ok)
            cand[nc++] = i;
    }
    return cand[rnd() % nc];     /* the oldest is always a candidate */
}

static void store(uintptr_t addr, unsigned n, uint32_t v, int release)
{
    int t = cur < 0 ? 0 : cur;
    yield();
    if (sb[t].n == SB_CAP)
        drain_entry(t, 0u);      /* a full buffer stalls the store until its oldest drains */
    sb[t].e[sb[t].n].addr = addr;
    sb[t].e[sb[t].n].n = n;
    sb[t].e[sb[t].n].v = v;
    sb[t].e[sb[t].n].release = release;
    ++sb[t].n;
    if (cur < 0)
        while (sb[0].n)          /* set-up, before the CPUs start: straight to memory */
            drain_entry(0, 0u);
}

static uint32_t load(uintptr_t addr, unsigned n)
{
    int t = cur < 0 ? 0 : cur;
    uint32_t v = 0;
    unsigned k, i;
    yield();
    for (k = 0; k < n; ++k) {
        uintptr_t a = addr + k;
        unsigned char b = *(unsigned char *)a;
        for (i = sb[t].n; i-- > 0u;)
            if (a >= sb[t].e[i].addr && a < sb[t].e[i].addr + sb[t].e[i].n) {
                b = (unsigned char)(sb[t].e[i].v >> (8u * (a - sb[t].e[i].addr)));
                break;
            }
        v |= (uint32_t)b << (8u * k);
    }
    return v;
}

uint8_t sb_rd8(uintptr_t addr) { return (uint8_t)load(addr, 1u); }
void sb_wr8(uintptr_t addr, uint8_t v) { store(addr, 1u, v, 0); }
uint32_t sb_rd32(uintptr_t addr) { return load(addr, 4u); }
void sb_wr32(uintptr_t addr, uint32_t v) { store(addr, 4u, v, 0); }

void sb_fence(int line)
{
    int k, t = cur < 0 ? 0 : cur;
    ++fences;
    for (k = 0; k < opt.ndrop; ++k)
        if (opt.drop_all || opt.drop[k] == line) {
            ++fences_dropped;
            return;
        }
    yield();                     /* the stall: the other CPU may run first */
    while (sb[t].n) {            /* until the buffer is empty */
        drain_entry(t, pick(t));
        yield();
    }
}

static void producer(void)
{
    uint32_t w[MAX_WORDS], seq = 0;
    int rc;
    for (;;) {
        ht_fill(w, opt.words, ++seq);
        rc = alb_export(&prod_ch, w);
        if (rc != ALB_OK) {
            fprintf(stderr, "sb-model: alb_export: expected ALB_OK, got %d\n", rc);
            error = 1;
            for (;;)
                yield();
        }
        ++exports;
        store((uintptr_t)&mem[BOOK_OFF], 4u, seq, 1);   /* release: after the Export's stores */
    }
}

static void consumer(void)
{
    uint32_t w[MAX_WORDS], last = 0, prev, fresh, after;
    unsigned bad;
    int r;
    for (imports = 0; imports < opt.imports; ++imports) {
        fresh = load((uintptr_t)&mem[BOOK_OFF], 4u);
        r = alb_import(&cons_ch, w);
        after = load((uintptr_t)&mem[BOOK_OFF], 4u);
        if (r != ALB_NEW && r != ALB_OLD) {
            fprintf(stderr, "sb-model: alb_import: expected ALB_NEW or ALB_OLD, got %d\n", r);
            error = 1;
            break;
        }
        if (after != fresh) {
            ++overtaken;
            if (after - fresh > max_overtake)
                max_overtake = after - fresh;
        }
        prev = last;
        bad = ht_judge(&tally, opt.words, r, w, &last, fresh, imports);
        if (bad && tally.violations <= 3u)
            fprintf(stderr, "sb-model: Import %llu (step %llu): %s (result %s, words -> seq %u / %u, previous %u, "
                    "exported before the Import %u)\n", (unsigned long long)imports, (unsigned long long)steps,
                    ht_violation_name(bad), r == ALB_NEW ? "New" : "Old", (unsigned)(w[0] ^ ht_salt(0)),
                    (unsigned)(w[opt.words - 1u] ^ ht_salt(opt.words - 1u)), (unsigned)prev, (unsigned)fresh);
        if (bad && tally.violations == opt.stop_after) {
            ++imports;
            break;
        }
    }
    consumer_done = 1;
    for (;;)
        yield();
}

static void schedule(void)
{
    static char stack[2][STACK];
    static unsigned p_drain = 3u, p_switch = 3u;     /* static: kept across the switches */
    int t;
    for (t = 0; t < 2; ++t) {
        getcontext(&cpu_ctx[t]);
        cpu_ctx[t].uc_stack.ss_sp = stack[t];
        cpu_ctx[t].uc_stack.ss_size = STACK;
        cpu_ctx[t].uc_link = 0;
        makecontext(&cpu_ctx[t], t == 0 ? consumer : producer, 0);
    }
    cur = 0;
    for (steps = 0; !consumer_done && !error && steps < opt.max_steps; ++steps) {
        if (steps % opt.epoch == 0u) {       /* new probabilities: 1/2 .. 1/64 */
            p_drain = 1u + (unsigned)(rnd() % 6u);
            p_switch = 1u + (unsigned)(rnd() % 6u);
        }
        if ((sb[0].n || sb[1].n) && one_in(p_drain)) {
            t = sb[0].n && sb[1].n ? (int)(rnd() & 1u) : sb[0].n ? 0 : 1;
            drain_entry(t, pick(t));
            continue;
        }
        if (one_in(p_switch))
            cur ^= 1;
        run_cpu(cur);
    }
}

static int parse(int argc, char **argv)
{
    int i;
    for (i = 1; i + 1 < argc; i += 2) {
        const char *k = argv[i], *v = argv[i + 1];
        if (!strcmp(k, "--kind"))
            opt.kind = !strcmp(v, "four-slot") ? ALB_FOUR_SLOT : !strcmp(v, "three-buffer") ? ALB_THREE_BUFFER : 99u;
        else if (!strcmp(k, "--mode"))
            opt.pso = !strcmp(v, "pso") ? 1u : !strcmp(v, "tso") ? 0u : 99u;
        else if (!strcmp(k, "--imports"))
            opt.imports = strtoull(v, 0, 10);
        else if (!strcmp(k, "--stop-after"))
            opt.stop_after = strtoull(v, 0, 10);
        else if (!strcmp(k, "--words"))
            opt.words = (unsigned)strtoul(v, 0, 10);
        else if (!strcmp(k, "--seed"))
            opt.seed = strtoull(v, 0, 10);
        else if (!strcmp(k, "--epoch"))
            opt.epoch = (unsigned)strtoul(v, 0, 10);
        else if (!strcmp(k, "--drop")) {       /* none, all, or LINE[,LINE...] */
            char *p = (char *)v;
            opt.drop_text = v;
            opt.ndrop = 0;
            opt.drop_all = !strcmp(v, "all");
            if (opt.drop_all)
                opt.ndrop = 1;
            else if (strcmp(v, "none"))
                while (*p && opt.ndrop < MAX_DROP) {
                    opt.drop[opt.ndrop++] = (int)strtol(p, &p, 10);
                    if (*p == ',')
                        ++p;
                    else if (*p)
                        return -1;
                }
        } else if (!strcmp(k, "--json"))
            opt.json = v;
        else if (!strcmp(k, "--label"))
            opt.label = v;
        else
            return -1;
    }
    if (i != argc || opt.kind > ALB_FOUR_SLOT || opt.pso > 1u || opt.words < 2u || opt.words > MAX_WORDS ||
        opt.imports == 0u || opt.epoch == 0u)
        return -1;
    if (opt.max_steps == 0u)
        opt.max_steps = opt.imports * 4000u;
    return 0;
}

int main(int argc, char **argv)
{
    uint32_t w[MAX_WORDS];
    int status;
    const char *kind;
    FILE *f;

    if (parse(argc, argv) != 0) {
        fprintf(stderr, "usage: %s [--kind three-buffer|four-slot] [--mode tso|pso] [--drop none|all|LINE[,LINE]] "
                "[--seed S] [--imports N] [--words 2..%u] [--stop-after V] [--epoch STEPS] [--json FILE] "
                "[--label NAME]\n", argv[0], MAX_WORDS);
        return 2;
    }
    rng = opt.seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
    kind = opt.kind == ALB_FOUR_SLOT ? "four-slot" : "three-buffer";
    ht_fill(w, opt.words, 0u);
    if (alb_channel_setup_kind(&prod_ch, (uintptr_t)mem, 4u * opt.words, opt.kind) != ALB_OK ||
        alb_channel_setup_kind(&cons_ch, (uintptr_t)mem, 4u * opt.words, opt.kind) != ALB_OK ||
        alb_producer_init(&prod_ch, w) != ALB_OK || alb_consumer_init(&cons_ch) != ALB_OK) {
        fprintf(stderr, "sb-model: channel set-up failed\n");
        return 2;
    }
    fences = fences_dropped = 0;
    schedule();
    status = error ? 2 : tally.violations ? 1 : consumer_done ? 0 : 3;
    if (opt.json && (f = fopen(opt.json, "w")) != 0) {
        fprintf(f, "{\n  \"label\": \"%s\",\n  \"kind\": \"%s\",\n  \"mode\": \"%s\",\n  \"drop\": \"%s\",\n"
                "  \"seed\": %llu,\n  \"payload_words\": %u,\n  \"imports\": %llu,\n  \"exports\": %llu,\n"
                "  \"new\": %llu,\n  \"old\": %llu,\n  \"torn\": %llu,\n  \"back_in_time\": %llu,\n  \"stale\": %llu,\n"
                "  \"wrong_new\": %llu,\n  \"wrong_old\": %llu,\n  \"violations\": %llu,\n"
                "  \"first_violation_at\": %llu,\n  \"overtaken\": %llu,\n  \"steps\": %llu,\n  \"drains\": %llu,\n"
                "  \"fences_dropped\": %llu,\n  \"exit\": %d\n}\n",
                opt.label, kind, opt.pso ? "pso" : "tso", opt.drop_text, (unsigned long long)opt.seed, opt.words,
                (unsigned long long)imports, (unsigned long long)exports, (unsigned long long)tally.news,
                (unsigned long long)tally.olds, (unsigned long long)tally.torn, (unsigned long long)tally.back,
                (unsigned long long)tally.stale, (unsigned long long)tally.wrong_new,
                (unsigned long long)tally.wrong_old, (unsigned long long)tally.violations,
                (unsigned long long)tally.first_violation, (unsigned long long)overtaken,
                (unsigned long long)steps, (unsigned long long)drains, (unsigned long long)fences_dropped, status);
        fclose(f);
    }
    printf("sb-model %s %s (%s, drop %s, seed %llu, %u words): %llu Imports (New %llu, Old %llu), %llu Exports, "
           "producer overtook %llu Imports (max %llu Exports in one), %llu steps, %llu fences dropped\n",
           opt.label, kind, opt.pso ? "pso" : "tso", opt.drop_text, (unsigned long long)opt.seed, opt.words,
           (unsigned long long)imports, (unsigned long long)tally.news, (unsigned long long)tally.olds,
           (unsigned long long)exports, (unsigned long long)overtaken, (unsigned long long)max_overtake,
           (unsigned long long)steps, (unsigned long long)fences_dropped);
    if (status == 3)
        printf("sb-model: expected %llu Imports within %llu steps, got %llu\n", (unsigned long long)opt.imports,
               (unsigned long long)opt.max_steps, (unsigned long long)imports);
    printf("sb-model: %llu violations (%llu torn, %llu back in time, %llu stale, %llu wrong New, %llu wrong Old)"
           ", first at Import %llu\n", (unsigned long long)tally.violations, (unsigned long long)tally.torn,
           (unsigned long long)tally.back, (unsigned long long)tally.stale, (unsigned long long)tally.wrong_new,
           (unsigned long long)tally.wrong_old, (unsigned long long)tally.first_violation);
    return status;
}
