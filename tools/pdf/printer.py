"""Print a built HTML page (the book's single-page build) to PDF with headless Chromium.

Chromium's own ``--print-to-pdf`` prints as soon as the page has loaded, before MathJax has
typeset the formulas. So Chromium is driven over its DevTools protocol instead (a websocket;
tornado's client, which Jupyter already installs, so nothing new is needed): load the page
from file://, wait for ``MathJax.startup.promise`` and the fonts, open the solutions
(``--open-solutions``; the student book has none), prepare the page for paper (PREPARE: a
title page, no link to a local file, folded code cells shown as their outputs), then
``Page.printToPDF`` with an outline (bookmarks) and tags (a tagged PDF, for screen readers)
and the page numbers at the foot. That print is read back (pypdf) for the page each entry
of the table of contents landed on; the numbers are written into the contents and the page
is printed again. The print stylesheet (book/_ext/static/classroom_print.css) hides the
navigation and the screen controls, wraps code at spaces and keeps figures whole.
Everything is local: no network is used.

Usage::

    python -m tools.pdf.printer book/_build/singlehtml/index.html book/_build/pdf/book.pdf
"""

from __future__ import annotations

import argparse
import base64
import io
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
# dropdown admonitions into <details>: open both. A folded code cell (myst-nb's
# hide-input / hide-cell, <details class="hide">) is left to PREPARE.
OPEN_SOLUTIONS = """
document.querySelectorAll(".solution .toggle-hidden, .solution.toggle-hidden")
  .forEach(e => e.classList.remove("toggle-hidden"));
document.querySelectorAll("details.dropdown, .solution details:not(.hide)")
  .forEach(d => { d.open = true; });
document.querySelectorAll(".solution").length
"""
# The exercises' hints (book/_ext/classroom.py: a folded "Hint" admonition) print open in
# both editions: on paper a folded box would be a title over nothing.
OPEN_HINTS = """
document.querySelectorAll(".hint .toggle-hidden, .hint.toggle-hidden")
  .forEach(e => e.classList.remove("toggle-hidden"));
document.querySelectorAll(".hint").length
"""
# Paper shows no screen controls and links only what a reader of the PDF can open. Called
# with the title page's lines; returns what it changed (the caller's log, and the tests).
# - Folded code cells: on paper the code stays hidden and the outputs are shown (the
#   print stylesheet hides the toggle and the code of an open <details class="hide">).
# - Links: into this document (#id) and to the web (http(s), mailto) stay; any other link
#   (the reference site, a file beside the build: file:// in the PDF, which names a folder
#   of the machine that built it) keeps its text and loses its target.
# - Links of the single-page build into another chapter read "#document-<page>#<id>",
#   which no element has, or "#document-<page>", an empty span before the chapter: each
#   points at the element <id> of that chapter (or the chapter's heading) instead, under
#   an id of its own (ids repeat across chapters: every chapter has "exercises").
# - The animation's caption says "press ▶ to play" (the Japanese edition: "▶ を押すと再生
#   される。"): the paper has its first frame only.
# - A number in e-notation (1e-12, in code, outputs and text) is kept on one line.
# - The title page: the theme's print header (its <h1>) with the edition, the package
#   version, the date and the licences.
PREPARE = r"""
(lines => {
  const seen = {folded: 0, unlinked: 0, relinked: 0, captions: 0, numbers: 0};
  document.querySelectorAll("details.hide").forEach(d => { d.open = true; seen.folded++; });
  const unique = new Map();
  for (const a of document.querySelectorAll("a[href]")) {
    const href = a.getAttribute("href");
    const parts = href.match(/^#(document-[^#]+)(?:#(.+))?$/);
    if (parts) {
      const start = document.getElementById(parts[1]);
      const chapter = start && start.nextElementSibling;
      const target = chapter && (!parts[2] || chapter.id === parts[2] ? chapter
        : chapter.querySelector(`[id="${CSS.escape(parts[2])}"]`));
      if (target) {
        if (!unique.has(target)) {
          let id = `${parts[1]}--${parts[2] || "top"}`;
          const heading = target.tagName === "SECTION" && target.querySelector(
            ":scope > h1, :scope > h2, :scope > h3, :scope > h4, :scope > h5, :scope > h6");
          if (heading) {
            // A section is found by its heading, a line of text: the chapter's empty
            // <span id="document-..."> stays at the foot of the page before it.
            heading.insertAdjacentHTML("afterbegin", `<span id="${id}"></span>`);
          } else if (document.querySelectorAll(`[id="${CSS.escape(target.id)}"]`).length === 1) {
            id = target.id;  // an equation, a figure: its id is the document's only one
          } else {
            target.id = id;
          }
          unique.set(target, id);
        }
        a.setAttribute("href", "#" + unique.get(target));
        seen.relinked++;
        continue;
      }
    }
    if (!/^(#.|https?:[/][/]|mailto:)/.test(href)) {
      a.removeAttribute("href");
      seen.unlinked++;
    }
  }
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node; (node = walker.nextNode());) {
    const text = node.nodeValue.replace(/;?\s*press\s+\u25b6\s+to\s+play\b/g, "")
      .replace(/\u25b6\s*を押すと再生される。?/g, "");
    if (text !== node.nodeValue) { node.nodeValue = text; seen.captions++; }
  }
  // A number in e-notation is one token: its line may not break after "1e-".
  const numbers = [];
  const all = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node; (node = all.nextNode());) {
    if (/\d[eE][-+]?\d/.test(node.nodeValue)
        && !node.parentElement.closest("script, style, mjx-container, .ep-nobreak")) {
      numbers.push(node);
    }
  }
  for (const node of numbers) {
    const text = node.nodeValue, pieces = document.createDocumentFragment();
    let last = 0;
    for (const m of text.matchAll(/[-+]?[\d.]*\d[eE][-+]?\d+/g)) {
      const number = document.createElement("span");
      number.className = "ep-nobreak";
      number.textContent = m[0];
      pieces.append(text.slice(last, m.index), number);
      last = m.index + m[0].length;
      seen.numbers++;
    }
    pieces.append(text.slice(last));
    node.replaceWith(pieces);
  }
  const header = document.getElementById("jb-print-docs-body")
    || document.querySelector("article") || document.body;
  const title = header.querySelector(":scope > h1");
  const page = document.createElement("div");
  page.className = "ep-title-page";
  header.prepend(page);
  if (title) page.append(title);
  for (const [cls, text] of lines) {
    const p = document.createElement("p");
    p.className = cls;
    p.textContent = text;
    page.append(p);
  }
  return seen;
})
"""
# The table of contents gets a slot for its page numbers at the first print, as wide as
# the number will be (hidden), so that filling them in moves nothing; TOC_PAGES fills them
# with the pages that print found. A link's target is a named destination of the PDF.
TOC_SLOTS = """
(() => {
  const links = [...document.querySelectorAll("#jb-print-toc a[href^='#']")];
  for (const a of links) {
    const slot = document.createElement("span");
    slot.className = "ep-toc-page";
    slot.textContent = "888";
    a.append(slot);
  }
  return links.map(a => a.getAttribute("href").slice(1));
})()
"""
TOC_PAGES = """
(pages => {
  for (const a of document.querySelectorAll("#jb-print-toc a[href^='#']")) {
    const slot = a.querySelector(".ep-toc-page");
    slot.textContent = pages[a.getAttribute("href").slice(1)] || "";
    slot.style.visibility = "visible";
  }
})
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
  // A line of code too long for the column, with no space to wrap at (the print stylesheet
  // wraps code at spaces only, never inside a token such as 1e-12): the block shrinks.
  for (const el of document.querySelectorAll("pre")) {
    if (el.scrollWidth > el.clientWidth + 1) {
      el.style.zoom = (0.99 * el.clientWidth / el.scrollWidth).toFixed(3);
      fitted++;
    }
  }
  return fitted;
})()
"""
# Every page has its number at the foot (Chromium's template fills .pageNumber); no header.
FOOTER = ('<div style="font-size:8px;width:100%;text-align:center">'
          '<span class="pageNumber"></span></div>')
