# flapsim — the commands users drive. Every target installs missing Debian
# packages first (tools/install_deps.sh), then configures and builds as needed.
#   make run             the full pipeline on the default hawkmoth wing:
#                        wing -> FEM -> reduction -> flexible FSI hover at 26.1 Hz
#   make test            build and run every test (ctest)
#   make test-asan       every test again, built with ASan + UBSan
#   make hawkmoth-model  regenerate out/hawkmoth/ (mesh, FEM, beam, chain)
#   make phase-study     the rotation-phase sweeps (rigid and flexible wing)
#   make plots           PNG figures of the phase study in out/plots
#   make sweep-plots SWEEP=DIR/sweep.csv   mean lift against each varied key
#   make validate        reference-vs-computed table of the validation cases
#   make bench           Google Benchmark programs (kernel throughput, whole runs)
# See README.md for the rest.

BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=
OUT        ?= out
MAKEFLAGS  += --no-print-directory

.PHONY: all deps build run test test-asan bench hawkmoth-model clean help

all: build

help:
	@sed -n '1,15p' Makefile

deps:
	@tools/install_deps.sh

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j$(JOBS)

run: build
	@$(BUILD)/flapsim check wings/hawkmoth.toml
	@$(MAKE) --no-print-directory run-pipeline

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

$(ASAN_BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DFLAPSIM_SANITIZE=ON $(CMAKE_ARGS)

test-asan: deps $(ASAN_BUILD)/CMakeCache.txt
	cmake --build $(ASAN_BUILD) -j$(JOBS)
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j$(JOBS)

bench: build
	@for b in $(BUILD)/bench/*; do echo "== $$b"; $$b --benchmark_min_time=0.2; done

clean:
	rm -rf $(BUILD) $(ASAN_BUILD)

include tools/hawkmoth_model.mk
include tools/pipeline.mk
