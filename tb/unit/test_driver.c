/*
 * test_driver.c -- host unit tests of the ALBATROSS C driver (c-driver/),
 * built against the counting, trapping port layer in tb/unit/port/.
 *
 * Single-threaded and deterministic.  The partner of the side under test is
 * played by writing the control bytes into the RAM array directly, or, for
 * a partner that acts in the middle of a call, by the port's scripted hook.
 * Each check that fails prints what was expected and what was got; the last
 * line is "driver-unit: N checks, F failed" and the exit status is 1 if any
 * check failed.
 *
 * This file: main, the port self-test, setup, initialisation and attach,
 * and a first export/import.  The other tests are in test_transfer.c and
 * test_errors.c; the checks and helpers in unit_helpers.c (unit_test.h).
 */
#include "unit_test.h"

/* ------------------------------------------------------------------------ */
/* tests                                                                      */

static void test_port_traps(void)
{
    uint8_t snap[UNIT_RAM_BYTES];

    CTX("port self-test");
    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    memcpy(snap, unit_port.ram, sizeof snap);
    port_reset(UNIT_RAM_BASE + 64u, UNIT_RAM_BASE + 128u);
    alb_wr8(UNIT_RAM_BASE + 63u, 1u);
    check_int("write below the window traps", 1, (long)unit_port.traps);
    check_int("trapped load returns 0", 0, alb_rd8(UNIT_RAM_BASE + 128u));
    check_int("read above the window traps", 2, (long)unit_port.traps);
    port_reset(UNIT_RAM_BASE, UNIT_RAM_BASE + UNIT_RAM_BYTES + 8u);
    alb_wr32(UNIT_RAM_BASE + UNIT_RAM_BYTES, 0u);
    alb_wr32(UNIT_RAM_BASE + UNIT_RAM_BYTES - 2u, 0u);
    alb_wr8(UNIT_RAM_BASE - 1u, 0u);
    alb_wr32(0u, 0u);
    check_int("accesses outside the RAM trap", 4, (long)unit_port.traps);
    alb_wr32(UNIT_RAM_BASE + 2u, 0u);
    check_int("misaligned word access traps", 5, (long)unit_port.traps);
    check_bytes("trapped accesses leave the RAM alone", snap, unit_port.ram, sizeof snap);
    check_int("accesses are counted", 5, (long)ram_accesses());
}

static void test_setup_args(void)
{
    alb_channel_t ch;
    unsigned off;

    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    port_reset(0u, 0u);
    for (off = 1u; off <= 3u; ++off) {
        CTX("alb_channel_setup, base offset %u", off);
        check_int("misaligned base", ALB_ERR_ARG, alb_channel_setup(&ch, ch_base + off, 8u));
    }
    CTX("alb_channel_setup");
    check_int("size 0", ALB_ERR_ARG, alb_channel_setup(&ch, ch_base, 0u));
    check_int("null channel", ALB_ERR_ARG, alb_channel_setup(0, ch_base, 8u));
    memset(&ch, 0x55, sizeof ch);
    check_int("aligned base, size 5", ALB_OK, alb_channel_setup(&ch, ch_base, 5u));
    check_true("base kept", ch.base == ch_base, "ch.base differs");
    check_int("size kept", 5, (long)ch.size);
    check_int("no Actual copy yet", 0, ch.actual);
    check_int("no ReadLocked copy yet", 0, ch.read_locked);
    check_int("set-up makes no RAM access", 0, (long)ram_accesses());
    check_no_trap();
}

static void test_uninitialised(void)
{
    alb_channel_t p, c, zero;
    uint8_t v[8], d[8], keep[8];

    CTX("uninitialised sides");
    new_channel(&p, &c, 8u);
    set_control(1u, 1u);
    pattern(v, sizeof v, 1u);
    memset(d, 0x77, sizeof d);
    memcpy(keep, d, sizeof d);
    port_reset(0u, 0u);     /* any access at all traps */
    check_int("alb_import, consumer never initialised", ALB_ERR_ARG, alb_import(&c, d));
    check_int("alb_export, producer never initialised", ALB_ERR_ARG, alb_export(&p, v));
    check_bytes("*dst unchanged", keep, d, sizeof d);

    memset(&zero, 0, sizeof zero);    /* never set up */
    check_int("alb_producer_init, never set up", ALB_ERR_ARG, alb_producer_init(&zero, v));
    check_int("alb_producer_attach, never set up", ALB_ERR_ARG, alb_producer_attach(&zero));
    check_int("alb_consumer_init, never set up", ALB_ERR_ARG, alb_consumer_init(&zero));
    check_int("alb_consumer_attach, never set up", ALB_ERR_ARG, alb_consumer_attach(&zero));
    check_int("alb_import, never set up", ALB_ERR_ARG, alb_import(&zero, d));
    check_int("alb_export, never set up", ALB_ERR_ARG, alb_export(&zero, v));
    check_int("alb_producer_init, null value", ALB_ERR_ARG, alb_producer_init(&p, 0));
    check_int("null channel: producer_init", ALB_ERR_ARG, alb_producer_init(0, v));
    check_int("null channel: consumer_init", ALB_ERR_ARG, alb_consumer_init(0));
    check_int("null channel: import", ALB_ERR_ARG, alb_import(0, d));
    check_int("null channel: export", ALB_ERR_ARG, alb_export(0, v));
    check_int("no RAM access by any rejected call", 0, (long)ram_accesses());
    check_int("no trap", 0, (long)unit_port.traps);

    /* each side's object knows only its own side */
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(8u));
    check_int("alb_producer_init", ALB_OK, alb_producer_init(&p, v));
    check_int("alb_consumer_init", ALB_OK, alb_consumer_init(&c));
    port_reset(0u, 0u);
    check_int("alb_import on the producer's object", ALB_ERR_ARG, alb_import(&p, d));
    check_int("alb_export on the consumer's object", ALB_ERR_ARG, alb_export(&c, v));
    check_int("alb_import, null destination", ALB_ERR_ARG, alb_import(&c, 0));
    check_int("alb_export, null source", ALB_ERR_ARG, alb_export(&p, 0));
    check_bytes("*dst unchanged", keep, d, sizeof d);
    check_int("no RAM access by any rejected call", 0, (long)ram_accesses());
    check_int("no trap", 0, (long)unit_port.traps);
}

