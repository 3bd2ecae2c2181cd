/*
 * test_four_slot.c -- host unit tests of the four-slot channel kind of the
 * C driver (docs/four_slot.md): set-up, init, attach, the statement order and
 * access counts of Export and Import, the fences, and the errors (invalid
 * control bytes give ALB_ERR_CORRUPT without a read outside the channel).
 * The window of the port is the four-slot channel, so any access past
 * Buffer4 traps.  Part of driver-unit (see test_driver.c).
 */
#include "unit_test.h"

static uintptr_t a_slot(unsigned p) { return ch_base + ALB_OFF_SLOT(p); }
static uintptr_t fs_buf(unsigned b) { return ch_base + ALB_OFF_BUFFER(b, ch_size); }

/* The first n word loads of the log are at addr[0..n-1]. */
static void check_loads(const char *what, const uintptr_t *addr, unsigned n)
{
    unsigned long i, lim = unit_port.nlog < UNIT_LOG_MAX ? unit_port.nlog : UNIT_LOG_MAX;
    unsigned k = 0u;
    char m[120];

    for (i = 0; i < lim && k < n; ++i) {
        if (unit_port.log[i].kind != UNIT_RD32)
            continue;
        snprintf(m, sizeof m, "%s: word load %u at 0x%lx", what, k, (unsigned long)unit_port.log[i].addr);
        check_true(m, unit_port.log[i].addr == addr[k], "wrong address");
        ++k;
    }
    check_int(what, (long)n, (long)k);
}

/* Fresh RAM and a four-slot channel of the given size, both sides set up;
 * the control word as after a cold start (Actual = ReadLocked = 1, slots 0). */
static void fs_channel(alb_channel_t *p, alb_channel_t *c, uint32_t size)
{
    memset(unit_port.ram, RAM_FILL, sizeof unit_port.ram);
    ch_size = size;
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(size));
    check_int("setup_kind (producer)", ALB_OK, alb_channel_setup_kind(p, ch_base, size, ALB_FOUR_SLOT));
    check_int("setup_kind (consumer)", ALB_OK, alb_channel_setup_kind(c, ch_base, size, ALB_FOUR_SLOT));
    *ram(ch_base + ALB_OFF_ACTUAL) = 1u;
    *ram(ch_base + ALB_OFF_READLOCKED) = 1u;
    *ram(a_slot(0u)) = 0u;
    *ram(a_slot(1u)) = 0u;
}

static void fs_setup(void)
{
    alb_channel_t ch;

    CTX("four-slot set-up");
    port_reset(0u, 0u);
    check_int("unknown kind", ALB_ERR_ARG, alb_channel_setup_kind(&ch, ch_base, 8u, 2u));
    check_int("misaligned base", ALB_ERR_ARG, alb_channel_setup_kind(&ch, ch_base + 2u, 8u, ALB_FOUR_SLOT));
    check_int("size 0", ALB_ERR_ARG, alb_channel_setup_kind(&ch, ch_base, 0u, ALB_FOUR_SLOT));
    memset(&ch, 0x55, sizeof ch);
    check_int("four-slot", ALB_OK, alb_channel_setup_kind(&ch, ch_base, 8u, ALB_FOUR_SLOT));
    check_int("kind kept", ALB_FOUR_SLOT, ch.kind);
    check_int("no copies yet", 0, ch.actual | ch.read_locked | ch.fs_actual | ch.fs_read_locked | ch.last | ch.slot[0] | ch.slot[1]);
    check_int("alb_channel_setup is three-buffer", ALB_OK, alb_channel_setup(&ch, ch_base, 8u));
    check_int("three-buffer kind", ALB_THREE_BUFFER, ch.kind);
    check_int("set-up makes no RAM access", 0, (long)ram_accesses());
    check_int("layout: 4 + 4 strides", 4 + 4 * 8, (long)ALB_FS_CHANNEL_BYTES(5u));
    check_int("layout: buffer of pair 1, slot 0", 3, (long)ALB_FS_BUFFER(1u, 0u));
    check_int("layout: pair of Buffer4", 1, (long)ALB_FS_PAIR(4u));
    check_int("layout: slot of Buffer3", 0, (long)ALB_FS_SLOT(3u));
    check_no_trap();
}

