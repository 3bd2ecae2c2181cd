"""albatross_schedule -- the ALBATROSS schedule compiler (the paper, sections 3.3, 4.a, 4.d).

    albatross-schedule DESCRIPTION.toml -o DIR     (pip install ./compiler; make deps)

reads a human-written system description and builds the pre-calculated
cyclic plan that albatross_controller executes: the worst case is the normal
case, and spare bus capacity becomes redundant transfers.  Standard library
only (Python 3.11, tomllib).  Bad input ends with a clear message naming the
file, line, channel and field, and exit status 2; nothing is written then.

Description (TOML)
------------------
[system]
  name          C identifier, names the system (header guards, report)
  clock_hz      controller / bus clock in Hz (positive integer)
  boards        list of board names (C identifiers), index = position, 1..16
  ram_bytes     dual-ported RAM per board: a power of two (default 4096),
                or a table {board = bytes, ...} (missing boards: 4096)
  mode          "time-rigid" (default) | "position-synchronised"
  types_header  optional C header that the board headers #include for the
                user types named in `type`

[bus]           timing model of the controller RTL, all optional (default)
  access_cycles       2   clocks per bus access, fault-free, back to back
  first_access_extra  1   phase alignment of the first access of a slot
  fetch_cycles        10  the controller's per-slot entry fetch
  timeout_cycles      8   clocks until an unanswered access fails
  retries_per_slot    2   failed accesses every slot must absorb
  guard_cycles        6   idle clocks at the end of every slot (the controller starts
                          no access later than deadline - timeout - 2: >= timeout - retries)
  n_chan              16  the controller's N_CHAN (channel ids 0..n_chan-1)
  poll_cycles         16  position poll interval (position-synchronised)

[faults]        optional, the fault hypothesis the plan tolerates (faults.py)
  rate          probability that a bus access fails (stationary, per access)
  mean_burst    mean run of failed accesses (two-state chain), default 1
  probability   the target of the bounds "at the target" (e.g. 0.999999999)

[board.<name>]  optional, a board's Import loop timing (termination bounds)
  core          "picorv32" | "serv": T and V from termination.CORE_TIMING
  clock_hz      the board CPU's clock (default [system] clock_hz)
  import_t_clocks / import_v_clocks   T and V in the CPU's clocks

[[channel]]     one per channel; the id is the position (0, 1, ...)
  name          C identifier (LookForNew<name>, Make<name>Available)
  kind          "copy" (= "three_buffer", default) | "four_slot" (a copy
                channel of the wait-free four-slot kind) | "time" | "status"
  type          C type of the value; default: a generated <name>_t
                (copy: struct { uint8_t bytes[size]; }, time: uint32_t,
                status: struct { uint32_t word[1 + 2*n_chan]; })
  size          value bytes (copy only; 1..16380)
  producer      board that publishes the value (copy only)
  consumers     1..4 boards (not the producer), or "all"
  max_period_us required maximal period between two transfers (integer us)
  sync          true: the position channel that starts every cycle
                (position-synchronised mode only, exactly one, copy)
  priority      integer, default 0; higher gets redundant slots first
  max_slots     optional cap on this channel's slots per cycle
  max_import_passes  optional: at most this many passes per three-buffer Import

Plan
----
Slot length L = fetch + first_access_extra + access_cycles*A
                + retries_per_slot*(timeout + access_cycles + 1) + guard,
A = fault-free accesses when the value is new at every destination:
COPY 3 + W + ND*(W + 3), TIME/STATUS ND*(W + 3).  The cycle C is the
smallest max_period (clocks); every channel gets one slot per cycle, then
redundant slots are added round-robin (priority, then shortest period) while
they fit (time and the 255-entry ROM), and all slots are placed so each
channel's slots are spread evenly (its largest gap minimised).  In
position-synchronised mode the sync channel is entry 0 at start 0 (SYNC
flag) and poll_cycles stay idle at the end of the cycle.  Then, for every
three-buffer consumer whose board has timing, the Import bound (termination):
while D <= T (no bound) the channel's slots are capped and the plan rebuilt.

Outputs in DIR: rom.hex, <board>.h, <board>.c, <board>_ram.hex,
report.json, report.txt, timeline.svg (see docs/compiler.md).

Modules (standard library only):
  model        the description's constants, ScheduleError, Bus/Channel/System/Slot/Plan
  source       reading the TOML file, locating and collecting errors (line, column, field)
  description  validating the description: every fault of it, before any planning
  cnames       every name the generated C declares (the templates), and the names check
  layout       RAM layout of every board's channel instances
  plan         slot lengths, the cycle, redundancy, placement, bounds
  multirate    multi-rate plans: minor cycle, repetitions, bases, fragments (when single-rate does not fit)
  spare        a multi-rate plan's redundant entries in its spare time
  rejection    why a description has no multi-rate plan (a proof or the give-up) and what would fit
  modes        [[mode]]: several schedules, each planned over one RAM layout
  fourslot     the channel kinds: [layout.four_slot] of the contract, bytes, images, flag
  termination  board Import timing, D, the Import bounds, spacing the slots
  rom          the schedule ROM: encoder, hex image, verify_rom
  contract     the contract (ROM format, channel layout) from rtl/albatross_contract.toml
  contract_gen the files generated from it (python -m albatross_schedule.contract_gen)
  cgen         generated C: board headers, set-up sources, RAM images
  report       report.json and report.txt
  picture      timeline.svg (a lane group per mode)
  picture_cluster  timeline.svg of a multi-rate plan: the cluster as stacked minor cycles
  pipeline     the whole compilation (compile_system, compile_file)
  cli          the command line (main); __main__ runs it
"""