# A box that does not break across pages (the print stylesheet's .ep-keep) must be short:
# one taller than the space left on a page moves whole to the next and leaves that space
# empty, and one taller than a page breaks anyway. Exercises, proofs, admonitions, code
# cells and blocks, and tables up to a third of a page are kept whole; longer ones break
# where they must.
KEEP = """
(height => {
  let kept = 0;
  // A cell's input box too, not only the code block in it: else its frame stays behind.
  const boxes = ".admonition, .proof, div.cell, .cell_input, .exercise, table, div.highlight";
  for (const el of document.querySelectorAll(boxes)) {
    if (el.getBoundingClientRect().height < height) { el.classList.add("ep-keep"); kept++; }
  }
  return kept;
})
"""
PAPER = {"paperWidth": 8.27, "paperHeight": 11.69, "marginTop": 0.6, "marginBottom": 0.6,
         "marginLeft": 0.6, "marginRight": 0.6}  # A4, in inches
# The width of the printed column in CSS pixels (96 per inch): the page is laid out at it.
COLUMN = int((PAPER["paperWidth"] - PAPER["marginLeft"] - PAPER["marginRight"]) * 96)
PAGE_HEIGHT = int((PAPER["paperHeight"] - PAPER["marginTop"] - PAPER["marginBottom"]) * 96)


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


