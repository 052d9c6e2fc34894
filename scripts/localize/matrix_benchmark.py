#!/usr/bin/env python3
"""The localisation test matrix: RSSI logs from an independent generator whose model differs from
the range fit's assumptions (exponent 2.0-3.5, shadowing 3-8 dB as a 2D random field correlated
over 0.5-5 m, fast fading 0-4 dB, phone level -48..-38 dBm against the assumed -45, a -95 dBm
floor that drops or blank-marks weak scans), run through `rigdesign localize --method all`, and
summarised per path class: mean error of each method, the better estimator's ratio to paper 4's
WLS, and how often the truth lies in each method's stated 95 % region.

Usage: matrix_benchmark.py RIGDESIGN [--runs-per-path 50] [--seed 1] [--out DIR] [--json FILE]
                           [--with-walls] [--extra ARG ...]
Standard library only. The error of the range fit (nls) is its probability-weighted error over
its hypotheses (the error of the stated belief: ambiguous hypotheses are not ranked by accident);
paper 4's methods report one point.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
GENERATOR = os.path.join(HERE, "independent_rssi_generator.py")
METHODS = ("wls", "nls", "map")


def generate(out, runs, seed):
    """Writes the matrix (logs, truth, walls, manifest.csv) into `out` and reads the manifest."""
    subprocess.run([sys.executable, GENERATOR, "--matrix", str(runs), "--seed", str(seed),
                    "--out", out], check=True)
    with open(os.path.join(out, "manifest.csv"), newline="") as f:
        return list(csv.DictReader(f))


def merged_truth(out, manifest):
    """One truth file for every run (BSSIDs are unique per run), so one call reads all logs."""
    path = os.path.join(out, "all_truth.csv")
    with open(path, "w", newline="\n") as f:
        f.write("bssid,x,y,z\n")
        for run in manifest:
            f.write(f"{run['bssid']},{run['phone_x']},{run['phone_y']},{run['phone_z']}\n")
    return path


def localize(rigdesign, out, manifest, truth, extra, with_walls):
    """One call over every log, or with the generator's wall maps one call per log (--walls)."""
    command = [rigdesign, "localize", "--method", "all", "--checkpoints", "0", "--json",
               "--truth", truth] + extra
    logs = [os.path.join(out, run["stem"] + "_rssi.csv") for run in manifest]
    started = time.perf_counter()
    if not with_walls:
        for log in logs:
            command += ["--log", log]
        result = subprocess.run(command, check=True, capture_output=True, text=True)
        return json.loads(result.stdout), time.perf_counter() - started
    report = {"logs": []}
    for run, log in zip(manifest, logs):
        walls = os.path.join(out, run["stem"] + "_walls.csv")
        result = subprocess.run(command + ["--log", log, "--walls", walls], check=True,
                                capture_output=True, text=True)
        report["logs"] += json.loads(result.stdout)["logs"]
    return report, time.perf_counter() - started


def error_of(emitter):
    """The method's error: probability-weighted over its hypotheses (inf when unsolved)."""
    kpis = emitter.get("kpis", {})
    value = kpis.get("expected_error_m")
    return math.inf if value is None else float(value)


def summarise(manifest, report):
    rows = {}
    for run, log in zip(manifest, report["logs"]):
        for emitter in log["emitters"]:
            key = (run["path"], emitter["method"])
            row = rows.setdefault(key, {"errors": [], "first": [], "inside": 0, "runs": 0,
                                        "ambiguous": 0, "levels": []})
            row["runs"] += 1
            row["errors"].append(error_of(emitter))
            row["first"].append(float(emitter["kpis"]["error_m"] or math.inf)
                                if emitter.get("kpis") else math.inf)
            row["inside"] += 1 if emitter.get("kpis", {}).get("in_region") else 0
            row["ambiguous"] += 1 if emitter.get("ambiguous") else 0
            level = emitter.get("kpis", {}).get("credible_level")
            if level is not None:
                row["levels"].append(float(level))
    return rows


def mean(values):
    finite = [v for v in values if math.isfinite(v)]
    return sum(finite) / len(finite) if finite else math.inf


