"""Helpers shared by the pipeline's plot and report scripts: input checks that fail with a clear
message, the ensemble file of `crumple-analyze ensemble`, the figure output (-o FILE and
--format png|svg, saved alike by every plot script), the experimental constants from data/ and
the law they give, the fragmentation-model density phi(xi; a) of docs/STATISTICS.md §3.3, and
for runs paired by seed: each run's values by seed, a mean with its s.e.m., and the error of a
ratio of means."""
import csv
import json
import math
import os
import statistics
import sys

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def die(msg):
    print(f"{os.path.basename(sys.argv[0])}: error: {msg}", file=sys.stderr)
    sys.exit(2)


def load_json(path, what):
    if not os.path.isfile(path):
        die(f"missing {what}: {path}")
    try:
        with open(path) as f:
            return json.load(f)
    except json.JSONDecodeError as e:
        die(f"{what} {path} is not valid JSON: {e}")


def load_ensemble(path):
    """ensemble.json as `crumple-analyze ensemble` writes it (the ensemble statistics and fits;
    analysis/README.md); dies naming the file when it is not one."""
    e = load_json(path, "ensemble file")
    missing = [k for k in ("cycles", "fits", "stages", "threshold_sensitivity", "runs") if k not in e]
    if missing:
        die(f"{path} is not an ensemble file of `crumple-analyze ensemble` (no {', '.join(missing)}); "
            "make it with: crumple-analyze ensemble -o ENSEMBLE.json RUN.analysis ...")
    return e


def per_seed(ens, key):
    """{seed: {cycle: value}} of one statistic over an ensemble's runs (cycles without it left
    out): what two ensembles of the same seeds are paired by."""
    out = {}
    for r in ens.get("runs") or []:
        out[r["seed"]] = {c["cycle"]: c[key] for c in r.get("cycles", []) if c.get(key) is not None}
    return out


def mean_sem(xs):
    """Mean and s.e.m. (n - 1) of a list; (None, None) when empty, no s.e.m. from one value."""
    if not xs:
        return None, None
    m = statistics.fmean(xs)
    return m, (statistics.stdev(xs) / math.sqrt(len(xs)) if len(xs) > 1 else None)


FIG_FORMATS = ("png", "svg")


def add_figure_args(ap):
    """-o FILE and --format png|svg on a plot script's command line (make reproduce passes
    --format $(FIG_FORMAT)); figure_output() resolves them."""
    ap.add_argument("-o", "--output", required=True,
                    help="figure file (.png or .svg; without an extension, --format's is added)")
    ap.add_argument("--format", choices=FIG_FORMATS,
                    help="figure format (default: the output's extension, else png)")


def figure_output(args):
    """The figure's path and format from -o and --format; dies (exit 2) when they disagree or
    the extension is not a figure format, so a make variable cannot silently pick another."""
    ext = os.path.splitext(args.output)[1].lower().lstrip(".")
    if not ext:
        fmt = args.format or FIG_FORMATS[0]
        return f"{args.output}.{fmt}", fmt
    if ext not in FIG_FORMATS:
        die(f"output {args.output}: a figure is written as {' or '.join(FIG_FORMATS)}, "
            f"not .{ext}")
    if args.format and args.format != ext:
        die(f"--format {args.format} but the output {args.output} ends in .{ext}")
    return args.output, ext


def save_figure(fig, path, fmt, dpi):
    """Writes the figure; in SVG the text stays text (searchable, editable) and the file carries
    no date and stable ids, so the same data give the same file."""
    import matplotlib
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": "crumple"}):
        fig.savefig(path, format=fmt, dpi=dpi,
                    metadata={"Date": None} if fmt == "svg" else None)


def ensemble_cli(doc):
    """The plot scripts' command line, ENSEMBLE -o OUTPUT [--format png|svg]: returns the
    arguments (args.output and args.format resolved by figure_output) and the loaded
    ensemble.json."""
    import argparse
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ensemble", help="ensemble.json from crumple-analyze ensemble")
    add_figure_args(ap)
    args = ap.parse_args()
    args.output, args.format = figure_output(args)
    return args, load_ensemble(args.ensemble)


