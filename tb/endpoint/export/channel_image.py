#!/usr/bin/env python3
"""channel_image.py OUT [BASE_WORD] -- the DPRAM image of tb/endpoint/export:
the pair test's channel at word BASE_WORD (default 0) with Actual and
ReadLocked both Buffer1 and value 0 (soc/firmware/board.h's pair_make(0)) in
Buffer1, and the consumer's start flag (BOARD_START_MAGIC at byte 0x100 of the
window): what tb/pico/firmware/producer.c writes before it releases the
consumer.  One 32-bit word per line for $readmemh; the layout's offsets come
from the contract (rtl/albatross_contract.toml via the compiler package)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', '..', 'compiler'))
from albatross_schedule import contract  # noqa: E402

WORDS = 1024
START_FLAG_WORD = 0x100 // 4
START_MAGIC = 0x5354
SALT = 0x5A5A5A5A
M = 0xFFFFFFFF


def mix(x):
    x ^= (x << 13) & M
    x ^= x >> 17
    x ^= (x << 5) & M
    return (x + 0x9E3779B9) & M


def main():
    out = sys.argv[1]
    base = int(sys.argv[2], 0) if len(sys.argv) > 2 else 0
    c = contract.load()
    mem = [0] * WORDS
    mem[base] = c.initial_control_word()      # Actual = ReadLocked = the initial index
    assert c.initial_index == c.buffer1, "the image's value 0 sits in Buffer1"
    h1 = mix(0)
    h2 = mix(h1)
    b1 = base + c.control_words
    mem[b1:b1 + 4] = [0, h1, h2, 0 ^ h1 ^ h2 ^ SALT]
    mem[START_FLAG_WORD] = START_MAGIC
    with open(out, 'w') as f:
        f.write(''.join('%08x\n' % w for w in mem))


if __name__ == '__main__':
    main()