def median(values):
    ordered = sorted(values)
    n = len(ordered)
    return (ordered[n // 2] if n % 2 else 0.5 * (ordered[n // 2 - 1] + ordered[n // 2])) if n else math.inf


def wilson(successes, n, z=1.96):
    """95 % Wilson interval of a proportion."""
    if n == 0:
        return (0.0, 1.0)
    p = successes / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return (centre - half, centre + half)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rigdesign")
    parser.add_argument("--runs-per-path", type=int, default=50)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", help="keep the generated logs here (default: a temporary folder)")
    parser.add_argument("--json", help="write the summary as JSON here")
    parser.add_argument("--with-walls", action="store_true",
                        help="give the range fit each log's wall map (--walls)")
    parser.add_argument("--extra", nargs=argparse.REMAINDER, default=[],
                        help="further arguments for rigdesign localize")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as temporary:
        out = args.out or temporary
        os.makedirs(out, exist_ok=True)
        manifest = generate(out, args.runs_per_path, args.seed)
        report, seconds = localize(args.rigdesign, out, manifest, merged_truth(out, manifest),
                                   args.extra, args.with_walls)
    rows = summarise(manifest, report)
    paths = sorted({run["path"] for run in manifest}, key=["loop", "corner", "room", "hallway"].index)
    print(f"{len(manifest)} logs ({args.runs_per_path} per path, seed {args.seed}"
          f"{', wall maps given' if args.with_walls else ''}); "
          f"rigdesign localize --method all took {seconds:.1f} s")
    print(f"{'path':8} {'method':6} {'runs':>4} {'mean m':>8} {'median m':>8} {'first mean':>10} "
          f"{'in 95 %':>8} {'ambiguous':>9}")
    summary = {"runs_per_path": args.runs_per_path, "seed": args.seed, "classes": {}}
    totals = {m: {"errors": [], "inside": 0, "runs": 0, "levels": []} for m in METHODS}
    for path in paths:
        for method in METHODS:
            row = rows[(path, method)]
            totals[method]["errors"] += row["errors"]
            totals[method]["inside"] += row["inside"]
            totals[method]["runs"] += row["runs"]
            totals[method]["levels"] += row["levels"]
            print(f"{path:8} {method:6} {row['runs']:4d} {mean(row['errors']):8.2f} "
                  f"{median(row['errors']):8.2f} {mean(row['first']):10.2f} "
                  f"{row['inside']:4d}/{row['runs']:<3d} {row['ambiguous']:9d}")
            summary["classes"].setdefault(path, {})[method] = {
                "mean_m": mean(row["errors"]), "median_m": median(row["errors"]),
                "first_mean_m": mean(row["first"]), "in_region": row["inside"],
                "runs": row["runs"], "ambiguous": row["ambiguous"]}
    # Two measures of nls's error against WLS's (one estimate, so both are the same for WLS):
    # its point estimate (the first hypothesis, what a user acts on and what the issue measured)
    # and the probability-weighted error over all its hypotheses (stricter: a far hypothesis
    # with 20 % counts a fifth of its distance even when the first one is right).
    print()
    print(f"{'':8} nls / wls mean error: {'point estimate':>14} {'weighted':>9}  target")
    firsts = []
    for path in paths:
        wls = mean(rows[(path, "wls")]["errors"])
        point = mean(rows[(path, "nls")]["first"]) / wls
        weighted = mean(rows[(path, "nls")]["errors"]) / wls
        firsts += rows[(path, "nls")]["first"]
        print(f"{path:8} {'':21} {point:14.2f} {weighted:9.2f}  <= 1.10")
        summary["classes"][path]["nls_over_wls"] = {"point": point, "weighted": weighted}
    wls_all = mean(totals["wls"]["errors"])
    overall = {"point": mean(firsts) / wls_all, "weighted": mean(totals["nls"]["errors"]) / wls_all}
    print(f"{'all':8} {'':21} {overall['point']:14.2f} {overall['weighted']:9.2f}  <= 0.60")
    summary["nls_over_wls"] = overall
    for method in METHODS:
        inside, runs = totals[method]["inside"], totals[method]["runs"]
        low, high = wilson(inside, runs)
        print(f"{method}: truth in the stated 95 % region in {inside}/{runs} = "
              f"{100.0 * inside / runs:.1f} % (95 % interval {100 * low:.1f}-{100 * high:.1f} %)")
        summary.setdefault("coverage", {})[method] = inside / runs
        levels = totals[method]["levels"]
        if levels:
            # Calibrated regions hold the truth at level q in a share q of the runs.
            shares = {q: sum(1 for v in levels if v <= q) / len(levels) for q in (0.5, 0.9, 0.95)}
            print("   truth within the highest-density region of " + ", ".join(
                f"{int(100 * q)} %: {100 * share:.1f} %" for q, share in shares.items()))
            summary.setdefault("calibration", {})[method] = shares
    if args.json:
        with open(args.json, "w", newline="\n") as f:
            json.dump(summary, f, indent=2)


if __name__ == "__main__":
    main()
