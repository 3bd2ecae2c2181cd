# tools/mk/suite.mk -- how the suite runs (make test, make check): every
# recipe line through tools/recipe_shell.sh, which times it (builds too) and
# keeps a build's output off the console unless the build fails.  Set in the
# environment by the test and check targets (Makefile), unset by
# tools/run_test.sh for the test's own command, so that a test's inner make
# runs as usual.  (So a recipe must not call $(shell ...) while it runs: the
# script would take it for a build.  Functions expanded when the makefiles
# are read, as every fragment's are, are not affected.)
ifneq ($(ALB_SUITE),)
SHELL = $(CURDIR)/tools/recipe_shell.sh $@
endif

# Verilator's run-time library compiled once per distinct command line, not
# once per object folder (tools/objcache.sh).
export OBJCACHE := $(CURDIR)/tools/objcache.sh
