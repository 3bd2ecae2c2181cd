# tools/mk/tb.mk -- the Verilator co-simulation testbench (tb/dpram/tb_dpram.cpp):
# simulated CPUs run the real C driver against the RTL RAM.
#
# Variants: the real RAM and driver, a RAM without byte arbitration, and the
# driver mutated by tb/mutants/driver/*.sed (each must be caught: negative tests).

VERILATOR_ROOT_DIR := $(shell verilator --getenv VERILATOR_ROOT 2>/dev/null)
TB_CXXFLAGS := -std=c++17 -O3 -g0 -U_FORTIFY_SOURCE -Wall -Wextra -Werror -Itb/common -Ic-driver -Itb/common/port \
               -isystem $(VERILATOR_ROOT_DIR)/include -isystem $(VERILATOR_ROOT_DIR)/include/vltstd
TB_CFLAGS   := -std=c99 -O2 -Wall -Wextra -Werror -pedantic -U_FORTIFY_SOURCE -Ic-driver -Itb/common/port
TB_SRC      := tb/dpram/tb_dpram.cpp tb/dpram/tb_dpram_common.cpp tb/dpram/tb_dpram_exhaustive.cpp \
               tb/dpram/tb_dpram_random.cpp tb/dpram/tb_dpram_crash.cpp \
               tb/common/ram_bus.cpp tb/common/ref_ram.cpp tb/common/sim_cpu.cpp tb/common/protocol_checker.cpp
