# make rate-check: is the plastic flow rate-independent at the protocol's loading rates?
#
# Runs a 1500-node sheet (RATE_NODES) through RATE_CYCLES cycles of the protocol at
# integrator.plastic_rate = RATE_VALUES (by default half, once and twice the default 1e4 /s) for
# every seed, analyses each run, and compares, per cycle, the change of the ensemble-mean crease
# length (l and P at the analysis's default threshold) between rates with the seed-to-seed spread
# (pipeline/checks/rate_check.py). Runs are file targets (runs/rate_check/), so `make -j` runs
# them in parallel, a finished run is not redone and a killed one resumes. About 12 minutes on
# 2 cores with the defaults. Result: $(RESULTS)/rate_check/RATE_CHECK.md and rate_check.json.
#   make rate-check RATE_VALUES="2500 5000 10000 20000" RATE_SEEDS="1 2 3 4 5 6"
RATE_VALUES ?= 5000 10000 20000
RATE_SEEDS  ?= 1 2 3 4
RATE_CYCLES ?= 2
RATE_NODES  ?= 1500
RATE_DIR    := runs/rate_check
RATE_OUT    := $(RESULTS)/rate_check
RATE_RUNS   := $(foreach r,$(RATE_VALUES),$(foreach s,$(RATE_SEEDS),$(RATE_DIR)/rate$(r)_seed$(s).h5))
RATE_STATS  := $(RATE_RUNS:.h5=.analysis/stats.json)

.PHONY: rate-check rate-check-report
.SECONDARY: $(RATE_RUNS) $(RATE_STATS)

rate-check: build
	$(MAKE) --no-print-directory -j $(JOBS) rate-check-report BUILD=$(BUILD) \
	  RATE_VALUES="$(RATE_VALUES)" RATE_SEEDS="$(RATE_SEEDS)" RATE_CYCLES=$(RATE_CYCLES)
	@echo "rate check: $(RATE_OUT)/RATE_CHECK.md"

rate-check-report: $(RATE_OUT)/RATE_CHECK.md

# rate<r>_seed<s>.h5: the rate and the seed come back out of the target's name.
$(RATE_DIR)/rate%.h5: $(PROTOCOL)
	@mkdir -p $(RATE_DIR)
	$(SIM) $(PROTOCOL) -o $@ --quiet --threads 1 --seed $(word 2,$(subst _seed, ,$*)) \
	  --set mesh.nodes=$(RATE_NODES) --set protocol.cycles=$(RATE_CYCLES) \
	  --set integrator.plastic_rate=$(word 1,$(subst _seed, ,$*)) $(if $(wildcard $@.tmp),--resume,--force)

$(RATE_DIR)/%.analysis/stats.json: $(RATE_DIR)/%.h5
	$(ANALYZE) $< -o $(RATE_DIR)/$*.analysis --bootstrap 20 > /dev/null

$(RATE_OUT)/RATE_CHECK.md: $(RATE_STATS) pipeline/checks/rate_check.py
	@mkdir -p $(RATE_OUT)
	$(PYTHON) pipeline/checks/rate_check.py -o $(RATE_OUT) $(RATE_STATS)
