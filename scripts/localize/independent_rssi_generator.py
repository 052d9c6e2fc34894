#!/usr/bin/env python3
"""Independent synthetic Wi-Fi RSSI log generator (Python 3 standard library only).

Written from the physics alone, sharing nothing with the localisation tool it
tests, so a bug in the tool cannot hide behind the same bug here.

Model
-----
A phone (Wi-Fi hotspot) stands still at (px, py, 1.0 m).  A robot whose antenna
is at z = 0.35 m drives a polyline and scans once per step (0.1 m, 1 Hz by
default).  For a true robot position p the reading is

    rssi = A - 10 n log10(max(d, 0.1)) - wall_loss + S(p) + F

  d          3D distance antenna -> phone,
  wall_loss  sum of the attenuations of all wall segments that the 2D line
             robot -> phone crosses,
  S          stationary Gaussian shadowing field, std sigma_s, covariance
             sigma_s^2 exp(-|delta| / L), from M = 800 random Fourier features
             (fixed per run, so a revisited place sees the same shadowing),
  F          independent Gaussian fast fading per scan, std sigma_f.
The value is rounded to whole dBm; below the receiver floor it is not heard.
The logged x, y carry N(0, 0.05^2) noise; z is logged as 0.35.

Files (in --out DIR, stem from --name)
--------------------------------------
<stem>_rssi.csv   optional first line "# floor_dbm: -95", then
                  "t,x,y,z,bssid,rssi"; with --unheard rows an unheard scan is a
                  line with an empty rssi field, with --unheard drop it is left out.
<stem>_truth.csv  "bssid,x,y,z": the phone.
<stem>_walls.csv  "x1,y1,x2,y2,attenuation_db" (header only when no walls).
manifest.csv      matrix mode only: one line per run with its drawn parameters.
"""
import argparse
import math
import os
import random
import sys

TWO_PI = 2.0 * math.pi
ANTENNA_Z = 0.35
PHONE_Z = 1.0
MIN_DISTANCE_M = 0.1
POSITION_NOISE_M = 0.05
FIELD_TERMS = 800
LOOP_CENTRE = (0.0, 0.0)
LOOP_RADIUS_M = 12.0
LOOP_STOP_M = 5.0
WALL_DB = 8.0
DOOR_DB = 3.0
PATHS = ("loop", "corner", "room", "hallway")
MANIFEST_HEADER = ("run,path,stem,bssid,phone_x,phone_y,phone_z,level_dbm,exponent,"
                   "shadowing_db,correlation_m,fading_db,floor_dbm,floor_comment,"
                   "unheard,readings,heard")


def fmt(value):
    """Write a number with at most 4 decimals and no trailing zeros; never '-0'."""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def bssid_for(index):
    """Build a locally administered MAC whose last three bytes encode the run index."""
    return "02:00:00:" + ":".join(f"{(index >> s) & 255:02x}" for s in (16, 8, 0))


def sample_wavenumber(corr_m, rng):
    """Draw |k| from the radial spectral density k (1 + L^2 k^2)^-3/2 of the 2D
    exponential covariance by inverting its CDF 1 - (1 + L^2 k^2)^-1/2."""
    u = rng.random()
    return math.sqrt(1.0 / (1.0 - u) ** 2 - 1.0) / corr_m


class ShadowField:
    """Stationary Gaussian shadowing S(x, y) built from random Fourier features.

    The features are drawn once per run, so S is a function of place only: the
    robot sees the same shadowing each time it passes a spot, unlike fading."""

    def __init__(self, sigma_db, corr_m, rng, terms=FIELD_TERMS):
        self.amp = sigma_db * math.sqrt(2.0 / terms)
        self.features = []
        for _ in range(terms):
            k = sample_wavenumber(corr_m, rng)
            direction = rng.random() * TWO_PI
            phase = rng.random() * TWO_PI
            self.features.append((k * math.cos(direction), k * math.sin(direction), phase))

    def __call__(self, x, y):
        return self.amp * sum(math.cos(kx * x + ky * y + ph) for kx, ky, ph in self.features)


def crosses(p, q, wall):
    """Whether segment p -> q crosses the wall segment a -> b.

    The wall parameter is half-open [0, 1) so two walls sharing a vertex (drawn
    head to tail) count a ray through that vertex once, not twice."""
    ax, ay, bx, by, _ = wall
    rx, ry = q[0] - p[0], q[1] - p[1]
    sx, sy = bx - ax, by - ay
    denom = rx * sy - ry * sx
    if abs(denom) < 1e-12:
        return False
    wx, wy = ax - p[0], ay - p[1]
    t = (wx * sy - wy * sx) / denom
    u = (wx * ry - wy * rx) / denom
    return 0.0 < t < 1.0 and 0.0 <= u < 1.0