def print_pdf(page: Path, pdf: Path, open_solutions: bool = False, timeout: float = 300,
              title_page: list[tuple[str, str]] | None = None) -> dict:
    """Print one local HTML file to a PDF file; return what was seen (for the caller's log).

    title_page: the lines added under the title on the first page, (CSS class, text)."""
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
            hints = tools.evaluate(OPEN_HINTS)
            prepared = tools.evaluate(f"{PREPARE}({json.dumps(title_page or [])})")
            images = tools.evaluate("document.images.length")
            fitted = tools.evaluate(FIT)
            kept = tools.evaluate(f"{KEEP}({PAGE_HEIGHT / 3})")
            errors = tools.evaluate(
                "[...document.querySelectorAll('mjx-merror')].map(e =>"
                " (e.getAttribute('data-mjx-error') || '') + ' in: ' +"
                " (e.closest('section') || document.body).id)")
            if errors:
                raise RuntimeError(f"MathJax could not typeset {len(errors)} formulas in "
                                   f"{page}: {errors[:5]}")
            targets = tools.evaluate(TOC_SLOTS)
            # Print, read on which page each entry of the contents landed, write the numbers
            # in and print again; the slots keep the layout, and a last read checks it.
            pages: dict[str, int] = {}
            passes = 0
            while True:
                passes += 1
                data = base64.b64decode(tools.call(
                    "Page.printToPDF", timeout=timeout, printBackground=True, **PAPER,
                    displayHeaderFooter=True, headerTemplate="<span></span>",
                    footerTemplate=FOOTER, generateDocumentOutline=True,
                    generateTaggedPDF=True)["data"])
                found = destination_pages(data, targets)
                if found == pages:
                    break
                if passes == 3:
                    raise RuntimeError(f"{page}: the contents' page numbers did not settle")
                pages = found
                tools.evaluate(f"{TOC_PAGES}({json.dumps(pages)})")
        finally:
            tools.close()
    finally:
        proc.terminate()
        proc.wait(timeout=30)
        shutil.rmtree(profile, ignore_errors=True)
    if missing := [t for t in targets if t not in pages]:
        raise RuntimeError(f"{page}: entries of the contents with no page: {missing[:5]}")
    pdf.parent.mkdir(parents=True, exist_ok=True)
    pdf.write_bytes(data)
    return {"formulas": formulas, "solutions": solutions, "hints": hints, "images": images,
            "fitted": fitted, "kept": kept, "passes": passes, "contents": len(pages), **prepared}


def destination_pages(data: bytes, names: list[str]) -> dict[str, int]:
    """The page (from 1) of each named destination of a PDF: Chromium names the target of
    every link into the document by the element's id."""
    from pypdf import PdfReader

    reader = PdfReader(io.BytesIO(data))
    wanted = set(names)
    found = {name[1:]: reader.get_destination_page_number(dest)
             for name, dest in reader.named_destinations.items() if name[1:] in wanted}
    return {name: page + 1 for name, page in found.items() if page is not None}


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
