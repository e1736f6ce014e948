"""Read crumple's outputs into numpy arrays and pandas frames, with units.

Importable from a checkout (no installation; Debian's python3-h5py, -numpy, -pandas and -yaml):

    import sys; sys.path.insert(0, "pipeline/python")
    import crumple
    run = crumple.load_run("runs/quick/axial_crumpling/seed1.h5")        # a crumple-sim run file
    ana = crumple.load_analysis("runs/quick/axial_crumpling/seed1.analysis")  # crumple-analyze's
    ens = crumple.load_ensemble("results/ensemble.json")                 # crumple-analyze ensemble

Every table is a pandas DataFrame whose ``attrs["units"]`` maps each column to its unit, and
``units`` on each object does the same for its arrays. The layouts are docs/FILE_FORMAT.md (run
file) and analysis/README.md (analysis folder).
"""
from .analysis_folder import Analysis, load_analysis, load_ensemble
from .run_file import Run, load_run

__all__ = ["Run", "Analysis", "load_run", "load_analysis", "load_ensemble"]
