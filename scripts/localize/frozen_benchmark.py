#!/usr/bin/env python3
"""Score `rigdesign localize` on the frozen validation set (frozen_rssi_generator.py).

Usage:
  frozen_benchmark.py RIGDESIGN_BINARY [--out DIR] [--json FILE] [--no-walls] [--calibrated-wls]
                      [--extra ARG ...]

Generates the 250 frozen logs (5 classes x seeds 101-150) into a temporary directory (or
--out), runs for each
  RIGDESIGN localize --log <stem>_rssi.csv --truth <stem>_truth.csv
                     --walls <stem>_walls.csv --method all --json [extra args]
(the wall map is passed: the robot team is assumed to have one; --no-walls omits it) and
reads logs[*].emitters[*]: method (wls, nls, map), kpis.error_m (the reported estimate's
error), kpis.nearest_hypothesis_error_m and kpis.in_region (truth in the 95 % region; may be
null).  A missing emitter or a null error counts as "no solution", separately from the mean.

--calibrated-wls adds paper 4's WLS at its best, "wls_cal": the level and exponent calibrated
on the log itself with its truth (`localize --calibrate`, wall map included), then
`--method wls --rssi-at-1m A --exponent N`. An unusable fit (an exponent outside the tool's
[0.5, 10], a singular or degenerate fit) makes `--calibrate` exit 2: that log is recorded as
"calibration refused" and counts as unsolved for wls_cal. Calibrating on
the very log it then solves is an oracle no field team has; it bounds the paper's method from
above rather than reproducing the thesis's per-environment calibration.

Everything after --extra is passed to the tool unchanged (so it must come last), e.g.
  frozen_benchmark.py build/rel/src/rigdesign --extra --cutoff -90
This set is for reporting, not tuning: see the generator's docstring.
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import frozen_rssi_generator as gen  # noqa: E402  (sibling script, standard library only)

METHODS = ["wls", "nls", "map"]
CALIBRATED = "wls_cal"


def parse_args(argv):
    """Hand-rolled so that --extra can swallow arguments that themselves start with '--'."""
    usage = __doc__.split("\n\n")[1]
    extra = []
    if "--extra" in argv:
        k = argv.index("--extra")
        argv, extra = argv[:k], argv[k + 1:]
    opts = {"binary": None, "out": None, "json": None, "walls": True, "calibrated": False}
    it = iter(argv)
    for a in it:
        if a in ("--out", "--json"):
            v = next(it, None)
            if v is None:
                sys.exit(f"{a} needs a value\n{usage}")
            opts[a[2:]] = v
        elif a == "--no-walls":
            opts["walls"] = False
        elif a == "--calibrated-wls":
            opts["calibrated"] = True
        elif a in ("-h", "--help"):
            print(__doc__)
            sys.exit(0)
        elif a.startswith("-") or opts["binary"]:
            sys.exit(f"unexpected argument {a!r}\n{usage}")
        else:
            opts["binary"] = a
    if not opts["binary"]:
        sys.exit(usage)
    opts["extra"] = extra
    return opts


def run_log(binary, directory, stem, walls, extra):
    """One tool call; returns {method: {error, nearest, in_region}} plus notes on oddities."""
    base = os.path.join(directory, stem)
    cmd = [binary, "localize", "--log", base + "_rssi.csv", "--truth", base + "_truth.csv"]
    if walls:
        cmd += ["--walls", base + "_walls.csv"]
    cmd += ["--method", "all", "--json"] + extra
    proc = subprocess.run(cmd, capture_output=True, text=True)
    notes, result = [], {}
    if proc.returncode != 0:
        notes.append(f"exit {proc.returncode}: {proc.stderr.strip()[:200]}")
        return result, notes
    try:
        doc = json.loads(proc.stdout)
    except json.JSONDecodeError as e:
        notes.append(f"bad JSON: {e}")
        return result, notes
    emitters = [e for log in doc.get("logs", []) for e in log.get("emitters", [])]
    if not emitters:
        notes.append("no emitter reported (never heard?)")
    for e in emitters:
        k = e.get("kpis") or {}
        m = e.get("method")
        if m in result:
            notes.append(f"two {m} emitters (kept the first)")
            continue
        result[m] = {"error": k.get("error_m"), "nearest": k.get("nearest_hypothesis_error_m"),
                     "in_region": k.get("in_region"),
                     "hypotheses": len(e.get("hypotheses") or []),
                     "heard_share": k.get("heard_share"), "used": e.get("used")}
        if k.get("heard_share") == 0:
            notes.append(f"{m}: heard_share 0")
    for m in METHODS:
        if result.get(m, {}).get("error") is None:
            notes.append(f"{m}: no solution")
    return result, notes


def run_calibrated_wls(binary, directory, stem, walls):
    """Paper 4's WLS with the level and exponent calibrated on this log and its truth."""
    base = os.path.join(directory, stem)
    common = ["--log", base + "_rssi.csv", "--truth", base + "_truth.csv", "--json"]
    if walls:
        common += ["--walls", base + "_walls.csv"]
    proc = subprocess.run([binary, "localize", "--calibrate"] + common,
                          capture_output=True, text=True)
    unsolved = {"error": None, "nearest": None, "in_region": None}
    if proc.returncode == 2:  # a singular or unusable fit (an exponent outside [0.5, 10])
        return dict(unsolved, refused=True), [
            "calibration refused: " + proc.stderr.strip().splitlines()[0]]
    if proc.returncode != 0:
        return unsolved, [f"calibration exit {proc.returncode}"]
    fit = json.loads(proc.stdout)["calibrations"][0]
    level, exponent = fit["rssi_at_1m_dbm"], fit["exponent"]
    notes = []
    proc = subprocess.run([binary, "localize", "--method", "wls", "--rssi-at-1m", f"{level:.4f}",
                           "--exponent", f"{exponent:.4f}"] + common,
                          capture_output=True, text=True)
    if proc.returncode != 0:  # e.g. a binary older than the refusal of unusable fits
        return unsolved, [f"calibrated wls exit {proc.returncode}: {proc.stderr.strip()[:200]}"]
    emitters = [e for log in json.loads(proc.stdout).get("logs", []) for e in log["emitters"]]
    k = (emitters[0].get("kpis") or {}) if emitters else {}
    return {"error": k.get("error_m"), "nearest": k.get("nearest_hypothesis_error_m"),
            "in_region": k.get("in_region")}, notes


