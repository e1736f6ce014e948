"""crumple-analyze's outputs (analysis/README.md) as pandas frames with units: a run's analysis
folder (stats.json and its CSV tables) and an ensemble document (`crumple-analyze ensemble`)."""
import json
import os

import pandas as pd

from .units import unit_of

TABLES = ("cycles", "stages", "sensitivity", "facets", "distribution")


def _with_units(df):
    df.attrs["units"] = {c: unit_of(c) for c in df.columns}
    return df


class Analysis:
    """A run's analysis folder. Attributes: path, stats (dict, stats.json), and one DataFrame
    per table: cycles, stages, sensitivity, facets, distribution (empty when absent); each
    with attrs["units"]. crease_map(n) and facet_map(n) are the paths of cycle n's images."""

    def __init__(self, path):
        self.path = path
        stats = os.path.join(path, "stats.json")
        if not os.path.isfile(stats):
            raise FileNotFoundError(f"{path}: no stats.json (not a crumple-analyze folder?)")
        with open(stats) as f:
            self.stats = json.load(f)
        for name in TABLES:
            csv = os.path.join(path, name + ".csv")
            df = pd.read_csv(csv) if os.path.isfile(csv) else pd.DataFrame()
            setattr(self, name, _with_units(df))

    def __repr__(self):
        return f"Analysis({self.path!r}: {len(self.cycles)} cycles)"

    def crease_map(self, n):
        return os.path.join(self.path, f"crease_{n:04d}.png")

    def facet_map(self, n):
        return os.path.join(self.path, f"facets_{n:04d}.png")


def load_analysis(path):
    """Reads a crumple-analyze output folder (RUN.analysis/); see Analysis."""
    return Analysis(path)


def load_ensemble(path):
    """An ensemble document (`crumple-analyze ensemble -o FILE`): (its per-cycle rows as a
    DataFrame with attrs["units"], the whole document as a dict)."""
    with open(path) as f:
        doc = json.load(f)
    if "cycles" not in doc:
        raise ValueError(f"{path}: no cycles (not an ensemble document?)")
    return _with_units(pd.DataFrame(doc["cycles"])), doc
