#!/usr/bin/env python3
"""Issue 37 item 5: the studio in a real browser.

Starts `rigdesign serve` on a copy of the TurtleBot 4 rig, drives Debian's headless Chromium
through chromedriver (the W3C WebDriver protocol, spoken here with the standard library),
moves the OAK-D once by the numeric fields and once by dragging the gizmo, and checks after
each that the page shows what `rigdesign metrics` computes for the rig written by hand with the
pose the page shows. Saves, and diffs the file: only the OAK-D's pose line may change, to the
numbers typed and dragged. A screenshot is kept as an artifact.

usage: studio_browser_test.py RIGDESIGN SOURCE_DIR ARTIFACT_DIR
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from webdriver_client import TAB, WebDriver, free_port  # noqa: E402


def number_text(value):
    """A number as the rig file writes it: integers without a fraction, else Python's repr
    (the shortest text that reads back exactly, as the C++ side writes)."""
    value = float(value)
    return str(int(value)) if value == int(value) else repr(value)


def pose_line(fields):
    """The OAK-D's pose line as the studio saves a pose that was a description link: as
    numbers, keeping the sensor's housing (the oakd_link box it still sits in, issue 52)."""
    xyz = ", ".join(number_text(v) for v in fields[:3])
    rpy = ", ".join(number_text(v) for v in fields[3:])
    return f"     pose: {{xyz: [{xyz}], rpy_deg: [{rpy}], housing: oakd_link}}}}"


def metrics_of(binary, folder, text, sensors):
    path = os.path.join(folder, "by_hand.yaml")
    with open(path, "w") as out:
        out.write(text)
    run = subprocess.run([binary, "metrics", path, "--sensors", sensors, "--json"],
                         capture_output=True, text=True, check=True)
    return json.loads(run.stdout)


def curves_of(binary, folder, sensors):
    """The SC curves `rigdesign coverage` writes for by_hand.yaml (coverage.csv, 8 digits)."""
    out = os.path.join(folder, "coverage_out")
    subprocess.run([binary, "coverage", os.path.join(folder, "by_hand.yaml"), "--sensors", sensors,
                    "--out", out, "--no-3d", "--angles", "0"], capture_output=True, check=True)
    with open(os.path.join(out, "coverage.csv")) as f:
        rows = list(csv.DictReader(f))
    return ([float(r["theta_deg"]) for r in rows], [float(r["sc_complete"]) for r in rows],
            [float(r["sc_floor"]) for r in rows])


def expect_curves_match(page, curves):
    """The page's curves, angle by angle, are the ones `rigdesign coverage` computes."""
    theta, complete, floor = curves
    coverage = page["coverage"]
    assert len(coverage["curve_theta_deg"]) == len(theta), (len(coverage["curve_theta_deg"]), len(theta))
    for i, t in enumerate(theta):
        assert abs(coverage["curve_theta_deg"][i] - t) < 1e-6, (i, t)
        assert abs(coverage["curve_complete"][i] - complete[i]) < 1e-7, (t, complete[i])
        assert abs(coverage["curve_floor"][i] - floor[i]) < 1e-7, (t, floor[i])


def front_of(numbers):
    """The page's front sector: SC complete and floor minima and the R2 front verdict."""
    sector = numbers["coverage"]["sectors"][0]
    verdict = next(r["verdict"] for r in numbers["requirements"]
                   if r["id"] == "R2" and r["title"].endswith("front"))
    return sector["complete"]["min"], sector["floor"]["min"], verdict


def expect_page_matches_metrics(page, report):
    complete, floor, verdict = front_of(page)
    sector = report["coverage"]["sectors"][0]
    expected_verdict = next(r["verdict"] for r in report["requirements"]["results"]
                            if r["id"] == "R2" and r["title"].endswith("front"))
    assert abs(complete - sector["complete"]["min"]) < 1e-9, (complete, sector)
    assert abs(floor - sector["floor"]["min"]) < 1e-9, (floor, sector)
    assert abs(page["coverage"]["complete"]["mean"] - report["coverage"]["complete"]["mean"]) < 1e-9
    assert verdict == expected_verdict, (verdict, expected_verdict)
    return complete, floor, verdict


def fields_of(driver):
    return [float(driver.js(f"return document.getElementById('{name}').value"))
            for name in ("x", "y", "z", "roll", "pitch", "yaw")]