def read_csv(path):
    """Rows of a CSV file as dicts; lines starting with '#' are comments."""
    if not os.path.isfile(path):
        die(f"missing data file: {path}")
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def write_csv(path, rows, comment=None):
    """rows (dicts with the same keys) to a CSV file, whole or not at all: written beside it
    and renamed; `comment` becomes a first line starting with '#'."""
    tmp = path + ".new"
    with open(tmp, "w", newline="") as f:
        if comment:
            f.write(f"# {comment}\n")
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, path)


def law_constants():
    """c1, c2 of the crease-length law (data/crease_length_law_constants.csv)."""
    rows = {r["name"]: float(r["value"]) for r in
            read_csv(os.path.join(REPO, "data", "crease_length_law_constants.csv"))}
    return rows["c1"], rows["c2"]


def collapses(fit):
    """Whether a fit of the law to several compactions at once (`crumple-analyze collapse`) puts
    the groups on one curve within their errors: χ²/dof below 2 (loose, since the weights are the
    s.e.m. of a few seeds). The sweep report and the predictions both judge by this one rule. No
    degrees of freedom, no collapse."""
    return fit["dof"] > 0 and fit["chi2"] / fit["dof"] < 2


def experiment(D, cycles):
    """The experimental law l/L0 = c1 (1 - D) ln(1 + c2 n/D) (docs/STATISTICS.md §2.1) at
    compaction D: its C = c1 (1 - D), n0 = D/c2 and, for each cycle number n of `cycles`, its
    value and its increment from n - 1. None when D is unknown or outside (0, 1). This evaluates
    the reference law for the tables and the report; it fits nothing."""
    if D is None or not 0 < D < 1:
        return None
    c1, c2 = law_constants()
    law = lambda n: c1 * (1 - D) * math.log1p(c2 * n / D)  # noqa: E731
    return {"c1": c1, "c2": c2, "D": D, "C": c1 * (1 - D), "n0": D / c2,
            "note": "law l/L0 = c1 (1 - D) ln(1 + c2 n/D) (docs/STATISTICS.md §2.1); "
                    "no published uncertainty",
            "cycles": [{"cycle": n, "law": law(n), "law_increment": law(n) - law(n - 1)}
                       for n in cycles]}


def phi(xi, a):
    """phi(xi; a) = a(a+1)/(2 Gamma(a)) z^(a/2-1) exp(-sqrt z), z = a(a+1) xi."""
    import numpy as np
    from scipy.special import gammaln
    k = a * (a + 1.0)
    z = k * np.asarray(xi, dtype=float)
    return np.exp(math.log(k) - math.log(2.0) - gammaln(a) + (a / 2 - 1) * np.log(z) - np.sqrt(z))


def sweep_groups(points):
    """The groups of a sweep's points file (runs/sweeps/NAME/points.json), in the order of the
    sweep file's grid."""
    order = []
    for p in points["points"]:
        if p["group"] not in order:
            order.append(p["group"])
    return order


def ratio_of_means(xs, ys):
    """mean(ys) / mean(xs) over paired runs, and its standard error by the delta method with the
    runs' covariance: P(n) and P(1) of one run are correlated (either way), so their s.e.m. do
    not add as if independent. var R = (var y - 2 R cov(x, y) + R^2 var x) / (n mean(x)^2), which
    holds for mean(y) = 0 too. Needs mean(x) > 0; None for the error with fewer than two runs."""
    n = len(xs)
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    r = my / mx
    if n < 2:
        return r, None
    vx, vy = statistics.variance(xs), statistics.variance(ys)
    cov = statistics.covariance(xs, ys)
    var = (vy - 2 * r * cov + r * r * vx) / (n * mx * mx)
    return r, math.sqrt(max(var, 0.0))