def summarise(rows):
    """Numbers for one group of logs: per method mean/median/unsolved, nls/wls, nls region."""
    out = {}
    for m in METHODS:
        errs = [r[m]["error"] for r in rows if r.get(m, {}).get("error") is not None]
        near = [r[m]["nearest"] for r in rows if r.get(m, {}).get("nearest") is not None]
        out[m] = {"solved": len(errs), "unsolved": len(rows) - len(errs),
                  "mean_m": statistics.mean(errs) if errs else None,
                  "median_m": statistics.median(errs) if errs else None,
                  "nearest_mean_m": statistics.mean(near) if near else None}
    cal = [r[CALIBRATED]["error"] for r in rows
           if r.get(CALIBRATED, {}).get("error") is not None]
    if cal or any(CALIBRATED in r for r in rows):
        out[CALIBRATED] = {"solved": len(cal), "unsolved": len(rows) - len(cal),
                           "refused": sum(1 for r in rows if r.get(CALIBRATED, {}).get("refused")),
                           "mean_m": statistics.mean(cal) if cal else None,
                           "median_m": statistics.median(cal) if cal else None}
        paired = [r for r in rows if r.get(CALIBRATED, {}).get("error") is not None
                  and r.get("nls", {}).get("error") is not None]
        out["nls_wls_cal_ratio"] = (
            statistics.mean(r["nls"]["error"] for r in paired)
            / statistics.mean(r[CALIBRATED]["error"] for r in paired)) if paired else None
    # ratio of means over the logs both wls and nls solved (a fair pairing)
    both = [r for r in rows if r.get("wls", {}).get("error") is not None
            and r.get("nls", {}).get("error") is not None]
    out["nls_wls_ratio"] = (statistics.mean(r["nls"]["error"] for r in both)
                            / statistics.mean(r["wls"]["error"] for r in both)
                            if both and any(r["wls"]["error"] for r in both) else None)
    out["paired_logs"] = len(both)
    # share of logs with truth in nls's region; a null in_region is left out of the share
    flags = [r["nls"]["in_region"] for r in rows
             if r.get("nls", {}).get("in_region") is not None]
    out["nls_in_region"] = sum(1 for f in flags if f)
    out["nls_region_known"] = len(flags)
    out["nls_in_region_share"] = out["nls_in_region"] / len(flags) if flags else None
    out["logs"] = len(rows)
    return out


