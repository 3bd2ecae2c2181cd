/*
 * test_errors.c -- host unit tests of the ALBATROSS C driver: corrupt
 * ReadLocked, corrupt attach, call sequences and the typed interface.
 * Part of the driver-unit binary; see test_driver.c.
 */
#include "unit_test.h"

/* ReadLocked out of range (4..255): alb_export reports it and publishes
 * anyway.  ReadLocked = 0 (the consumer has not started): the same choice of
 * buffer, and ALB_OK. */
void test_corrupt_read_locked(void)
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
            check_int("alb_export", bad == ALB_NOT_STARTED ? ALB_OK : ALB_ERR_CORRUPT,
                      alb_export(&p, v));
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
            check_int("second alb_export", bad == ALB_NOT_STARTED ? ALB_OK : ALB_ERR_CORRUPT,
                      alb_export(&p, w));
            b2 = *ram(a_actual());
            check_true("second export: a buffer other than the last Actual",
                       b2 >= 1u && b2 <= 3u && b2 != b, "wrong buffer");
            if (b2 >= 1u && b2 <= 3u)
                check_bytes("second export: payload", w, ram(a_buf(b2)), sizeof w);
            check_no_trap();
        }
}

/* Attach to corrupt control bytes (4..255: ALB_ERR_CORRUPT) and to bytes
 * never set (0: ALB_ERR_ARG, the side must init). */
void test_corrupt_attach(void)
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
        check_int("alb_producer_attach", bad == ALB_NOT_STARTED ? ALB_ERR_ARG : ALB_ERR_CORRUPT,
                  alb_producer_attach(&p));
        check_int("alb_consumer_attach", bad == ALB_NOT_STARTED ? ALB_ERR_ARG : ALB_ERR_CORRUPT,
                  alb_consumer_attach(&c));
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
void test_sequence(void)
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

/* The typed interface of the paper, section 3.1. */
typedef struct {
    int16_t  range[5];
    uint8_t  quality;
    double   heading;
    char     tag[3];
} RadarShot;

ALB_CHANNEL(RadarMap, RadarShot)
ALB_CHANNEL_DEFINE(RadarMap);

void test_typed(void)
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
    *ram(a_actual()) = 9u;
    memcpy(&keep, &got, sizeof got);
    check_true("LookForNewRadarMap, corrupt Actual: false", !LookForNewRadarMap(&got),
               "returned true");
    check_bytes("LookForNewRadarMap, corrupt Actual: *v unchanged", (const uint8_t *)&keep,
                (const uint8_t *)&got, sizeof got);
    check_no_trap();
}
