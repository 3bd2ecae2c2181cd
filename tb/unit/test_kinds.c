/*
 * test_kinds.c -- host unit test of the driver built with channel kinds
 * compiled out (albatross.h, "Kinds compiled in"; tools/mk/driver.mk builds
 * it once per set of -D flags, with the same flags as the driver).  For each
 * kind and direction: compiled out, every call of that direction returns
 * ALB_ERR_ARG without a RAM access, even on a channel whose private copies
 * of its kind look set up; compiled in, the calls work (attach, Export, Import).  Its own
 * main; part of driver-unit.
 */
#include "unit_test.h"

/* The kinds compiled in: albatross.h gives the defaults. */

#define SIZE 8u   /* two words: a value and taken_at (alb_read) */

/* Fresh RAM holding a cold-start control word (Actual = ReadLocked = 1,
 * slots 0) and one channel of the kind for each side; the window is the
 * four-slot channel (the larger). */
static void kind_channel(alb_channel_t *p, alb_channel_t *c, unsigned kind)
{
    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    ch_size = SIZE;
    *ram(ch_base + ALB_OFF_ACTUAL) = 1u;
    *ram(ch_base + ALB_OFF_READLOCKED) = 1u;
    *ram(ch_base + ALB_OFF_SLOT0) = 0u;
    *ram(ch_base + ALB_OFF_SLOT1) = 0u;
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(SIZE));
    check_int("setup_kind (producer)", ALB_OK, alb_channel_setup_kind(p, ch_base, SIZE, kind));
    check_int("setup_kind (consumer)", ALB_OK, alb_channel_setup_kind(c, ch_base, SIZE, kind));
}

static void test_kind(unsigned kind, int exports, int imports)
{
    static const char *name[2] = {"three-buffer", "four-slot"};
    alb_channel_t p, c;
    uint8_t v[SIZE], d[SIZE], snap[UNIT_RAM_BYTES];
    alb_sample_t st;

    pattern(v, sizeof v, kind + 1u);
    kind_channel(&p, &c, kind);
    memcpy(snap, unit_port.ram, sizeof snap);
    if (!exports) {
        CTX("%s Export compiled out", name[kind]);
        check_int("alb_producer_init", ALB_ERR_ARG, alb_producer_init(&p, v));
        check_int("alb_producer_attach", ALB_ERR_ARG, alb_producer_attach(&p));
        check_int("alb_export", ALB_ERR_ARG, alb_export(&p, v));
        if (kind == ALB_FOUR_SLOT)     /* the private copy as if attached */
            p.fs_actual = 1u;
        else
            p.actual = 1u;
        check_int("alb_export, private copy set", ALB_ERR_ARG, alb_export(&p, v));
        check_int("no RAM access", 0, (long)ram_accesses());
        check_bytes("RAM unchanged", snap, unit_port.ram, sizeof snap);
    } else {
        CTX("%s Export compiled in", name[kind]);
        check_int("alb_producer_attach", ALB_OK, alb_producer_attach(&p));
        check_int("alb_export", ALB_OK, alb_export(&p, v));
        check_true("alb_export stores", ram_accesses() > 0u, "no RAM access");
    }
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(SIZE));
    memcpy(snap, unit_port.ram, sizeof snap);
    memset(d, 0, sizeof d);
    if (!imports) {
        CTX("%s Import compiled out", name[kind]);
        check_int("alb_consumer_init", ALB_ERR_ARG, alb_consumer_init(&c));
        check_int("alb_consumer_attach", ALB_ERR_ARG, alb_consumer_attach(&c));
        check_int("alb_import", ALB_ERR_ARG, alb_import(&c, d));
        if (kind == ALB_FOUR_SLOT)     /* the private copies as if attached */
            c.fs_read_locked = c.last = 1u;
        else
            c.read_locked = 1u;
        check_int("alb_import, private copy set", ALB_ERR_ARG, alb_import(&c, d));
        check_int("alb_read", ALB_ERR_ARG, alb_read(&c, d, 100u, 0u, &st));
        check_int("no RAM access", 0, (long)ram_accesses());
        check_bytes("RAM unchanged", snap, unit_port.ram, sizeof snap);
        check_fill("*dst unchanged", d, sizeof d, 0u);
    } else {
        CTX("%s Import compiled in", name[kind]);
        check_int("alb_consumer_attach", ALB_OK, alb_consumer_attach(&c));
        check_int("alb_import", exports ? ALB_NEW : (kind == ALB_FOUR_SLOT ? ALB_NEW : ALB_OLD),
                  alb_import(&c, d));
        if (exports)
            check_bytes("alb_import: the exported value", v, d, sizeof d);
    }
    check_no_trap();
}

int main(void)
{
    printf("driver-unit kinds: three-buffer export %d import %d, four-slot export %d import %d\n",
           ALB_THREE_BUFFER_EXPORT, ALB_THREE_BUFFER_IMPORT, ALB_FOUR_SLOT_EXPORT, ALB_FOUR_SLOT_IMPORT);
    test_kind(ALB_THREE_BUFFER, ALB_THREE_BUFFER_EXPORT, ALB_THREE_BUFFER_IMPORT);
    test_kind(ALB_FOUR_SLOT, ALB_FOUR_SLOT_EXPORT, ALB_FOUR_SLOT_IMPORT);
    printf("driver-unit kinds: %lu checks, %lu failed\n", g_checks, g_fails);
    return g_fails == 0u ? EXIT_SUCCESS : EXIT_FAILURE;
}
