"""Print a built HTML page (the book's single-page build) to PDF with headless Chromium.

Chromium's own ``--print-to-pdf`` prints as soon as the page has loaded, before MathJax has
typeset the formulas. So Chromium is driven over its DevTools protocol instead (a websocket;
tornado's client, which Jupyter already installs, so nothing new is needed): load the page
from file://, wait for ``MathJax.startup.promise`` and the fonts, open the solutions
(``--open-solutions``; the student book has none), then ``Page.printToPDF``. The print
stylesheet (book/_ext/classroom_print.css) hides the navigation, wraps long outputs and
keeps figures whole. Everything is local: no network is used.

Usage::

    python -m tools.pdf.printer book/_build/singlehtml/index.html book/_build/pdf/book.pdf
"""

from __future__ import annotations

import argparse
import base64
import itertools
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from tornado.httpclient import HTTPClient
from tornado.ioloop import IOLoop
from tornado.websocket import websocket_connect

# Runs in the page before printing; resolves when MathJax has typeset everything.
READY = """
(async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    await MathJax.startup.promise;
  }
  await document.fonts.ready;
  await Promise.all([...document.images].map(img => img.complete ? null :
      new Promise(done => { img.onload = img.onerror = done; })));
  return [document.querySelectorAll("mjx-container").length,
          document.querySelectorAll(".math").length,
          [...document.images].filter(img => !img.naturalWidth).map(img => img.src)];
})()
"""
# sphinx-togglebutton folds a solution (":class: dropdown") into .toggle-hidden, and
# dropdown admonitions into <details>: open both, leave the folded code cells as they are.
OPEN_SOLUTIONS = """
document.querySelectorAll(".solution .toggle-hidden, .solution.toggle-hidden")
  .forEach(e => e.classList.remove("toggle-hidden"));
document.querySelectorAll("details.dropdown, .solution details")
  .forEach(d => { d.open = true; });
document.querySelectorAll(".solution").length
"""


# After the print layout is in place: a formula or table wider than its column is scaled
# down to fit (CSS zoom) instead of being cut at the margin; MathJax 3 does not break lines.
FIT = """
(() => {
  let fitted = 0;
  const inner = el => {
    const s = getComputedStyle(el);
    return el.clientWidth - parseFloat(s.paddingLeft) - parseFloat(s.paddingRight);
  };
  for (const el of document.querySelectorAll("mjx-container, table")) {
    // A box may already scroll (book/_static/reader.css): its content is scrollWidth wide.
    const need = Math.max(el.scrollWidth, el.getBoundingClientRect().width);
    const block = el.tagName === "TABLE" || el.getAttribute("display") === "true"
      ? el.parentElement : el.closest("p, li, td, th, dd, figcaption, div") || el.parentElement;
    const room = inner(block);
    if (room > 0 && need > room + 1) {
      el.style.zoom = (0.99 * room / need).toFixed(3);
      fitted++;
    }
  }
  return fitted;
})()
"""
PAPER = {"paperWidth": 8.27, "paperHeight": 11.69, "marginTop": 0.6, "marginBottom": 0.6,
         "marginLeft": 0.6, "marginRight": 0.6}  # A4, in inches
# The width of the printed column in CSS pixels (96 per inch): the page is laid out at it.
COLUMN = int((PAPER["paperWidth"] - PAPER["marginLeft"] - PAPER["marginRight"]) * 96)


def find_chromium() -> str:
    """The Chromium to use: $CHROMIUM, or Debian's chromium on PATH."""
    for name in (os.environ.get("CHROMIUM"), "chromium", "chromium-browser", "google-chrome"):
        if name and shutil.which(name):
            return str(shutil.which(name))
    raise FileNotFoundError("no Chromium found: install Debian's chromium or set CHROMIUM")


class DevTools:
    """A minimal DevTools-protocol client over one websocket."""

    def __init__(self, url: str) -> None:
        self.loop = IOLoop()
        self.ws = self.loop.run_sync(lambda: websocket_connect(url, max_message_size=1 << 30))
        self.ids = itertools.count(1)

    def call(self, method: str, timeout: float = 120, **params: Any) -> dict[str, Any]:
        ident = next(self.ids)

        async def go() -> dict[str, Any]:
            await self.ws.write_message(json.dumps({"id": ident, "method": method,
                                                    "params": params}))
            while True:
                message = await self.ws.read_message()
                if message is None:
                    raise ConnectionError("Chromium closed the connection")
                data = json.loads(message)
                if data.get("id") == ident:
                    if "error" in data:
                        raise RuntimeError(f"{method}: {data['error']}")
                    return dict(data.get("result", {}))

        return self.loop.run_sync(go, timeout=timeout)

    def evaluate(self, script: str, timeout: float = 120) -> Any:
        result = self.call("Runtime.evaluate", timeout=timeout, expression=script,
                           awaitPromise=True, returnByValue=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"script failed in the page: {result['exceptionDetails']}")
        return result["result"].get("value")

    def close(self) -> None:
        self.ws.close()
        self.loop.close()