from .cgen import board_instances, render_board_c, render_board_header, render_ram_hex
from .description import load_description, load_toml, parse_description
from .faults import Hypothesis, plan_for_hypothesis
from .layout import allocate_ram, channel_bytes, verify_ram_layout
from .model import (DEFAULT_RAM_BYTES, MODE_RIGID, MODE_SYNC, Bus, Channel, Plan, ScheduleError,
                    Slot, System)
from .pipeline import compile_file, compile_system, generate, self_check, write_outputs
from .picture import render_svg
from .plan import build_plan, channel_bounds, channel_gaps, place_slots, slot_length, transfer_accesses
from .report import build_report, render_report_txt
from .rom import (CRC_POLY, CRC_SEED, FLAG_SYNC, KIND_CODE, KIND_NAME, MAX_BASE_WORD, MAX_BOARDS, MAX_DESTS,
                  MAX_ENTRIES, MAX_WORDS, ROM_MAGIC, encode_entry, encode_rom, parse_rom_hex,
                  rom_crc, rom_hex, verify_rom)
from .cli import main

__all__ = [
    "Bus", "CRC_POLY", "Hypothesis", "plan_for_hypothesis", "CRC_SEED", "Channel", "DEFAULT_RAM_BYTES", "FLAG_SYNC", "KIND_CODE", "KIND_NAME",
    "MAX_BASE_WORD", "MAX_BOARDS", "MAX_DESTS", "MAX_ENTRIES", "MAX_WORDS", "MODE_RIGID", "MODE_SYNC",
    "Plan", "ROM_MAGIC", "ScheduleError", "Slot", "System", "allocate_ram", "board_instances",
    "build_plan", "build_report", "channel_bounds", "channel_bytes", "channel_gaps",
    "compile_file", "compile_system", "encode_entry", "encode_rom", "generate", "load_description",
    "load_toml", "main", "parse_description", "parse_rom_hex", "place_slots", "render_board_c",
    "render_board_header", "render_ram_hex", "render_report_txt", "render_svg", "rom_crc", "rom_hex", "self_check",
    "slot_length", "transfer_accesses", "verify_ram_layout", "verify_rom", "write_outputs",
]
