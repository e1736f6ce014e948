#!/usr/bin/python3
"""Single-fold calibration of the yield (paper Fig. 3b) from crumple-sim run files of
protocols/single_fold.yaml.

For each run: the angle theta_f between the mean normals of the two flaps (the triangles beyond
the fold's free strip, with a margin) in the last frame, c_f = 2 sin(theta_f / 2), and the
paper's collapse variable x = beta (c0 - alpha), alpha = 0.05, beta = 0.04 lambda, with
lambda = sqrt(n / A) and the sheet side as the length unit. A line is fitted to all runs with
c_f >= 0.5 (the range of the paper's figure); the residual measures the collapse across
resolutions. The offset alpha that collapses this project's runs best is reported beside the
paper's. c0 is the hinge yield the run used (its stored integrator.plastic_c0, which a run with
material.yield_radius derived on its mesh, docs/MODEL.md §7.5). Runs with a yield radius are
also compared at equal radius across resolutions: one material should keep one fold.

usage: fold_calibration.py -o results/calibration runs/calibration/fold_*.h5
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die  # noqa: E402

import h5py  # noqa: E402
import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

ALPHA, BETA_PER_LAMBDA, CF_MIN = 0.05, 0.04, 0.5


def fold_stage(cfg, path):
    for st in cfg.get("protocol", {}).get("stages", []) or []:
        if st.get("type") == "fold":
            return st
    die(f"{path}: the run's protocol has no fold stage")


def measure(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        die(f"cannot open run file {path}: {e}")
    with f:
        status = f["meta"].attrs.get("status", b"")
        status = status.decode() if isinstance(status, bytes) else str(status)
        if "complete" not in status:
            die(f"{path}: run not complete (status '{status}')")
        text = f["config"][()]
        cfg = yaml.safe_load(text.decode() if isinstance(text, bytes) else text)
        ref = f["mesh/ref_positions"][()]
        tri = f["mesh/triangles"][()]
        last = sorted(f["frames"].keys())[-1]
        x = f["frames"][last]["x"][()]
        prov = {k: f["meta"].attrs.get(k) for k in ("program_version", "git_revision", "seed")}
        prov = {k: (v.decode() if isinstance(v, bytes) else str(v)) for k, v in prov.items()}
    st = fold_stage(cfg, path)
    side = float(cfg["mesh"]["size"])
    angle = math.radians(float(st.get("angle", 180)))
    line = math.radians(float(st.get("line_angle", 90)))
    radius = float(st.get("radius", 0.05)) * side
    centre = ref.mean(axis=0)
    across_dir = np.array([-math.sin(line), math.cos(line), 0.0])
    across = ((ref[tri].mean(axis=1) - centre) @ across_dir)
    margin = 1.2 * 0.5 * angle * radius  # the free strip's half-width, and a fifth more
    p = x[tri]
    normals = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])  # area-weighted
    n1, n2 = normals[across < -margin].sum(axis=0), normals[across > margin].sum(axis=0)
    if not (np.linalg.norm(n1) > 0 and np.linalg.norm(n2) > 0):
        die(f"{path}: no flap triangles beyond the fold's strip")
    cos = np.dot(n1, n2) / (np.linalg.norm(n1) * np.linalg.norm(n2))
    theta = math.acos(max(-1.0, min(1.0, cos)))
    n = ref.shape[0]
    area = 0.5 * np.abs(np.cross(ref[tri[:, 1]] - ref[tri[:, 0]], ref[tri[:, 2]] - ref[tri[:, 0]])[:, 2]).sum()
    lam = math.sqrt(n / (area / side ** 2))
    c0 = float(cfg["integrator"]["plastic_c0"])
    r_y = cfg.get("material", {}).get("yield_radius")
    return dict(run=os.path.basename(path), nodes=n, prov=prov, lam=lam, c0=c0, lam_c0=lam * c0,
                r_y_mm=None if r_y is None else 1e3 * float(r_y),
                theta_deg=math.degrees(theta), c_f=2 * math.sin(theta / 2))


def provenance(rows):
    """crumple-sim version(s), git revision(s) and seeds of the runs, for the outputs' headers."""
    def values(key):
        return ", ".join(sorted({r["prov"][key] for r in rows}))
    return (f"crumple-sim {values('program_version')} (git {values('git_revision')}), "
            f"seeds {values('seed')}")


def spread_at_equal_radius(rows):
    """For each yield radius run at two or more resolutions: (R_y in mm, [(nodes, c_f)], the
    largest difference of c_f between them)."""
    out = []
    for r_y in sorted({r["r_y_mm"] for r in rows if r["r_y_mm"] is not None}):
        pts = [(r["nodes"], r["c_f"]) for r in rows if r["r_y_mm"] == r_y]
        if len({n for n, _ in pts}) >= 2:
            cf = [c for _, c in pts]
            out.append((r_y, pts, max(cf) - min(cf)))
    return out


