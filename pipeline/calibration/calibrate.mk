# make calibrate: the single-fold calibration of the yield curvature (paper Fig. 3b).
#
# Folds the sheet of protocols/single_fold.yaml at two resolutions for a sweep of
# integrator.plastic_c0, then plots the final fold c_f against beta (c0 - alpha) (alpha = 0.05,
# beta = 0.04 lambda, lambda = sqrt(n/A) with the sheet side as the length unit) and fits the
# line; results/calibration/ gets fold_calibration.csv, fold_calibration.png and
# FOLD_CALIBRATION.md. Runs are file targets (runs/calibration/), so `make -j` runs them in
# parallel and a finished run is not redone. About 10 minutes on 2 cores with the defaults.
#   make calibrate CAL_NODES="300 1200" CAL_C0="0.05 0.1 0.2"
CAL_NODES ?= 300 1200
CAL_C0    ?= 0.05 0.1 0.2 0.3 0.45 0.6 0.8
CAL_PROTO := protocols/single_fold.yaml
CAL_DIR   := runs/calibration
CAL_OUT   := $(RESULTS)/calibration
CAL_RUNS  := $(foreach n,$(CAL_NODES),$(foreach c,$(CAL_C0),$(CAL_DIR)/fold_n$(n)_c$(c).h5))

.PHONY: calibrate calibration-report
.SECONDARY: $(CAL_RUNS)

calibrate: build
	$(MAKE) --no-print-directory -j $(JOBS) calibration-report BUILD=$(BUILD) \
	  CAL_NODES="$(CAL_NODES)" CAL_C0="$(CAL_C0)"
	@echo "calibration: $(CAL_OUT)/FOLD_CALIBRATION.md"

calibration-report: $(CAL_OUT)/FOLD_CALIBRATION.md

# fold_n<nodes>_c<c0>.h5: the two numbers come back out of the target's name.
$(CAL_DIR)/fold_n%.h5: $(CAL_PROTO)
	@mkdir -p $(CAL_DIR)
	$(SIM) $(CAL_PROTO) -o $@ --quiet --threads 1 \
	  --set mesh.nodes=$(word 1,$(subst _c, ,$*)) --set integrator.plastic_c0=$(word 2,$(subst _c, ,$*)) \
	  $(if $(wildcard $@.tmp),--resume,--force)

$(CAL_OUT)/FOLD_CALIBRATION.md: $(CAL_RUNS) pipeline/calibration/fold_calibration.py
	@mkdir -p $(CAL_OUT)
	$(PYTHON) pipeline/calibration/fold_calibration.py -o $(CAL_OUT) $(CAL_RUNS)
