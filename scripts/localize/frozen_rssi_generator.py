#!/usr/bin/env python3
"""Frozen, independent validation set of Wi-Fi RSSI logs for `rigdesign localize`.

The set is FROZEN: its five classes and the seeds 101..150 were fixed on 2026-11-27,
before any tuning of the estimator against it (101..105 first; 106..150 added the same day,
before any estimator change was measured on them, so that a 95 % region's coverage can be
told from chance: 25 logs at a true 95 % give 25/25 in 28 % of sets).  Do not change the model, the classes,
the seeds or the order of random draws: that would silently make a new set.  Results are
reported on this set; it is not for tuning (tune on another generator).

It is written independently of the estimator and of the tool's other generator, with
deliberately different assumptions, so that a fit does not merely recover its own model.

Model (one emitter = one phone per log, one robot antenna on a path):
  rssi = A - 10 n log10(max(d, 0.2)) - walls + S(x, y) + fading
  * d: 3D distance antenna -> phone.  Per log A ~ U[-56, -34] dBm, n ~ U[1.7, 3.6].
  * S: spatially correlated shadowing, a bilinear interpolation of i.i.d. Gaussian values on
    a square lattice (spacing ~ U[1.5, 6] m, random offset), normalised so its marginal sd
    is the drawn sd ~ U[2, 9] dB everywhere; fixed per log (a revisited place sees the same
    value), evaluated at the antenna's true position.
  * walls: segments with a loss ~ U[3, 15] dB each; a reading loses the sum over walls the
    2D segment antenna -> phone crosses.
  * fading per scan: 10 log10(Exp(1)) (Rayleigh power, mean power 1, so a -2.5 dB mean in
    dB) clipped to [-20, +6] dB and scaled by a per-log factor ~ U[0.3, 1.0].
  * receiver floor per log ~ U[-97, -84] dBm: a reading below it is an unheard scan (empty
    rssi); heard values are rounded to whole dBm (and clipped at 0 dBm, the format's limit).
  * robot speed ~ U[0.3, 1.0] m/s, scan period ~ U[0.5, 2.0] s, antenna height
    ~ U[0.3, 0.5] m, phone height ~ U[0.5, 1.5] m; logged x, y carry N(0, 0.05^2) m noise,
    logged z is the antenna height.
  * every scene is finally rotated by a random angle and shifted by up to 50 m, so nothing
    can rely on axis-aligned walls or a phone near the origin.

Classes:
  loop_far       a circle or rounded rectangle of radius 10-15 m round the phone (within 2 m
                 of the centre), driven once or twice, then a straight approach to the phone
                 stopping 4-6 m short; no walls.
  walled_room    a 4-7 x 4-7 m room walled on all sides but a 0.8-1.2 m door gap; the path
                 circles it once 1.5-3 m outside; the phone inside, >= 0.5 m from the walls.
  l_corner       an L path (legs 15-25 m at 90 deg); the phone 3-8 m off both legs near the
                 inner corner; with 50 % chance two building walls between legs and phone.
  corridor_side  a straight path 30-45 m; the phone 2-4 m to one side in the middle 60 %.
  anywhere       a random polyline of 4-7 legs (6-15 m, random turns) in a 40 x 40 m area;
                 the phone uniform in the path's bounding box grown by 5 m; 0-4 walls 3-10 m.

Usage:
  frozen_rssi_generator.py --frozen OUT_DIR
  frozen_rssi_generator.py --class NAME --seed S --out DIR
Per log <stem> = <class>_<seed>: <stem>_rssi.csv, <stem>_truth.csv, <stem>_walls.csv, and
manifest.csv in the output directory.  Standard library only; deterministic (string seeds).
"""
import argparse
import csv
import math
import os
import random
import sys

CLASSES = ["loop_far", "walled_room", "l_corner", "corridor_side", "anywhere"]
FROZEN_SEEDS = list(range(101, 151))  # fixed 2026-11-27, before any tuning