static void fs_init_attach(void)
{
    alb_channel_t p, c;
    uint8_t v[13], d[13];
    unsigned bad;

    CTX("four-slot init");
    fs_channel(&p, &c, 13u);
    memset(ram(ch_base), 0xEE, 4u);
    pattern(v, sizeof v, 3u);
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(13u));
    check_int("producer init", ALB_OK, alb_producer_init(&p, v));
    check_counts("producer init", 0, 3, 0, words(13u));
    check_bytes("Buffer1 holds the initial value", v, ram(fs_buf(1u)), sizeof v);
    check_int("Slot0", 0, *ram(a_slot(0u)));
    check_int("Slot1", 0, *ram(a_slot(1u)));
    check_int("Actual", 1, *ram(ch_base + ALB_OFF_ACTUAL));
    check_int("ReadLocked untouched", 0xEE, *ram(ch_base + ALB_OFF_READLOCKED));
    check_fence_between("initial value before the slot bytes", UNIT_WR32, 0u, UNIT_WR8, a_slot(0u));
    check_fence_between("slot bytes before Actual", UNIT_WR8, a_slot(1u), UNIT_WR8, ch_base + ALB_OFF_ACTUAL);
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(13u));
    check_int("consumer init", ALB_OK, alb_consumer_init(&c));
    check_counts("consumer init", 0, 1, 0, 0);
    check_int("ReadLocked", 1, *ram(ch_base + ALB_OFF_READLOCKED));
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(13u));
    check_int("first Import after a cold start: Old", ALB_OLD, alb_import(&c, d));
    check_bytes("the initial value", v, d, sizeof d);
    check_counts("Import, nothing new", 0, 0, 1 + words(13u), 0);

    CTX("four-slot attach");
    fs_channel(&p, &c, 8u);
    *ram(ch_base + ALB_OFF_ACTUAL) = 4u;
    *ram(a_slot(1u)) = 1u;
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
    check_int("producer attach", ALB_OK, alb_producer_attach(&p));
    check_counts("producer attach", 0, 0, 1, 0);
    check_int("Actual copy", 4, p.fs_actual);
    check_int("three-buffer copies stay 0", 0, p.actual | c.read_locked);
    check_int("Slot1 copy", 1, p.slot[1]);
    check_int("Slot0 copy", 0, p.slot[0]);
    check_int("consumer attach", ALB_OK, alb_consumer_attach(&c));
    check_int("the last value read is forgotten", 0, c.last);
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
    check_int("first Import after attach: New", ALB_NEW, alb_import(&c, d));
    check_counts("Import after attach", 0, 1, 2 + words(8u), 0);
    {
        const uintptr_t want[3] = {ch_base, ch_base, ch_base + ALB_OFF_BUFFER(4u, 8u)};
        check_loads("control word, control word, Buffer4 (pair 1, Slot1 = 1)", want, 3u);
    }

    for (bad = 0u; bad < 256u; ++bad) {
        int actual_ok = bad >= 1u && bad <= 4u, slot_ok = bad <= 1u;
        CTX("four-slot attach, control byte 0x%02x", bad);
        fs_channel(&p, &c, 8u);
        *ram(ch_base + ALB_OFF_ACTUAL) = (uint8_t)bad;
        port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
        check_int("producer attach, Actual", actual_ok ? ALB_OK : bad == ALB_NOT_STARTED ? ALB_ERR_ARG
                  : ALB_ERR_CORRUPT, alb_producer_attach(&p));
        fs_channel(&p, &c, 8u);
        *ram(a_slot(bad & 1u)) = (uint8_t)bad;
        check_int("producer attach, a slot byte", slot_ok ? ALB_OK : ALB_ERR_CORRUPT, alb_producer_attach(&p));
        fs_channel(&p, &c, 8u);
        *ram(ch_base + ALB_OFF_READLOCKED) = (uint8_t)bad;
        check_int("consumer attach, ReadLocked", actual_ok ? ALB_OK : bad == ALB_NOT_STARTED ? ALB_ERR_ARG
                  : ALB_ERR_CORRUPT, alb_consumer_attach(&c));
        check_no_trap();
    }
}

/* Exports against every ReadLocked: the pair other than the consumer's, the
 * slot of that pair not completed last; exactly one buffer, its slot byte
 * and Actual change; 1 + 2 + W accesses; the fences in place. */
