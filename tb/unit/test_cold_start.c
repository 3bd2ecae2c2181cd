/*
 * test_cold_start.c -- host unit tests of the ALBATROSS C driver: the cold
 * start on an all-zero RAM (albatross.h, "Start-up"; docs/protocol.md, "Cold
 * start").  Part of the driver-unit binary; see test_driver.c.
 *
 * Both kinds, both orders of the two inits, and 200 seeded random
 * interleavings of init, Export and Import per kind, each from a RAM of
 * zeros (no RAM image).  What must hold:
 *   - an Import before the producer's init returns ALB_OLD, reads no buffer
 *     and leaves *dst unchanged (nothing has been published);
 *   - an Export before the consumer's init (ReadLocked = 0) returns ALB_OK;
 *   - every Export writes neither Actual's buffer nor the buffer (four-slot:
 *     the pair) ReadLocked names, a ReadLocked of 0 counting as Buffer1 (what
 *     the consumer's init stores): so the producer never comes back to
 *     Buffer1 before the consumer starts, and the consumer's init may count
 *     Buffer1's value as read;
 *   - every Import after the producer's init returns the newest value, New
 *     exactly when an Export came since the consumer's last Import (the
 *     initial value counts as read, as with the RAM image);
 *   - nothing is ever ALB_ERR_CORRUPT and no access leaves the channel.
 */
#include "unit_test.h"

#define CS_SIZE 10u

static uint32_t cs_bytes(unsigned kind)
{
    return kind == ALB_FOUR_SLOT ? ALB_FS_CHANNEL_BYTES(CS_SIZE) : ALB_CHANNEL_BYTES(CS_SIZE);
}

static void cs_channel(alb_channel_t *p, alb_channel_t *c, unsigned kind)
{
    memset(unit_port.ram, 0, sizeof unit_port.ram);       /* a zeroed RAM */
    ch_size = CS_SIZE;
    port_reset(ch_base, ch_base + cs_bytes(kind));
    check_int("setup (producer)", ALB_OK, alb_channel_setup_kind(p, ch_base, CS_SIZE, kind));
    check_int("setup (consumer)", ALB_OK, alb_channel_setup_kind(c, ch_base, CS_SIZE, kind));
}

/* The state the checks expect. */
struct cs_model {
    int p_up, c_up;            /* each side's init done */
    int published;             /* producer init done: Actual names a buffer */
    int unread;                /* an Export since the consumer's last Import */
    unsigned latest;           /* values[latest] is the newest published */
};

static void cs_export(alb_channel_t *p, unsigned kind, struct cs_model *m,
                      uint8_t values[][CS_SIZE], unsigned k)
{
    unsigned act = *ram(a_actual()), rl = *ram(a_rl());
    unsigned long j;

    port_reset(ch_base, ch_base + cs_bytes(kind));
    check_int("Export", ALB_OK, alb_export(p, values[k]));
    for (j = 0; j < unit_port.nlog && j < UNIT_LOG_MAX; ++j) {
        unsigned b;
        if (unit_port.log[j].kind != UNIT_WR32)
            continue;
        b = (unsigned)((unit_port.log[j].addr - ch_base - ALB_OFF_BUFFERS) / ALB_STRIDE(CS_SIZE)) + 1u;
        check_true("Export avoids Actual's buffer", b != act, "wrote into Actual's buffer");
        /* ReadLocked = 0 (consumer not started) counts as Buffer1, the value
         * its init stores and the RAM image holds */
        if (kind == ALB_FOUR_SLOT)
            check_true("Export avoids the pair ReadLocked names (0: Buffer1's)",
                       ALB_FS_PAIR(b) != ALB_FS_PAIR(rl == ALB_NOT_STARTED ? ALB_BUFFER1 : rl),
                       "wrote into the consumer's pair");
        else
            check_true("Export avoids the buffer ReadLocked names (0: Buffer1)",
                       b != (rl == ALB_NOT_STARTED ? ALB_BUFFER1 : rl),
                       "wrote into ReadLocked's buffer");
    }
    m->latest = k;
    m->unread = 1;
    check_no_trap();
}

static void cs_import(alb_channel_t *c, unsigned kind, struct cs_model *m,
                      uint8_t values[][CS_SIZE])
{
    uint8_t d[CS_SIZE], keep[CS_SIZE];
    int r;

    memset(d, 0x5a, sizeof d);
    memcpy(keep, d, sizeof d);
    port_reset(ch_base, ch_base + cs_bytes(kind));
    r = alb_import(c, d);
    if (!m->published) {
        check_int("Import before the producer's init: Old", ALB_OLD, r);
        check_int("Import before the producer's init: no buffer read", 0,
                  (long)unit_port.count[UNIT_RD32] - (kind == ALB_FOUR_SLOT ? 1 : 0));
        check_bytes("Import before the producer's init: *dst unchanged", keep, d, sizeof d);
    } else {
        check_int("Import", m->unread ? ALB_NEW : ALB_OLD, r);
        check_bytes("Import: the newest value", values[m->latest], d, sizeof d);
        m->unread = 0;
    }
    check_no_trap();
}