# ---------------------------------------------------------------- geometry helpers
def arc(cx, cy, r, a0, a1, steps):
    """Points on a circular arc from angle a0 to a1 (inclusive), for polyline paths."""
    return [(cx + r * math.cos(a0 + (a1 - a0) * k / steps),
             cy + r * math.sin(a0 + (a1 - a0) * k / steps)) for k in range(steps + 1)]


def rounded_rect(hx, hy, r):
    """Closed counter-clockwise rounded rectangle (half sides hx, hy, corner radius r),
    starting at the right side's midpoint; the straight sides come from joining the arcs."""
    pts = [(hx, 0.0)]
    corners = [(hx - r, hy - r, 0.0), (-hx + r, hy - r, 0.5 * math.pi),
               (-hx + r, -hy + r, math.pi), (hx - r, -hy + r, 1.5 * math.pi)]
    for cx, cy, a in corners:
        pts += arc(cx, cy, r, a, a + 0.5 * math.pi, 8)
    pts.append((hx, 0.0))
    return pts


def rotate_start(loop, k):
    """Same closed loop (first point == last) started at its k-th vertex."""
    core = loop[:-1]
    k %= len(core)
    core = core[k:] + core[:k]
    return core + [core[0]]


def segments_cross(p, q, a, b):
    """True when 2D segments p-q and a-b properly intersect (orientation test).
    Touching at an end point counts as crossing; collinear overlap does not (measure 0)."""
    def orient(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])
    d1, d2 = orient(a, b, p), orient(a, b, q)
    d3, d4 = orient(p, q, a), orient(p, q, b)
    return d1 * d2 <= 0 and d3 * d4 <= 0 and not (d1 == d2 == 0)


def resample(path, step):
    """Points every `step` metres of arc length along the polyline (the scan positions)."""
    out, carry = [path[0]], 0.0
    for (x0, y0), (x1, y1) in zip(path, path[1:]):
        seg = math.hypot(x1 - x0, y1 - y0)
        s = step - carry
        while s <= seg + 1e-9:
            f = s / seg
            out.append((x0 + f * (x1 - x0), y0 + f * (y1 - y0)))
            s += step
        carry = seg - (s - step)
    return out


# ---------------------------------------------------------------- shadowing field
class Shadowing:
    """Bilinear interpolation of i.i.d. N(0, 1) lattice values, scaled to sd.
    Lattice values are drawn lazily from their own string-seeded RNG per node, so a value
    does not depend on the order the path visits places.  Dividing by sqrt(sum w^2) keeps
    the marginal sd equal to `sd` everywhere (plain bilinear would halve it at cell centres)
    while keeping the field continuous."""

    def __init__(self, sd, spacing, ox, oy, key):
        self.sd, self.h, self.ox, self.oy, self.key = sd, spacing, ox, oy, key
        self.nodes = {}

    def node(self, i, j):
        if (i, j) not in self.nodes:
            self.nodes[(i, j)] = random.Random(f"{self.key}:{i}:{j}").gauss(0.0, 1.0)
        return self.nodes[(i, j)]

    def __call__(self, x, y):
        u, v = (x - self.ox) / self.h, (y - self.oy) / self.h
        i, j = math.floor(u), math.floor(v)
        fu, fv = u - i, v - j
        w = [((1 - fu) * (1 - fv), i, j), (fu * (1 - fv), i + 1, j),
             ((1 - fu) * fv, i, j + 1), (fu * fv, i + 1, j + 1)]
        num = sum(wk * self.node(a, b) for wk, a, b in w)
        return self.sd * num / math.sqrt(sum(wk * wk for wk, _, _ in w))


