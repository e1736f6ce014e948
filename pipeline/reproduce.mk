# make reproduce: deps -> build -> runs -> analysis -> ensemble statistics and fits -> figures ->
# results/REPORT.md.
#
# Every run is a file target (runs/PRESET/seedS.h5), so `make -j` runs seeds in parallel, a
# finished run is never redone, and a killed run (its RUN.h5.tmp holds a checkpoint) resumes.
#   make reproduce PRESET=tiny|quick|paper SEEDS="1 2 3" PROTOCOL=protocols/other.yaml FIG_FORMAT=svg
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
# The figures' file format, png or svg; every plot script gets --format $(FIG_FORMAT) and the report
# links the files of that format. One word of the two, else refused before anything runs.
FIG_FORMAT ?= png
ifneq ($(filter-out png svg,$(FIG_FORMAT))$(words $(FIG_FORMAT)),1)
$(error FIG_FORMAT='$(FIG_FORMAT)': choose png (the default) or svg)
endif
IMAGES := $(RESULTS)/images

RUNS  := $(foreach s,$(SEEDS_USED),$(RUNDIR)/seed$(s).h5)
STATS := $(foreach s,$(SEEDS_USED),$(RUNDIR)/seed$(s).analysis/stats.json)

.PHONY: reproduce report runs analysis
.SECONDARY: $(RUNS) $(STATS) $(addsuffix .config,$(RUNS))

# The build must finish before the runs start; the runs then go in parallel, here or (with
# SCHEDULER=slurm, pipeline/slurm/slurm.mk) as a Slurm array with the report as a dependent job.
REPRODUCE_VARS = PRESET=$(PRESET) SEEDS="$(SEEDS_USED)" PROTOCOL=$(PROTOCOL) BUILD=$(BUILD) \
  RESULTS=$(RESULTS) FIG_FORMAT=$(FIG_FORMAT)
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

# A run depends on its configuration as crumple-sim resolves it (RUN.h5.config, rewritten only
# when it changes; pipeline/sweeps/run_config.py), not on the protocol and preset files' dates: an
# edit there that changes no run's configuration (a comment, a key the preset overrides) redoes
# nothing, one that does redoes exactly the runs it changes. An invalid configuration stops here,
# before any run. A run made before its configuration file stands when it stored the same one.
$(RUNDIR)/seed%.h5.config: resolve-run-config
	@$(PYTHON) pipeline/sweeps/run_config.py $(RUNDIR)/seed$*.h5 -- $(SIM) $(PROTOCOL) --seed $* \
	  $(PRESET_SETS)
.PHONY: resolve-run-config
resolve-run-config:

$(RUNDIR)/seed%.h5: $(RUNDIR)/seed%.h5.config
	@mkdir -p $(RUNDIR)
	$(SIM) $(PROTOCOL) -o $@ --seed $* --threads $(RUN_THREADS) $(PRESET_SETS) \
	  $(if $(wildcard $@.tmp),--resume,--force)

$(RUNDIR)/seed%.analysis/stats.json: $(RUNDIR)/seed%.h5
	$(ANALYZE) $< -o $(RUNDIR)/seed$*.analysis

# The report: ensemble statistics and fits (crumple-analyze ensemble, their one implementation),
# tabulated (ensemble.csv), the four figures in $(IMAGES) (crease length against the law, where the
# creases were made, facet areas, crease maps of the first seed), then REPORT.md, which copies that
# seed's crease and facet images into $(IMAGES) too and ends with an index of every file there.
# The folder's images are removed first, so the index lists this report's only (no figures of
# another FIG_FORMAT or of a run with more cycles). $(RESULTS)/.fig_format changes only when
# FIG_FORMAT does, and then remakes the report in the new format.
# `pipeline/report/check_report.py $(RESULTS)/REPORT.md` checks that it is complete.
SHOWN := $(dir $(firstword $(STATS)))
ANALYSES := $(foreach s,$(SEEDS_USED),$(RUNDIR)/seed$(s).analysis)
FIG := --format $(FIG_FORMAT)
# where the figures were before they moved to images/: removed, not to be mistaken for current ones
OLD_FIGURES := $(foreach f,crease_length stages facets maps,$(RESULTS)/$(f).png)
$(RESULTS)/REPORT.md: $(STATS) $(ANALYZE) $(RESULTS)/.fig_format \
    $(wildcard pipeline/plots/*.py pipeline/report/*.py)
	@mkdir -p $(IMAGES)
	rm -f $(IMAGES)/*.png $(IMAGES)/*.svg $(OLD_FIGURES)
	$(ANALYZE) ensemble -o $(RESULTS)/ensemble.json $(ANALYSES)
	$(PYTHON) pipeline/plots/ensemble.py $(RESULTS)/ensemble.json -o $(RESULTS)/ensemble.csv
	$(PYTHON) pipeline/plots/plot_crease_length.py $(RESULTS)/ensemble.json \
	  -o $(IMAGES)/crease_length.$(FIG_FORMAT) $(FIG)
	$(PYTHON) pipeline/plots/plot_stages.py $(RESULTS)/ensemble.json -o $(IMAGES)/stages.$(FIG_FORMAT) $(FIG)
	$(PYTHON) pipeline/plots/plot_facets.py $(RESULTS)/ensemble.json -o $(IMAGES)/facets.$(FIG_FORMAT) $(FIG)
	$(PYTHON) pipeline/plots/plot_maps.py $(SHOWN) -o $(IMAGES)/maps.$(FIG_FORMAT) $(FIG)
	$(PYTHON) pipeline/report/make_report.py --ensemble $(RESULTS)/ensemble.json \
	  --runs $(SHOWN) --preset $(PRESET) --protocol $(PROTOCOL) $(FIG) -o $@

.PHONY: fig-format
$(RESULTS)/.fig_format: fig-format
	@mkdir -p $(@D)
	@echo $(FIG_FORMAT) | cmp -s - $@ || echo $(FIG_FORMAT) > $@
