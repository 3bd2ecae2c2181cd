/*
 * litex_pair.c -- the program of the LiteX test SoC (tools/litex/albatross_soc.py,
 * tools/mk/litex.mk): LiteX's VexRiscv (data cache) runs the real driver
 * (mmio port layer) on the channels of the generated header
 * albatross_channels.h, in the window LiteX maps uncached (ALBATROSS_BASE,
 * generated/mem.h).  On each channel (a three-buffer and a four-slot one) it
 * is producer and consumer at once: it writes the start image, attaches
 * both sides, then for seq 1..LITEX_VALUES exports the pair value seq
 * (soc/firmware/board.h), imports it (must be New and whole, that seq) and
 * imports again (must be Old, the same value).  The last value stays in the
 * three-buffer channel for the harness, which reads it through the DPRAM's
 * other port.  Exit code (to the TOHOST CSR, via crt0.S): 0, or
 * 0x10 + k a driver error on channel k, 0x20 + k a wrong value on channel k.
 */
#include <stdint.h>
#include "albatross.h"
#include "alb_port.h"
#include "board.h"
#include "generated/albatross_channels.h"

#ifndef LITEX_VALUES
#define LITEX_VALUES 200u
#endif

static alb_channel_t prod, cons;

static int run(unsigned k, uintptr_t base, uint32_t bytes, int kind)
{
    pair_value_t v, got;
    uint32_t seq, i;

    if (alb_channel_setup_kind(&prod, base, bytes, kind) != ALB_OK ||
        alb_channel_setup_kind(&cons, base, bytes, kind) != ALB_OK)
        return 0x10 + (int)k;
    /* Start image: value 0 in Buffer1, Actual = ReadLocked = Buffer1. */
    pair_make(&v, 0u);
    for (i = 0u; i < sizeof v / 4u; ++i)
        alb_wr32(base + ALB_OFF_BUFFER(1u, sizeof v) + 4u * i, ((const uint32_t *)&v)[i]);
    alb_wr8(base + ALB_OFF_ACTUAL, ALB_BUFFER1);
    alb_wr8(base + ALB_OFF_READLOCKED, ALB_BUFFER1);
    if (kind == ALB_FOUR_SLOT) {
        alb_wr8(base + ALB_OFF_SLOT0, (uint8_t)ALB_FS_INITIAL_SLOT);
        alb_wr8(base + ALB_OFF_SLOT1, (uint8_t)ALB_FS_INITIAL_SLOT);
    }
    /* Four-slot: alb_consumer_init, as tb/pico/firmware/consumer.c does (value 0 counts as read). */
    if (alb_producer_attach(&prod) != ALB_OK ||
        (kind == ALB_FOUR_SLOT ? alb_consumer_init(&cons) : alb_consumer_attach(&cons)) != ALB_OK)
        return 0x10 + (int)k;
    for (seq = 1u; seq <= LITEX_VALUES; ++seq) {
        pair_make(&v, seq);
        if (alb_export(&prod, &v) != ALB_OK)
            return 0x10 + (int)k;
        if (alb_import(&cons, &got) != ALB_NEW || got.seq != seq || !pair_ok(&got))
            return 0x20 + (int)k;
        if (alb_import(&cons, &got) != ALB_OLD || got.seq != seq || !pair_ok(&got))
            return 0x20 + (int)k;
    }
    return 0;
}

int main(void)
{
    int r = run(0u, ALBATROSS_PAIR_BASE, ALBATROSS_PAIR_BYTES, ALBATROSS_PAIR_KIND);

    if (r == 0)
        r = run(1u, ALBATROSS_PAIR4_BASE, ALBATROSS_PAIR4_BYTES, ALBATROSS_PAIR4_KIND);
    return r;
}