# ---------------------------------------------------------------- classes
# Each returns (path polyline, walls [(x1, y1, x2, y2, dB)], phone (x, y)).
def loop_far(rng):
    if rng.random() < 0.5:
        r = rng.uniform(10, 15)
        loop = arc(0.0, 0.0, r, 0.0, 2 * math.pi, 72)
    else:
        hx, hy = rng.uniform(10, 15), rng.uniform(10, 15)
        loop = rounded_rect(hx, hy, rng.uniform(2, 5))
    loop = rotate_start(loop, rng.randrange(len(loop) - 1))
    if rng.random() < 0.5:
        loop = loop + loop[1:]  # driven twice
    # the phone within 2 m of the loop centre (uniform in the disc)
    rr, aa = 2.0 * math.sqrt(rng.random()), rng.uniform(0, 2 * math.pi)
    px, py = rr * math.cos(aa), rr * math.sin(aa)
    ex, ey = loop[-1]
    dist = math.hypot(px - ex, py - ey)
    stop = rng.uniform(4, 6)
    f = max(dist - stop, 0.0) / dist
    path = loop + [(ex + f * (px - ex), ey + f * (py - ey))]
    return path, [], (px, py)


def walled_room(rng):
    hw, hh = rng.uniform(4, 7) / 2, rng.uniform(4, 7) / 2
    corners = [(-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh)]
    door_side, gap = rng.randrange(4), rng.uniform(0.8, 1.2)
    walls = []
    for k in range(4):
        (x1, y1), (x2, y2) = corners[k], corners[(k + 1) % 4]
        db = rng.uniform(3, 15)  # one loss per side; the door side's two pieces share it
        if k != door_side:
            walls.append((x1, y1, x2, y2, db))
            continue
        length = math.hypot(x2 - x1, y2 - y1)
        s0 = rng.uniform(0.3, length - 0.3 - gap)  # gap start along the side
        f0, f1 = s0 / length, (s0 + gap) / length
        walls.append((x1, y1, x1 + f0 * (x2 - x1), y1 + f0 * (y2 - y1), db))
        walls.append((x1 + f1 * (x2 - x1), y1 + f1 * (y2 - y1), x2, y2, db))
    c = rng.uniform(1.5, 3.0)
    # the room's outline offset by c is a rounded rectangle with corner radius c
    loop = rounded_rect(hw + c, hh + c, c)
    loop = rotate_start(loop, rng.randrange(len(loop) - 1))
    phone = (rng.uniform(-hw + 0.5, hw - 0.5), rng.uniform(-hh + 0.5, hh - 0.5))
    return loop, walls, phone


def l_corner(rng):
    # leg 1 along +x ending at the corner (0, 0), leg 2 along +y; inner side is x < 0, y > 0
    l1, l2 = rng.uniform(15, 25), rng.uniform(15, 25)
    path = [(-l1, 0.0), (0.0, 0.0), (0.0, l2)]
    a, b = rng.uniform(3, 8), rng.uniform(3, 8)  # phone's distance from leg 2 and leg 1
    phone = (-a, b)
    walls = []
    if rng.random() < 0.5:
        # a building corner facing the path's corner: walls parallel to each leg between
        # the leg and the phone, meeting at (-o2, o1)
        o1, o2 = rng.uniform(1, b - 1), rng.uniform(1, a - 1)
        walls.append((-o2, o1, -o2 - rng.uniform(8, 15), o1, rng.uniform(3, 15)))
        walls.append((-o2, o1, -o2, o1 + rng.uniform(8, 15), rng.uniform(3, 15)))
    return path, walls, phone


def corridor_side(rng):
    length = rng.uniform(30, 45)
    side = rng.choice([-1.0, 1.0])
    phone = (rng.uniform(0.2, 0.8) * length, side * rng.uniform(2, 4))
    return [(0.0, 0.0), (length, 0.0)], [], phone