static void test_init_attach(void)
{
    alb_channel_t p, c;
    uint8_t v[13], d[13];
    unsigned a, r;

    CTX("init, size 13");
    new_channel(&p, &c, 13u);
    pattern(v, sizeof v, 2u);
    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
    check_int("alb_producer_init", ALB_OK, alb_producer_init(&p, v));
    check_counts("alb_producer_init", 0, 1, 0, words(13u));
    check_words_at("alb_producer_init writes Buffer1", UNIT_WR32, a_buf(1u), words(13u));
    check_fence_between("initial value before Actual", UNIT_WR32, 0u, UNIT_WR8, a_actual());
    check_int("Actual in RAM", 1, *ram(a_actual()));
    check_int("producer's copy of Actual", 1, p.actual);
    check_bytes("Buffer1 holds the initial value", v, ram(a_buf(1u)), sizeof v);
    check_int("ReadLocked untouched", RAM_FILL, *ram(a_rl()));

    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
    check_int("alb_consumer_init", ALB_OK, alb_consumer_init(&c));
    check_counts("alb_consumer_init", 0, 1, 0, 0);
    check_int("ReadLocked in RAM", 1, *ram(a_rl()));
    check_int("consumer's copy of ReadLocked", 1, c.read_locked);
    check_int("Actual untouched", 1, *ram(a_actual()));

    port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
    memset(d, 0x77, sizeof d);
    check_int("alb_import right after init: Old", ALB_OLD, alb_import(&c, d));
    check_counts("alb_import after init", 1, 0, words(13u), 0);
    check_bytes("alb_import after init returns the initial value", v, d, sizeof d);

    for (a = 1u; a <= 3u; ++a)
        for (r = 1u; r <= 3u; ++r) {
            CTX("attach, Actual=%u ReadLocked=%u", a, r);
            new_channel(&p, &c, 13u);
            set_control(a, r);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
            check_int("alb_producer_attach", ALB_OK, alb_producer_attach(&p));
            check_int("producer's copy of Actual", (long)a, p.actual);
            check_counts("alb_producer_attach", 1, 0, 0, 0);
            port_reset(ch_base, ch_base + ALB_CHANNEL_BYTES(13u));
            check_int("alb_consumer_attach", ALB_OK, alb_consumer_attach(&c));
            check_int("consumer's copy of ReadLocked", (long)r, c.read_locked);
            check_counts("alb_consumer_attach", 1, 0, 0, 0);
            check_int("Actual untouched", (long)a, *ram(a_actual()));
            check_int("ReadLocked untouched", (long)r, *ram(a_rl()));
        }
}

static void test_export_import(void)
{
    alb_channel_t p, c;
    uint8_t v[3][24], d[24];
    unsigned i;

    CTX("export/import, size 24");
    new_channel(&p, &c, 24u);
    pattern(v[0], sizeof v[0], 10u);
    pattern(v[1], sizeof v[1], 11u);
    pattern(v[2], sizeof v[2], 12u);
    alb_producer_init(&p, v[0]);
    alb_consumer_init(&c);
    for (i = 0; i < 6u; ++i) {
        CTX("export/import, size 24, round %u", i);
        check_int("alb_export", ALB_OK, alb_export(&p, v[1 + i % 2u]));
        memset(d, 0, sizeof d);
        check_int("first alb_import: New", ALB_NEW, alb_import(&c, d));
        check_bytes("first alb_import: the exported bytes", v[1 + i % 2u], d, sizeof d);
        memset(d, 0, sizeof d);
        check_int("second alb_import: Old", ALB_OLD, alb_import(&c, d));
        check_bytes("second alb_import: the same bytes", v[1 + i % 2u], d, sizeof d);
    }
    CTX("export/import, size 24, two exports then import");
    check_int("alb_export", ALB_OK, alb_export(&p, v[0]));
    check_int("alb_export", ALB_OK, alb_export(&p, v[2]));
    check_int("alb_import: New", ALB_NEW, alb_import(&c, d));
    check_bytes("alb_import: the newest value", v[2], d, sizeof d);
    check_int("alb_import: Old", ALB_OLD, alb_import(&c, d));
    check_no_trap();
}

int main(void)
{
    test_port_traps();
    test_setup_args();
    test_uninitialised();
    test_init_attach();
    test_export_import();
    test_sweep();
    test_selection();
    test_corrupt_actual();
    test_import_loop();
    test_corrupt_read_locked();
    test_corrupt_attach();
    test_sequence();
    test_typed();
    test_four_slot();
    test_sample();
    test_cold_start();
    printf("driver-unit: %lu checks, %lu failed\n", g_checks, g_fails);
    return g_fails == 0u ? EXIT_SUCCESS : EXIT_FAILURE;
}
