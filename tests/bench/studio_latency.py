#!/usr/bin/env python3
"""Issue 37 item 3: how long the studio takes from a pose change to the new curves and verdicts
on screen, for every bundled rig, in Debian's headless Chromium (software WebGL, no GPU).

For each rig and mount, 12 small pose changes (z +-1 cm, pitch -1/0/+1 deg) are made as the
gizmo makes them (the drag begun, the mount's pivot moved, then the page's own raster-path
request), one at a time; each is timed from the change to the numbers drawn (curves, verdicts: the DOM and the 2D
canvases updated) and to the first animation frame after that (what is on screen, including a
software-rendered WebGL frame on a machine without a GPU). Prints per rig the medians and the
largest time to the frame, and the server's share; exits 1 when a rig's median to the frame is
50 ms or more (the target).

usage: studio_latency.py RIGDESIGN SOURCE_DIR
"""
import os
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from webdriver_client import WebDriver, free_port  # noqa: E402

TARGET_MS = 50.0
CHANGES = 12

MEASURE = """
const done = arguments[arguments.length - 1];
const changes = arguments[0];
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
(async () => {
  const out = {};
  for (const mount of studio.numbers.mounts.map((m) => JSON.parse(JSON.stringify(m)))) {
    const pivot = studio.pivots.get(mount.id);
    const times = [];
    setDragging(true);  // what the gizmo does when a drag starts
    for (let i = 0; i < changes; i++) {
      const xyz = [mount.xyz[0], mount.xyz[1], mount.xyz[2] + (i % 2 ? 0.01 : -0.01)];
      const rpy = [mount.rpy_deg[0], mount.rpy_deg[1] + (i % 3) - 1, mount.rpy_deg[2]];
      const before = studio.updates;
      const started = performance.now();
      setPivotPose(pivot, xyz, rpy);
      sendPose(mount.id, false);
      while (studio.updates === before && (studio.inFlight || studio.queued)) await sleep(1);
      if (studio.updates === before) { times.push(null); continue; }  // refused (inside the body)
      const drawn = performance.now() - started;
      await new Promise((resolve) => requestAnimationFrame(resolve));
      times.push([performance.now() - started, studio.lastServerMs, drawn]);
    }
    setDragging(false);
    setPivotPose(pivot, mount.xyz, mount.rpy_deg);
    sendPose(mount.id, true, {xyz: mount.xyz, rpy_deg: mount.rpy_deg});
    while (studio.inFlight || studio.queued) await sleep(5);
    out[mount.id] = times;
  }
  done(out);
})();
"""


def measure(binary, source, rig, driver_port):
    server = subprocess.Popen([binary, "serve", rig, "--port", "0", "--no-open"], cwd=source,
                              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    driver = WebDriver(driver_port)
    try:
        url = next((line.strip() for line in server.stdout
                    if line.strip().startswith("http://127.0.0.1:")), None)
        driver.start()
        driver.go(url)
        driver.wait("document.getElementById('status').textContent === 'ready' || "
                    "!document.getElementById('errors').hidden", "the page")
        if not driver.js("return document.getElementById('status').textContent === 'ready'"):
            return None
        return driver.js_async(MEASURE, CHANGES)
    finally:
        driver.stop()
        server.terminate()
        server.wait(timeout=30)


def main(binary, source):
    rigs = sorted(f for f in os.listdir(os.path.join(source, "rigs")) if f.endswith(".yaml"))
    driver_port = free_port()
    chromedriver = subprocess.Popen(["chromedriver", f"--port={driver_port}"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    failed = []
    try:
        WebDriver(driver_port).wait_ready()
        print(f"studio latency: pose change -> numbers drawn -> next frame, {CHANGES} changes per "
              "mount, headless Chromium (SwiftShader)")
        print(f"{'rig':34s} {'mounts':>6s} {'frame median ms':>16s} {'frame max ms':>13s} "
              f"{'server median ms':>17s} {'drawn median ms':>16s}")
        for rig in rigs:
            result = measure(binary, source, os.path.join("rigs", rig), driver_port)
            if result is None:
                print(f"{rig:34s} (does not load in the studio: not a rig with mounts)")
                continue
            times = [t for mount in result.values() for t in mount if t is not None]
            total = [t[0] for t in times]
            server = [t[1] for t in times]
            median = statistics.median(total)
            print(f"{rig:34s} {len(result):6d} {median:16.1f} {max(total):13.1f} "
                  f"{statistics.median(server):17.1f} {statistics.median([t[2] for t in times]):16.1f}")
            if median >= TARGET_MS:
                failed.append(rig)
    finally:
        chromedriver.terminate()
        chromedriver.wait(timeout=30)
    if failed:
        print(f"studio latency: median over {TARGET_MS:.0f} ms for {', '.join(failed)}",
              file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main(*sys.argv[1:3])
