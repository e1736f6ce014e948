# make calibrate: the single-fold calibration of the yield (paper Fig. 3b).
#
# Folds the sheet of protocols/single_fold.yaml at two resolutions for a sweep of the yield
# radius material.yield_radius (docs/MODEL.md §7.5; CAL_YIELD_MM in millimetres), then plots the
# final fold c_f against the yield radius, resolution by resolution (one material: the curves
# coincide), and against the paper's variables beta (c0 - alpha) (alpha = 0.05, beta = 0.04
# lambda, lambda = sqrt(n/A) with the sheet side as the length unit, c0 the hinge yield each mesh
# derived) with a fitted line; results/calibration/ gets fold_calibration.csv,
# fold_calibration.png and FOLD_CALIBRATION.md. Runs are file targets (runs/calibration/), so
# `make -j` runs them in parallel and a finished run is not redone. About 10 minutes on 2 cores
# with the defaults.
#   make calibrate CAL_NODES="300 1200" CAL_YIELD_MM="40 10 5"
CAL_NODES    ?= 300 1200
CAL_YIELD_MM ?= 80 40 20 13 10 7 5
CAL_PROTO := protocols/single_fold.yaml
CAL_DIR   := runs/calibration
CAL_OUT   := $(RESULTS)/calibration
CAL_RUNS  := $(foreach n,$(CAL_NODES),$(foreach r,$(CAL_YIELD_MM),$(CAL_DIR)/fold_n$(n)_r$(r)mm.h5))

.PHONY: calibrate calibration-report
.SECONDARY: $(CAL_RUNS)

calibrate: build
	$(MAKE) --no-print-directory -j $(JOBS) calibration-report BUILD=$(BUILD) \
	  CAL_NODES="$(CAL_NODES)" CAL_YIELD_MM="$(CAL_YIELD_MM)"
	@echo "calibration: $(CAL_OUT)/FOLD_CALIBRATION.md"

calibration-report: $(CAL_OUT)/FOLD_CALIBRATION.md

# fold_n<nodes>_r<mm>mm.h5: the two numbers come back out of the target's name.
$(CAL_DIR)/fold_n%mm.h5: $(CAL_PROTO)
	@mkdir -p $(CAL_DIR)
	$(SIM) $(CAL_PROTO) -o $@ --quiet --threads 1 \
	  --set mesh.nodes=$(word 1,$(subst _r, ,$*)) --set material.yield_radius=$(word 2,$(subst _r, ,$*))e-3 \
	  $(if $(wildcard $@.tmp),--resume,--force)

$(CAL_OUT)/FOLD_CALIBRATION.md: $(CAL_RUNS) pipeline/calibration/fold_calibration.py
	@mkdir -p $(CAL_OUT)
	$(PYTHON) pipeline/calibration/fold_calibration.py -o $(CAL_OUT) $(CAL_RUNS)

# make calibrate-yield: the one fitted material constant, the yield radius (issue 36;
# docs/SCIENCE.md). Runs the protocol's calibration sweep (pipeline/sweeps/
# yield_radius_calibration_six_seeds.yaml: one cycle at Δ̃ = 0.27 with the protocol's unfold
# for a bracket of material.yield_radius, seeds 1-6, 3000 nodes, creases above the protocol's
# 18.3 degrees; resumable) and finds the radius at which P after cycle 1 meets the experiments'
# law (pipeline/calibration/yield_calibration.py): results/yield_radius_calibration_six_seeds/
# CALIBRATION.md, calibration.json, .csv and the figure. About 15 minutes on 2 cores.
# CALIBRATE_SWEEP=yield_radius_calibration_flat_unfold is the same on seeds 1-3 (3.34 mm, the
# protocol's radius until 2026-12-07; docs/studies/yield_radius_calibration_flat_unfold/),
# CALIBRATE_SWEEP=yield_radius_calibration_flat_unfold_6000 on 6000 nodes (seeds 1-3; about 35
# minutes on 2 cores; docs/studies/yield_radius_calibration_flat_unfold_6000/),
# CALIBRATE_SWEEP=yield_radius_calibration redoes the calibration at the former unfold
# (flatten_length 0.05, docs/studies/yield_radius_calibration/), CALIBRATE_SWEEP=yield_calibration
# the older one of a yield angle at 1500 nodes (docs/studies/yield_calibration/).
CALIBRATE_SWEEP ?= yield_radius_calibration_six_seeds
.PHONY: calibrate-yield
calibrate-yield:
	$(MAKE) --no-print-directory sweep SWEEP=$(CALIBRATE_SWEEP)
	$(PYTHON) pipeline/calibration/yield_calibration.py --points runs/sweeps/$(CALIBRATE_SWEEP)/points.json \
	  --groups $(RESULTS)/$(CALIBRATE_SWEEP)/groups --out $(RESULTS)/$(CALIBRATE_SWEEP) \
	  -o $(RESULTS)/$(CALIBRATE_SWEEP)/calibration.$(FIG_FORMAT)

# make predictions: the calibrated simulation beside the experiments (issue 36, item 4;
# pipeline/calibration/predictions.py): P per cycle at Δ̃ = 0.27, n0, the compaction sweep's global
# c1, c2 and collapse, and the facet-area shape per cycle, each against its goal, from the
# compaction sweep of the protocol's material (pipeline/sweeps/compaction_flat_unfold.yaml: the
# flatter unfold, R_y = 3.34 mm; 3000 nodes, resumable; PREDICT_GROUPS limits it to some
# compactions and PREDICT_SEEDS to some seeds, and the report says which were fitted). The
# calibration is the kept one the protocol states
# (docs/studies/yield_radius_calibration_flat_unfold/). Writes PREDICTIONS.md, predictions.json
# and the figure into results/compaction_flat_unfold/ beside the sweep's report, so that
# make keep-study SWEEP=compaction_flat_unfold keeps them too. PREDICT_SWEEP and
# PREDICT_CALIBRATION name another compaction sweep and the calibration of its material: the
# former unfold is PREDICT_SWEEP=compaction
# PREDICT_CALIBRATION=docs/studies/yield_radius_calibration/calibration.json. A sweep of one
# group at 0.27 (not a compaction sweep) names it with PREDICT_GROUP, e.g. the six-seed prediction
# PREDICT_SWEEP=flat_unfold_six_seeds_calibrated PREDICT_GROUP=yield_radius-3.55e-3
# PREDICT_CALIBRATION=docs/studies/yield_radius_calibration_six_seeds/calibration.json.
PREDICT_GROUP ?=
PREDICT_GROUPS ?=
PREDICT_SEEDS ?=
PREDICT_SWEEP ?= compaction_flat_unfold
PREDICT_CALIBRATION ?= docs/studies/yield_radius_calibration_flat_unfold/calibration.json
.PHONY: predictions
predictions:
	$(MAKE) --no-print-directory sweep SWEEP=$(PREDICT_SWEEP) SWEEP_GROUPS="$(PREDICT_GROUPS)" SWEEP_SEEDS="$(PREDICT_SEEDS)"
	$(PYTHON) pipeline/calibration/predictions.py --sweep-results $(RESULTS)/$(PREDICT_SWEEP) \
	  --points runs/sweeps/$(PREDICT_SWEEP)/points.json --calibration $(PREDICT_CALIBRATION) \
	  $(if $(PREDICT_GROUP),--group $(PREDICT_GROUP)) \
	  --out $(RESULTS)/$(PREDICT_SWEEP) -o $(RESULTS)/$(PREDICT_SWEEP)/predictions.$(FIG_FORMAT)