def line_fit(x, y):
    """Least-squares line y = a + b x; returns a, b and the RMS residual."""
    b, a = np.polyfit(x, y, 1)
    return a, b, float(np.sqrt(np.mean((y - a - b * x) ** 2)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="run files of protocols/single_fold.yaml")
    ap.add_argument("-o", "--output", required=True, help="output folder")
    args = ap.parse_args()
    rows = sorted((measure(p) for p in args.runs), key=lambda r: (r["nodes"], r["c0"]))
    for r in rows:
        r["x"] = BETA_PER_LAMBDA * r["lam"] * (r["c0"] - ALPHA)
    sel = [r for r in rows if r["c_f"] >= CF_MIN]
    if len({r["nodes"] for r in sel}) < 2 or len(sel) < 3:
        die(f"need runs at two resolutions with c_f >= {CF_MIN} to test the collapse")
    xs, ys = np.array([r["x"] for r in sel]), np.array([r["c_f"] for r in sel])
    a, b, rms = line_fit(xs, ys)
    # The offset that collapses these runs best (a line through all selected points).
    alphas = np.linspace(-0.2, 0.2, 401)
    scores = [line_fit(np.array([BETA_PER_LAMBDA * r["lam"] * (r["c0"] - al) for r in sel]), ys)[2]
              for al in alphas]
    best = float(alphas[int(np.argmin(scores))])

    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "fold_calibration.csv"), "w", newline="") as f:
        f.write(f"# {provenance(rows)}\n")
        w = csv.writer(f)
        w.writerow(["run", "nodes", "lambda", "yield_radius_mm", "c0", "lambda_c0", "theta_f_deg",
                    "c_f", "x"])
        for r in rows:
            r_y = "" if r["r_y_mm"] is None else f"{r['r_y_mm']:g}"
            w.writerow([r["run"], r["nodes"], f"{r['lam']:.3f}", r_y, f"{r['c0']:.6g}", f"{r['lam_c0']:.3f}",
                        f"{r['theta_deg']:.2f}", f"{r['c_f']:.4f}", f"{r['x']:.4f}"])

    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for n in sorted({r["nodes"] for r in rows}):
        rr = [r for r in rows if r["nodes"] == n]
        lab = f"n = {n} (lambda = {rr[0]['lam']:.1f})"
        ax[0].plot([r["x"] for r in rr], [r["c_f"] for r in rr], "o", label=lab)
        if all(r["r_y_mm"] is not None for r in rows):
            ax[1].plot([r["r_y_mm"] for r in rr], [r["c_f"] for r in rr], "o-", label=lab)
        else:
            ax[1].plot([r["c0"] for r in rr], [r["c_f"] for r in rr], "o-", label=lab)
    xl = np.linspace(0, max(r["x"] for r in rows), 50)
    ax[0].plot(xl, a + b * xl, "k--", lw=1, label=f"fit c_f >= {CF_MIN}: {a:.2f} {b:+.2f} x")
    ax[0].set_xlabel("beta (c0 - alpha),  alpha = 0.05, beta = 0.04 lambda")
    ax[0].set_ylabel("c_f = 2 sin(theta_f / 2)")
    ax[0].set_title("collapse variables (paper Fig. 3b)")
    if all(r["r_y_mm"] is not None for r in rows):
        ax[1].set_xscale("log")
        ax[1].set_xlabel("yield radius R_y (mm)")
        ax[1].set_title("the same runs against the sheet's yield radius")
    else:
        ax[1].set_xlabel("yield curvature c0")
        ax[1].set_title("the same runs against c0")
    for axis in ax:
        axis.set_ylim(0, 2.05)
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "fold_calibration.png"), dpi=120)

    with open(os.path.join(args.output, "FOLD_CALIBRATION.md"), "w") as f:
        f.write("# Single-fold calibration of the yield (paper Fig. 3b)\n\n")
        f.write("Protocol `protocols/single_fold.yaml`; theta_f is the angle between the flaps' "
                "normals after the release, c_f = 2 sin(theta_f / 2), x = beta (c0 - alpha) with "
                "alpha = 0.05, beta = 0.04 lambda, lambda = sqrt(n/A) (sheet side = 1).\n\n")
        f.write("![fold calibration](fold_calibration.png)\n\n")
        f.write("| nodes | lambda | R_y (mm) | c0 | lambda c0 | theta_f (deg) | c_f | x |\n"
                "|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            r_y = "-" if r["r_y_mm"] is None else f"{r['r_y_mm']:g}"
            f.write(f"| {r['nodes']} | {r['lam']:.1f} | {r_y} | {r['c0']:.4g} | {r['lam_c0']:.2f} | "
                    f"{r['theta_deg']:.1f} | {r['c_f']:.3f} | {r['x']:.3f} |\n")
        f.write(f"\nLine through the {len(sel)} runs with c_f >= {CF_MIN}: c_f = {a:.3f} {b:+.3f} x, "
                f"RMS residual {rms:.3f}.\n")
        f.write(f"The offset alpha that collapses these runs best: {best:.3f} "
                f"(RMS residual {min(scores):.3f}); the paper's alpha is {ALPHA}.\n")
        spread = spread_at_equal_radius(rows)
        if spread:
            f.write("\nOne yield radius, several resolutions (c_f at each; one material should "
                    "keep one fold):\n\n| R_y (mm) | c_f by node count | largest difference |\n"
                    "|---|---|---|\n")
            for r_y, pts, d in spread:
                cells = ", ".join(f"{c:.3f} ({n})" for n, c in sorted(pts))
                f.write(f"| {r_y:g} | {cells} | {d:.3f} |\n")
        f.write(f"\nRuns: {provenance(rows)}.\n")
    print(f"fold calibration: {len(rows)} runs, c_f = {a:.3f} {b:+.3f} x (c_f >= {CF_MIN}), "
          f"RMS {rms:.3f}; best alpha {best:.3f} (RMS {min(scores):.3f})")


if __name__ == "__main__":
    main()
