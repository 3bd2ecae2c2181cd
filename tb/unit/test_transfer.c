/*
 * test_transfer.c -- host unit tests of the ALBATROSS C driver: export and
 * import: the size and alignment sweep, buffer selection, corrupt Actual
 * and the import loop.
 * Part of the driver-unit binary; see test_driver.c.
 */
#include "unit_test.h"

/* Access counts, exact bytes and guard bytes for one size and alignment. */
static void sweep_one(uint32_t size, unsigned so, unsigned dof)
{
    static union { uint32_t align; uint8_t b[BIG + 16u]; } sbuf, dbuf;
    alb_channel_t p, c;
    uint8_t init[BIG], snap[UNIT_RAM_BYTES], keep[BIG];
    uint8_t *src = sbuf.b + so, *dst = dbuf.b + 4u + dof;
    const uint8_t guard = 0x5a;
    unsigned b;

    CTX("size %u, source offset %u, destination offset %u", (unsigned)size, so, dof);
    new_channel(&p, &c, size);
    pattern(init, size, 3u);
    alb_producer_init(&p, init);
    alb_consumer_init(&c);
    memset(sbuf.b, 0xee, sizeof sbuf.b);
    pattern(src, size, 100u + size + so);
    memcpy(keep, src, size);

    /* Export: 2 accesses beyond the payload */
    memcpy(snap, unit_port.ram, sizeof snap);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    check_int("alb_export", ALB_OK, alb_export(&p, src));
    check_counts("alb_export", 1, 1, 0, words(size));
    check_int("alb_export: accesses beyond the payload", 2,
              (long)(unit_port.count[UNIT_RD8] + unit_port.count[UNIT_WR8]));
    b = *ram(a_actual());
    check_int("alb_export: published buffer (Actual=1, ReadLocked=1)", 3, (long)b);
    check_int("producer's copy of Actual", 3, p.actual);
    if (b >= 1u && b <= 3u) {
        check_words_at("alb_export: payload words", UNIT_WR32, a_buf(b), words(size));
        check_bytes("alb_export: payload in the RAM", src, ram(a_buf(b)), size);
        check_ram_unchanged("alb_export writes only its buffer and Actual", snap,
                            a_buf(b), a_buf(b) + ALB_STRIDE(size), 1);
    }
    check_bytes("alb_export leaves the source alone", keep, src, size);
    check_fence_between("release: data before Actual", UNIT_WR32, 0u, UNIT_WR8, a_actual());
    check_int("alb_export: last access stores Actual", (long)a_actual(),
              unit_port.nlog ? (long)unit_port.log[(unit_port.nlog - 1u) % UNIT_LOG_MAX].addr : -1);

    /* Import, new data: 3 accesses beyond the payload */
    memset(dbuf.b, guard, sizeof dbuf.b);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    check_int("alb_import: New", ALB_NEW, alb_import(&c, dst));
    check_counts("alb_import (new)", 2, 1, words(size), 0);
    check_int("alb_import (new): accesses beyond the payload", 3,
              (long)(unit_port.count[UNIT_RD8] + unit_port.count[UNIT_WR8]));
    check_words_at("alb_import (new): payload words", UNIT_RD32, a_buf(3u), words(size));
    check_bytes("alb_import (new): exact bytes", keep, dst, size);
    check_fill("alb_import (new): guard bytes before *dst", dbuf.b, 4u + dof, guard);
    check_fill("alb_import (new): guard bytes after *dst", dst + size,
               sizeof dbuf.b - (4u + dof + size), guard);
    check_int("ReadLocked in RAM", 3, *ram(a_rl()));
    check_int("consumer's copy of ReadLocked", 3, c.read_locked);
    check_fence_between("ReadLocked store before Actual load", UNIT_WR8, a_rl(),
                        UNIT_RD8, a_actual());
    check_fence_between("acquire: Actual before data", UNIT_RD8, a_actual(), UNIT_RD32, 0u);

    /* Import, no new data: 1 access beyond the payload */
    memset(dbuf.b, guard, sizeof dbuf.b);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    check_int("alb_import: Old", ALB_OLD, alb_import(&c, dst));
    check_counts("alb_import (no new)", 1, 0, words(size), 0);
    check_words_at("alb_import (no new): payload words", UNIT_RD32, a_buf(3u), words(size));
    check_bytes("alb_import (no new): exact bytes", keep, dst, size);
    check_fill("alb_import (no new): guard bytes before *dst", dbuf.b, 4u + dof, guard);
    check_fill("alb_import (no new): guard bytes after *dst", dst + size,
               sizeof dbuf.b - (4u + dof + size), guard);
    check_fence_between("acquire: Actual before data", UNIT_RD8, a_actual(), UNIT_RD32, 0u);

    /* The next Import finds a new Actual (set in the RAM, no producer call in
     * the log): its ReadLocked store, which hands the buffer just read back to
     * the producer, must follow a fence after that read's data loads (a
     * weakly ordered CPU may otherwise make the store visible first). */
    *ram(a_actual()) = 1u;
    check_int("alb_import after a new Actual: New", ALB_NEW, alb_import(&c, dst));
    check_fence_between("release: the last Import's data loads before the ReadLocked store",
                        UNIT_RD32, 0u, UNIT_WR8, a_rl());

    /* Two exports in a row: store of Actual, fence, load of ReadLocked */
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(size));
    alb_export(&p, src);
    alb_export(&p, init);
    check_counts("two alb_exports", 2, 2, 0, 2 * words(size));
    check_fence_between("Actual store before ReadLocked load", UNIT_WR8, a_actual(),
                        UNIT_RD8, a_rl());
}

