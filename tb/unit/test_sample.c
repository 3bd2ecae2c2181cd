/*
 * test_sample.c -- host unit tests of the sampling read (alb_read and the
 * typed Read<Name> of ALB_SAMPLING) on both channel
 * kinds: never received before the first New, the age from the payload's
 * last word (taken_at), the stale boundary (age == bound is fresh, bound + 1
 * stale), a stale New, a value taken after now (age 0), wrap-around of the
 * 32-bit time, a restart (never received again until a New), an unaligned
 * destination, and the errors (st untouched).  One channel object plays both
 * sides, as in test_typed.  Part of driver-unit (see test_driver.c).
 */
#include "unit_test.h"

#define SMP_WORDS 3u                       /* value words; + taken_at */
#define SMP_SIZE  (4u * (SMP_WORDS + 1u))

typedef struct { uint32_t value[SMP_WORDS]; uint32_t taken_at; } smp_msg;

ALB_CHANNEL(SmpVar, smp_msg)
ALB_SAMPLING(SmpVar, smp_msg)
ALB_CHANNEL_DEFINE(SmpVar);

static void smp_channel(alb_channel_t *ch, unsigned kind)
{
    smp_msg zero;

    memset(&zero, 0, sizeof zero);
    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    ch_size = SMP_SIZE;
    port_reset(ch_base, ch_base + (kind == ALB_FOUR_SLOT ? ALB_FS_CHANNEL_BYTES(SMP_SIZE)
                                                         : ALB_CHANNEL_BYTES(SMP_SIZE)));
    check_int("setup_kind", ALB_OK, alb_channel_setup_kind(ch, ch_base, SMP_SIZE, kind));
    check_int("alb_producer_init", ALB_OK, alb_producer_init(ch, &zero));
    check_int("alb_consumer_init", ALB_OK, alb_consumer_init(ch));
}

/* Publish value seq with taken_at t (as the controller would). */
static void smp_publish(alb_channel_t *ch, uint32_t seq, uint32_t t)
{
    smp_msg m;
    unsigned k;

    for (k = 0u; k < SMP_WORDS; ++k)
        m.value[k] = seq * 0x01010101u + k;
    m.taken_at = t;
    check_int("alb_export", ALB_OK, alb_export(ch, &m));
}

/* One alb_read; checks result, status, is_new, age and the value. */
static void smp_expect(alb_channel_t *ch, const char *what, uint32_t max_age, uint32_t now,
                       int result, int status, int is_new, uint32_t age, uint32_t seq)
{
    smp_msg m;
    alb_sample_t st;
    char b[160];

    memset(&st, 0x5a, sizeof st);
    snprintf(b, sizeof b, "%s: result", what);
    check_int(b, result, alb_read(ch, &m, max_age, now, &st));
    snprintf(b, sizeof b, "%s: status", what);
    check_int(b, status, st.status);
    snprintf(b, sizeof b, "%s: is_new", what);
    check_int(b, is_new, st.is_new);
    snprintf(b, sizeof b, "%s: age_clocks", what);
    check_int(b, (long)age, (long)st.age_clocks);
    snprintf(b, sizeof b, "%s: value", what);
    check_int(b, seq == 0u ? 0l : (long)(seq * 0x01010101u + 2u), (long)m.value[2]);
}

static void smp_kind(unsigned kind)
{
    alb_channel_t *ch = &alb_ch_SmpVar;
    const uint32_t B = 1000u;

    CTX("alb_read, %s", kind == ALB_FOUR_SLOT ? "four-slot" : "three-buffer");
    smp_channel(ch, kind);
    check_int("set-up: not received", 0, ch->received);
    /* the start image (value 0, taken_at 0): read, but never received */
    smp_expect(ch, "before any New", B, 50u, ALB_OLD, ALB_SAMPLE_NEVER, 0, 50u, 0u);
    smp_expect(ch, "before any New, older than the bound", B, 5000u, ALB_OLD, ALB_SAMPLE_NEVER, 0, 5000u, 0u);

    /* the stale boundary: age == bound is fresh, bound + 1 stale */
    smp_publish(ch, 1u, 10000u);
    smp_expect(ch, "first New, age == bound", B, 10000u + B, ALB_NEW, ALB_SAMPLE_NEW, 1, B, 1u);
    smp_expect(ch, "Old, age == bound", B, 10000u + B, ALB_OLD, ALB_SAMPLE_OLD, 0, B, 1u);
    smp_expect(ch, "Old, age == bound + 1", B, 10001u + B, ALB_OLD, ALB_SAMPLE_STALE, 0, B + 1u, 1u);
    smp_expect(ch, "Old, bound 0, age 0", 0u, 10000u, ALB_OLD, ALB_SAMPLE_OLD, 0, 0u, 1u);

    /* a New value that is already stale */
    smp_publish(ch, 2u, 20000u);
    smp_expect(ch, "stale New", B, 20001u + B, ALB_NEW, ALB_SAMPLE_STALE, 1, B + 1u, 2u);
    smp_expect(ch, "then Old, fresh", 2u * B, 20001u + B, ALB_OLD, ALB_SAMPLE_OLD, 0, B + 1u, 2u);

    /* taken after now was read (now read before the Import): age 0 */
    smp_publish(ch, 3u, 30000u);
    smp_expect(ch, "taken_at after now", B, 29990u, ALB_NEW, ALB_SAMPLE_NEW, 1, 0u, 3u);

    /* wrap-around: taken_at just below 2^32, now past 0 */
    smp_publish(ch, 4u, 0xFFFFFF00u);
    smp_expect(ch, "wrap, age 0x110 == bound", 0x110u, 0x10u, ALB_NEW, ALB_SAMPLE_NEW, 1, 0x110u, 4u);
    smp_expect(ch, "wrap, age 0x110 > bound", 0x10Fu, 0x10u, ALB_OLD, ALB_SAMPLE_STALE, 0, 0x110u, 4u);
    smp_expect(ch, "wrap, taken_at after now", B, 0xFFFFFE00u, ALB_OLD, ALB_SAMPLE_OLD, 0, 0u, 4u);
    smp_publish(ch, 5u, 0x7FFFFFF0u);
    smp_expect(ch, "age 2^31 - 1 (largest)", 0xFFFFFFFFu, 0xFFFFFFEFu, ALB_NEW, ALB_SAMPLE_NEW, 1, 0x7FFFFFFFu, 5u);

    /* a restart of the consumer: never received again until a New */
    smp_publish(ch, 6u, 40000u);
    check_int("re-setup", ALB_OK, alb_channel_setup_kind(ch, ch_base, SMP_SIZE, kind));
    check_int("alb_consumer_attach", ALB_OK, alb_consumer_attach(ch));
    check_int("alb_producer_attach", ALB_OK, alb_producer_attach(ch));
    smp_expect(ch, "before the first New after a restart", B, 40000u, ALB_NEW, ALB_SAMPLE_NEW, 1, 0u, 6u);
    check_no_trap();
}

