"""A small W3C WebDriver client (the standard library only) for Debian's chromedriver and
headless Chromium: what the studio's browser test and its latency benchmark drive the page
with. WebGL runs on SwiftShader (no GPU needed)."""
import base64
import json
import socket
import time
import urllib.error
import urllib.request

ELEMENT = "element-6066-11e4-a52e-4f735466cecf"
TAB = "\ue004"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class WebDriver:
    def __init__(self, port):
        self.base = f"http://127.0.0.1:{port}"
        self.session = None

    def call(self, method, path, body=None):
        data = None if body is None else json.dumps(body).encode()
        request = urllib.request.Request(self.base + path, data=data, method=method,
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request, timeout=120) as response:
                return json.loads(response.read())["value"]
        except urllib.error.HTTPError as error:
            raise RuntimeError(f"WebDriver {method} {path}: {error.read().decode()[:2000]}")

    def start(self):
        capabilities = {"alwaysMatch": {"browserName": "chrome", "goog:chromeOptions": {
            "binary": "/usr/bin/chromium",
            # WebGL without a GPU: SwiftShader, which current Chromium enables only when asked.
            "args": ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
                     "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                     "--window-size=1400,900", "--no-first-run",
                     # Frames at the display's rate, as in a window the user looks at: without
                     # these, headless Chromium treats its window as in the background.
                     "--disable-renderer-backgrounding", "--disable-background-timer-throttling",
                     "--disable-backgrounding-occluded-windows"]}}}
        self.session = self.call("POST", "/session", {"capabilities": capabilities})["sessionId"]

    def s(self, path):
        return f"/session/{self.session}{path}"

    def go(self, url):
        self.call("POST", self.s("/url"), {"url": url})

    def js(self, script, *args):
        return self.call("POST", self.s("/execute/sync"), {"script": script, "args": list(args)})

    def find(self, css):
        return self.call("POST", self.s("/element"), {"using": "css selector", "value": css})[ELEMENT]

    def click(self, css):
        self.call("POST", self.s(f"/element/{self.find(css)}/click"), {})

    def type_into(self, css, text):
        element = self.find(css)
        self.call("POST", self.s(f"/element/{element}/clear"), {})
        self.call("POST", self.s(f"/element/{element}/value"), {"text": text})

    def drag(self, start, end):
        moves = [{"type": "pointerMove", "x": round(start[0]), "y": round(start[1]),
                  "origin": "viewport", "duration": 0},
                 {"type": "pointerDown", "button": 0}]
        for step in range(1, 11):  # in steps, so the page sees a drag (raster updates)
            t = step / 10
            moves.append({"type": "pointerMove", "origin": "viewport", "duration": 60,
                          "x": round(start[0] + t * (end[0] - start[0])),
                          "y": round(start[1] + t * (end[1] - start[1]))})
        moves.append({"type": "pointerUp", "button": 0})
        self.call("POST", self.s("/actions"), {"actions": [
            {"type": "pointer", "id": "mouse", "parameters": {"pointerType": "mouse"},
             "actions": moves}]})

    def screenshot(self, path):
        with open(path, "wb") as out:
            out.write(base64.b64decode(self.call("GET", self.s("/screenshot"))))

    def wait(self, condition, what, seconds=180):
        deadline = time.time() + seconds
        while time.time() < deadline:
            if self.js("return " + condition):
                return
            time.sleep(0.1)
        errors = self.js("return document.getElementById('errors').textContent")
        raise AssertionError(f"timed out waiting for {what}; page errors: {errors}")

    def stop(self):
        if self.session:
            self.call("DELETE", self.s(""))

    def wait_ready(self):
        """Until chromedriver answers (it starts in the background)."""
        for _ in range(100):
            try:
                self.call("GET", "/status")
                return
            except (OSError, RuntimeError):
                time.sleep(0.1)
        raise RuntimeError("chromedriver did not start")

    def js_async(self, script, *args):
        """Runs `script` with a callback as its last argument; returns what it is called with."""
        return self.call("POST", self.s("/execute/async"), {"script": script, "args": list(args)})
