# tools/pipeline.mk — runs, the rotation-phase study and the figures (docs/fsi.md,
# docs/hawkmoth_walkthrough.md). Included from the top-level Makefile, which defines
# BUILD, OUT, `build` and `program`; uses the case of tools/case.mk and the model of tools/model.mk.
#
#   make run [CASE=cases/x.toml]   run a case (default cases/hover_flexible.toml: the
#                       hawkmoth wing -> FEM -> reduction -> flexible FSI hover at 26.1 Hz)
#                       into out/<case name>/, with the model of its wing when it needs
#                       one (out/<case name>_run/ when the case has its wing's name, whose
#                       model is out/<wing>/); leaves preview.png and run.pvsm there
#   make run WING=wings/x.toml [CASE=...]   the case flown with another wing (its model
#                       made first when the case is flexible), into out/<case name>_<wing>/;
#                       WING= works alike for movie, phase-study (out/phase_study_<wing>/),
#                       plots (out/plots_<wing>/) and convergence (out/convergence/<case name>_<wing>/)
#   make phase-study    rigid (dpsi = -0.20..+0.10) and flexible (-0.10..+0.10) sweeps,
#                       6 cycles each (nothing truncated), all 12 cases over the cores
#   make phase-study CASE=cases/x.toml [PHASES=-0.2:0.05:0.1]
#                       the rotation-phase sweep of any case, into out/phase_study/<case name>/
#   make plots          figures of the study (the paper's Figs. 12-15), PDF and PNG, in
#                       $(OUT)/plots, and mean lift against the phase of each table (tools/plot_sweep.py)
#   make figures        docs/figures from a fresh phase study
#   make sweep-plots SWEEP=DIR/sweep.csv   mean lift (and power) against each varied key
#                       of any sweep, in DIR/plots (or SWEEP_PLOTS=...)
#   make optimize-plots DIR=DIR   of a flapsim optimize folder: objective against evaluation,
#                       the path through the keys, the optimum's lift over a cycle beside the
#                       start's, in DIR/plots (or OPTIMIZE_PLOTS=...)
#   make validate       reference-vs-computed table of the validation cases
#   make reproduce      every claim of the two papers beside flapsim's, for each leading-edge
#                       model: docs/reproduction.md and docs/figures/reproduction_*.pdf/png
#                       (tools/reproduce.py; REPRODUCE_JOBS, REPRODUCE_ARGS="--quick" etc.)
#   make snapshot RUN=DIR   the run's ParaView state (DIR/run.pvsm) rendered headless at
#                       phases 0, 0.25, 0.5, 0.75 of the last wingbeat: DIR/snapshots/*.png
#   make movie [CASE=cases/x.toml]   the state's front view over the case's last wingbeat,
#                       DIR/movie.mp4 (the run first if its folder has no state or the case is newer)
#
# The coupled runs are small (6 x 10 panels): one OpenMP thread per run is faster than
# two on a busy machine, and the sweeps already fill the cores with whole cases.