def anywhere(rng):
    x, y = rng.uniform(-15, 15), rng.uniform(-15, 15)
    heading = rng.uniform(0, 2 * math.pi)
    path = [(x, y)]
    for leg in range(rng.randint(4, 7)):
        length = rng.uniform(6, 15)
        for _ in range(50):  # redraw the turn until the leg stays inside the 40 x 40 m area
            h = heading + (rng.uniform(-0.75, 0.75) * math.pi if leg else 0.0)
            nx, ny = x + length * math.cos(h), y + length * math.sin(h)
            if abs(nx) <= 20 and abs(ny) <= 20:
                break
            heading = rng.uniform(0, 2 * math.pi)
        else:  # could not stay inside: head back to the centre instead
            h = math.atan2(-y, -x)
            nx, ny = x + length * math.cos(h), y + length * math.sin(h)
        x, y, heading = nx, ny, h
        path.append((x, y))
    xs, ys = [p[0] for p in path], [p[1] for p in path]
    box = (min(xs) - 5, max(xs) + 5, min(ys) - 5, max(ys) + 5)
    phone = (rng.uniform(box[0], box[1]), rng.uniform(box[2], box[3]))
    walls = []
    for _ in range(rng.randint(0, 4)):
        cx, cy = rng.uniform(box[0], box[1]), rng.uniform(box[2], box[3])
        half, a = rng.uniform(3, 10) / 2, rng.uniform(0, math.pi)
        dx, dy = half * math.cos(a), half * math.sin(a)
        walls.append((cx - dx, cy - dy, cx + dx, cy + dy, rng.uniform(3, 15)))
    return path, walls, phone


BUILDERS = {"loop_far": loop_far, "walled_room": walled_room, "l_corner": l_corner,
            "corridor_side": corridor_side, "anywhere": anywhere}


# ---------------------------------------------------------------- one log
def make_log(cls, seed):
    """Build one log in memory; the order of draws below is part of the frozen set."""
    rng = random.Random(f"{cls}:{seed}")
    p = {"A": rng.uniform(-56, -34), "n": rng.uniform(1.7, 3.6),
         "sd": rng.uniform(2, 9), "spacing": rng.uniform(1.5, 6),
         "fading": rng.uniform(0.3, 1.0), "floor": rng.uniform(-97, -84),
         "period": rng.uniform(0.5, 2.0), "speed": rng.uniform(0.3, 1.0),
         "ant_z": rng.uniform(0.3, 0.5)}
    path, walls, phone = BUILDERS[cls](rng)
    phone_z = rng.uniform(0.5, 1.5)
    # random rigid motion of the whole scene
    th, tx, ty = rng.uniform(0, 2 * math.pi), rng.uniform(-50, 50), rng.uniform(-50, 50)
    c, s = math.cos(th), math.sin(th)

    def move(x, y):
        return (c * x - s * y + tx, s * x + c * y + ty)
    path = [move(*q) for q in path]
    walls = [move(w[0], w[1]) + move(w[2], w[3]) + (w[4],) for w in walls]
    px, py = move(*phone)
    shadow = Shadowing(p["sd"], p["spacing"], rng.uniform(0, p["spacing"]),
                       rng.uniform(0, p["spacing"]), f"{cls}:{seed}:field:{rng.getrandbits(48)}")
    rows, clipped = [], 0
    for k, (x, y) in enumerate(resample(path, p["speed"] * p["period"])):
        d = math.sqrt((x - px) ** 2 + (y - py) ** 2 + (p["ant_z"] - phone_z) ** 2)
        loss = sum(w[4] for w in walls
                   if segments_cross((x, y), (px, py), (w[0], w[1]), (w[2], w[3])))
        g = max(rng.expovariate(1.0), 1e-300)
        fade = p["fading"] * min(max(10 * math.log10(g), -20.0), 6.0)
        rssi = p["A"] - 10 * p["n"] * math.log10(max(d, 0.2)) - loss + shadow(x, y) + fade
        heard = rssi >= p["floor"]
        if heard and rssi > 0:
            clipped += 1
        value = str(min(int(round(rssi)), 0)) if heard else ""
        rows.append((k * p["period"], x + rng.gauss(0, 0.05), y + rng.gauss(0, 0.05),
                     p["ant_z"], value))
    return p, walls, (px, py, phone_z), rows, clipped


