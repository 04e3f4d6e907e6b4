# tools/hawkmoth_model.mk — `make hawkmoth-model`: regenerate out/hawkmoth/
# (mesh, FEM modes, equivalent beam and bar chain) from the hawkmoth wing file.
# Included from the top-level Makefile, which defines BUILD, OUT and `build`.
#
# Each stage is a file target whose prerequisites are its real inputs (the wing
# file, the outline it names and the flapsim binary), so make re-runs only the
# stages whose inputs changed, and a second `make hawkmoth-model` right after the
# first does nothing. Every command writes its files atomically, so an interrupted
# stage never leaves a newer-looking half-written output behind.
#
#   make hawkmoth-model                      default: 10 bodies
#   make hawkmoth-model HAWKMOTH_BODIES=16   another chain (re-runs the reduction only)

HAWKMOTH_WING    ?= wings/hawkmoth.toml
HAWKMOTH_OUTLINE ?= wings/outlines/hawkmoth1_outline.csv
HAWKMOTH_OUT     ?= $(OUT)/hawkmoth
HAWKMOTH_BODIES  ?= 10

HAWKMOTH_BIN    := $(BUILD)/flapsim
HAWKMOTH_INPUTS := $(HAWKMOTH_WING) $(HAWKMOTH_OUTLINE) $(HAWKMOTH_BIN)

# The number of bodies is an input of the reduction: remember it in a file that
# changes only when the value does.
# (Only when this target is asked for, so other make commands leave out/ alone.)
HAWKMOTH_BODIES_FILE := $(HAWKMOTH_OUT)/.bodies
ifneq ($(filter hawkmoth-model,$(MAKECMDGOALS)),)
$(shell mkdir -p $(HAWKMOTH_OUT) && \
  if [ "$$(cat $(HAWKMOTH_BODIES_FILE) 2>/dev/null)" != "$(HAWKMOTH_BODIES)" ]; then \
    echo "$(HAWKMOTH_BODIES)" > $(HAWKMOTH_BODIES_FILE); fi)
endif

# `build` runs first (cmake relinks flapsim only if a source changed, keeping its
# time stamp otherwise); the stage files are then judged against the binary.
hawkmoth-model: build $(HAWKMOTH_OUT)/mesh.msh $(HAWKMOTH_OUT)/modes.csv $(HAWKMOTH_OUT)/chain.toml

# Stage 1: mesh (mesh.msh, mesh.vtu).
$(HAWKMOTH_OUT)/mesh.msh $(HAWKMOTH_OUT)/mesh.vtu &: $(HAWKMOTH_INPUTS)
	$(HAWKMOTH_BIN) mesh $(HAWKMOTH_WING) -o $(HAWKMOTH_OUT)

# Stage 2: FEM modes and static load cases (modes.csv, fem.vtu). The commands mesh
# the wing themselves; the mesh stage is a prerequisite so the stages run in order.
$(HAWKMOTH_OUT)/modes.csv $(HAWKMOTH_OUT)/fem.vtu &: $(HAWKMOTH_INPUTS) $(HAWKMOTH_OUT)/mesh.msh
	$(HAWKMOTH_BIN) modes $(HAWKMOTH_WING) -o $(HAWKMOTH_OUT)

# Stage 3: equivalent beam and bar chain, with the chain-vs-FEM report.
$(HAWKMOTH_OUT)/chain.toml $(HAWKMOTH_OUT)/beam.csv $(HAWKMOTH_OUT)/reduction.vtm \
$(HAWKMOTH_OUT)/report.md $(HAWKMOTH_OUT)/summary.json &: \
    $(HAWKMOTH_INPUTS) $(HAWKMOTH_BODIES_FILE) $(HAWKMOTH_OUT)/modes.csv
	$(HAWKMOTH_BIN) reduce $(HAWKMOTH_WING) -o $(HAWKMOTH_OUT) --bodies $(HAWKMOTH_BODIES)
