"""Pictures of VPython 7 programs as real VPython draws them: GlowScript/WebGL in headless
Chromium (WebGL2 through ANGLE on SwiftShader, software, deterministic for a still scene).

Runs with the fidelity venv's Python (``make fidelity`` builds ``.fidelity-venv`` with
vpython, selenium, numpy, pillow); needs Debian's ``chromium`` and ``chromium-driver``.

How, for each program:

1. run it with this Python; vpython's no-notebook server listens on a free port
   (``VPYTHON_HTTP_PORT``) and opens no browser (``VPYTHON_NO_LAUNCH_BROWSER=1``); the
   program's ``import vpython`` waits until a browser has connected,
2. open ``http://localhost:PORT/`` in the (one, reused) headless Chromium,
3. wait until the program has reached its end (it runs with a line appended that prints a
   marker; vpython's server then keeps running for the page) and a settling time,
4. take GlowScript's own ``canvas.screenshot(true)`` (what ``scene.capture`` uses: the WebGL
   canvas after a render with the label overlay drawn on it), again and again until two
   in a row are identical, and save it as RGB composited over the page's background.

usage: python realvpython.py OUT_DIR PROGRAM.py [PROGRAM.py ...] [--settle 3]
writes OUT_DIR/<name>.png and OUT_DIR/<name>.json (GlowScript's camera, versions).
"""
from __future__ import annotations

import argparse
import base64
import io
import json
import os
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service

CHROMEDRIVER = "/usr/bin/chromedriver"
CHROME_FLAGS = ["--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                "--enable-unsafe-swiftshader", "--window-size=1400,1000",
                "--force-device-scale-factor=1", "--hide-scrollbars"]

_SHOT = """
var cb = arguments[arguments.length - 1];
canvas.activated[0].screenshot(true).then(function (u) { cb(u); },
                                          function (e) { cb('ERR ' + e); });
"""
_END = "__springscene_fidelity_end__"
_READY = ("return typeof canvas !== 'undefined' && !!canvas.activated && "
          "canvas.activated.length > 0 && !!canvas.activated[0];")
_BACKGROUND = """
var el = canvas.activated[0].__canvas_element;
while (el) {
  var c = getComputedStyle(el).backgroundColor;
  if (c && c !== 'rgba(0, 0, 0, 0)' && c !== 'transparent') return c;
  el = el.parentElement;
}
return 'rgb(255, 255, 255)';"""
_INFO = """
var c = canvas.activated[0];
function v(a) { return a ? [a.x, a.y, a.z] : null; }
return {user_agent: navigator.userAgent,
        glowscript: window.glowscript ? glowscript.version : '?',
        camera: {range: c.range, center: v(c.center), forward: v(c.forward), fov: c.fov,
                 width: c.width, height: c.height}};"""


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("", 0))
        return s.getsockname()[1]


def _wait_port(port: int, timeout: float) -> None:
    end = time.time() + timeout
    while time.time() < end:
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=0.5):
                return
        except OSError:
            time.sleep(0.2)
    raise RuntimeError(f"vpython's server did not open port {port}")


def _decode(url: str) -> np.ndarray:
    if not url.startswith("data:image/png;base64,"):
        raise RuntimeError(f"GlowScript's screenshot failed: {url[:200]}")
    data = base64.b64decode(url.split(",", 1)[1])
    return np.asarray(Image.open(io.BytesIO(data)).convert("RGBA"))


def _over_background(rgba: np.ndarray, css: str) -> np.ndarray:
    """RGB as the page shows the canvas: toDataURL's un-premultiplied RGBA over the page."""
    inner = css[css.index("(") + 1:css.index(")")]
    rgb = np.array([float(p) for p in inner.split(",")[:3]])
    alpha = rgba[..., 3:4].astype(np.float64) / 255.0
    shown = rgba[..., :3] * alpha + rgb * (1.0 - alpha)
    return np.clip(np.rint(shown), 0, 255).astype(np.uint8)


def open_browser(timeout: float = 240.0):
    """A headless Chromium (selenium) drawing WebGL on SwiftShader."""
    opts = webdriver.ChromeOptions()
    for flag in CHROME_FLAGS:
        opts.add_argument(flag)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=opts)
    driver.set_script_timeout(timeout)
    return driver


def _stable_shot(driver, timeout: float) -> tuple[np.ndarray, int]:
    t0, prev, n = time.time(), None, 0
    while time.time() - t0 < timeout:
        img = _decode(driver.execute_async_script(_SHOT))
        n += 1
        if prev is not None and np.array_equal(prev, img):
            return img, n
        prev = img
        time.sleep(1.0)
    raise RuntimeError("the picture never settled")


def shoot(driver, program: Path, out: Path, settle: float = 3.0,
          timeout: float = 240.0) -> dict:
    """Real VPython's picture of ``program`` to ``out`` (RGB PNG); returns what it knows
    (GlowScript's camera and version, the browser, the seconds taken)."""
    port = _free_port()
    run = out.with_suffix(".run.py")
    run.write_text(program.read_text() + f"\nprint({_END!r}, flush=True)\n")
    env = dict(os.environ, VPYTHON_HTTP_PORT=str(port), VPYTHON_NO_LAUNCH_BROWSER="1")
    t0 = time.time()
    log = open(out.with_suffix(".log"), "w")
    proc = subprocess.Popen([sys.executable, str(run)], cwd=str(program.parent), env=env,
                            stdout=log, stderr=subprocess.STDOUT)
    try:
        _wait_port(port, 30)
        driver.get(f"http://localhost:{port}/")
        while not driver.execute_script(_READY):
            if time.time() - t0 > timeout:
                raise RuntimeError("GlowScript made no canvas")
            time.sleep(0.3)
        while _END not in out.with_suffix(".log").read_text():
            if time.time() - t0 > timeout or proc.poll() is not None:
                raise RuntimeError(f"{program.name} did not reach its end")
            time.sleep(0.3)
        time.sleep(settle)
        rgba, captures = _stable_shot(driver, timeout)
        rgb = _over_background(rgba, driver.execute_script(_BACKGROUND))
        Image.fromarray(rgb).save(out)
        meta = driver.execute_script(_INFO)
        meta.update(program=program.name, captures=captures,
                    seconds=round(time.time() - t0, 1))
        return meta
    finally:
        if proc.poll() is None:
            proc.kill()
        proc.wait()
        log.close()
        run.unlink()


def versions() -> dict:
    """The versions of what draws the reference: vpython, selenium, Chromium."""
    import vpython  # noqa: PLC0415  (the fidelity venv's package, only here)
    out = subprocess.run(["chromium", "--version"], capture_output=True, text=True).stdout
    return {"vpython": vpython.__version__, "chromium": out.strip()}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out_dir")
    ap.add_argument("programs", nargs="+")
    ap.add_argument("--settle", type=float, default=3.0)
    a = ap.parse_args(argv)
    out_dir = Path(a.out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    driver = open_browser()
    info = {"versions": versions(), "pictures": {}}
    try:
        for prog in a.programs:
            prog = Path(prog).resolve()
            name = prog.name[:-3] if prog.name.endswith(".py") else prog.name
            meta = shoot(driver, prog, out_dir / f"{name}.png", a.settle)
            info["pictures"][name] = meta
            print(f"{name}: {meta['seconds']} s", flush=True)
    finally:
        driver.quit()
    (out_dir / "realvpython.json").write_text(json.dumps(info, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
