"""Headless Chromium for the interactive page's tests: Debian's ``chromium`` and
``chromium-driver`` through selenium, WebGL on SwiftShader (software), as
/work/shared/tools/realvpy_shot.py and benchmarks/fidelity/realvpython.py draw real
VPython; pictures are GlowScript's own ``canvas.screenshot(true)`` (what VPython's
``scene.capture`` saves: the WebGL canvas with the labels' 2D overlay on top).

Chromium missing: the tests skip, or fail when SPRINGSCENE_REQUIRE_BACKENDS is set (CI:
``make setup`` installs it as root).
"""

from __future__ import annotations

import base64
import io
import os
import shutil
import tempfile
from pathlib import Path

import numpy as np
import pytest

CHROMIUM = os.environ.get("SPRINGSCENE_CHROMIUM", "/usr/bin/chromium")
CHROMEDRIVER = os.environ.get("SPRINGSCENE_CHROMEDRIVER", "/usr/bin/chromedriver")
FLAGS = ["--headless=new", "--no-sandbox", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--force-device-scale-factor=1", "--hide-scrollbars",
         "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--window-size=1000,900"]

SHOT_JS = """
var done = arguments[arguments.length - 1];
window.springscene.canvas(arguments[0]).screenshot(true).then(
    function (url) { done(url); }, function (e) { done('ERR ' + e); });
"""


def require_chromium() -> None:
    """Skip when Chromium, its driver or selenium is missing, unless CI demands them."""
    missing = [p for p in (CHROMIUM, CHROMEDRIVER) if not Path(p).exists()]
    try:
        import selenium  # noqa: F401,PLC0415  only the browser tests need it
    except ImportError:
        missing.append("selenium")
    if missing:
        if os.environ.get("SPRINGSCENE_REQUIRE_BACKENDS"):
            pytest.fail(f"headless Chromium is required here but missing: {missing}")
        pytest.skip(f"headless Chromium missing: {missing}")


class Browser:
    """One headless Chromium (a fresh profile), closed by :meth:`close`."""

    def __init__(self) -> None:
        from selenium import webdriver  # noqa: PLC0415  heavy: selenium
        from selenium.webdriver.chrome.service import Service  # noqa: PLC0415

        self.profile = tempfile.mkdtemp(prefix="springscene-chromium-")
        opts = webdriver.ChromeOptions()
        for flag in FLAGS + [f"--user-data-dir={self.profile}"]:
            opts.add_argument(flag)
        opts.binary_location = CHROMIUM
        self.driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=opts)
        self.driver.set_script_timeout(60)

    def open(self, page: Path, paused: bool = True) -> None:
        """Open the page from the disk; wait for the player to be ready."""
        self.driver.get(page.resolve().as_uri() + ("#paused" if paused else ""))
        self.wait("return !!(window.springscene && window.springscene.ready)", 30)

    def js(self, code: str, *args):
        return self.driver.execute_script(code, *args)

    def wait(self, condition_js: str, seconds: float):
        """Poll ``condition_js`` until it is truthy; its value."""
        from selenium.webdriver.support.ui import WebDriverWait  # noqa: PLC0415

        return WebDriverWait(self.driver, seconds, poll_frequency=0.1).until(
            lambda d: d.execute_script(condition_js))

    def canvas_picture(self, canvas_id: int = 0) -> np.ndarray:
        """GlowScript's own screenshot of a canvas (labels included), RGB."""
        from PIL import Image  # noqa: PLC0415  heavy: Pillow

        url = self.driver.execute_async_script(SHOT_JS, canvas_id)
        assert url.startswith("data:image/png;base64,"), url[:200]
        img = Image.open(io.BytesIO(base64.b64decode(url.split(",", 1)[1])))
        return np.asarray(img.convert("RGB"))

    def close(self) -> None:
        try:
            self.driver.quit()
        finally:
            shutil.rmtree(self.profile, ignore_errors=True)
