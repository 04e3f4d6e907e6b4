# tools/pipeline.mk — the whole pipeline and the rotation-phase study (docs/fsi.md,
# docs/hawkmoth_walkthrough.md). Included from the top-level Makefile, which defines
# BUILD, OUT and `build`; uses the hawkmoth model of tools/hawkmoth_model.mk.
#
#   make run-pipeline   wing -> FEM -> reduction -> flexible FSI hover at 26.1 Hz
#   make phase-study    rigid (dpsi = -0.20..+0.10) and flexible (-0.10..+0.10) sweeps,
#                       5 cycles each, all 12 cases over the cores
#   make plots          PNG figures of the study (the paper's Figs. 12-15) in $(OUT)/plots,
#                       and mean lift against the phase of each table (tools/plot_sweep.py)
#   make sweep-plots SWEEP=DIR/sweep.csv   mean lift (and power) against each varied key
#                       of any sweep, in DIR/plots (or SWEEP_PLOTS=...)
#   make validate       reference-vs-computed table of the validation cases
#
# The coupled runs are small (6 x 10 panels): one OpenMP thread per run is faster than
# two on a busy machine, and the sweeps already fill the cores with whole cases.

PIPELINE_BIN      := $(BUILD)/flapsim
PIPELINE_PYTHON   ?= /usr/bin/python3
PIPELINE_CHAIN    ?= $(OUT)/hawkmoth/chain.toml
# Factor on every joint spring of the reduced chain (flapsim run --spring-scale); 1 = the
# springs as reduced from the calibrated wings/hawkmoth.toml. Override for sensitivity
# studies, e.g. 'make phase-study PIPELINE_SPRINGS=4'.
PIPELINE_SPRINGS  ?= 1
PHASE_OUT         ?= $(OUT)/phase_study
PHASE_JOBS        ?= $(shell nproc)
PLOTS_OUT         ?= $(OUT)/plots

.PHONY: run-pipeline phase-study plots sweep-plots validate

# The reduction stage of tools/hawkmoth_model.mk keeps the body count in a file it
# refreshes only when `hawkmoth-model` is a goal; do the same for these goals, which
# need the chain too (same file and default as there).
ifneq ($(filter run run-pipeline phase-study plots validate,$(MAKECMDGOALS)),)
$(shell mkdir -p $(OUT)/hawkmoth && \
  if [ "$$(cat $(OUT)/hawkmoth/.bodies 2>/dev/null)" != "$(or $(HAWKMOTH_BODIES),10)" ]; then \
    echo "$(or $(HAWKMOTH_BODIES),10)" > $(OUT)/hawkmoth/.bodies; fi)
endif

run-pipeline: build $(PIPELINE_CHAIN)
	@start=$$(date +%s.%N); \
	OMP_NUM_THREADS=1 $(PIPELINE_BIN) run cases/hover_flexible.toml --chain $(PIPELINE_CHAIN) \
	  --spring-scale $(PIPELINE_SPRINGS) -o $(OUT)/hover_flexible || exit $$?; \
	end=$$(date +%s.%N); \
	echo "FSI run: $$(awk "BEGIN{printf \"%.1f\", $$end - $$start}") s wall"; \
	xvfb-run -a $(PIPELINE_PYTHON) tools/render_run.py $(OUT)/hover_flexible --phases 0.25 \
	  -o $(OUT)/hover_flexible/preview.png > /dev/null || exit $$?; \
	echo "preview: $(OUT)/hover_flexible/preview.png (the wing at mid-downstroke of the last wingbeat)"; \
	echo "ParaView: cd $(OUT)/hover_flexible && paraview --state=run.pvsm"; \
	echo "          (the FEM and the chain: $(OUT)/hawkmoth/fem.vtu, reduction.vtm)"

phase-study: build $(PIPELINE_CHAIN)
	@start=$$(date +%s.%N); \
	OMP_NUM_THREADS=1 $(PIPELINE_BIN) sweep cases/rotation_phase_rigid_coupled.toml \
	  --vary kinematics.rotation_phase=-0.20:0.05:0.10 -o $(PHASE_OUT)/rigid -j $(PHASE_JOBS) \
	  > $(PHASE_OUT).rigid.log 2>&1 & rigid=$$!; \
	OMP_NUM_THREADS=1 $(PIPELINE_BIN) sweep cases/rotation_phase_flexible.toml \
	  --chain $(PIPELINE_CHAIN) --spring-scale $(PIPELINE_SPRINGS) \
	  --vary kinematics.rotation_phase=-0.10:0.05:0.10 -o $(PHASE_OUT)/flexible -j $(PHASE_JOBS) \
	  > $(PHASE_OUT).flexible.log 2>&1 & flexible=$$!; \
	wait $$rigid; r=$$?; wait $$flexible; f=$$?; \
	cat $(PHASE_OUT).rigid.log $(PHASE_OUT).flexible.log; \
	end=$$(date +%s.%N); \
	echo "phase study: $$(awk "BEGIN{printf \"%.1f\", $$end - $$start}") s wall; tables $(PHASE_OUT)/rigid/sweep.csv, $(PHASE_OUT)/flexible/sweep.csv"; \
	test $$r -eq 0 -a $$f -eq 0

plots:
	@test -f $(PHASE_OUT)/rigid/sweep.csv -a -f $(PHASE_OUT)/flexible/sweep.csv || \
	  $(MAKE) --no-print-directory phase-study
	$(PIPELINE_PYTHON) tools/plot_phase_study.py $(PHASE_OUT) $(PLOTS_OUT)
	$(PIPELINE_PYTHON) tools/plot_sweep.py $(PHASE_OUT)/rigid/sweep.csv $(PLOTS_OUT)/rigid
	$(PIPELINE_PYTHON) tools/plot_sweep.py $(PHASE_OUT)/flexible/sweep.csv $(PLOTS_OUT)/flexible

# Any sweep's table (docs/sweeps.md, "Plotting a sweep").
sweep-plots:
	@test -n "$(SWEEP)" || { echo "usage: make sweep-plots SWEEP=DIR/sweep.csv [SWEEP_PLOTS=OUTPUT_DIR]" >&2; exit 2; }
	$(PIPELINE_PYTHON) tools/plot_sweep.py $(SWEEP) $(SWEEP_PLOTS)

validate: build $(PIPELINE_CHAIN)
	@test -f $(PHASE_OUT)/rigid/sweep.csv -a -f $(PHASE_OUT)/flexible/sweep.csv || \
	  $(MAKE) --no-print-directory phase-study
	$(PIPELINE_PYTHON) tools/validate.py --build $(BUILD) --out $(OUT)
