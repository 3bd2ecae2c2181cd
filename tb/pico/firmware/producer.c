/*
 * producer.c -- PicoRV32 producer of the pair test (tb/pico/).  Writes the
 * channel's start image into the DPRAM (control bytes Buffer1, Buffer1 and
 * value 0 in Buffer1: what a RAM image from the schedule compiler holds),
 * attaches with the real driver, releases the consumer, then exports
 * PAIR_VALUES values 1..N with a pseudo-random pause between exports so that
 * the two cores meet in many different phases.  Built with
 * -DPAIR_KIND=ALB_FOUR_SLOT, the channel is of the four-slot kind (the start
 * image also holds Slot0 = Slot1 = 0); default ALB_THREE_BUFFER.  Exit code 0, or
 * 0x10 + driver error.  STAT: 0 exports, 1 exports, 2 cycles in alb_export,
 * 3 retired instructions.
 */
#include "albatross.h"
#include "alb_port.h"
#include "board.h"

#ifndef PAIR_KIND
#define PAIR_KIND ALB_THREE_BUFFER   /* the channel kind: ALB_THREE_BUFFER or ALB_FOUR_SLOT */
#endif

static alb_channel_t ch;

int main(void)
{
    pair_value_t v;
    uint32_t seq, k, pause, rng = 0x12345678u, t0, cycles = 0u;
    int r;

    if (alb_channel_setup_kind(&ch, BOARD_CHANNEL, sizeof v, PAIR_KIND) != ALB_OK)
        return 0x11;
    /* Start image: value 0 in Buffer1, Actual = ReadLocked = Buffer1. */
    pair_make(&v, 0u);
    for (k = 0u; k < sizeof v / 4u; ++k)
        alb_wr32(BOARD_CHANNEL + ALB_OFF_BUFFER(1u, sizeof v) + 4u * k,
                 ((const uint32_t *)&v)[k]);
    alb_wr8(BOARD_CHANNEL + ALB_OFF_ACTUAL, ALB_BUFFER1);
    alb_wr8(BOARD_CHANNEL + ALB_OFF_READLOCKED, ALB_BUFFER1);
    if (PAIR_KIND == ALB_FOUR_SLOT) {
        alb_wr8(BOARD_CHANNEL + ALB_OFF_SLOT0, (uint8_t)ALB_FS_INITIAL_SLOT);
        alb_wr8(BOARD_CHANNEL + ALB_OFF_SLOT1, (uint8_t)ALB_FS_INITIAL_SLOT);
    }
    r = alb_producer_attach(&ch);
    if (r != ALB_OK)
        return 0x10 - r;
    alb_fence();
    alb_wr32(BOARD_START_FLAG, BOARD_START_MAGIC);

    for (seq = 1u; seq <= PAIR_VALUES; ++seq) {
        pair_make(&v, seq);
        t0 = board_cycles();
        r = alb_export(&ch, &v);
        cycles += board_cycles() - t0;
        if (r != ALB_OK)
            return 0x10 - r;
        rng = pair_mix(rng);
        for (pause = rng & 63u; pause != 0u; --pause)
            __asm__ volatile("" ::: "memory");
    }
    board_stat(0u, PAIR_VALUES);
    board_stat(1u, PAIR_VALUES);
    board_stat(2u, cycles);
    board_stat(3u, board_instret());
    return 0;
}
