"""A crumple-sim run file (docs/FILE_FORMAT.md) as numpy arrays and pandas frames.

The small parts (meta, config, mesh, the per-frame, per-cycle and per-stage tables, the step log)
are read at once; the fields of a frame, cycle or stage end (x, v, p) are read when asked for,
since a long run at many nodes holds gigabytes of them.
"""
import os

import h5py
import numpy as np
import pandas as pd
import yaml

from .units import run_units


def _text(v):
    return v.decode() if isinstance(v, bytes) else v


def _attrs(obj):
    return {k: _text(v.item() if isinstance(v, np.generic) else v) for k, v in obj.attrs.items()}


def _frame_table(group, names, units, columns):
    """One row per subgroup of `group` (in its order), from the subgroups' attributes."""
    rows = []
    for name in names:
        a = _attrs(group[name])
        rows.append({"name": name, **{c: a.get(c, np.nan) for c in columns}})
    df = pd.DataFrame(rows, columns=["name"] + columns)
    df.attrs["units"] = {c: units.get(c) for c in columns}
    return df


class Run:
    """A run file. Attributes: path, meta (dict), config (dict: the resolved configuration),
    units (array or column -> unit), mesh (dict of arrays), frames, cycles, stage_ends, log
    (DataFrames). Fields: frame(i), cycle(n), stage_end(i) (dicts of x, v, p as present)."""

    def __init__(self, path):
        self.path = path
        if not os.path.isfile(path):
            raise FileNotFoundError(f"{path}: no such run file")
        with h5py.File(path, "r") as f:
            if "meta" not in f or "mesh" not in f:
                raise ValueError(f"{path}: not a crumple run file (no /meta or /mesh)")
            self.meta = _attrs(f["meta"])
            self.config = yaml.safe_load(_text(f["config"][()])) if "config" in f else {}
            self.units = run_units(self.meta.get("length_unit_m", 1.0))
            self.mesh = {k: f["mesh"][k][()] for k in f["mesh"]}
            self._frames = sorted(f["frames"]) if "frames" in f else []
            self._cycles = sorted(f["cycles"]) if "cycles" in f else []
            self._stages = sorted(f["stage_ends"]) if "stage_ends" in f else []
            self.frames = _frame_table(f["frames"], self._frames, self.units,
                                       ["t", "cycle", "stage", "step"]) if self._frames else \
                _frame_table(None, [], self.units, ["t", "cycle", "stage", "step"])
            self.cycles = _frame_table(f["cycles"], self._cycles, self.units,
                                       ["cycle", "t", "compaction"]) if self._cycles else \
                _frame_table(None, [], self.units, ["cycle", "t", "compaction"])
            cols = ["cycle", "stage_index", "stage", "t", "compaction", "roll_axis_deg", "wall"]
            self.stage_ends = _frame_table(f["stage_ends"], self._stages, self.units, cols) \
                if self._stages else _frame_table(None, [], self.units, cols)
            if "log" in f:
                self.log = pd.DataFrame({k: f["log"][k][()] for k in f["log"]})
                self.log_counters = _attrs(f["log"])
            else:
                self.log, self.log_counters = pd.DataFrame(), {}
            self.log.attrs["units"] = {c: self.units.get(c) for c in self.log.columns}

    def __repr__(self):
        return (f"Run({self.path!r}: {len(self.mesh['ref_positions'])} nodes, "
                f"{len(self._frames)} frames, {len(self._cycles)} cycles)")

    def _fields(self, group, names, i):
        with h5py.File(self.path, "r") as f:
            g = f[group][names[i]]
            return {k: g[k][()] for k in ("x", "v", "p") if k in g}

    def frame(self, i):
        """Fields of frame i (0-based, the frames table's row): x (n, 3), v (n, 3), p (hinges)."""
        return self._fields("frames", self._frames, i)

    def cycle(self, n):
        """Fields at the end of cycle n (from 1): x (n, 3) and p (hinges)."""
        return self._fields("cycles", self._cycles, n - 1)

    def stage_end(self, i):
        """The plastic field p at stage end i (0-based, the stage_ends table's row)."""
        return self._fields("stage_ends", self._stages, i)


def load_run(path):
    """Reads a crumple-sim run file (RUN.h5); see Run."""
    return Run(path)