def wall_loss(p, q, walls):
    """Total attenuation of the walls between robot and phone (each crossing counts)."""
    return sum(w[4] for w in walls if crosses(p, q, w))


def path_loss_rssi(robot, phone, level, exponent, walls):
    """Deterministic part of the reading: log-distance loss plus wall losses."""
    d = math.sqrt((robot[0] - phone[0]) ** 2 + (robot[1] - phone[1]) ** 2
                  + (ANTENNA_Z - PHONE_Z) ** 2)
    d = max(d, MIN_DISTANCE_M)
    return level - 10.0 * exponent * math.log10(d) - wall_loss(robot, phone, walls)


def layout_loop(rng, step):
    """One CCW circle (r = 12 m, from angle 0) then straight at the phone until 5 m away."""
    r, a = 3.0 * math.sqrt(rng.random()), rng.random() * TWO_PI
    cx, cy = LOOP_CENTRE
    phone = (cx + r * math.cos(a), cy + r * math.sin(a))
    n = max(3, round(TWO_PI * LOOP_RADIUS_M / step))
    verts = [(cx + LOOP_RADIUS_M * math.cos(TWO_PI * i / n),
              cy + LOOP_RADIUS_M * math.sin(TWO_PI * i / n)) for i in range(n)]
    start = (cx + LOOP_RADIUS_M, cy)
    verts.append(start)
    dx, dy = phone[0] - start[0], phone[1] - start[1]
    frac = (math.hypot(dx, dy) - LOOP_STOP_M) / math.hypot(dx, dy)
    verts.append((start[0] + frac * dx, start[1] + frac * dy))
    return phone, verts, []


def layout_corner(rng, step):
    """L corridor around a block; the phone is inside the block behind two walls."""
    phone = (rng.uniform(-6.0, -1.0), rng.uniform(3.0, 15.0))
    walls = [(-20.0, 0.8, -0.8, 0.8, WALL_DB), (-0.8, 0.8, -0.8, 20.0, WALL_DB)]
    return phone, [(-20.0, 0.0), (0.0, 0.0), (0.0, 20.0)], walls


def layout_room(rng, step):
    """Corridor past a closed room (with a weaker door) that holds the phone."""
    phone = (rng.uniform(-2.5, 2.5), rng.uniform(2.5, 7.5))
    walls = [(-3.0, 2.0, -0.5, 2.0, WALL_DB), (-0.5, 2.0, 0.5, 2.0, DOOR_DB),
             (0.5, 2.0, 3.0, 2.0, WALL_DB), (3.0, 2.0, 3.0, 8.0, WALL_DB),
             (3.0, 8.0, -3.0, 8.0, WALL_DB), (-3.0, 8.0, -3.0, 2.0, WALL_DB)]
    return phone, [(-15.0, 0.0), (10.0, 0.0), (10.0, 12.0)], walls


def layout_hallway(rng, step):
    """Straight hallway; the phone is 2-6 m to one side, side chosen by a coin."""
    x, dist = rng.uniform(-10.0, 10.0), rng.uniform(2.0, 6.0)
    side = 1.0 if rng.random() < 0.5 else -1.0
    return (x, side * dist), [(-20.0, 0.0), (20.0, 0.0)], []


LAYOUTS = {"loop": layout_loop, "corner": layout_corner,
           "room": layout_room, "hallway": layout_hallway}


def walk(vertices, step):
    """Sample a polyline at (about) constant spacing, keeping every corner exactly."""
    points = []
    for (ax, ay), (bx, by) in zip(vertices, vertices[1:]):
        length = math.hypot(bx - ax, by - ay)
        if length < 1e-12:
            continue
        n = max(1, round(length / step))
        points.extend((ax + (bx - ax) * i / n, ay + (by - ay) * i / n) for i in range(n))
    points.append(vertices[-1])
    return points


