# SCHEDULER=slurm: `make reproduce` and `make sweep` submit their runs to Slurm instead of
# running them here (pipeline/slurm/submit.py; README.md, "Running on a Slurm cluster"). The
# default, SCHEDULER=local, runs them with make -j on this machine.
#   SLURM_PARTITION, SLURM_ACCOUNT  where to run (sbatch --partition, --account)
#   SLURM_TIME                      time limit per job (sbatch --time, e.g. 12:00:00)
#   SLURM_MODULES                   modules each job loads first ("gcc hdf5 opencv")
#   SLURM_SIGNAL_LEAD               seconds before the limit a run is told to checkpoint (300)
#   SLURM_EXTRA                     further sbatch options ("--qos=long --mem-per-cpu=2G")
#   SLURM_WAIT=1                    wait for the jobs; fail when one failed
SCHEDULER ?= local
SLURM_PARTITION ?=
SLURM_ACCOUNT ?=
SLURM_TIME ?=
SLURM_MODULES ?=
SLURM_SIGNAL_LEAD ?= 300
SLURM_EXTRA ?=
SLURM_WAIT ?=
ifeq ($(filter $(SCHEDULER),local slurm),)
$(error SCHEDULER=$(SCHEDULER): choose local (the default) or slurm)
endif
SLURM_SUBMIT = $(PYTHON) pipeline/slurm/submit.py --partition '$(SLURM_PARTITION)' \
  --account '$(SLURM_ACCOUNT)' --time '$(SLURM_TIME)' --modules '$(SLURM_MODULES)' \
  --extra '$(SLURM_EXTRA)' --signal-lead $(SLURM_SIGNAL_LEAD) $(if $(SLURM_WAIT),--wait)
