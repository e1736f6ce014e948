"""The units of crumple's outputs, in one place (docs/FILE_FORMAT.md, analysis/README.md).

Lengths in a run file are in the unit of the mesh coordinates, /meta@length_unit_m metres (1 for
the shipped protocols, which give the sheet in metres). Time is the simulated time of the model
as integrated: with mass scaling (material.mass_scale) it is the time of the heavier sheet, not
of the real one. Curvatures (p) are per hinge in the units of c = 2 sin(theta/2), dimensionless.
L0 is the sheet's side (the experiments' unit of crease length).
"""


def length_unit(length_unit_m):
    """The name of a run file's length unit: "m" when it is the metre, else "(X m)"."""
    return "m" if float(length_unit_m) == 1.0 else f"({float(length_unit_m):g} m)"


def run_units(length_unit_m):
    L = length_unit(length_unit_m)
    return {
        "ref_positions": L, "rest_lengths": L, "hinge_factor": "1",
        "x": L, "v": f"{L}/s", "p": "1 (c = 2 sin(theta/2))",
        "crease": "1 (flag: |p| > /meta@crease_threshold)",
        "t": "s (simulated; mass-scaled time when material.mass_scale > 1)",
        "h": "s", "a_ratio": "1", "a_ratio_avg": "1",
        "e_stretch": "J", "e_bend": "J", "e_contact": "J", "e_external": "J", "e_kinetic": "J",
        "compaction": "1 (final / initial piston gap)", "wall": "s (wall clock)",
        "roll_axis_deg": "degree (in-plane roll axis from x, 0-180)",
        "cycle": "1", "stage": "- (stage type)", "stage_index": "1", "step": "1",
        "mode": "0 implicit, 1 explicit",
        "order": "1", "newton_iters": "1", "cg_iters": "1", "rejections": "1",
    }


# Columns of the analysis tables (analysis/README.md) and the ensemble rows.
ANALYSIS_UNITS = {
    "cycle": "1", "stage_index": "1", "stage": "-", "t": "s (simulated)",
    "crease_edges": "1", "crease_length_m": "m", "crease_length_L0": "L0",
    "new_crease_length_m": "m", "new_crease_length_L0": "L0", "lost_crease_length_L0": "L0",
    "perimeter_P": "L0", "n_facets": "1", "mean_area_m2": "m^2", "mean_area_x": "sheet area",
    "a_fit": "1", "a_fit_lo": "1", "a_fit_hi": "1", "a_moment": "1", "a_univ": "1",
    "ks_distance": "1", "ks_pvalue": "1", "dangling_fraction": "1",
    "n_single_triangle_facets": "1", "single_triangle_fraction": "1",
    "new_length_share_after_compress": "1", "compaction": "1 (final / initial piston gap)",
    "factor_of_c0": "c0", "threshold": "1 (|p|, c = 2 sin(theta/2))",
    "facet_id": "1", "area_m2": "m^2", "x": "sheet area", "xi": "mean x",
    "touches_border": "bool", "bin_lo": "mean x", "bin_hi": "mean x", "count": "1",
    "density": "1 / (mean x)",
    # the facet law cut at the resolution floor (analysis/fits/truncated_shape.hpp)
    "n_facets_above_floor": "1", "a_fit_above_floor": "1", "a_univ_above_floor": "1",
    "mean_area_x_above_floor": "sheet area", "law_share_below_floor": "1",
    "ks_distance_above_floor": "1", "ks_pvalue_above_floor": "1",
    "fit_above_floor_edge": "- (edge of the search: a_min, a_max, theta)",
}


def unit_of(column):
    """The unit of an analysis or ensemble column: its own, or that of the quantity it is the
    mean, s.d. or s.e.m. of (ensemble rows: KEY_mean, KEY_sd, KEY_sem)."""
    if column in ANALYSIS_UNITS:
        return ANALYSIS_UNITS[column]
    for suffix in ("_mean", "_sd", "_sem", "_n"):
        if column.endswith(suffix):
            base = column[: -len(suffix)]
            if base in ANALYSIS_UNITS:
                return "1" if suffix == "_n" else ANALYSIS_UNITS[base]
    return None