def write_log(cls, seed, out_dir):
    p, walls, phone, rows, clipped = make_log(cls, seed)
    stem = f"{cls}_{seed}"
    bssid = f"02:00:00:00:{seed % 256:02x}:{CLASSES.index(cls) + 1:02x}"
    with open(os.path.join(out_dir, stem + "_rssi.csv"), "w", newline="") as f:
        f.write(f"# floor_dbm: {p['floor']:.2f}\n# scan_period_s: {p['period']:.3f}\n")
        f.write("t,x,y,z,bssid,rssi\n")
        for t, x, y, z, v in rows:
            # t is written with the same 3 decimals as the period header, so steps agree
            f.write(f"{t:.3f},{x:.3f},{y:.3f},{z:.3f},{bssid},{v}\n")
    with open(os.path.join(out_dir, stem + "_truth.csv"), "w", newline="") as f:
        f.write(f"bssid,x,y,z\n{bssid},{phone[0]:.3f},{phone[1]:.3f},{phone[2]:.3f}\n")
    with open(os.path.join(out_dir, stem + "_walls.csv"), "w", newline="") as f:
        f.write("x1,y1,x2,y2,attenuation_db\n")
        for w in walls:
            f.write(",".join(f"{v:.3f}" for v in w[:4]) + f",{w[4]:.2f}\n")
    heard = sum(1 for r in rows if r[4] != "")
    print(f"{stem}: {len(rows)} scans, {heard} heard, {len(walls)} walls, "
          f"A={p['A']:.1f} n={p['n']:.2f} sd={p['sd']:.1f} floor={p['floor']:.1f}"
          + (f", {clipped} clipped at 0 dBm" if clipped else ""))
    return [cls, seed, stem, f"{p['A']:.2f}", f"{p['n']:.3f}", f"{p['sd']:.2f}",
            f"{p['spacing']:.2f}", f"{p['fading']:.3f}", f"{p['floor']:.2f}",
            f"{p['period']:.3f}", f"{p['speed']:.3f}", f"{phone[0]:.3f}", f"{phone[1]:.3f}",
            f"{phone[2]:.3f}", len(walls), len(rows), heard]


MANIFEST_HEADER = ["class", "seed", "stem", "A_dbm", "n", "shadowing_sd_db", "lattice_m",
                   "fading_scale", "floor_dbm", "scan_period_s", "speed_mps", "phone_x",
                   "phone_y", "phone_z", "walls", "scans", "heard"]


def generate(jobs, out_dir):
    """Write the logs (class, seed) and manifest.csv into out_dir; return the stems."""
    os.makedirs(out_dir, exist_ok=True)
    manifest = [write_log(cls, seed, out_dir) for cls, seed in jobs]
    with open(os.path.join(out_dir, "manifest.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(MANIFEST_HEADER)
        w.writerows(manifest)
    return [row[2] for row in manifest]


def frozen_jobs():
    return [(cls, seed) for cls in CLASSES for seed in FROZEN_SEEDS]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--frozen", metavar="OUT_DIR", help="write the frozen set (250 logs)")
    ap.add_argument("--class", dest="cls", choices=CLASSES, help="one log of this class")
    ap.add_argument("--seed", type=int, help="seed of the one log")
    ap.add_argument("--out", help="output directory of the one log")
    a = ap.parse_args(argv)
    if a.frozen:
        generate(frozen_jobs(), a.frozen)
    elif a.cls and a.seed is not None and a.out:
        generate([(a.cls, a.seed)], a.out)
    else:
        ap.error("give --frozen OUT_DIR, or --class NAME --seed S --out DIR")
    return 0


if __name__ == "__main__":
    sys.exit(main())