def print_pdf(page: Path, pdf: Path, open_solutions: bool = False, timeout: float = 300) -> dict:
    """Print one local HTML file to a PDF file; return what was seen (for the caller's log)."""
    if not page.is_file():
        raise FileNotFoundError(f"page {page} does not exist: build it first")
    profile = tempfile.mkdtemp(prefix="print-pdf-")
    proc = subprocess.Popen(
        [find_chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
         "--remote-debugging-port=0", f"--user-data-dir={profile}",
         "--allow-file-access-from-files", "about:blank"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )
    try:
        port_file = Path(profile) / "DevToolsActivePort"
        deadline = time.monotonic() + 60
        while not (port_file.exists() and port_file.read_text().strip()):
            if time.monotonic() > deadline or proc.poll() is not None:
                raise RuntimeError("Chromium did not start its DevTools endpoint")
            time.sleep(0.1)
        port = port_file.read_text().split()[0]
        targets = json.loads(HTTPClient().fetch(f"http://127.0.0.1:{port}/json/list").body)
        url = next(t["webSocketDebuggerUrl"] for t in targets if t["type"] == "page")
        tools = DevTools(url)
        try:
            tools.call("Page.enable")
            # Lay the page out as it will be printed, so that FIT measures the real column.
            tools.call("Emulation.setEmulatedMedia", media="print")
            tools.call("Emulation.setDeviceMetricsOverride", width=COLUMN, height=1100,
                       deviceScaleFactor=1, mobile=False)
            tools.call("Page.navigate", url=page.resolve().as_uri())
            # The document must exist before READY can look at it.
            tools.evaluate("new Promise(r => document.readyState === 'complete' ? r() :"
                           " addEventListener('load', () => r()))", timeout)
            formulas, math, broken = tools.evaluate(READY, timeout)
            if broken:  # a figure that would be missing from the paper
                raise RuntimeError(f"{page}: images that did not load: {broken[:5]}")
            if math and not formulas:  # e.g. MathJax from a CDN, and no network
                raise RuntimeError(f"{page} has {math} formulas but MathJax typeset none")
            solutions = tools.evaluate(OPEN_SOLUTIONS) if open_solutions else 0
            images = tools.evaluate("document.images.length")
            fitted = tools.evaluate(FIT)
            errors = tools.evaluate(
                "[...document.querySelectorAll('mjx-merror')].map(e =>"
                " (e.getAttribute('data-mjx-error') || '') + ' in: ' +"
                " (e.closest('section') || document.body).id)")
            if errors:
                raise RuntimeError(f"MathJax could not typeset {len(errors)} formulas in "
                                   f"{page}: {errors[:5]}")
            result = tools.call("Page.printToPDF", timeout=timeout, printBackground=True,
                                **PAPER, displayHeaderFooter=True,
                                headerTemplate="<span></span>",
                                footerTemplate='<div style="font-size:8px;width:100%;'
                                'text-align:center"><span class="pageNumber"></span></div>')
        finally:
            tools.close()
    finally:
        proc.terminate()
        proc.wait(timeout=30)
        shutil.rmtree(profile, ignore_errors=True)
    pdf.parent.mkdir(parents=True, exist_ok=True)
    pdf.write_bytes(base64.b64decode(result["data"]))
    return {"formulas": formulas, "solutions": solutions, "images": images, "fitted": fitted}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("page", type=Path, help="the built HTML file (singlehtml/index.html)")
    parser.add_argument("pdf", type=Path, help="the PDF to write")
    parser.add_argument("--open-solutions", action="store_true",
                        help="unfold the solutions (the instructor's copy)")
    args = parser.parse_args(argv)
    start = time.perf_counter()
    seen = print_pdf(args.page, args.pdf, args.open_solutions)
    print(f"wrote {args.pdf} ({seen['formulas']} formulas, {seen['fitted']} scaled to fit, "
          f"{seen['solutions']} solutions opened, {time.perf_counter() - start:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
