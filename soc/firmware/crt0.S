/* crt0.S -- rv32i start-up for the PicoRV32 test boards: set the stack
 * pointer, clear .bss, call main(), store its result to TOHOST, then loop.
 * .data needs no copy: the whole image is loaded into RAM by $readmemh. */
#include "board.h"

    .section .text.start, "ax"
    .globl _start
_start:
    la    sp, __stack_top
    la    t0, __bss_start
    la    t1, __bss_end
1:  bgeu  t0, t1, 2f
    sw    zero, 0(t0)
    addi  t0, t0, 4
    j     1b
2:  call  main
    li    t0, BOARD_TOHOST
    sw    a0, 0(t0)
3:  j     3b