PIPELINE_BIN      := $(BUILD)/flapsim
PIPELINE_PYTHON   ?= /usr/bin/python3
PIPELINE_CHAIN    ?= $(MODEL_OUT)/chain.toml
# Factor on every joint spring of the reduced chain (flapsim run --spring-scale); 1 = the
# springs as reduced from the calibrated wings/hawkmoth.toml. Override for sensitivity
# studies, e.g. 'make phase-study PIPELINE_SPRINGS=4'.
PIPELINE_SPRINGS  ?= 1
PHASE_OUT         ?= $(OUT)/phase_study$(if $(RUN_WING),_$(MODEL_NAME))
PHASE_JOBS        ?= $(shell nproc)
PLOTS_OUT         ?= $(OUT)/plots$(if $(RUN_WING),_$(MODEL_NAME))
PHASES            ?= -0.20:0.05:0.10
# A flexible case without its own chain runs with its wing's chain (tools/case.mk).
RUN_CHAIN         := $(if $(CASE_NEEDS_MODEL),$(PIPELINE_CHAIN))
# A case named as its wing (cases/mav_film_wing.toml flies wings/mav_film_wing.toml) would
# run into its wing's model folder, out/<wing>/, whose summary.json flapsim run does not
# replace ('make run CASE=cases/mav_film_wing.toml' stopped there, exit 4): its run goes
# to out/<case name>_run/.
# make run WING=wings/x.toml: the case flown with that wing (flapsim run --wing; a flexible
# case with the chain of that wing's model, out/<wing>/), into out/<case name>_<wing>/.
RUN_WING          := $(if $(filter command line,$(origin WING)),$(WING))
RUN_NAME          := $(CASE_NAME)$(if $(RUN_WING),_$(MODEL_NAME))
RUN_OUT           ?= $(OUT)/$(RUN_NAME)$(if $(and $(RUN_CHAIN),$(filter $(MODEL_OUT),$(OUT)/$(RUN_NAME))),_run)
RUN_WING_OPTION   := $(if $(RUN_WING),--wing $(RUN_WING))

.PHONY: run run-pipeline phase-study plots figures sweep-plots optimize-plots validate reproduce snapshot movie


# The check stops a case with bad input before the run; its warnings, which the run prints
# again, are shown only when it fails (before, every warning was printed twice).
run: program $(RUN_CHAIN)
	@said=$$($(PIPELINE_BIN) check $(CASE) $(if $(RUN_CHAIN),--chain $(RUN_CHAIN)) $(RUN_WING_OPTION) 2>&1 > /dev/null) || \
	  { status=$$?; printf '%s\n' "$$said" >&2; exit $$status; }
	@start=$$(date +%s.%N); \
	OMP_NUM_THREADS=1 $(PIPELINE_BIN) run $(CASE) $(if $(RUN_CHAIN),--chain $(RUN_CHAIN)) $(RUN_WING_OPTION) \
	  --spring-scale $(PIPELINE_SPRINGS) -o $(RUN_OUT) || exit $$?; \
	end=$$(date +%s.%N); \
	echo "FSI run: $$(awk "BEGIN{printf \"%.1f\", $$end - $$start}") s wall"; \
	if [ -f $(RUN_OUT)/run.pvsm ]; then \
	  $(XVFB_RUN) $(PIPELINE_PYTHON) tools/render_run.py $(RUN_OUT) --phases 0.25 \
	    -o $(RUN_OUT)/preview.png > /dev/null || exit $$?; \
	  echo "preview: $(RUN_OUT)/preview.png (the wing a quarter into the last cycle: mid-downstroke of a wingbeat)"; \
	  echo "ParaView: cd $(RUN_OUT) && paraview --state=run.pvsm"; \
	else \
	  echo "preview and ParaView state: none (the case writes no frames: [output] vtk_every = 0; set it to 1 or more for pictures)"; \
	fi; \
	$(if $(RUN_CHAIN),echo "          (the FEM and the chain: $(MODEL_OUT)/fem.vtu, reduction.vtm)")

run-pipeline: run

ifeq ($(origin CASE),command line)
# The rotation-phase sweep of the given case.
phase-study: program $(RUN_CHAIN)
	@mkdir -p $(PHASE_OUT)
	OMP_NUM_THREADS=1 $(PIPELINE_BIN) sweep $(CASE) $(if $(RUN_CHAIN),--chain $(RUN_CHAIN)) $(RUN_WING_OPTION) \
	  --spring-scale $(PIPELINE_SPRINGS) --vary kinematics.rotation_phase=$(PHASES) \
	  -o $(PHASE_OUT)/$(CASE_NAME) -j $(PHASE_JOBS)
