# crumple: one entry point for everything. `make reproduce` and `make test` work on a fresh
# Debian 12 machine: both install what is missing first (`make deps`).
# Recursive makes (the pipeline's second stage, the sweeps, the calibration) without their
# entering/leaving-directory lines.
MAKEFLAGS += --no-print-directory
BUILD     ?= build
JOBS      ?= $(shell nproc)
PRESET    ?= quick
PROTOCOL  ?= protocols/axial_crumpling.yaml
CMAKE_ARGS ?=

SUDO := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)
DEB_PACKAGES := build-essential cmake git pkg-config libeigen3-dev libhdf5-dev hdf5-tools \
  libyaml-cpp-dev libopencv-dev libcgal-dev libcli11-dev libspdlog-dev libfmt-dev \
  nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev \
  python3-matplotlib python3-numpy python3-h5py python3-scipy python3-yaml \
  python3-pandas

.PHONY: all deps deps-paraview build test test-all test-sanitize test-slurm bench bench-axial physics-check reproduce calibrate docs clean

all: build

# Installs the Debian packages of a list that are missing; a no-op (well under a second) when all
# are there. $(call install_debs,TARGET,PACKAGES)
define install_debs
	@missing=$$(dpkg-query -W -f='$${Package} $${Status}\n' $(2) 2>/dev/null \
	  | awk '$$NF=="installed"{print $$1}' | sort > .deps-present-$(1); \
	  for p in $(2); do grep -qx "$$p" .deps-present-$(1) || echo $$p; done); \
	rm -f .deps-present-$(1); \
	if [ -n "$$missing" ]; then \
	  echo "make $(1): installing$$(echo $$missing | sed 's/^/ /')"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	else echo "make $(1): all packages present"; fi
endef

deps:
	$(call install_debs,deps,$(DEB_PACKAGES))

# ParaView (pvpython) and a virtual X server, for the test that opens a run's XDMF files with
# ParaView's own reader (tests/io/test_paraview.py; skipped with a message without them).
PARAVIEW_PACKAGES := paraview python3-paraview xvfb xauth
deps-paraview: deps
	$(call install_debs,deps-paraview,$(PARAVIEW_PACKAGES))

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# The fast suite (everything not labelled slow); the whole of it runs in a few minutes.
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE slow

test-all: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The fast suite built with AddressSanitizer and UndefinedBehaviorSanitizer in its own build
# folder (-O1 with debug lines: the reports name source lines). Any report fails the test that
# made it; the child processes the tests start (crumple-sim, crumple-analyze) are instrumented too.
# Tests labelled sanitize_skip (too slow instrumented, their code covered by others) are left out.
SANITIZE_BUILD ?= build-sanitize
SANITIZE_ENV := ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitize/lsan.supp:print_suppressions=0
test-sanitize: deps
	@test -f $(SANITIZE_BUILD)/CMakeCache.txt || cmake -S . -B $(SANITIZE_BUILD) \
	  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DCRUMPLE_SANITIZE=ON \
	  -DCRUMPLE_BUILD_BENCH=OFF $(CMAKE_ARGS)
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && $(SANITIZE_ENV) ctest --output-on-failure -j $(JOBS) -LE 'slow|sanitize_skip'

# The Slurm path against a real one-node Slurm on this machine (installs Debian's slurmctld,
# slurmd, slurm-client and munge when missing; tests/slurm/test_slurm.sh): the tiny sweep
# locally and through Slurm with identical results, and a run stopped by SIGTERM failing the
# submission and resuming on the next. About two minutes; run by .ci/run.
test-slurm: build
	tests/slurm/test_slurm.sh $(BUILD)/test-slurm

