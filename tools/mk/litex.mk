# tools/mk/litex.mk -- ALBATROSS in a LiteX SoC (LiteX from PyPI, no network
# and no FPGA toolchain needed).  tools/litex/albatross_litex.py is the
# integration (AlbatrossDPRAM: rtl/albatross_dpram.v as an uncached Wishbone
# slave of the SoC bus, port B for the other side; the channel header
# generator); tools/litex/albatross_soc.py builds the test SoC with it
# (LiteX's VexRiscv "standard": I and D caches; ROM, SRAM, the DPRAM at
# 0x9000_0000, a TOHOST CSR) and writes its Verilog and headers.
#   make test-litex-soc    generate the SoC with LiteX, build
#                          tb/litex/firmware/litex_pair.c against the
#                          generated headers (mem.h's ALBATROSS_BASE, the
#                          channel header), simulate LiteX's sim.v with
#                          Verilator (tb/litex/test_litex_soc.cpp): 200
#                          values on a three-buffer and a four-slot channel,
#                          each Import checked on the core; the last value
#                          read back through the DPRAM's port B;
#                          build/reports/litex_soc.json
#   make test-litex-cached-window-negative
#                          the same SoC with the window at 0x3000_0000
#                          (cacheable for VexRiscv): LiteX must refuse it
#                          ("not in IO region"), so a window a data cache
#                          would serve is never built
# LiteX needs, besides litex and pythondata-cpu-vexriscv,
# pythondata-software-picolibc and pythondata-software-compiler-rt even with
# compile_software=False (its Builder names their folders in
# variables.mak); make deps installs them.  Its own simulator files
# (litex_sim, SimPlatform's build) need more (litedram, liteeth,
# pythondata-misc-tapcfg) and are not used: the harness simulates sim.v itself.
# Cost: generation about 5 s, Verilator build about 25 s, the run < 1 s.

LX_DIR   := $(BUILD)/litex
LX_ABS   := $(abspath $(LX_DIR))
LX_PY    := tools/litex/albatross_soc.py tools/litex/albatross_litex.py compiler/albatross_schedule/fourslot.py \
            rtl/albatross_contract.toml
LX_NEED   = @$(PYTHON) -c 'import litex, pythondata_cpu_vexriscv, pythondata_software_picolibc, \
pythondata_software_compiler_rt' 2>/dev/null || { echo "LiteX or a pythondata package it needs is missing \
(litex, pythondata-cpu-vexriscv, pythondata-software-picolibc, pythondata-software-compiler-rt); run make deps"; exit 1; }
LX_GEN   := $(LX_DIR)/software/include/generated
LX_CXX   := -O2 -std=c++17 $(TB_COMMON_INC) -I$(abspath c-driver) -I$(LX_ABS)/software/include

$(LX_DIR)/gateware/sim.v: $(LX_PY) $(CORE_dpram) tools/mk/litex.mk
	$(LX_NEED)
	@mkdir -p $(LX_DIR)
	$(PYTHON) tools/litex/albatross_soc.py --output-dir $(LX_ABS) > $(LX_DIR)/generate.log 2>&1 \
	    || { cat $(LX_DIR)/generate.log; exit 1; }
	@tail -1 $(LX_DIR)/generate.log

$(LX_DIR)/fw/litex_pair.elf: tb/litex/firmware/litex_pair.c tb/litex/firmware/link.ld c-driver/albatross.c \
        soc/firmware/crt0.S soc/firmware/board.h $(DRV_HDRS) $(LX_DIR)/gateware/sim.v
	@$(DRV_RV_NEED)
	@mkdir -p $(@D)
	$(DRV_RV_CC) $(FW_CFLAGS) -I$(LX_DIR)/software/include \
	    -include $(LX_GEN)/albatross_board.h -o $@ soc/firmware/crt0.S tb/litex/firmware/litex_pair.c \
	    c-driver/albatross.c -T tb/litex/firmware/link.ld -Wl,--no-warn-rwx-segments -lgcc

# The run folder: LiteX's sim.v reads its memories' images by relative name;
# the ROM's is the program.
$(LX_DIR)/run/sim_rom.init: $(LX_DIR)/fw/litex_pair.hex
	@mkdir -p $(@D)
	cp $(LX_DIR)/gateware/sim_sram.init $(LX_DIR)/gateware/sim_mem.init $(@D)/
	cp $< $@

$(LX_DIR)/obj/Vsim: $(LX_DIR)/gateware/sim.v tb/litex/test_litex_soc.cpp tb/litex/litex.vlt tb/common/report.h \
        tools/mk/litex.mk
	$(VEX_NEED)
	$(VERILATOR_BUILD) -j 2 -O3 -Wall --timescale 1ns/1ps --top-module sim tb/litex/litex.vlt \
	    -CFLAGS "$(LX_CXX)" --Mdir $(@D) $$(cat $(LX_DIR)/gateware/sources.txt) $(abspath tb/litex/test_litex_soc.cpp) \
	    > $(LX_DIR)/build.log 2>&1 || { cat $(LX_DIR)/build.log; exit 1; }

TESTS += litex-soc litex-cached-window-negative
.PHONY: test-litex-soc test-litex-cached-window-negative
test-litex-soc: $(LX_DIR)/obj/Vsim $(LX_DIR)/run/sim_rom.init
	@tools/run_test.sh litex-soc bash -c 'cd $(LX_DIR)/run && $(LX_ABS)/obj/Vsim --values 200 \
	    --report $(abspath $(REPORTS))/litex_soc.json'

test-litex-cached-window-negative: $(LX_PY)
	$(LX_NEED)
	@mkdir -p $(LX_DIR)-cached
	@tools/run_test.sh litex-cached-window-negative bash -c 'if $(PYTHON) tools/litex/albatross_soc.py \
	    --output-dir $(LX_ABS)-cached --origin 0x30000000 > $(LX_DIR)-cached/generate.log 2>&1; then \
	    echo "expected LiteX to refuse the DPRAM window at 0x3000_0000 (cacheable), it built the SoC"; exit 1; \
	    elif grep -q "not in IO region, it must be cached" $(LX_DIR)-cached/generate.log; then \
	    echo "LiteX refused the uncached window outside the I/O region, as expected:"; \
	    grep "not in IO region" $(LX_DIR)-cached/generate.log; \
	    else echo "expected the refusal \"not in IO region, it must be cached\", got:"; \
	    tail -5 $(LX_DIR)-cached/generate.log; exit 1; fi'