static void cs_producer_init(alb_channel_t *p, unsigned kind, struct cs_model *m,
                             uint8_t values[][CS_SIZE])
{
    port_reset(ch_base, ch_base + cs_bytes(kind));
    check_int("producer init on a zeroed RAM", ALB_OK, alb_producer_init(p, values[0]));
    m->p_up = m->published = 1;
    m->latest = 0u;            /* the initial value counts as read */
    check_no_trap();
}

static void cs_consumer_init(alb_channel_t *c, unsigned kind, struct cs_model *m)
{
    port_reset(ch_base, ch_base + cs_bytes(kind));
    check_int("consumer init on a zeroed RAM", ALB_OK, alb_consumer_init(c));
    m->c_up = 1;
    m->unread = m->latest != 0u;   /* only an Export's value is New (values 1..3) */
    check_no_trap();
}

/* The two fixed orders, step by step. */
static void cs_orders(unsigned kind, uint8_t values[][CS_SIZE])
{
    alb_channel_t p, c;
    struct cs_model m;
    int order;

    for (order = 0; order < 2; ++order) {
        CTX("cold start, %s, %s first", kind == ALB_FOUR_SLOT ? "four-slot" : "three-buffer",
            order ? "consumer" : "producer");
        memset(&m, 0, sizeof m);
        cs_channel(&p, &c, kind);
        if (order) {
            cs_consumer_init(&c, kind, &m);
            cs_import(&c, kind, &m, values);         /* nothing published: Old */
            cs_producer_init(&p, kind, &m, values);
            cs_import(&c, kind, &m, values);         /* the initial value: Old */
            cs_export(&p, kind, &m, values, 1u);
            cs_import(&c, kind, &m, values);         /* New */
        } else {
            cs_producer_init(&p, kind, &m, values);
            cs_export(&p, kind, &m, values, 1u);     /* ReadLocked = 0: ALB_OK */
            cs_export(&p, kind, &m, values, 2u);
            cs_consumer_init(&c, kind, &m);
            cs_import(&c, kind, &m, values);         /* New: the second value */
            cs_import(&c, kind, &m, values);         /* Old */
            cs_export(&p, kind, &m, values, 3u);
        }
        cs_export(&p, kind, &m, values, 2u);
        cs_import(&c, kind, &m, values);
        cs_import(&c, kind, &m, values);
    }
}

/* Seeded random interleavings: the inits at random points among Exports
 * (once the producer is up) and Imports (once the consumer is up). */
static void cs_random(unsigned kind, uint8_t values[][CS_SIZE])
{
    alb_channel_t p, c;
    struct cs_model m;
    uint32_t lcg;
    unsigned seed, i;

    for (seed = 1u; seed <= 200u; ++seed) {
        memset(&m, 0, sizeof m);
        cs_channel(&p, &c, kind);
        lcg = seed * 2654435761u;
        for (i = 0; i < 40u; ++i) {
            unsigned pick;
            lcg = lcg * 1103515245u + 12345u;
            pick = (lcg >> 16) & 3u;
            CTX("cold start, %s, seed %u, step %u",
                kind == ALB_FOUR_SLOT ? "four-slot" : "three-buffer", seed, i);
            if (pick == 0u && !m.p_up)
                cs_producer_init(&p, kind, &m, values);
            else if (pick == 1u && !m.c_up)
                cs_consumer_init(&c, kind, &m);
            else if (pick == 2u && m.p_up)
                cs_export(&p, kind, &m, values, 1u + ((lcg >> 20) % 3u));
            else if (m.c_up)
                cs_import(&c, kind, &m, values);
        }
    }
}

/* The sampling read before anything was published: alb_import's ALB_OLD,
 * status NEVER, *dst unchanged. */
static void cs_sample(unsigned kind)
{
    alb_channel_t p, c;
    alb_sample_t st;
    uint8_t d[8], keep[8];

    CTX("cold start, %s, alb_read before the producer's init",
        kind == ALB_FOUR_SLOT ? "four-slot" : "three-buffer");
    memset(unit_port.ram, 0, sizeof unit_port.ram);
    ch_size = 8u;
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
    check_int("setup", ALB_OK, alb_channel_setup_kind(&p, ch_base, 8u, kind));
    check_int("setup", ALB_OK, alb_channel_setup_kind(&c, ch_base, 8u, kind));
    check_int("consumer init", ALB_OK, alb_consumer_init(&c));
    memset(d, 0x3c, sizeof d);
    memcpy(keep, d, sizeof d);
    memset(&st, 0xff, sizeof st);
    check_int("alb_read: Old", ALB_OLD, alb_read(&c, d, 100u, 50u, &st));
    check_int("alb_read: status NEVER", ALB_SAMPLE_NEVER, st.status);
    check_int("alb_read: not new", 0, st.is_new);
    check_bytes("alb_read: *dst unchanged", keep, d, sizeof d);
    check_no_trap();
}

void test_cold_start(void)
{
    uint8_t values[4][CS_SIZE];
    unsigned k, kind;

    for (k = 0; k < 4u; ++k)
        pattern(values[k], CS_SIZE, 70u + k);
    for (kind = ALB_THREE_BUFFER; kind <= ALB_FOUR_SLOT; ++kind) {
        cs_orders(kind, values);
        cs_random(kind, values);
        cs_sample(kind);
    }
}
