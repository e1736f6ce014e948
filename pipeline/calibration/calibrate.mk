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