# bench_radial at physical mass: the explicit-only variant is timed over ten spans of 0.01 s
# spread over the interval (each from the block-Jacobi hybrid's state there) and scaled (its
# step is set by stability); `bench_radial --help` for the rest. Its warm state at t0 is kept
# (a second run skips the warm-up) and bench_precond solves on it. BENCH_THICKNESS is the sheet's
# h_eff in mm (0.25: the paper's Fig. 5 sheet).
BENCH_NODES ?= 3000
BENCH_THICKNESS ?= 0.125
BENCH_WARM = $(BUILD)/bench_radial_warm_$(BENCH_NODES)_h$(BENCH_THICKNESS).h5
BENCH_RADIAL ?= --nodes $(BENCH_NODES) --thickness $(BENCH_THICKNESS) --explicit-span 0.01 --explicit-samples 10 --warm-state $(BENCH_WARM)
bench: build
	@for b in bench_assembly bench_contact; do echo "== $$b"; $(BUILD)/tests/bench/$$b || exit 1; done
	@echo "== bench_radial"; $(BUILD)/tests/bench/bench_radial $(BENCH_RADIAL)
	@echo "== bench_precond"; $(BUILD)/tests/bench/bench_precond --nodes $(BENCH_NODES) --thickness $(BENCH_THICKNESS) --warm-state $(BENCH_WARM)

# The speed of the axial-crumpling protocol (issue 32): one cycle of protocols/axial_crumpling.yaml
# at BENCH_NODES nodes on BENCH_THREADS threads, and where its time went, read from the run file
# (pipeline/bench/bench_axial.py). BENCH_BASELINE=OLD_CRUMPLE_SIM times that binary alternately
# with this build's, BENCH_REPEATS runs each, and prints the ratios of total wall. The runs and
# summary.json stay in $(BUILD)/bench-axial.
BENCH_THREADS ?= 2
BENCH_SEED ?= 1
BENCH_REPEATS ?= 1
BENCH_BASELINE ?=
bench-axial: build
	$(PYTHON) pipeline/bench/bench_axial.py --binary $(SIM) --nodes $(BENCH_NODES) \
	  --threads $(BENCH_THREADS) --seed $(BENCH_SEED) --repeats $(BENCH_REPEATS) \
	  $(if $(BENCH_BASELINE),--baseline $(BENCH_BASELINE)) --out-dir $(BUILD)/bench-axial \
	  --json $(BUILD)/bench-axial/summary.json

# Is the physics unchanged? This build's crumple-sim against PHYSICS_OLD (a binary, required) on
# the same sheets: the crease length and P per cycle against the seed-to-seed spread
# (pipeline/bench/physics_check.py; runs kept in $(BUILD)/physics-check, so a rerun is quick).
PHYSICS_OLD ?=
PHYSICS_NODES ?= 1500
PHYSICS_CYCLES ?= 3
PHYSICS_SEEDS ?= 1 2 3 4
PHYSICS_JOBS ?= 2
ifneq ($(filter physics-check,$(MAKECMDGOALS)),)
ifeq ($(strip $(PHYSICS_OLD)),)
$(error make physics-check: give PHYSICS_OLD=PATH, the crumple-sim binary to compare this build's with)
endif
endif
physics-check: build
	$(PYTHON) pipeline/bench/physics_check.py --new $(SIM) --old $(PHYSICS_OLD) --analyze $(ANALYZE) \
	  --nodes $(PHYSICS_NODES) --cycles $(PHYSICS_CYCLES) --seeds $(PHYSICS_SEEDS) \
	  --jobs $(PHYSICS_JOBS) --threads 1 --out-dir $(BUILD)/physics-check \
	  --json $(BUILD)/physics-check/summary.json

include pipeline/slurm/slurm.mk
include pipeline/reproduce.mk
include pipeline/sweep.mk
include pipeline/calibration/calibrate.mk
include pipeline/checks/rate_check.mk
include pipeline/recipes.mk

# docs/CONFIG.md's key tables from the schema (the test config_doc_current checks them).
docs: build
	$(PYTHON) pipeline/docs/update_config_doc.py --sim $(SIM) --doc docs/CONFIG.md

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) runs results