static void fs_export_order(void)
{
    alb_channel_t p, c;
    uint8_t v[9], snap[UNIT_RAM_BYTES];
    unsigned rl, n, pair, slot, buffer, expect_slot[2];

    for (rl = 1u; rl <= 4u; ++rl) {
        fs_channel(&p, &c, 9u);
        check_int("producer attach", ALB_OK, alb_producer_attach(&p));
        *ram(ch_base + ALB_OFF_READLOCKED) = (uint8_t)rl;
        expect_slot[0] = expect_slot[1] = 0u;
        for (n = 0u; n < 5u; ++n) {
            CTX("four-slot Export %u, ReadLocked %u", n, rl);
            pair = 1u - ((rl - 1u) >> 1);
            slot = 1u - expect_slot[pair];
            buffer = 1u + 2u * pair + slot;
            pattern(v, sizeof v, 10u * rl + n);
            memcpy(snap, unit_port.ram, sizeof snap);
            port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(9u));
            check_int("Export", ALB_OK, alb_export(&p, v));
            check_counts("Export", 0, 2, 1, words(9u));
            check_bytes("the value in the chosen buffer", v, ram(fs_buf(buffer)), sizeof v);
            check_int("slot byte of the pair", (long)slot, *ram(a_slot(pair)));
            check_int("Actual", (long)buffer, *ram(ch_base + ALB_OFF_ACTUAL));
            snap[a_slot(pair) - UNIT_RAM_BASE] = (uint8_t)slot;
            check_ram_unchanged("nothing else written", snap, fs_buf(buffer), fs_buf(buffer) + 12u, 1);
            check_true("a fence first (the last Actual store before loading ReadLocked)",
                       unit_port.nlog > 0u && unit_port.log[0].kind == UNIT_FENCE, "no fence before the load");
            check_fence_between("the data before the slot byte", UNIT_WR32, 0u, UNIT_WR8, a_slot(pair));
            check_fence_between("the slot byte before Actual", UNIT_WR8, a_slot(pair), UNIT_WR8,
                                ch_base + ALB_OFF_ACTUAL);
            expect_slot[pair] = slot;
        }
    }
}

/* Imports: nothing new (1 + W), new (3 + W) with the fences, the slot byte
 * loaded after the announcement, New decided by the buffer read. */
static void fs_import_order(void)
{
    alb_channel_t p, c;
    uint8_t v[8], w[8], d[8];

    CTX("four-slot Import");
    fs_channel(&p, &c, 8u);
    check_int("producer attach", ALB_OK, alb_producer_attach(&p));
    check_int("consumer init", ALB_OK, alb_consumer_init(&c));
    pattern(v, sizeof v, 41u);
    check_int("Export", ALB_OK, alb_export(&p, v));    /* pair 1, slot 1: Buffer4 */
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
    check_int("Import: New", ALB_NEW, alb_import(&c, d));
    check_bytes("the value", v, d, sizeof d);
    check_counts("Import, new", 0, 1, 2 + words(8u), 0);
    check_int("ReadLocked := Actual", 4, *ram(ch_base + ALB_OFF_READLOCKED));
    check_fence_between("ReadLocked stored before the slot load", UNIT_WR8, 0u, UNIT_RD32, ch_base);
    {
        const uintptr_t want[4] = {ch_base, ch_base, ch_base + ALB_OFF_BUFFER(4u, 8u),
                                   ch_base + ALB_OFF_BUFFER(4u, 8u) + 4u};
        check_loads("control word twice, then Buffer4", want, 4u);
    }
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
    check_int("Import: Old", ALB_OLD, alb_import(&c, d));
    check_counts("Import, nothing new", 0, 0, 1 + words(8u), 0);
    check_bytes("the same value", v, d, sizeof d);
    /* A new Actual in the other pair (set in the RAM): the announcement, which
     * hands the pair just read back to the producer, must follow a fence
     * after that read's data loads. */
    *ram(ch_base + ALB_OFF_ACTUAL) = 1u;
    check_int("Import after a new Actual: New", ALB_NEW, alb_import(&c, d));
    check_fence_between("release: the last Import's data loads before the ReadLocked store",
                        UNIT_RD32, ch_base + ALB_OFF_BUFFER(4u, 8u), UNIT_WR8, ch_base + ALB_OFF_READLOCKED);

    /* The producer completes a value in the announced pair (Slot1 := 0,
     * Buffer3) but has not yet stored Actual when the consumer loads the
     * slot byte: the consumer reads Buffer3, New; its next Import, with
     * Actual still 4, reads Buffer3 again and reports Old (the mapping as
     * first proposed reported New twice here: docs/four_slot.md). */
    CTX("four-slot Import, Actual lagging the slot byte");
    fs_channel(&p, &c, 8u);
    check_int("consumer init", ALB_OK, alb_consumer_init(&c));
    *ram(ch_base + ALB_OFF_ACTUAL) = 4u;
    *ram(a_slot(1u)) = 1u;
    pattern(w, sizeof w, 42u);
    memcpy(ram(fs_buf(3u)), w, sizeof w);
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
    unit_port.hook_at = 3u;                     /* before the second control load */
    unit_port.hook_addr = a_slot(1u);
    unit_port.hook_value = 0u;
    check_int("Import reads the completed slot: New", ALB_NEW, alb_import(&c, d));
    check_bytes("Buffer3's value", w, d, sizeof d);
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
    check_int("Import with Actual still lagging: Old", ALB_OLD, alb_import(&c, d));
    check_counts("Import, Actual lagging", 0, 1, 2 + words(8u), 0);
    check_bytes("Buffer3's value again", w, d, sizeof d);
    *ram(ch_base + ALB_OFF_ACTUAL) = 3u;
    port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
    check_int("Import once Actual names Buffer3: Old", ALB_OLD, alb_import(&c, d));
    check_counts("Import, nothing new", 0, 0, 1 + words(8u), 0);
}