def simulate(path, seed, prm):
    """Run one drive; returns (phone, walls, rows) with rows (t, x_log, y_log, rssi|None).

    Separate named streams keep e.g. the field unchanged when only fading changes."""
    rng = {k: random.Random(f"{seed}:{k}") for k in ("phone", "field", "fading", "noise")}
    phone, vertices, walls = LAYOUTS[path](rng["phone"], prm["step_m"])
    field = ShadowField(prm["shadowing_db"], prm["correlation_m"], rng["field"])
    rows = []
    for i, (x, y) in enumerate(walk(vertices, prm["step_m"])):
        value = (path_loss_rssi((x, y), phone, prm["level_dbm"], prm["exponent"], walls)
                 + field(x, y) + rng["fading"].gauss(0.0, prm["fading_db"]))
        rssi = math.floor(value + 0.5)
        x_log = x + rng["noise"].gauss(0.0, POSITION_NOISE_M)
        y_log = y + rng["noise"].gauss(0.0, POSITION_NOISE_M)
        rows.append((i / prm["rate_hz"], x_log, y_log, rssi if rssi >= prm["floor_dbm"] else None))
    return phone, walls, rows


def write_lines(path, lines):
    """Write LF-terminated lines so output bytes do not depend on the platform."""
    with open(path, "w", newline="\n", encoding="ascii") as fh:
        fh.write("".join(line + "\n" for line in lines))


def write_run(out_dir, stem, bssid, prm, phone, walls, rows):
    """Write the three per-run CSV files; returns (readings, heard)."""
    lines = [f"# floor_dbm: {fmt(prm['floor_dbm'])}"] if prm["floor_comment"] else []
    lines.append("t,x,y,z,bssid,rssi")
    for t, x, y, rssi in rows:
        if rssi is None and prm["unheard"] == "drop":
            continue
        lines.append(f"{fmt(t)},{fmt(x)},{fmt(y)},{fmt(ANTENNA_Z)},{bssid},"
                     + ("" if rssi is None else str(rssi)))
    write_lines(os.path.join(out_dir, f"{stem}_rssi.csv"), lines)
    write_lines(os.path.join(out_dir, f"{stem}_truth.csv"),
                ["bssid,x,y,z", f"{bssid},{fmt(phone[0])},{fmt(phone[1])},{fmt(PHONE_Z)}"])
    write_lines(os.path.join(out_dir, f"{stem}_walls.csv"),
                ["x1,y1,x2,y2,attenuation_db"] + [",".join(fmt(v) for v in w) for w in walls])
    return len(rows), sum(1 for r in rows if r[3] is not None)


def draw_matrix_params(seed, run):
    """Draw one run's parameters from its own stream (reproducible, independent runs).

    Values are rounded to 4 decimals before use so the manifest states them exactly."""
    rng = random.Random(f"{seed}:matrix:{run}")
    return {"exponent": round(rng.uniform(2.0, 3.5), 4),
            "shadowing_db": round(rng.uniform(3.0, 8.0), 4),
            "correlation_m": round(math.exp(rng.uniform(math.log(0.5), math.log(5.0))), 4),
            "fading_db": round(rng.uniform(0.0, 4.0), 4),
            "level_dbm": round(rng.uniform(-48.0, -38.0), 4),
            "floor_dbm": -95.0,
            "floor_comment": rng.random() < 0.5,
            "unheard": "rows" if rng.random() < 0.5 else "drop",
            "step_m": 0.1, "rate_hz": 1.0}


def run_matrix(args):
    """Write RUNS_PER_PATH runs for each path class plus manifest.csv."""
    paths = [p.strip() for p in args.paths.split(",") if p.strip()]
    bad = [p for p in paths if p not in LAYOUTS]
    if bad:
        sys.exit(f"unknown path(s): {', '.join(bad)}")
    os.makedirs(args.out, exist_ok=True)
    manifest, run = [MANIFEST_HEADER], 0
    for path in paths:
        for _ in range(args.matrix):
            run += 1
            prm, stem, bssid = draw_matrix_params(args.seed, run), f"{path}_{run:03d}", bssid_for(run)
            phone, walls, rows = simulate(path, f"{args.seed}:run:{run}", prm)
            readings, heard = write_run(args.out, stem, bssid, prm, phone, walls, rows)
            values = [phone[0], phone[1], PHONE_Z, prm["level_dbm"], prm["exponent"],
                      prm["shadowing_db"], prm["correlation_m"], prm["fading_db"], prm["floor_dbm"]]
            manifest.append(",".join([str(run), path, stem, bssid] + [fmt(v) for v in values]
                                     + ["yes" if prm["floor_comment"] else "no", prm["unheard"],
                                        str(readings), str(heard)]))
    write_lines(os.path.join(args.out, "manifest.csv"), manifest)
    print(f"wrote {run} runs to {args.out}")


