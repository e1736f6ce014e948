# make sweep SWEEP=NAME: every point of pipeline/sweeps/NAME.yaml as a file target, analysed,
# grouped into ensembles, fitted together (the collapse, when the grid varies the compaction)
# and reported in results/NAME/REPORT.md (pipeline/sweeps/README.md).
#
# The points are expanded (and each group's configuration checked by crumple-sim) into
# runs/sweeps/NAME/points.mk, which a second make reads: a finished run is never redone, a
# killed one (RUN.h5.tmp holds its checkpoint) resumes, `-j` runs points side by side, and a
# point whose arguments changed (its RUN.h5.args) is run again, or extended when the change is
# more cycles and nothing else (crumple-sim --extend). Run logs: RUN.h5.log.
SWEEP ?=
SWEEP_FILE    = pipeline/sweeps/$(SWEEP).yaml
SWEEP_DIR     = runs/sweeps/$(SWEEP)
SWEEP_RESULTS = results/$(SWEEP)
SWEEP_NAMES  := $(notdir $(basename $(wildcard pipeline/sweeps/*.yaml)))
# SWEEP_SEEDS="1 2": only these of the sweep's seeds (a first part of a long sweep; running
# without it later reuses every finished run and completes the rest).
SWEEP_SEEDS  ?=
# SWEEP_GROUPS="compaction-0.63 compaction-0.27": only these grid points (named as their run
# folders), likewise.
SWEEP_GROUPS ?=
# Runs kept as summaries by make keep-runs (a sweep made in parts on machines that do not share
# runs/): a point with no run here whose run is kept there is analysed from it, not run.
# SWEEP_KEPT= runs every point here.
SWEEP_KEPT   ?= docs/studies/$(SWEEP)/runs
# What the second make (or a Slurm job) is given; SWEEP_DIR and SWEEP_RESULTS may be overridden
# on the command line to keep a sweep elsewhere (the Slurm test does).
SWEEP_VARS    = SWEEP=$(SWEEP) BUILD=$(BUILD) SWEEP_DIR=$(SWEEP_DIR) SWEEP_RESULTS=$(SWEEP_RESULTS)

.PHONY: sweep sweep-runs sweep-report keep-study keep-runs study-figures convergence

ifneq ($(SWEEP),)
-include $(SWEEP_DIR)/points.mk
endif

sweep: build
	@test -n "$(SWEEP)" -a -f "$(SWEEP_FILE)" || { \
	  echo "make sweep: give SWEEP=NAME, one of: $(SWEEP_NAMES)"; exit 2; }
	$(PYTHON) pipeline/sweeps/expand_sweep.py $(SWEEP_FILE) --out-dir $(SWEEP_DIR) \
	  --results $(SWEEP_RESULTS) --sim $(SIM) $(if $(strip $(SWEEP_SEEDS)),--seeds $(SWEEP_SEEDS)) \
	  $(if $(strip $(SWEEP_GROUPS)),--groups $(SWEEP_GROUPS)) \
	  $(if $(strip $(SWEEP_KEPT)),--kept $(SWEEP_KEPT))
ifeq ($(SCHEDULER),slurm)
	$(SLURM_SUBMIT) --name sweep-$(SWEEP) --points $(SWEEP_DIR)/points.json --final sweep-report \
	  --make-vars '$(SWEEP_VARS)' --log-dir $(SWEEP_DIR)/slurm \
	  --threads $$($(PYTHON) -c "import json; print(json.load(open('$(SWEEP_DIR)/points.json'))['threads'])")
else
	$(MAKE) --no-print-directory -j $(JOBS) sweep-report $(SWEEP_VARS)
	@echo "sweep report: $(SWEEP_RESULTS)/REPORT.md"
endif

sweep-runs: $(SWEEP_RUNS)
sweep-report: $(SWEEP_RESULTS)/REPORT.md

# The collapse (when the grid varies the compaction), the convergence table (when it varies the
# node count alone), the history test (when the sweep names a test compaction), the figures,
# then the report.
$(SWEEP_RESULTS)/REPORT.md: $(SWEEP_ENSEMBLES) $(SWEEP_DIR)/points.json $(ANALYZE) \
    $(wildcard pipeline/plots/*.py pipeline/report/*.py pipeline/sweeps/*.py)
	@mkdir -p $(SWEEP_RESULTS)
	$(if $(SWEEP_COLLAPSE),$(ANALYZE) collapse -o $(SWEEP_RESULTS)/collapse.json $(SWEEP_ENSEMBLES))
	$(if $(SWEEP_CONVERGENCE),$(PYTHON) pipeline/sweeps/convergence.py --points $(SWEEP_DIR)/points.json \
	  --results $(SWEEP_RESULTS))
	$(if $(SWEEP_HISTORY),$(PYTHON) pipeline/sweeps/history_test.py --points $(SWEEP_DIR)/points.json \
	  --results $(SWEEP_RESULTS) --compaction $(SWEEP_HISTORY))
	$(PYTHON) pipeline/plots/plot_sweep.py --points $(SWEEP_DIR)/points.json \
	  --results $(SWEEP_RESULTS)
	$(PYTHON) pipeline/report/make_sweep_report.py --points $(SWEEP_DIR)/points.json \
	  --results $(SWEEP_RESULTS) -o $@

# make convergence: the protocol's resolution ladder of issue 36 at the yield radius calibrated
# on six seeds (pipeline/sweeps/convergence_six_seeds.yaml), 3000 to 24000 nodes; the rungs kept
# as run summaries (docs/studies/convergence_six_seeds/runs/) are analysed from them, the rest
# run; SWEEP_GROUPS="nodes-3000 nodes-6000 nodes-12000" runs the rungs a small machine affords
# first, and the report says which are left. The same ladder at the three-seed radius is
# SWEEP=convergence_flat_unfold, at the former unfold SWEEP=convergence (make sweep).
convergence:
	$(MAKE) --no-print-directory sweep SWEEP=convergence_six_seeds

# make keep-study SWEEP=NAME: the sweep's report, figures, fits and per-group tables (no runs)
# into docs/studies/NAME/, to be committed (pipeline/sweeps/keep_study.py). KEEP_FIT_AS=TAG keeps
# only the last fit, one over a subset of the groups, as collapse_TAG.json, predictions_TAG.json
# and PREDICTIONS_TAG.md beside the study's own (e.g. after make predictions PREDICT_GROUPS=...).
KEEP_FIT_AS ?=
keep-study:
	$(PYTHON) pipeline/sweeps/keep_study.py --points $(SWEEP_DIR)/points.json \
	  --results $(SWEEP_RESULTS) --out docs/studies/$(SWEEP) $(if $(KEEP_FIT_AS),--fit-as $(KEEP_FIT_AS))

# make keep-runs SWEEP=NAME: each finished run of the sweep as a small summary (its analysis, roll
# axes, wall and what it was made from) in docs/studies/NAME/runs/GROUP/seedS.json, to be
# committed, so that make sweep on another machine, or after runs/ is gone, takes it in place of
# the run and runs only the rest (pipeline/sweeps/kept_runs.py).
keep-runs:
	$(PYTHON) pipeline/sweeps/kept_runs.py --points $(SWEEP_DIR)/points.json --out $(SWEEP_KEPT)

# make study-figures: the collapse, convergence, calibration and prediction figures of every kept
# study, from its JSON (the per-group figure, crease_length.png, comes with make sweep, which has
# the ensembles).
study-figures:
	@for d in docs/studies/*/; do \
	  if [ -f $$d/collapse.json ]; then $(PYTHON) pipeline/plots/plot_sweep.py --results $$d \
	    --collapse-only && echo "$$d"collapse.png || exit 1; fi; \
	  if [ -f $$d/convergence.json ]; then $(PYTHON) pipeline/plots/plot_sweep.py --results $$d \
	    --convergence-only && echo "$$d"convergence.png || exit 1; fi; \
	  if [ -f $$d/calibration.json ]; then $(PYTHON) pipeline/calibration/yield_calibration.py \
	    --replot $$d/calibration.json -o $$d/calibration.png && echo "$$d"calibration.png || exit 1; fi; \
	  if [ -f $$d/predictions.json ]; then $(PYTHON) pipeline/calibration/predictions.py \
	    --replot $$d/predictions.json -o $$d/predictions.png && echo "$$d"predictions.png || exit 1; fi; done