/* Invalid control bytes: ALB_ERR_CORRUPT, no buffer read, *dst unchanged, no
 * access outside the channel; a corrupt ReadLocked does not stop Export. */
static void fs_errors(void)
{
    alb_channel_t p, c;
    uint8_t v[8], d[8], keep[8];
    unsigned bad;

    for (bad = 0u; bad < 256u; ++bad) {
        CTX("four-slot Import, Actual 0x%02x", bad);
        fs_channel(&p, &c, 8u);
        check_int("consumer init", ALB_OK, alb_consumer_init(&c));
        *ram(ch_base + ALB_OFF_ACTUAL) = (uint8_t)bad;
        memset(d, 0x77, sizeof d);
        memcpy(keep, d, sizeof d);
        port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
        if (bad >= 1u && bad <= 4u) {
            check_true("valid Actual: a value", alb_import(&c, d) >= 0, "an error");
        } else {
            check_int("invalid Actual (0: nothing published, Old)",
                      bad == ALB_NOT_STARTED ? ALB_OLD : ALB_ERR_CORRUPT, alb_import(&c, d));
            check_counts("invalid Actual: one load", 0, 0, 1, 0);
            check_bytes("*dst unchanged", keep, d, sizeof d);
        }
        check_no_trap();

        CTX("four-slot Import, slot byte 0x%02x", bad);
        fs_channel(&p, &c, 8u);
        check_int("consumer init", ALB_OK, alb_consumer_init(&c));
        *ram(ch_base + ALB_OFF_ACTUAL) = 3u;
        *ram(a_slot(1u)) = (uint8_t)bad;
        memset(d, 0x77, sizeof d);
        port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
        if (bad <= 1u) {
            check_int("valid slot: New", ALB_NEW, alb_import(&c, d));
        } else {
            check_int("invalid slot byte", ALB_ERR_CORRUPT, alb_import(&c, d));
            check_counts("invalid slot: no buffer read", 0, 1, 2, 0);
            check_bytes("*dst unchanged", keep, d, sizeof d);
        }
        check_no_trap();

        CTX("four-slot Export, ReadLocked 0x%02x", bad);
        fs_channel(&p, &c, 8u);
        check_int("producer attach", ALB_OK, alb_producer_attach(&p));
        *ram(ch_base + ALB_OFF_READLOCKED) = (uint8_t)bad;
        pattern(v, sizeof v, bad);
        port_reset(ch_base, ch_base + ALB_FS_CHANNEL_BYTES(8u));
        check_int("Export", (bad >= 1u && bad <= 4u) || bad == ALB_NOT_STARTED ? ALB_OK : ALB_ERR_CORRUPT,
                  alb_export(&p, v));
        check_counts("Export: fixed accesses", 0, 2, 1, 2);
        if (bad < 1u || bad > 4u)   /* the pair other than Actual's (Buffer1): pair 1, slot 1 */
            check_bytes("published all the same, into Buffer4", v, ram(fs_buf(4u)), sizeof v);
        check_no_trap();
    }
    CTX("four-slot, uninitialised sides");
    fs_channel(&p, &c, 8u);
    port_reset(0u, 0u);
    check_int("Export before init or attach", ALB_ERR_ARG, alb_export(&p, v));
    check_int("Import before init or attach", ALB_ERR_ARG, alb_import(&c, d));
    check_int("null dst", ALB_ERR_ARG, alb_import(&c, 0));
    check_int("no RAM access", 0, (long)ram_accesses());
}

ALB_CHANNEL(FsVar, uint32_t)
ALB_CHANNEL_DEFINE(FsVar);

static void fs_typed(void)
{
    alb_channel_t p, c;
    uint32_t x = 0x12345678u, y = 0u;

    CTX("four-slot typed interface");
    fs_channel(&p, &c, 4u);
    check_int("setup", ALB_OK, alb_channel_setup_kind(&alb_ch_FsVar, ch_base, 4u, ALB_FOUR_SLOT));
    check_int("producer attach", ALB_OK, alb_producer_attach(&alb_ch_FsVar));
    check_int("consumer init", ALB_OK, alb_consumer_init(&c));
    check_int("MakeFsVarAvailable", ALB_OK, MakeFsVarAvailable(&x));
    alb_ch_FsVar = c;
    check_true("LookForNewFsVar: new", LookForNewFsVar(&y), "returned false");
    check_int("value", (long)x, (long)y);
    check_true("LookForNewFsVar: nothing new", !LookForNewFsVar(&y), "returned true");
    check_no_trap();
}

void test_four_slot(void)
{
    fs_setup();
    fs_init_attach();
    fs_export_order();
    fs_import_order();
    fs_errors();
    fs_typed();
}