/* After a restart that finds its value already read: Old and never received. */
static void smp_restart_old(void)
{
    alb_channel_t *ch = &alb_ch_SmpVar;

    CTX("alb_read, three-buffer restart with nothing new");
    smp_channel(ch, ALB_THREE_BUFFER);
    smp_publish(ch, 1u, 500u);
    smp_expect(ch, "New", 100u, 550u, ALB_NEW, ALB_SAMPLE_NEW, 1, 50u, 1u);
    check_int("re-setup", ALB_OK, alb_channel_setup(ch, ch_base, SMP_SIZE));
    check_int("alb_consumer_attach", ALB_OK, alb_consumer_attach(ch));
    check_int("alb_producer_attach", ALB_OK, alb_producer_attach(ch));
    smp_expect(ch, "Old after restart: never", 100u, 550u, ALB_OLD, ALB_SAMPLE_NEVER, 0, 50u, 1u);
    smp_publish(ch, 2u, 600u);
    smp_expect(ch, "New after restart", 100u, 650u, ALB_NEW, ALB_SAMPLE_NEW, 1, 50u, 2u);
    check_no_trap();
}

static void smp_typed_and_errors(void)
{
    alb_channel_t *ch = &alb_ch_SmpVar, small;
    smp_msg m;
    alb_sample_t st, keep;
    uint32_t raw[SMP_WORDS + 2u];
    uint8_t *odd = (uint8_t *)raw + 1;
    uint32_t t;

    CTX("ReadSmpVar and alb_read errors");
    smp_channel(ch, ALB_THREE_BUFFER);
    smp_publish(ch, 7u, 0x12345678u);
    check_int("ReadSmpVar", ALB_NEW, ReadSmpVar(&m, &st, 0x12345678u + 9u, 10u));
    check_int("ReadSmpVar: status", ALB_SAMPLE_NEW, st.status);
    check_int("ReadSmpVar: age", 9, (long)st.age_clocks);
    check_int("ReadSmpVar: taken_at", 0x12345678, (long)m.taken_at);
    check_int("ReadSmpVar: stale", ALB_OLD, ReadSmpVar(&m, &st, 0x12345678u + 11u, 10u));
    check_int("ReadSmpVar: stale status", ALB_SAMPLE_STALE, st.status);

    /* an unaligned destination: taken_at from bytes */
    check_int("unaligned dst", ALB_OLD, alb_read(ch, odd, 100u, 0x12345678u + 3u, &st));
    memcpy(&t, odd + 4u * SMP_WORDS, 4u);
    check_int("unaligned dst: taken_at", 0x12345678, (long)t);
    check_int("unaligned dst: age", 3, (long)st.age_clocks);
    check_int("unaligned dst: status", ALB_SAMPLE_OLD, st.status);

    /* errors: st not written */
    memset(&keep, 0x77, sizeof keep);
    st = keep;
    check_int("null st", ALB_ERR_ARG, alb_read(ch, &m, 1u, 1u, 0));
    check_int("null dst", ALB_ERR_ARG, alb_read(ch, 0, 1u, 1u, &st));
    check_int("null channel", ALB_ERR_ARG, alb_read(0, &m, 1u, 1u, &st));
    check_int("alb_channel_setup (6 bytes)", ALB_OK, alb_channel_setup(&small, ch_base, 6u));
    check_int("payload not whole words", ALB_ERR_ARG, alb_read(&small, &m, 1u, 1u, &st));
    check_int("alb_channel_setup (2 bytes)", ALB_OK, alb_channel_setup(&small, ch_base, 2u));
    check_int("payload without taken_at", ALB_ERR_ARG, alb_read(&small, &m, 1u, 1u, &st));
    *ram(a_actual()) = 9u;
    check_int("corrupt Actual", ALB_ERR_CORRUPT, alb_read(ch, &m, 1u, 1u, &st));
    check_bytes("st untouched by the errors", (const uint8_t *)&keep, (const uint8_t *)&st, sizeof st);
    check_no_trap();
}

void test_sample(void)
{
    smp_kind(ALB_THREE_BUFFER);
    smp_kind(ALB_FOUR_SLOT);
    smp_restart_old();
    smp_typed_and_errors();
}