TB_HDR      := $(wildcard tb/common/*.h tb/dpram/*.h) tb/common/port/alb_port_impl.h c-driver/albatross.h c-driver/albatross_layout.h
MUTANTS     := $(patsubst tb/mutants/driver/%.sed,%,$(wildcard tb/mutants/driver/*.sed))
TB_IMPORTS  ?= 1000000
SOAK_IMPORTS ?= 100000000
# Wall-clock limits (seconds) around each test's command, a second line of
# defence behind tb_dpram's watchdogs in simulated cycles (tb/dpram/bounded.sh):
# the positive tests take about 30 s (exhaustive, 12 bytes), 5 s and 1 s; each negative
# one well under 10 s.
TB_TIMEOUT     ?= 900
TB_NEG_TIMEOUT ?= 120
TB_BOUNDED      = tb/dpram/bounded.sh

# Verilated RAM models: $(TB_DIR)/model-<module>/Vdut__ALL.a, and the
# Verilator run-time library once.
$(TB_DIR)/model-%/Vdut__ALL.a: $(RTL) $(TB_RTL)
	@mkdir -p $(@D)
	verilator --cc -O3 --prefix Vdut --top-module $* -GADDR_WIDTH=10 -Mdir $(@D) \
	    $(filter %/$*.v %/$*_core.v,$(RTL) $(TB_RTL))
	$(MAKE) -s -C $(@D) -f Vdut.mk OPT_FAST=-O3 CXX="$(CXX)" >/dev/null

# The same model with --trace (VCD waves), for make sim.
$(TB_DIR)/model-%-trace/Vdut__ALL.a: $(RTL) $(TB_RTL)
	@mkdir -p $(@D)
	verilator --cc --trace -O3 --prefix Vdut --top-module $* -GADDR_WIDTH=10 -Mdir $(@D) \
	    $(filter %/$*.v %/$*_core.v,$(RTL) $(TB_RTL))
	$(MAKE) -s -C $(@D) -f Vdut.mk OPT_FAST=-O3 CXX="$(CXX)" >/dev/null

$(TB_DIR)/verilated_vcd_c.o:
	@mkdir -p $(@D)
	$(CXX) -std=c++17 -O2 -DVM_TRACE=1 -isystem $(VERILATOR_ROOT_DIR)/include \
	    -isystem $(VERILATOR_ROOT_DIR)/include/vltstd -c $(VERILATOR_ROOT_DIR)/include/verilated_vcd_c.cpp -o $@

$(TB_DIR)/verilated.o:
	@mkdir -p $(@D)/vlrt
	cd $(@D)/vlrt && for f in verilated verilated_threads; do \
	    $(CXX) -std=c++17 -O2 -isystem $(VERILATOR_ROOT_DIR)/include -isystem $(VERILATOR_ROOT_DIR)/include/vltstd \
	        -c $(VERILATOR_ROOT_DIR)/include/$$f.cpp -o $$f.o || exit 1; done
	ld -r $(@D)/vlrt/verilated.o $(@D)/vlrt/verilated_threads.o -o $@

# Driver sources: the real one, and each mutant made from it by sed.  A
# mutant changes (or removes) exactly one line of the driver: one that does
# not apply, or applies to several lines, fails the build loudly.
$(TB_DIR)/mutants/%.c: tb/mutants/driver/%.sed c-driver/albatross.c
	@mkdir -p $(@D)
	sed -f $< c-driver/albatross.c > $@
	@if cmp -s $@ c-driver/albatross.c; then \
	    echo "mutant $* did not apply: c-driver/albatross.c no longer has the line tb/mutants/driver/$*.sed edits"; \
	    rm -f $@; exit 1; fi
	@n=$$(diff c-driver/albatross.c $@ | grep -c '^<'); if [ "$$n" -ne 1 ]; then \
	    echo "mutant $* changed $$n lines of c-driver/albatross.c, expected exactly 1 (tb/mutants/driver/$*.sed must match one line)"; \
	    rm -f $@; exit 1; fi

# The harness's own objects: only ram_bus.cpp includes the model's Vdut.h,
# so it is compiled once per RAM model ($(TB_DIR)/harness-<model>/ram_bus.o);
# every other source once for all models ($(TB_DIR)/harness/<source>.o).
# Every variant links them with its driver, so a driver mutant costs one C
# compile and another RAM model one C++ file.
TB_MODELS := albatross_dpram dpram_no_arbitration dpram_priority_a
TB_SHARED_OBJS := $(patsubst %.cpp,$(TB_DIR)/harness/%.o,$(filter-out ram_bus.cpp,$(notdir $(TB_SRC))))
tb_harness_objs = $(TB_SHARED_OBJS) $(TB_DIR)/harness-$(1)/ram_bus.o
$(TB_DIR)/harness/%.o: tb/dpram/%.cpp $(TB_HDR)
	@mkdir -p $(@D)
	$(CXX) $(TB_CXXFLAGS) -c $< -o $@
$(TB_DIR)/harness/%.o: tb/common/%.cpp $(TB_HDR)
	@mkdir -p $(@D)
	$(CXX) $(TB_CXXFLAGS) -c $< -o $@
define tb_harness
$(TB_DIR)/harness-$(1)/ram_bus.o: tb/common/ram_bus.cpp $(TB_HDR) $(TB_DIR)/model-$(1)/Vdut__ALL.a
	@mkdir -p $$(@D)
	$(CXX) $(TB_CXXFLAGS) -I$(TB_DIR)/model-$(1) -c $$< -o $$@
endef
$(foreach m,$(TB_MODELS),$(eval $(call tb_harness,$(m))))

# tb_dpram linked against <model> and <driver source>.
define tb_variant
$(TB_DIR)/$(1)/tb_dpram: $(call tb_harness_objs,$(2)) $(TB_DIR)/model-$(2)/Vdut__ALL.a $(TB_DIR)/verilated.o $(3)
	@mkdir -p $$(@D)
	$(CC) $(TB_CFLAGS) -c $(3) -o $$(@D)/driver.o
	$(CXX) $(call tb_harness_objs,$(2)) $$(@D)/driver.o \
	    $(TB_DIR)/model-$(2)/Vdut__ALL.a $(TB_DIR)/verilated.o -pthread -o $$@
endef
$(eval $(call tb_variant,albatross,albatross_dpram,c-driver/albatross.c))
$(eval $(call tb_variant,no-arbitration,dpram_no_arbitration,c-driver/albatross.c))
$(foreach m,$(MUTANTS),$(eval $(call tb_variant,$(m),albatross_dpram,$(TB_DIR)/mutants/$(m).c)))

$(eval $(call tb_variant,priority-a,dpram_priority_a,c-driver/albatross.c))

# The real RAM and driver with VCD tracing.
$(TB_DIR)/albatross-trace/tb_dpram: $(TB_SRC) $(TB_HDR) $(TB_DIR)/model-albatross_dpram-trace/Vdut__ALL.a \
        $(TB_DIR)/verilated.o $(TB_DIR)/verilated_vcd_c.o c-driver/albatross.c
	@mkdir -p $(@D)
	$(CC) $(TB_CFLAGS) -c c-driver/albatross.c -o $(@D)/driver.o
	$(CXX) $(TB_CXXFLAGS) -DVM_TRACE=1 -I$(TB_DIR)/model-albatross_dpram-trace $(TB_SRC) $(@D)/driver.o \
	    $(TB_DIR)/model-albatross_dpram-trace/Vdut__ALL.a $(TB_DIR)/verilated.o $(TB_DIR)/verilated_vcd_c.o \
	    -pthread -o $@

# The exhaustive mode: every interleaving of two Exports against two Imports
# of two-word values in make test (a torn value needs two words), of
# three-word values (its default, 12 bytes: about 15 times the schedules) in
# make test-slow.
TB_EXH_PAYLOAD ?= 8
TESTS += tb-exhaustive tb-random tb-crash
SLOW_TESTS += tb-exhaustive-wide

test-tb-exhaustive: $(TB)
	@tools/run_test.sh tb-exhaustive $(TB_BOUNDED) $(TB_TIMEOUT) $(TB) exhaustive --payload $(TB_EXH_PAYLOAD) \
	    --report $(REPORTS)/tb_exhaustive.json
test-tb-exhaustive-wide: $(TB)
	@tools/run_test.sh tb-exhaustive-wide $(TB_BOUNDED) $(TB_TIMEOUT) $(TB) exhaustive \
	    --report $(REPORTS)/tb_exhaustive_wide.json
test-tb-random: $(TB)
	@tools/run_test.sh tb-random $(TB_BOUNDED) $(TB_TIMEOUT) $(TB) random --imports $(TB_IMPORTS) --seed $(SEED) \
	    --report $(REPORTS)/tb_random.json
test-tb-crash: $(TB)
	@tools/run_test.sh tb-crash $(TB_BOUNDED) $(TB_TIMEOUT) $(TB) crash --seed $(SEED) --report $(REPORTS)/tb_crash.json

# The four-slot kind (docs/four_slot.md), same modes and checkers, plus the
# wait-free check (every Import exactly 1 + W or 3 + W accesses).  Exhaustive
# at 8 bytes (2 payload words): at 12 bytes one start state alone passes the
# 5 M-schedule watchdog (one more access per Export than the three-buffer kind).
TB_FS_PAYLOAD ?= 8
TESTS += tb-fs-exhaustive tb-fs-random tb-fs-crash

test-tb-fs-exhaustive: $(TB)
	@tools/run_test.sh tb-fs-exhaustive $(TB_BOUNDED) $(TB_TIMEOUT) $(TB) exhaustive --kind four_slot \
	    --payload $(TB_FS_PAYLOAD) --report $(REPORTS)/tb_fs_exhaustive.json
test-tb-fs-random: $(TB)
	@tools/run_test.sh tb-fs-random $(TB_BOUNDED) $(TB_TIMEOUT) $(TB) random --kind four_slot --imports $(TB_IMPORTS) \
	    --seed $(SEED) --report $(REPORTS)/tb_fs_random.json
test-tb-fs-crash: $(TB)
	@tools/run_test.sh tb-fs-crash $(TB_BOUNDED) $(TB_TIMEOUT) $(TB) crash --kind four_slot --seed $(SEED) \
	    --report $(REPORTS)/tb_fs_crash.json

# Negative tests: each passes only if the named checker catches the broken
# variant (NAME VARIANT MODE CHECKER [extra options]) before the mode's
# watchdogs stop it, and within TB_NEG_TIMEOUT seconds.  Together they cover
# every checker of the harness.  short_export (an Export that writes one
# payload word too few) once made crash mode search for ever for a crash
# point its calls never reach: it must now fail at once, by termination.
# import_never_returns (an Import that loops for ever) checks the watchdogs themselves.
# fs_*: the four-slot kind (docs/four_slot.md): fs_new_twice is the mapping as
# first proposed (New whenever Actual differs from the buffer read last);
# fs_index_from_actual and fs_slot_before_announce are wrong statement orders
# of the consumer; fs_ignore_readlocked a producer that ignores the consumer's
# pair; fs_three_buffer_producer a three-buffer producer on a four-slot
# channel (named as a kind mismatch by termination; -semantic: the fault it
# causes, with termination ignored).
NEGATIVE := \
  no-arbitration:no-arbitration:exhaustive:byte_atomicity \
  no-arbitration-protocol:no-arbitration:exhaustive:definite_results:--ignore,byte_atomicity \
  priority-a:priority-a:random:access_time \
  while_as_if:while_as_if:random:mutual_exclusion \
  ignore_readlocked:ignore_readlocked:random:definite_results \
  fresh_readlocked:fresh_readlocked:random:termination \
  fresh_readlocked-semantic:fresh_readlocked:random:in_channel:--ignore,termination \
  never_new:never_new:random:actuality \
  reader_writes_actual:reader_writes_actual:random:ownership \
  short_export-crash:short_export:crash:termination \
  import_never_returns:import_never_returns:random:watchdog \
  import_never_returns-exhaustive:import_never_returns:exhaustive:watchdog \
  import_never_returns-crash:import_never_returns:crash:watchdog \
  fs_new_twice:fs_new_twice:exhaustive:actuality:--kind,four_slot,--payload,8 \
  fs_index_from_actual:fs_index_from_actual:random:mutual_exclusion:--kind,four_slot \
  fs_slot_before_announce:fs_slot_before_announce:random:termination:--kind,four_slot \
  fs_slot_before_announce-semantic:fs_slot_before_announce:random:mutual_exclusion:--kind,four_slot,--ignore,termination \
  fs_ignore_readlocked:fs_ignore_readlocked:random:mutual_exclusion:--kind,four_slot \
  fs_three_buffer_producer:fs_three_buffer_producer:random:termination:--kind,four_slot \
  fs_three_buffer_producer-semantic:fs_three_buffer_producer:random:mutual_exclusion:--kind,four_slot,--ignore,termination
# no-arbitration-protocol (the torn bytes seen by the protocol's checks, found
# after some 20 million clocks: about 35 s) runs with make test-slow;
# definite_results has its make test negative in ignore_readlocked.
TB_NEG_SLOW := no-arbitration-protocol
define negative_test
$(if $(filter $(call neg_field,$(1),1),$(TB_NEG_SLOW)),SLOW_TESTS,TESTS) += tb-negative-$(call neg_field,$(1),1)
test-tb-negative-$(call neg_field,$(1),1): $(TB_DIR)/$(call neg_field,$(1),2)/tb_dpram
	@tools/run_test.sh tb-negative-$(call neg_field,$(1),1) $(TB_BOUNDED) $(TB_NEG_TIMEOUT) $$< $(call neg_field,$(1),3) \
	    --imports 2000000 --seed $(SEED) --variant $(call neg_field,$(1),1) \
	    --expect-caught-by $(call neg_field,$(1),4) $(subst $(comma), ,$(call neg_field,$(1),5)) \
	    --report $(REPORTS)/tb_negative_$(call neg_field,$(1),1).json
endef
$(foreach n,$(NEGATIVE),$(eval $(call negative_test,$(n))))

.PHONY: soak bench-tb
soak: $(TB) ## 100 million checked Imports (SOAK_IMPORTS=N to change)
	$(TB) random --imports $(SOAK_IMPORTS) --seed $(SEED) --report $(REPORTS)/tb_soak.json

BENCHES += bench-tb
bench-tb: $(TB)
	$(TB) bench --imports 300000 --seed $(SEED) --report $(REPORTS)/bench_tb.json

# The figure of the termination bound: accesses per Import beyond the payload against the
# writer:reader speed ratio (held fixed, 1:100 .. 100:1), both kinds, checkers
# on: build/reports/import_accesses_by_ratio.{json,svg}.  About 5 s of CPU.
BENCHES += bench-import-accesses
FIG_IMPORTS ?= 10000
.PHONY: bench-import-accesses
bench-import-accesses: $(TB) ## accesses per Import against the speed ratio, both kinds -> build/reports/import_accesses_by_ratio.svg
	@mkdir -p $(REPORTS)
	$(TB) ratio --kind three_buffer --imports $(FIG_IMPORTS) --seed $(SEED) --report $(REPORTS)/ratio_three_buffer.json
	$(TB) ratio --kind four_slot --imports $(FIG_IMPORTS) --seed $(SEED) --report $(REPORTS)/ratio_four_slot.json
	$(PYTHON) tb/dpram/plot_import_accesses.py $(REPORTS)/ratio_three_buffer.json $(REPORTS)/ratio_four_slot.json \
	    $(REPORTS)/import_accesses_by_ratio.json $(REPORTS)/import_accesses_by_ratio.svg
