# make reproduce: deps -> build -> runs -> analysis -> ensemble statistics and fits -> figures ->
# results/REPORT.md.
#
# Every run is a file target (runs/PRESET/seedS.h5), so `make -j` runs seeds in parallel, a
# finished run is never redone, and a killed run (its RUN.h5.tmp holds a checkpoint) resumes.
#   make reproduce PRESET=tiny|quick|paper SEEDS="1 2 3" PROTOCOL=protocols/other.yaml
PRESET_FILE := pipeline/presets/$(PRESET).mk
ifeq ($(wildcard $(PRESET_FILE)),)
$(error unknown PRESET '$(PRESET)': choose one of $(notdir $(basename $(wildcard pipeline/presets/*.mk))))
endif
include $(PRESET_FILE)

SEEDS_USED := $(if $(filter command line environment,$(origin SEEDS)),$(SEEDS),$(PRESET_SEEDS))
PROTO_NAME := $(basename $(notdir $(PROTOCOL)))
RUNDIR     := runs/$(PRESET)/$(PROTO_NAME)
RESULTS    ?= results
SIM        := $(BUILD)/sim/apps/crumple-sim
ANALYZE    := $(BUILD)/analysis/apps/crumple-analyze
PYTHON     := /usr/bin/python3
RUN_THREADS ?= $(or $(PRESET_THREADS),1)

RUNS  := $(foreach s,$(SEEDS_USED),$(RUNDIR)/seed$(s).h5)
STATS := $(foreach s,$(SEEDS_USED),$(RUNDIR)/seed$(s).analysis/stats.json)

.PHONY: reproduce report runs analysis
.SECONDARY: $(RUNS) $(STATS)

# The build must finish before the runs start; the runs then go in parallel, here or (with
# SCHEDULER=slurm, pipeline/slurm/slurm.mk) as a Slurm array with the report as a dependent job.
REPRODUCE_VARS = PRESET=$(PRESET) SEEDS="$(SEEDS_USED)" PROTOCOL=$(PROTOCOL) BUILD=$(BUILD) \
  RESULTS=$(RESULTS)
reproduce: build
ifeq ($(SCHEDULER),slurm)
	$(SLURM_SUBMIT) --name reproduce-$(PRESET) --targets $(STATS) --final report \
	  --make-vars '$(REPRODUCE_VARS)' --threads $(RUN_THREADS) --log-dir $(RUNDIR)/slurm
else
	$(MAKE) --no-print-directory -j $(JOBS) report $(REPRODUCE_VARS)
	@echo "report: $(RESULTS)/REPORT.md"
endif

runs: $(RUNS)
analysis: $(STATS)
report: $(RESULTS)/REPORT.md

$(RUNDIR)/seed%.h5: $(PROTOCOL) $(PRESET_FILE)
	@mkdir -p $(RUNDIR)
	$(SIM) $(PROTOCOL) -o $@ --seed $* --threads $(RUN_THREADS) $(PRESET_SETS) \
	  $(if $(wildcard $@.tmp),--resume,--force)

$(RUNDIR)/seed%.analysis/stats.json: $(RUNDIR)/seed%.h5
	$(ANALYZE) $< -o $(RUNDIR)/seed$*.analysis

# The report: ensemble statistics and fits (crumple-analyze ensemble, their one implementation),
# tabulated (ensemble.csv), the four figures (crease length against the law, where the creases
# were made, facet areas, crease maps of the first seed), then REPORT.md.
# `pipeline/report/check_report.py $(RESULTS)/REPORT.md` checks that it is complete.
SHOWN := $(dir $(firstword $(STATS)))
ANALYSES := $(foreach s,$(SEEDS_USED),$(RUNDIR)/seed$(s).analysis)
$(RESULTS)/REPORT.md: $(STATS) $(ANALYZE) $(wildcard pipeline/plots/*.py pipeline/report/*.py)
	@mkdir -p $(RESULTS)
	$(ANALYZE) ensemble -o $(RESULTS)/ensemble.json $(ANALYSES)
	$(PYTHON) pipeline/plots/ensemble.py $(RESULTS)/ensemble.json -o $(RESULTS)/ensemble.csv
	$(PYTHON) pipeline/plots/plot_crease_length.py $(RESULTS)/ensemble.json -o $(RESULTS)/crease_length.png
	$(PYTHON) pipeline/plots/plot_stages.py $(RESULTS)/ensemble.json -o $(RESULTS)/stages.png
	$(PYTHON) pipeline/plots/plot_facets.py $(RESULTS)/ensemble.json -o $(RESULTS)/facets.png
	$(PYTHON) pipeline/plots/plot_maps.py $(SHOWN) -o $(RESULTS)/maps.png
	$(PYTHON) pipeline/report/make_report.py --ensemble $(RESULTS)/ensemble.json \
	  --runs $(SHOWN) --preset $(PRESET) --protocol $(PROTOCOL) -o $@