def fmt(v, spec="6.2f"):
    return format(v, spec) if v is not None else " " * (int(spec.split(".")[0]) - 1) + "-"


def print_table(groups):
    head = f"{'class':<14}{'logs':>5}"
    for m in METHODS:
        head += f" | {m + ' mean':>9}{'median':>8}{'unsol':>6}"
    head += f" | {'nls/wls':>8} | {'nls in 95%':>11}"
    print(head)
    print("-" * len(head))
    for name, s in groups:
        line = f"{name:<14}{s['logs']:>5}"
        for m in METHODS:
            line += (f" | {fmt(s[m]['mean_m'], '9.2f')}{fmt(s[m]['median_m'], '8.2f')}"
                     f"{s[m]['unsolved']:>6}")
        share = (f"{s['nls_in_region']}/{s['nls_region_known']}"
                 f" {100 * s['nls_in_region_share']:3.0f}%"
                 if s["nls_in_region_share"] is not None else "-")
        line += f" | {fmt(s['nls_wls_ratio'], '8.2f')} | {share:>11}"
        print(line)


def main(argv):
    o = parse_args(argv)
    t0 = time.monotonic()
    tmp = None
    directory = o["out"]
    if directory is None:
        tmp = tempfile.TemporaryDirectory(prefix="frozen_rssi_")
        directory = tmp.name
    stems = gen.generate(gen.frozen_jobs(), directory)  # prints one line per log
    print()
    per_log, oddities = {}, []
    for stem in stems:
        result, notes = run_log(o["binary"], directory, stem, o["walls"], o["extra"])
        if o["calibrated"]:
            result[CALIBRATED], cal_notes = run_calibrated_wls(o["binary"], directory, stem,
                                                               o["walls"])
            notes += cal_notes
        per_log[stem] = result
        oddities += [f"{stem}: {n}" for n in notes]
    groups = []
    for cls in gen.CLASSES:
        rows = [per_log[s] for s in stems if s.startswith(cls + "_")]
        groups.append((cls, summarise(rows)))
    groups.append(("overall", summarise(list(per_log.values()))))
    walls_note = "with wall maps" if o["walls"] else "without wall maps (--no-walls)"
    print(f"frozen set, {len(stems)} logs, {walls_note}; errors in m over solved logs;"
          f" nls/wls = ratio of means over logs both solved")
    print_table(groups)
    if o["calibrated"]:
        print(f"\n{'class':<14} | wls_cal mean  median unsol refused | nls/wls_cal")
        for name, g in groups:
            c = g[CALIBRATED]
            print(f"{name:<14} | {fmt(c['mean_m'], '12.2f')}{fmt(c['median_m'], '8.2f')}"
                  f"{c['unsolved']:>6}{c['refused']:>8} | {fmt(g['nls_wls_cal_ratio'], '11.2f')}")
    elapsed = time.monotonic() - t0
    print(f"\n{len(oddities)} notes" + (":" if oddities else ""))
    for n in oddities:
        print("  " + n)
    print(f"run time {elapsed:.1f} s")
    if o["json"]:
        with open(o["json"], "w") as f:
            json.dump({"walls": o["walls"], "extra": o["extra"], "run_time_s": elapsed,
                       "classes": dict(groups), "logs": per_log, "notes": oddities},
                      f, indent=1)
    if tmp:
        tmp.cleanup()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
