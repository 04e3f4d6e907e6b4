# flapsim — the commands users drive. The targets that build (all but help, clean,
# plots, sweep-plots and optimize-plots) install missing Debian packages first (tools/install_deps.sh),
# then configure and build as needed.
#   make build           install missing packages, configure and build everything
#                        (build/flapsim, the tests and the benchmarks)
#   make program         the same for build/flapsim and its two shared modules only
#                        (what run, model and phase-study build)
#   make run [CASE=cases/x.toml]   a case (default: the full pipeline on the hawkmoth
#                        wing: wing -> FEM -> reduction -> flexible FSI hover at 26.1 Hz)
#                        into out/<case>/, with a preview PNG and a ParaView state
#   make run WING=wings/x.toml [CASE=...]   the case flown with another wing (its model
#                        made first for a flexible case), into out/<case>_<wing>/
#   make model WING=wings/x.toml [BODIES=N]   regenerate out/<wing>/ (mesh, FEM, beam,
#                        chain), re-running only the stages whose inputs changed
#   make hawkmoth-model  the same for the default wing (out/hawkmoth/)
#   make test            build and run every test (ctest)
#   make test-asan       every test again, built with ASan + UBSan
#   make phase-study [CASE=...]   the rotation-phase sweeps (rigid and flexible wing)
#   make convergence CASE=...   the case at 3 lattice and 3 time-step levels: observed
#                        order and Richardson-extrapolated mean lift (out/convergence/)
#   make plots           PDF and PNG figures of the phase study in out/plots
#   make figures         docs/figures from a fresh phase study
#   make sweep-plots SWEEP=DIR/sweep.csv   mean lift (and power) against each varied key
#   make optimize-plots DIR=DIR   objective, path and lift of a flapsim optimize folder
#   make validate        reference-vs-computed table of the validation cases
#   make reproduce       docs/reproduction.md: every claim of the two papers beside flapsim's
#   make snapshot RUN=DIR   a run's ParaView state rendered headless at 4 phases (PNG)
#   make movie [CASE=...]   MP4 of the state's view over the case's last wingbeat
#   make bench           Google Benchmark programs (kernel throughput, whole runs)
#   make fuzz            the loader fuzzer with many more mutants (FUZZ_MUTANTS per loader)
#   make fuzz-coverage   clang's libFuzzer on the wing, SVG, outline, case, chain and
#                        kinematics readers
#                        (FUZZ_SECONDS each, default 300; installs clang if missing)
#   make clean           remove build/ and build-asan/
#   make help            this list
# See README.md for the rest.

BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=
OUT        ?= out
MAKEFLAGS  += --no-print-directory

.PHONY: all deps build program test test-asan fuzz fuzz-coverage bench clean help

all: build

help:
	@sed -n '1,33p' Makefile

deps:
	@tools/install_deps.sh

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j$(JOBS)

# The program alone: a first `make run` compiles no test or benchmark (docs/performance.md,
# "Build time").
program: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) --target flapsim -j$(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

$(ASAN_BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DFLAPSIM_SANITIZE=ON $(CMAKE_ARGS)

test-asan: deps $(ASAN_BUILD)/CMakeCache.txt
	cmake --build $(ASAN_BUILD) -j$(JOBS)
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j$(JOBS)

# The fuzzers of `make test` (tests/io/test_fuzz_loaders.cpp, tests/app/test_fuzz_sweep_arguments.cpp)
# with more mutants: FUZZ_MUTANTS per loader (wing, case, chain, outline CSV, SVG drawing, sweep --cases
# table; a quarter each for four --vary seeds), same fixed seeds.
FUZZ_MUTANTS ?= 25000
fuzz: build
	FLAPSIM_FUZZ_MUTANTS=$(FUZZ_MUTANTS) $(BUILD)/tests/io/test_io --gtest_filter='FuzzLoaders.*'
	FLAPSIM_FUZZ_MUTANTS=$(FUZZ_MUTANTS) $(BUILD)/tests/app/test_app --gtest_filter='FuzzSweepArguments.*'

# Coverage-guided fuzzing (tools/coverage_fuzz.sh): the readers compiled with clang and
# instrumented, the rest linked from $(BUILD); FUZZ_SECONDS of one core each, two side by side.
FUZZ_SECONDS ?= 300
fuzz-coverage: build
	FUZZ_SECONDS=$(FUZZ_SECONDS) BUILD=$(BUILD) JOBS=$(JOBS) tools/coverage_fuzz.sh

# Every benchmark program (not CMake's files beside them); the first that fails stops it.
bench: build
	@for b in $(BUILD)/bench/bench_*; do \
	  test -f "$$b" -a -x "$$b" || continue; \
	  echo "== $$b"; "$$b" --benchmark_min_time=0.2 || exit $$?; \
	done

clean:
	rm -rf $(BUILD) $(ASAN_BUILD)

include tools/case.mk
include tools/model.mk
include tools/pipeline.mk
