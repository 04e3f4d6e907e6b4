# tools/model.mk — `make model WING=wings/<wing>.toml [BODIES=N]`: regenerate
# out/<wing>/ (mesh, FEM modes, equivalent beam and bar chain) from any wing file;
# `make hawkmoth-model` is the same with the default wing, wings/hawkmoth.toml.
# Included from the top-level Makefile, which defines BUILD, OUT and `program`.
#
# Each stage is a file target whose prerequisites are its real inputs: the wing file
# and every file it names (its outline CSV; tools/toml_inputs.py lists them; their paths
# and contents in .wing_source, below), the flapsim binary and, for the reduction, the
# number of bodies. So make re-runs only the
# stages whose inputs changed: a second `make model` right after the first does
# nothing, touching the outline re-runs mesh, modes and reduce, another BODIES re-runs
# the reduction only. Every command writes its files atomically, so an interrupted stage
# never leaves a newer-looking half-written output behind.
#
#   make model WING=wings/robofly.toml           out/robofly/, 10 bodies
#   make model WING=wings/my_wing.toml BODIES=6  out/my_wing/, a 6-body chain
#   make hawkmoth-model [BODIES=16]              out/hawkmoth/

WING         ?= $(or $(HAWKMOTH_WING),wings/hawkmoth.toml)
BODIES       ?= $(or $(HAWKMOTH_BODIES),10)
ifneq ($(word 2,$(WING)),)
$(error WING = "$(WING)" holds a space, which make cannot pass on as one path (a case's wing file is its WING): rename the file or its folder, or run build/flapsim mesh/modes/reduce directly)
endif
MODEL_NAME   := $(basename $(notdir $(WING)))
MODEL_OUT    ?= $(OUT)/$(MODEL_NAME)
MODEL_BIN    := $(BUILD)/flapsim
MODEL_PYTHON ?= /usr/bin/python3

.PHONY: model hawkmoth-model

# Read the wing's inputs and remember the number of bodies (in a file that changes only
# when the value does) only when a goal needs the model, so other make commands leave
# out/ alone.
MODEL_GOALS := model hawkmoth-model run run-pipeline phase-study convergence plots validate figures
ifneq ($(filter $(MODEL_GOALS),$(MAKECMDGOALS)),)
MODEL_FILES := $(shell $(MODEL_PYTHON) tools/toml_inputs.py wing $(WING))
$(shell mkdir -p $(MODEL_OUT) && \
  if [ "$$(cat $(MODEL_OUT)/.bodies 2>/dev/null)" != "$(BODIES)" ]; then \
    echo "$(BODIES)" > $(MODEL_OUT)/.bodies; fi)
# Which files, with which contents, the model is of (rewritten only when that changes):
# out/<wing>/ is named after the wing file's name alone, so another wing of the same name
# (wings/a/x.toml after wings/b/x.toml), or a wing restored with an older time stamp
# (cp -p, tar x, rsync -a), must re-run the stages; before, make judged by time stamps
# alone and flew the other wing's chain.
$(shell mkdir -p $(MODEL_OUT) && \
  for f in $(or $(MODEL_FILES),$(WING)); do realpath "$$f"; sha256sum < "$$f"; done \
    > $(MODEL_OUT)/.wing_source.new 2> /dev/null; \
  if cmp -s $(MODEL_OUT)/.wing_source.new $(MODEL_OUT)/.wing_source; then rm -f $(MODEL_OUT)/.wing_source.new; \
  else mv $(MODEL_OUT)/.wing_source.new $(MODEL_OUT)/.wing_source; fi)
endif
MODEL_INPUTS := $(or $(MODEL_FILES),$(WING)) $(MODEL_BIN) $(MODEL_OUT)/.wing_source

# `program` runs first (cmake relinks flapsim only if a source changed, keeping its time
# stamp otherwise; it builds no test or benchmark); the stage files are then judged
# against the binary.
model: program $(MODEL_OUT)/mesh.msh $(MODEL_OUT)/modes.csv $(MODEL_OUT)/chain.toml
	@echo "model of $(WING) ($(BODIES) bodies) in $(MODEL_OUT)/: mesh.vtu, fem.vtu (ParaView: fem_modes.pvsm), reduction.vtm, chain.toml, report.md"

hawkmoth-model: model

# Stage 1: mesh (mesh.msh, mesh.vtu).
$(MODEL_OUT)/mesh.msh $(MODEL_OUT)/mesh.vtu &: $(MODEL_INPUTS)
	$(MODEL_BIN) mesh $(WING) -o $(MODEL_OUT)

# Stage 2: FEM modes and static load cases (modes.csv, fem.vtu, and fem_modes.pvsm, the
# ParaView state animating mode 1). The commands mesh the wing themselves; the mesh stage
# is a prerequisite so the stages run in order.
$(MODEL_OUT)/modes.csv $(MODEL_OUT)/fem.vtu $(MODEL_OUT)/fem_modes.pvsm &: $(MODEL_INPUTS) $(MODEL_OUT)/mesh.msh
	$(MODEL_BIN) modes $(WING) -o $(MODEL_OUT)

# Stage 3: equivalent beam and bar chain, with the chain-vs-FEM report.
$(MODEL_OUT)/chain.toml $(MODEL_OUT)/beam.csv $(MODEL_OUT)/reduction.vtm \
$(MODEL_OUT)/report.md $(MODEL_OUT)/summary.json &: \
    $(MODEL_INPUTS) $(MODEL_OUT)/.bodies $(MODEL_OUT)/modes.csv
	$(MODEL_BIN) reduce $(WING) -o $(MODEL_OUT) --bodies $(BODIES)