else
phase-study: program $(PIPELINE_CHAIN)
	@mkdir -p $(PHASE_OUT)
	@start=$$(date +%s.%N); \
	OMP_NUM_THREADS=1 $(PIPELINE_BIN) sweep cases/rotation_phase_rigid_coupled.toml $(RUN_WING_OPTION) \
	  --vary kinematics.rotation_phase=-0.20:0.05:0.10 -o $(PHASE_OUT)/rigid -j $(PHASE_JOBS) \
	  > $(PHASE_OUT).rigid.log 2>&1 & rigid=$$!; \
	OMP_NUM_THREADS=1 $(PIPELINE_BIN) sweep cases/rotation_phase_flexible.toml $(RUN_WING_OPTION) \
	  --chain $(PIPELINE_CHAIN) --spring-scale $(PIPELINE_SPRINGS) \
	  --vary kinematics.rotation_phase=-0.10:0.05:0.10 -o $(PHASE_OUT)/flexible -j $(PHASE_JOBS) \
	  > $(PHASE_OUT).flexible.log 2>&1 & flexible=$$!; \
	wait $$rigid; r=$$?; wait $$flexible; f=$$?; \
	cat $(PHASE_OUT).rigid.log $(PHASE_OUT).flexible.log; \
	end=$$(date +%s.%N); \
	echo "phase study: $$(awk "BEGIN{printf \"%.1f\", $$end - $$start}") s wall; tables $(PHASE_OUT)/rigid/sweep.csv, $(PHASE_OUT)/flexible/sweep.csv"; \
	test $$r -eq 0 -a $$f -eq 0
endif

plots:
	@test -f $(PHASE_OUT)/rigid/sweep.csv -a -f $(PHASE_OUT)/flexible/sweep.csv || \
	  $(MAKE) --no-print-directory phase-study
	$(PIPELINE_PYTHON) tools/plot_phase_study.py $(PHASE_OUT) $(PLOTS_OUT)
	$(PIPELINE_PYTHON) tools/plot_sweep.py $(PHASE_OUT)/rigid/sweep.csv $(PLOTS_OUT)/rigid
	$(PIPELINE_PYTHON) tools/plot_sweep.py $(PHASE_OUT)/flexible/sweep.csv $(PLOTS_OUT)/flexible

# docs/figures from a fresh phase study (its own folder, emptied first), PDF and PNG, each
# with the CSV of the numbers it draws.
FIGURES_OUT   ?= docs/figures
FIGURES_STUDY ?= $(OUT)/figures/phase_study
figures: program $(PIPELINE_CHAIN)
	rm -rf $(FIGURES_STUDY)
	$(MAKE) --no-print-directory phase-study PHASE_OUT=$(FIGURES_STUDY)
	$(PIPELINE_PYTHON) tools/plot_phase_study.py $(FIGURES_STUDY) $(FIGURES_OUT) --prefix phase_

# Any sweep's table (docs/sweeps.md, "Plotting a sweep").
sweep-plots:
	@test -n "$(SWEEP)" || { echo "usage: make sweep-plots SWEEP=DIR/sweep.csv [SWEEP_PLOTS=OUTPUT_DIR]" >&2; exit 2; }
	$(PIPELINE_PYTHON) tools/plot_sweep.py $(SWEEP) $(SWEEP_PLOTS)

# A flapsim optimize folder (docs/optimize.md, "Plotting an optimisation").
optimize-plots:
	@test -n "$(DIR)" || { echo "usage: make optimize-plots DIR=OPTIMIZE_DIR [OPTIMIZE_PLOTS=OUTPUT_DIR]" >&2; exit 2; }
	$(PIPELINE_PYTHON) tools/plot_optimize.py $(DIR) $(OPTIMIZE_PLOTS)

validate: build $(PIPELINE_CHAIN)
	@test -f $(PHASE_OUT)/rigid/sweep.csv -a -f $(PHASE_OUT)/flexible/sweep.csv || \
	  $(MAKE) --no-print-directory phase-study
	$(PIPELINE_PYTHON) tools/validate.py --build $(BUILD) --out $(OUT)