def main(binary, source, artifacts):
    os.makedirs(artifacts, exist_ok=True)
    folder = tempfile.mkdtemp(prefix="studio_browser_")
    sensors = os.path.join(source, "sensors.yaml")
    with open(os.path.join(source, "rigs", "turtlebot4.yaml")) as f:
        original = f.read()
    # The copy names what the rig finds beside it by absolute path.
    rigs = os.path.join(source, "rigs")
    original = (original.replace("description: robots/", f"description: {rigs}/robots/")
                .replace("package_paths: [robots]", f"package_paths: [{rigs}/robots]")
                .replace("requirements: requirements/", f"requirements: {rigs}/requirements/"))
    link_line = "     pose: {urdf_link: oakd_rgb_camera_frame}}"
    assert link_line in original.splitlines(), "the OAK-D's pose line moved in rigs/turtlebot4.yaml"
    rig = os.path.join(folder, "turtlebot4.yaml")
    with open(rig, "w") as out:
        out.write(original)

    server = subprocess.Popen([binary, "serve", rig, "--port", "0", "--no-open",
                               "--sensors", sensors], stdout=subprocess.PIPE, text=True)
    driver_port = free_port()
    chromedriver = subprocess.Popen(["chromedriver", f"--port={driver_port}"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    driver = WebDriver(driver_port)
    try:
        url = None
        for line in server.stdout:
            if line.strip().startswith("http://127.0.0.1:"):
                url = line.strip()
                break
        assert url, "serve printed no address"
        driver.wait_ready()
        driver.start()
        driver.go(url)
        driver.wait("document.getElementById('status').textContent === 'ready'", "the page")
        before = front_of(driver.js("return window.studio.numbers"))
        print(f"loaded: front SC complete min {before[0]:.4f}, floor min {before[1]:.4f}, "
              f"R2 front {before[2]}")

        # 1. The OAK-D pitched 20 degrees up by its numeric field.
        driver.click("#mounts option[value='oakd']")
        driver.wait("window.studio.selected === 'oakd'", "the OAK-D selected")
        updates = driver.js("return window.studio.updates")
        driver.type_into("#pitch", "-20" + TAB)
        driver.wait(f"window.studio.updates > {updates} && window.studio.numbers.exact && "
                    "!window.studio.inFlight", "the numbers after the pitch")
        fields = fields_of(driver)
        assert fields[4] == -20, fields
        by_hand = original.replace(link_line, pose_line(fields))
        page = driver.js("return window.studio.numbers")
        after_field = expect_page_matches_metrics(page, metrics_of(binary, folder, by_hand, sensors))
        print(f"pitched -20 deg: front SC complete min {after_field[0]:.4f}, floor min "
              f"{after_field[1]:.4f}, R2 front {after_field[2]} (= rigdesign metrics)")
        assert after_field[2] != before[2], "the front verdict did not change"
        assert after_field[1] != before[1]

        # 2. The OAK-D dragged along the robot's x axis by the gizmo's arrow: where the arrow's
        # grip is on screen, from the gizmo's own scale (TransformControls r111: the x picker is
        # centred 0.6 of the gizmo's size along x).
        updates = driver.js("return window.studio.updates")
        grip = driver.js("return window.studioGrip('oakd')")
        start = grip["grip"]
        end = [start[0] + 60 * grip["direction"][0], start[1] + 60 * grip["direction"][1]]
        driver.drag(start, end)
        driver.wait(f"window.studio.updates > {updates} + 1 && window.studio.numbers.exact && "
                    "!window.studio.inFlight && !window.studio.dragging", "the numbers after the drag")
        dragged = fields_of(driver)
        assert dragged[0] != fields[0], ("the drag did not move the OAK-D", dragged, fields)
        by_hand = original.replace(link_line, pose_line(dragged))
        page = driver.js("return window.studio.numbers")
        after_drag = expect_page_matches_metrics(page, metrics_of(binary, folder, by_hand, sensors))
        expect_curves_match(page, curves_of(binary, folder, sensors))
        latencies = driver.js("return window.studio.rasterLatenciesMs")
        print(f"dragged to x = {dragged[0]} m: front SC complete min {after_drag[0]:.4f}, floor "
              f"min {after_drag[1]:.4f}, R2 front {after_drag[2]} (= rigdesign metrics; the 360-angle "
              f"curves = rigdesign coverage); "
              f"{len(latencies)} raster updates while dragging, change to numbers drawn: "
              f"median {sorted(latencies)[len(latencies) // 2]:.1f} ms, "
              f"max {max(latencies):.1f} ms" if latencies else "no raster updates")
        assert latencies, "no raster-path update while dragging"

        # 3. Save: only the OAK-D's pose line changes, to the numbers on the page.
        driver.click("#save")
        driver.wait("document.getElementById('check').textContent.startsWith('check exit code')",
                    "the check after saving")
        driver.screenshot(os.path.join(artifacts, "studio_turtlebot4.png"))
        with open(rig) as f:
            saved = f.read().splitlines()
        lines = original.splitlines()
        changed = [i for i, (a, b) in enumerate(zip(lines, saved)) if a != b]
        assert len(saved) == len(lines), "lines were added or removed"
        assert changed == [lines.index(link_line)], changed
        assert saved[changed[0]] == pose_line(dragged), (saved[changed[0]], pose_line(dragged))
        print("saved: one line changed:", saved[changed[0]].strip())
        print("check after save:", driver.js("return document.getElementById('check').textContent").splitlines()[0])
    finally:
        try:
            driver.stop()
        finally:
            chromedriver.terminate()
            server.terminate()
            server.wait(timeout=30)
            chromedriver.wait(timeout=30)
    assert server.returncode == 0, f"serve exited with {server.returncode}"
    print("studio browser test: ok")


if __name__ == "__main__":
    main(*sys.argv[1:4])
