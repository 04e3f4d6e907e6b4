# tools/case.mk — the case of `make run CASE=...`, `make movie CASE=...` and `make phase-study CASE=...`
# (default cases/hover_flexible.toml). Included by the top-level Makefile before
# tools/model.mk: a flexible case without its own chain file runs with the chain of its
# wing's model, so its wing becomes the WING of `make model` (out/<wing>/chain.toml).

CASE ?= cases/hover_flexible.toml

CASE_GOALS := run run-pipeline phase-study movie convergence
ifneq ($(filter $(CASE_GOALS),$(MAKECMDGOALS)),)
# make splits its values at spaces: a path with one would reach flapsim as several words
# (and the case's name as nothing: outputs into out/ itself). Said plainly instead.
ifneq ($(word 2,$(CASE)),)
$(error CASE = "$(CASE)" holds a space, which make cannot pass on as one path: rename the file or its folder, or run build/flapsim run "$(CASE)" directly)
endif
$(foreach v,$(shell /usr/bin/python3 tools/toml_inputs.py case $(CASE)),$(eval $(v)))
ifeq ($(CASE_KIND):$(CASE_CHAIN),flexible:)
ifneq ($(CASE_WING),)
WING ?= $(CASE_WING)
CASE_NEEDS_MODEL := 1
# The chain has the case's number of bodies (a 6-body case used to get the default
# 10-body chain and stop with "the case says 6 bodies, but the chain file ... has 10").
ifneq ($(CASE_BODIES),)
BODIES ?= $(CASE_BODIES)
endif
endif
endif
endif
