#!/usr/bin/env python3
"""Issue 33's check: on logs of the frozen independent generator (scripts/localize/
frozen_rssi_generator.py, written without reading the estimator, seeds frozen before any tuning),
the range fit's first hypothesis is on average no worse than 1.1 times paper 4's WLS on the same
logs, for the two classes that failed before: a loop 10-15 m round the phone, and a phone inside
a walled room the path circles.

Usage: frozen_bound_test.py RIGDESIGN SOURCE_DIR

Seeds 101-120 (loop) and 101-110 (room): the frozen set's first seeds, not chosen by the result
(the full 50 per class are reported in docs/localize.md; a sanitised build takes ~6 s per log).
The bound 1.1 is the issue's target, not a measured value.
"""
import json
import os
import subprocess
import sys
import tempfile

BOUND = 1.10
CASES = {"loop_far": range(101, 121), "walled_room": range(101, 111)}


def error_of(binary, base, method):
    """The reported estimate's error [m] for `method`, None when the method finds none."""
    command = [binary, "localize", "--log", base + "_rssi.csv", "--truth", base + "_truth.csv",
               "--walls", base + "_walls.csv", "--method", method, "--checkpoints", "0",
               "--json"]
    done = subprocess.run(command, capture_output=True, text=True, check=True)
    emitters = [e for log in json.loads(done.stdout)["logs"] for e in log["emitters"]]
    return emitters[0]["kpis"]["error_m"] if emitters else None


def main(binary, source_dir):
    sys.path.insert(0, os.path.join(source_dir, "scripts", "localize"))
    import frozen_rssi_generator as generator  # noqa: E402  (the frozen generator)
    failures = []
    with tempfile.TemporaryDirectory(prefix="frozen_bound_") as folder:
        for cls, seeds in CASES.items():
            stems = generator.generate([(cls, seed) for seed in seeds], folder)
            pairs = []
            for stem in stems:
                base = os.path.join(folder, stem)
                wls, nls = error_of(binary, base, "wls"), error_of(binary, base, "nls")
                if wls is None:  # nothing to compare with: WLS found no position
                    continue
                if nls is None:
                    failures.append(f"{stem}: the range fit found no position, WLS did")
                    continue
                pairs.append((wls, nls))
            wls_mean = sum(w for w, _ in pairs) / len(pairs)
            nls_mean = sum(n for _, n in pairs) / len(pairs)
            ratio = nls_mean / wls_mean
            print(f"{cls}: {len(pairs)} logs, WLS mean {wls_mean:.2f} m, range fit {nls_mean:.2f} m,"
                  f" ratio {ratio:.3f} (bound {BOUND})")
            if ratio > BOUND:
                failures.append(f"{cls}: ratio {ratio:.3f} above {BOUND}")
    for failure in failures:
        print("FAIL " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