def run_single(args):
    """Write one run with the parameters given on the command line."""
    prm = {"level_dbm": args.level_dbm, "exponent": args.exponent,
           "shadowing_db": args.shadowing_db, "correlation_m": args.correlation_m,
           "fading_db": args.fading_db, "floor_dbm": args.floor_dbm,
           "floor_comment": args.floor_comment == "yes", "unheard": args.unheard,
           "step_m": args.step_m, "rate_hz": args.rate_hz}
    os.makedirs(args.out, exist_ok=True)
    stem = args.name or f"{args.path}_s{args.seed}"
    phone, walls, rows = simulate(args.path, str(args.seed), prm)
    readings, heard = write_run(args.out, stem, bssid_for(1), prm, phone, walls, rows)
    print(f"{stem}: phone=({fmt(phone[0])}, {fmt(phone[1])}) readings={readings} heard={heard}")


def self_check(sigma=6.0, corr=1.5, fields=200, pairs=200):
    """Estimate the ensemble variance and correlations at lags L and 2L of the
    shadowing field, plus a wall-geometry sanity check; returns True if all pass."""
    rng = random.Random("self-check")
    s00 = s01 = s02 = 0.0
    for _ in range(fields):
        field = ShadowField(sigma, corr, rng)
        for _ in range(pairs):
            x, y = rng.uniform(0, 200 * corr), rng.uniform(0, 200 * corr)
            a = rng.random() * TWO_PI
            v0 = field(x, y)
            v1 = field(x + corr * math.cos(a), y + corr * math.sin(a))
            v2 = field(x + 2 * corr * math.cos(a), y + 2 * corr * math.sin(a))
            s00, s01, s02 = s00 + v0 * v0, s01 + v0 * v1, s02 + v0 * v2
    n = fields * pairs
    var = s00 / n
    c1, c2 = s01 / n / var, s02 / n / var
    print(f"field: sigma_s={sigma} L={corr} fields={fields} samples={n}")
    print(f"  variance  {var:.3f}  expected {sigma ** 2:.3f}  ratio {var / sigma ** 2:.4f}")
    print(f"  corr(L)   {c1:.4f}  expected {math.exp(-1):.4f}")
    print(f"  corr(2L)  {c2:.4f}  expected {math.exp(-2):.4f}")
    ok = abs(var / sigma ** 2 - 1) < 0.1 and abs(c1 - math.exp(-1)) < 0.05 \
        and abs(c2 - math.exp(-2)) < 0.05
    # Geometry: from the corridor, a phone inside the closed room is behind exactly one wall.
    _, verts, walls = layout_room(rng, 0.1)
    corridor, counts = walk(verts, 0.1), set()
    for _ in range(2000):
        phone = (rng.uniform(-2.5, 2.5), rng.uniform(2.5, 7.5))
        robot = rng.choice(corridor)
        counts.add(sum(1 for w in walls if crosses(robot, phone, w)))
    print(f"room walls crossed from corridor to inside: {sorted(counts)} (expected [1])")
    ok = ok and counts == {1}
    print("self-check", "PASSED" if ok else "FAILED")
    return ok


def parse_args(argv):
    """Command-line interface: single run, matrix of runs, or self-check."""
    p = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    p.add_argument("--out")
    p.add_argument("--path", choices=PATHS)
    p.add_argument("--seed", type=int)
    p.add_argument("--name")
    p.add_argument("--level-dbm", type=float, default=-40.0)
    p.add_argument("--exponent", type=float, default=2.5)
    p.add_argument("--shadowing-db", type=float, default=6.0)
    p.add_argument("--correlation-m", type=float, default=1.5)
    p.add_argument("--fading-db", type=float, default=2.0)
    p.add_argument("--floor-dbm", type=float, default=-95.0)
    p.add_argument("--floor-comment", choices=("yes", "no"), default="yes")
    p.add_argument("--unheard", choices=("drop", "rows"), default="drop")
    p.add_argument("--step-m", type=float, default=0.1)
    p.add_argument("--rate-hz", type=float, default=1.0)
    p.add_argument("--matrix", type=int, metavar="RUNS_PER_PATH")
    p.add_argument("--paths", default=",".join(PATHS))
    p.add_argument("--self-check", action="store_true")
    args = p.parse_args(argv)
    if not args.self_check:
        if args.out is None or args.seed is None:
            p.error("--out and --seed are required")
        if args.matrix is None and args.path is None:
            p.error("--path is required unless --matrix is given")
        if args.correlation_m <= 0 or args.step_m <= 0 or args.rate_hz <= 0:
            p.error("--correlation-m, --step-m and --rate-hz must be positive")
    return args


def main(argv=None):
    """Dispatch to the requested mode."""
    args = parse_args(argv)
    if args.self_check:
        return 0 if self_check() else 1
    if args.matrix is not None:
        run_matrix(args)
    else:
        run_single(args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
