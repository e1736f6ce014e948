# The README's recipes as make targets: each command block of README.md that a user types is one
# of these (or make reproduce, make sweep, ...), and tests/pipeline/test_readme_recipes.py runs
# every block as written.
#   make run RUN=runs/a.h5 [SEED=1] [SET="key=value ..."] [THREADS=1] [FORCE=1]
#       one run of PROTOCOL with the sheet and cycles of PRESET (its PRESET_SETS), SET on top; a
#       stopped run (RUN.tmp holds its checkpoint) is continued, a finished one left alone.
#   make compare RUN="runs/mine/seed*.h5" [OUT=DIR]
#       the runs analysed (RUN.analysis/ beside each), then make reproduce's report of them
#       (ensemble, figures, REPORT.md against the experiments) in OUT, by default compare/ beside
#       the first run.
#   make protocol NAME=mine [FROM=protocols/axial_crumpling.yaml]
#       protocols/NAME.yaml, copied from FROM when absent, checked as a run would check it.
# Bad input (a variable missing, a file not there) stops make before anything is built or
# written (exit 2). The variables are set on the command line only (not from the environment:
# names such as NAME or RUN are too common there).
RUN   :=
SEED  := 1
SET   :=
THREADS :=
FORCE :=
OUT   :=
NAME  :=
FROM  := protocols/axial_crumpling.yaml

.PHONY: run compare protocol

recipe_goal = $(filter $(1),$(MAKECMDGOALS))

# --- make run -----------------------------------------------------------------------------------
ifneq ($(call recipe_goal,run),)
ifneq ($(words $(RUN)),1)
$(error make run: give RUN=PATH, the one run file to write, e.g. RUN=runs/a.h5)
endif
ifeq ($(wildcard $(PROTOCOL)),)
$(error make run: PROTOCOL=$(PROTOCOL): no such protocol file)
endif
endif

# Finished: the run file is there, no checkpoint is pending and FORCE is not given.
RUN_DONE = $(and $(wildcard $(RUN)),$(if $(wildcard $(RUN).tmp),,yes),$(if $(FORCE),,yes))
# Threads: the preset's (1 for all of them), not crumple-sim's default of every core, which is
# many times slower when the cores are busy with other runs.
RUN_ARGS = --seed $(SEED) --threads $(or $(THREADS),$(RUN_THREADS)) $(PRESET_SETS) \
  $(foreach s,$(SET),--set $(s)) $(if $(FORCE),--force,$(if $(wildcard $(RUN).tmp),--resume))

# The simulator's command is echoed, so the recipe also shows how to call crumple-sim directly.
run: build
	@mkdir -p $(dir $(RUN))
	$(if $(RUN_DONE),@echo "make run: $(RUN) is finished (FORCE=1 runs it again)",$(SIM) $(PROTOCOL) -o $(RUN) $(RUN_ARGS))

# --- make compare -------------------------------------------------------------------------------
# The report is make reproduce's own (pipeline/reproduce.mk, target report), so the two never
# differ: its rule is given these runs' analyses in place of a preset's (STATS, ANALYSES, SHOWN),
# with every run file declared old (-o) so that no rule of the Makefile ever runs the simulator
# on them, and writes into a staging folder that replaces OUT only once the report is complete.
COMPARE_RUNS  = $(sort $(wildcard $(RUN)))
COMPARE_OUT   = $(patsubst %/,%,$(or $(OUT),$(dir $(firstword $(COMPARE_RUNS)))compare))
COMPARE_STAGE = $(COMPARE_OUT).part
compare_analysis = $(patsubst %.h5,%,$(1)).analysis
COMPARE_ANALYSES = $(foreach r,$(COMPARE_RUNS),$(call compare_analysis,$(r)))
# A folder make compare wrote holds this list of the runs it compared; only such a folder is
# replaced (OUT=results must not wipe make reproduce's results).
COMPARE_MARK  = compared_runs.txt