void test_sweep(void)
{
    uint32_t size;
    unsigned so, dof;

    for (size = 1u; size <= BIG; ++size)
        for (so = 0u; so < 4u; ++so)
            for (dof = 0u; dof < 4u; ++dof)
                sweep_one(size, so, dof);
}

/* Figure 4: the buffer written for every valid (Actual, ReadLocked). */
void test_selection(void)
{
    alb_channel_t p, c;
    uint8_t v[10], snap[UNIT_RAM_BYTES];
    unsigned a, r, want;

    pattern(v, sizeof v, 7u);
    for (a = 1u; a <= 3u; ++a)
        for (r = 1u; r <= 3u; ++r) {
            CTX("selection, Actual=%u ReadLocked=%u", a, r);
            want = a != r ? 6u - a - r : (a == 3u ? 2u : 3u);
            new_channel(&p, &c, 10u);
            set_control(a, r);
            alb_producer_attach(&p);
            memcpy(snap, unit_port.ram, sizeof snap);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(10u));
            check_int("alb_export", ALB_OK, alb_export(&p, v));
            check_counts("alb_export", 1, 1, 0, words(10u));
            check_int("buffer published in Actual", (long)want, *ram(a_actual()));
            check_int("producer's copy of Actual", (long)want, p.actual);
            check_words_at("payload written to the selected buffer", UNIT_WR32,
                           a_buf(want), words(10u));
            check_bytes("payload", v, ram(a_buf(want)), sizeof v);
            check_ram_unchanged("nothing else written", snap, a_buf(want),
                                a_buf(want) + ALB_STRIDE(10u), 1);
        }
}

/* Actual out of range (4..255): alb_import reports it and reads no buffer.
 * Actual = 0 (nothing published yet): ALB_OLD, the same, no error. */
void test_corrupt_actual(void)
{
    alb_channel_t p, c;
    uint8_t d[9], keep[9], v[9];
    unsigned bad, r;

    for (r = 1u; r <= 3u; ++r)
        for (bad = 0u; bad < 256u; ++bad) {
            if (bad >= 1u && bad <= 3u)
                continue;
            CTX("Actual=%u, ReadLocked=%u", bad, r);
            new_channel(&p, &c, 9u);
            set_control(bad, r);
            alb_consumer_attach(&c);
            memset(d, 0x77, sizeof d);
            memcpy(keep, d, sizeof d);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(9u));
            check_int("alb_import", bad == ALB_NOT_STARTED ? ALB_OLD : ALB_ERR_CORRUPT,
                      alb_import(&c, d));
            check_int("no buffer read", 0, (long)unit_port.count[UNIT_RD32]);
            check_int("no write", 0, (long)(unit_port.count[UNIT_WR8] + unit_port.count[UNIT_WR32]));
            check_bytes("*dst unchanged", keep, d, sizeof d);
            check_int("ReadLocked kept", (long)r, *ram(a_rl()));
            check_int("consumer's copy of ReadLocked kept", (long)r, c.read_locked);
            check_no_trap();
        }

    /* The producer publishes a corrupt value between the two loads of Actual */
    for (bad = 0u; bad < 256u; ++bad) {
        if (bad >= 1u && bad <= 3u)
            continue;
        CTX("Actual 2 then %u during the import, ReadLocked=1", bad);
        new_channel(&p, &c, 9u);
        set_control(2u, 1u);
        alb_consumer_attach(&c);
        memset(d, 0x77, sizeof d);
        memcpy(keep, d, sizeof d);
        port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(9u));
        unit_port.hook_at = 3u;     /* rd8 Actual, wr8 ReadLocked, rd8 Actual */
        unit_port.hook_addr = a_actual();
        unit_port.hook_value = (uint8_t)bad;
        check_int("alb_import", bad == ALB_NOT_STARTED ? ALB_OLD : ALB_ERR_CORRUPT,
                  alb_import(&c, d));
        check_int("no buffer read", 0, (long)unit_port.count[UNIT_RD32]);
        check_bytes("*dst unchanged", keep, d, sizeof d);
        check_no_trap();
    }

    /* After a repair the consumer goes on */
    CTX("Actual repaired after corruption");
    new_channel(&p, &c, 9u);
    pattern(v, sizeof v, 5u);
    alb_producer_init(&p, v);
    alb_consumer_init(&c);
    *ram(a_actual()) = 0xffu;
    check_int("alb_import, corrupt", ALB_ERR_CORRUPT, alb_import(&c, d));
    *ram(a_actual()) = 1u;
    check_int("alb_import, repaired", ALB_OLD, alb_import(&c, d));
    check_bytes("alb_import, repaired: value", v, d, sizeof v);
}

/* The selection loop repeats while the producer publishes again. */
void test_import_loop(void)
{
    alb_channel_t p, c;
    uint8_t d[8];

    CTX("Actual 2 then 3 during the import, ReadLocked=1");
    new_channel(&p, &c, 8u);
    set_control(2u, 1u);
    pattern(ram(a_buf(2u)), 8u, 20u);
    pattern(ram(a_buf(3u)), 8u, 30u);
    alb_consumer_attach(&c);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(8u));
    unit_port.hook_at = 3u;
    unit_port.hook_addr = a_actual();
    unit_port.hook_value = 3u;
    check_int("alb_import", ALB_NEW, alb_import(&c, d));
    check_counts("alb_import, loop taken twice", 3, 2, words(8u), 0);
    check_int("ReadLocked in RAM", 3, *ram(a_rl()));
    check_int("consumer's copy of ReadLocked", 3, c.read_locked);
    check_words_at("reads Buffer3", UNIT_RD32, a_buf(3u), words(8u));
    check_bytes("value of Buffer3", ram(a_buf(3u)), d, sizeof d);
}
