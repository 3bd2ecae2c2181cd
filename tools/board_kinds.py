#!/usr/bin/env python3
"""board_kinds.py -- the driver's kind flags for one board's firmware.

usage: board_kinds.py build/schedule/duo/sensor.c

Reads the board's generated set-up file (compiler/albatross_schedule.py
writes <board>.c) and prints the -D flags that compile out of the driver
(c-driver/albatross.c, albatross.h "Kinds compiled in") every kind and
direction the board does not use, e.g. for the FPGA sensor, a three-buffer
producer and a four-slot consumer:
    -DALB_THREE_BUFFER_IMPORT=0 -DALB_FOUR_SLOT_EXPORT=0
Each channel's kind is taken from its set-up call in alb_<board>_attach_all
(alb_channel_setup: three-buffer; alb_channel_setup_kind(..., ALB_FOUR_SLOT):
four-slot), its direction from the alb_producer_attach / alb_consumer_attach
call that follows.  Exits 1, printing nothing on stdout, if the file has no
such function or a channel has no direction: never a flag from a guess.
Standard library only.
"""
import re
import sys

SETUP = re.compile(r"alb_channel_setup(_kind)?\(&alb_ch_(\w+),[^;]*?(ALB_FOUR_SLOT|ALB_THREE_BUFFER)?\)\);")
SIDE = re.compile(r"alb_(producer|consumer)_attach\(&alb_ch_(\w+)\)")
MACRO = {("three_buffer", "producer"): "ALB_THREE_BUFFER_EXPORT",
         ("three_buffer", "consumer"): "ALB_THREE_BUFFER_IMPORT",
         ("four_slot", "producer"): "ALB_FOUR_SLOT_EXPORT",
         ("four_slot", "consumer"): "ALB_FOUR_SLOT_IMPORT"}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.split("\n\n")[1])
    text = open(sys.argv[1]).read()
    body = re.search(r"int alb_\w+_attach_all\([^)]*\)\s*\{(.*?)\n\}", text, re.S)
    if body is None:
        sys.exit("board_kinds.py: %s: no alb_<board>_attach_all" % sys.argv[1])
    kinds, used = {}, set()
    for m in SETUP.finditer(body.group(1)):
        kinds[m.group(2)] = "four_slot" if m.group(3) == "ALB_FOUR_SLOT" else "three_buffer"
    for m in SIDE.finditer(body.group(1)):
        if m.group(2) not in kinds:
            sys.exit("board_kinds.py: %s: %s attached but never set up" % (sys.argv[1], m.group(2)))
        used.add((kinds[m.group(2)], m.group(1)))
    sides = {name for _, name in SIDE.findall(body.group(1))}
    if not kinds or sides != set(kinds):
        sys.exit("board_kinds.py: %s: channels without a side: %s"
                 % (sys.argv[1], ", ".join(sorted(set(kinds) - sides)) or "none found"))
    print(" ".join("-D%s=0" % MACRO[k] for k in sorted(MACRO, key=MACRO.get) if k not in used))


if __name__ == "__main__":
    main()