ifneq ($(call recipe_goal,compare),)
ifeq ($(strip $(RUN)),)
$(error make compare: give RUN="RUN.h5 ...", the run files to compare (a pattern such as RUN="runs/mine/seed*.h5" will do))
endif
$(foreach r,$(RUN),$(if $(wildcard $(r)),,$(error make compare: RUN: $(r): $(if $(wildcard $(r).tmp),not finished ($(r).tmp holds its checkpoint; make run continues it),no such run file))))
ifeq ($(COMPARE_OUT),)
$(error make compare: OUT=$(OUT): give a folder to write into)
endif
ifneq ($(wildcard $(COMPARE_OUT)),)
ifeq ($(wildcard $(COMPARE_OUT)/.),)
$(error make compare: OUT=$(COMPARE_OUT) is a file, not a folder)
endif
ifneq ($(wildcard $(COMPARE_OUT)/*),)
ifeq ($(wildcard $(COMPARE_OUT)/$(COMPARE_MARK)),)
$(error make compare: OUT=$(COMPARE_OUT) holds other files (it is not a folder make compare wrote): give a new or empty folder)
endif
endif
endif
endif

# Shell: analyse run $(1) into its analysis folder unless that is newer than the run and the
# analyser (as a make rule would; the folders are not targets, their names come from RUN).
compare_analyse = a=$(call compare_analysis,$(1)); \
  if [ "$$a/stats.json" -nt $(1) ] && [ "$$a/stats.json" -nt $(ANALYZE) ]; then echo "$$a: up to date"; \
  else echo "$(ANALYZE) $(1) -o $$a"; $(ANALYZE) $(1) -o $$a || exit $$?; fi;

COMPARE_FAIL = { rm -rf $(COMPARE_STAGE); echo "make compare: failed; $(COMPARE_OUT) left as it was" >&2; exit 1; }

compare: build
	@$(foreach r,$(COMPARE_RUNS),$(call compare_analyse,$(r)))
	@rm -rf $(COMPARE_STAGE)
	@echo "make compare: make reproduce's report of $(words $(COMPARE_RUNS)) run(s), in $(COMPARE_STAGE)"
	@$(MAKE) --no-print-directory report RESULTS=$(COMPARE_STAGE) \
	  STATS="$(addsuffix /stats.json,$(COMPARE_ANALYSES))" ANALYSES="$(COMPARE_ANALYSES)" \
	  SHOWN=$(firstword $(COMPARE_ANALYSES))/ $(foreach r,$(COMPARE_RUNS),-o $(r)) || $(COMPARE_FAIL)
	@$(PYTHON) pipeline/report/check_report.py $(COMPARE_STAGE)/REPORT.md || $(COMPARE_FAIL)
	@printf '%s\n' $(COMPARE_RUNS) > $(COMPARE_STAGE)/$(COMPARE_MARK) \
	  && rm -rf $(COMPARE_OUT) && mv $(COMPARE_STAGE) $(COMPARE_OUT)
	@echo "make compare: $(COMPARE_OUT)/REPORT.md"

# --- make protocol ------------------------------------------------------------------------------
ifneq ($(call recipe_goal,protocol),)
ifneq ($(words $(NAME))$(findstring /,$(NAME))$(filter %.yaml,$(NAME)),1)
$(error make protocol: give NAME=NAME, a name (not a path): the protocol file is protocols/NAME.yaml)
endif
ifeq ($(wildcard protocols/$(NAME).yaml)$(wildcard $(FROM)),)
$(error make protocol: FROM=$(FROM): no such protocol file to copy)
endif
endif

# crumple-sim --print-config checks the file as a run would (every key, every stage's parameters
# and their order) and prints it resolved, every default filled in.
protocol: build
	@test -f protocols/$(NAME).yaml || { cp $(FROM) protocols/$(NAME).yaml && \
	  echo "make protocol: protocols/$(NAME).yaml, a copy of $(FROM)"; }
	$(SIM) protocols/$(NAME).yaml --print-config
	@echo "make protocol: protocols/$(NAME).yaml checked; make run RUN=runs/$(NAME).h5 PROTOCOL=protocols/$(NAME).yaml runs it"