# The papers' claims beside flapsim's (docs/reproduction.md): builds the program and the
# multibody tests (the Simbody check), then tools/reproduce.py runs everything from scratch
# into $(REPRODUCE_OUT), one OpenMP thread per run, REPRODUCE_JOBS runs at a time.
REPRODUCE_OUT  ?= $(OUT)/reproduce
REPRODUCE_JOBS ?= $(shell nproc)
REPRODUCE_ARGS ?=
reproduce: program
	cmake --build $(BUILD) --target test_mbd -j$(JOBS)
	@start=$$(date +%s.%N); \
	$(PIPELINE_PYTHON) tools/reproduce.py --build $(BUILD) --out $(REPRODUCE_OUT) --jobs $(REPRODUCE_JOBS) \
	  $(REPRODUCE_ARGS) || exit $$?; \
	end=$$(date +%s.%N); \
	echo "make reproduce: $$(awk "BEGIN{printf \"%.1f\", $$end - $$start}") s wall"

# Headless pictures of a run's ParaView state (tools/paraview_state.py: VTK's Python reads
# run.pvsm's objects and renders them offscreen; README, "ParaView"). xvfb-run -a starts
# its search for a free display at a number drawn from the shell's PID: two started at
# once from the same number could share one server and lose it when the other ends.
# -noreset: Xvfb resets when its last client leaves, and a window opened then fails.
XVFB_RUN := xvfb-run -a -n $$(( 100 + $$$$ % 800 )) -s "-screen 0 1280x1024x24 -noreset"
snapshot:
	@test -n "$(RUN)" || { echo "usage: make snapshot RUN=DIR (a run folder with run.pvsm)" >&2; exit 2; }
	$(XVFB_RUN) $(PIPELINE_PYTHON) tools/paraview_state.py $(RUN)/run.pvsm

# MOVIE_SIZE="W H" (default: the state's view, 960 x 540); MOVIE_FPS frames per second.
MOVIE_SIZE ?=
MOVIE_FPS  ?= 25
movie:
	@if [ ! -f $(RUN_OUT)/run.pvsm -o $(CASE) -nt $(RUN_OUT)/run.pvsm ]; then \
	  $(MAKE) --no-print-directory run CASE=$(CASE) || exit $$?; fi
	@test -f $(RUN_OUT)/run.pvsm || { echo "make movie: $(RUN_OUT) has no run.pvsm (the case writes no frames: [output] vtk_every = 0)" >&2; exit 2; }
	$(XVFB_RUN) $(PIPELINE_PYTHON) tools/paraview_state.py $(RUN_OUT)/run.pvsm --movie $(RUN_OUT)/movie.mp4 \
	  $(if $(MOVIE_SIZE),--size $(MOVIE_SIZE)) --fps $(MOVIE_FPS)

# Convergence study of a case (docs/uvlm.md, "Convergence study"): the case at
# CONVERGENCE_LEVELS lattice levels and as many time-step levels, each the last refined by
# 2, with the observed order and the Richardson-extrapolated mean lift (tools/convergence.py).
# CONVERGENCE_ARGS passes more, e.g. "--lattice 6x10,12x20,24x40 --study lattice".
CONVERGENCE_LEVELS ?= 3
CONVERGENCE_ARGS   ?=
CONVERGENCE_OUT    ?= $(OUT)/convergence/$(RUN_NAME)
.PHONY: convergence
convergence: program $(RUN_CHAIN)
	OMP_NUM_THREADS=1 /usr/bin/python3 tools/convergence.py $(CASE) --flapsim $(PIPELINE_BIN) \
	  $(if $(RUN_CHAIN),--chain $(RUN_CHAIN)) $(RUN_WING_OPTION) --levels $(CONVERGENCE_LEVELS) -j $(PHASE_JOBS) \
	  -o $(CONVERGENCE_OUT) $(CONVERGENCE_ARGS)
