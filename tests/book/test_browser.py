"""A reader's view of the built book and reference site, in headless Chromium, offline.

Every page of both builds is opened from file:// at desktop (1280 px, then the window
narrowed to 1200 px: look_at) and phone (400 px) width, with every host name unresolvable,
and looked at once MathJax (served from the build) has finished typesetting
(``MathJax.startup.promise``):

* no MathJax error (``mjx-merror``, e.g. "\\tag not allowed in split environment");
* the equation numbers MathJax renders across the book (its ``mjx-eqn:N`` ids) are exactly
  the note's 1..46;
* at 400 px no display equation reaches past the viewport unless it sits in a box that scrolls
  sideways, and nothing else in the page is cut off at the right edge;
* every image has loaded (naturalWidth > 0), no file the page asks for is missing, and no
  request leaves the machine (a failed load is reported with its URL);
* no inline formula is cut off: MathJax 3 does not break inline math, and the theme puts each
  inline formula in a box that hides what overflows it (pydata-sphinx-theme's ``span.math``,
  ``overflow: hidden``), so a formula wider than that box is cut with no way to scroll to its
  end; a box that scrolls (reader.css) is fine;
* at 1280 and 1200 px every display formula fits its text column, its equation number
  included (at 400 px it may scroll inside its own block, above); at every width nothing
  reaches past the window's edge (a check's mark sits in the margin, inside the window);
* no accessibility violation that axe-core finds for WCAG 2.1 A and AA (the rules tagged
  ``wcag2a``, ``wcag2aa``, ``wcag21a``, ``wcag21aa``), run in the page once MathJax is done:
  at 1200 px only its rules that read the layout (LAYOUT_RULES);
  axe.min.js, the version package-lock.json pins (`make test` installs it with ``npm ci``
  into node_modules/), is evaluated in the page from that file over the same DevTools pipe,
  in the visit the other checks make. The counts per rule and axe's time go to the terminal
  summary ("accessibility"); ``test_axe_reports_violations`` shows on a small page with known
  faults that the same run reports them;
* the animation's player can be worked from the keyboard: each of its controls takes the
  focus and has a name.

The pages are those of the book (its reference aside) and of the reference site.

Screenshots of every page at both widths are kept in ``<build>/_screenshots/``.

Chromium is driven through the DevTools protocol over a pipe (``--remote-debugging-pipe``:
JSON messages separated by NUL bytes on file descriptors 3 and 4), so nothing beyond the
standard library, Debian's chromium and axe-core from npm is needed. Skipped when Chromium or
axe-core is missing, except under CI=true, where it fails instead (.ci/run installs Debian's
chromium and npm, `make test` runs ``npm ci``).
"""

from __future__ import annotations

import base64
import fcntl
import json
import os
import subprocess
import time
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from tests.conftest import ROOT, SUMMARY

pytestmark = pytest.mark.slow

# A desktop, the narrowest desktop the theme lays out with its margin (1200 px: the column is
# narrowest there), and a phone.
WIDTHS = (1280, 1200, 400)
DESKTOPS = (1280, 1200)
# The browser's visits: the desktop widths in one (the page loaded at 1280 px, then the
# window narrowed: look_at), the phone in its own (a mobile viewport, loaded as a phone does).
VISITS = (DESKTOPS, (400,))
# axe-core runs every WCAG 2.1 A and AA rule at 1280 and 400 px. At 1200 px the page is the
# 1280 px page in a column 80 px narrower: what can change is layout, so the rules that read
# it run there (text against what is drawn behind it, boxes that scroll), at a fraction of
# the time of the whole set.
LAYOUT_RULES = {1200: ["color-contrast", "scrollable-region-focusable"]}
HEIGHT = 900
NOTE_EQUATIONS = set(range(1, 47))  # the note numbers its equations (1)-(46)
# WCAG 2.0 and 2.1, levels A and AA, as axe-core tags its rules (its doc/rule-descriptions.md).
AXE_TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]


class Browser:
    """One headless Chromium and one tab, spoken to over the DevTools pipe."""

    def __init__(self, binary: str, profile: Path, serving: str | None = None) -> None:
        """``serving``: a host name or address still reached (a local server's 127.0.0.1)."""
        to_child, self._commands = os.pipe()  # the browser reads commands on its fd 3
        self._replies, from_child = os.pipe()  # and writes replies and events on fd 4
        # Out of the way of 3 and 4 first, so the two dup2 calls in the child cannot clash.
        high = [fcntl.fcntl(fd, fcntl.F_DUPFD, 10) for fd in (to_child, from_child)]
        os.close(to_child)
        os.close(from_child)

        def wire() -> None:
            os.dup2(high[0], 3)
            os.dup2(high[1], 4)

        self.process = subprocess.Popen(
            [
                binary,
                "--headless",
                "--remote-debugging-pipe",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-dev-shm-usage",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                "--no-first-run",
                "--hide-scrollbars",
                # Offline: no host name resolves, so any request for the network fails (and is
                # recorded below) instead of quietly succeeding on a connected machine.
                "--host-resolver-rules=MAP * ~NOTFOUND"
                + (f", EXCLUDE {serving}" if serving else ""),
                f"--user-data-dir={profile}",
                "about:blank",
            ],
            # Not pass_fds=(3, 4): Python marks those inheritable in the child before
            # preexec_fn runs, which fails (EBADF) when 3 or 4 is closed in this process at
            # the fork (another thread's browser had just closed its own pipe there). The
            # child's dup2 makes 3 and 4 inheritable by itself, and every other descriptor
            # this process opened is non-inheritable (PEP 446): close_fds is not needed.
            close_fds=False,
            preexec_fn=wire,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        for fd in high:
            os.close(fd)
        self._buffer = b""
        self._next_id = 0
        self._events: list[dict] = []
        target = self.call("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.call("Target.attachToTarget", targetId=target, flatten=True)[
            "sessionId"
        ]
        for domain in ("Page", "Runtime", "Network"):
            self.call(f"{domain}.enable", session=True)

    def _read(self) -> dict:
        while b"\0" not in self._buffer:
            chunk = os.read(self._replies, 1 << 20)
            if not chunk:
                raise RuntimeError("Chromium closed the DevTools pipe")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method: str, session: bool = False, **params) -> dict:
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params}
        if session:
            message["sessionId"] = self.session
        os.write(self._commands, json.dumps(message).encode() + b"\0")
        while True:
            reply = self._read()
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self._events.append(reply)

    def events(self) -> list[dict]:
        """The events received since the last call, oldest first."""
        events, self._events = self._events, []
        return events

    def wait_for(self, method: str) -> None:
        while True:
            if any(e.get("method") == method for e in self.events()):
                return
            self._events.append(self._read())

    def evaluate(self, expression: str, timeout: int = 60_000):
        """The value of ``expression`` (a promise awaited). ``timeout`` (ms) ends a script
        that runs that long without yielding; its promise then never settles and the call
        waits for ever, so it must cover the longest run (axe-core on the longest page)."""
        result = self.call(
            "Runtime.evaluate",
            session=True,
            expression=expression,
            awaitPromise=True,
            returnByValue=True,
            timeout=timeout,
        )
        if "exceptionDetails" in result:
            raise RuntimeError(json.dumps(result["exceptionDetails"])[:2000])
        return result["result"].get("value")

    def close(self) -> None:
        try:
            self.call("Browser.close")
        except (RuntimeError, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        os.close(self._commands)
        os.close(self._replies)


# Run in the page once MathJax is done. Returns what the tests look at, as plain data.
LOOK = r"""
(async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    await MathJax.startup.promise;
  }
  const width = document.documentElement.clientWidth;
  const label = (el) => {
    const math = el.closest('div.math, .math');
    const id = math && (math.id || (math.closest('[id]') || {}).id);
    return (id || el.tagName.toLowerCase()) + ': ' + (el.textContent || '').slice(0, 60);
  };
  // Past the left or the right edge of the viewport.
  const outside = (el) => {
    const r = el.getBoundingClientRect();
    return r.left < -1 || r.right > width + 1;
  };
  // A box that scrolls sideways, itself inside the viewport, holds what overflows it: the
  // reader can scroll to it. (A scrolling box wider than the screen does not count.)
  const scrolls = (el) => ['auto', 'scroll'].includes(getComputedStyle(el).overflowX);
  const inScroller = (el) => {
    for (let a = el.parentElement; a && a !== document.body; a = a.parentElement) {
      if (scrolls(a) && !outside(a)) return true;
    }
    return false;
  };
  const shown = (el) => {
    // Inside a closed fold (a check's mark, a hidden cell) Chromium still lays an element
    // out, but the reader does not see it until the fold is opened.
    const fold = el.closest('details:not([open])');
    if (fold && !el.closest('summary')) return false;
    const r = el.getBoundingClientRect();
    if (r.width === 0 || r.height === 0) return false;
    const s = getComputedStyle(el);
    return s.visibility !== 'hidden' && s.display !== 'none';
  };
  const merrors = [...document.querySelectorAll('mjx-merror')].map(
    (e) => (e.getAttribute('data-mjx-error') || e.textContent) + ' | ' + label(e));
  const numbers = [...document.querySelectorAll('[id^="mjx-eqn:"]')].map(
    (e) => e.id.slice('mjx-eqn:'.length));
  const cutEquations = [];
  for (const eq of document.querySelectorAll('mjx-container[display="true"]')) {
    const math = eq.querySelector('mjx-math') || eq;
    if (outside(math) && !inScroller(math)) {
      cutEquations.push(label(eq));
    }
  }
  // An inline formula cut off by a box that hides its overflow: the typeset formula (its
  // mjx-math) reaches past a box around it, up to its line (the theme's span.math), that does
  // not scroll, so the end of the formula cannot be seen at all. (Not scrollWidth: MathJax's
  // assistive MathML, invisible and laid out in the browser's own wider MathML fonts, makes
  // every box look wider than what it shows.)
  const hides = (el) => ['hidden', 'clip'].includes(getComputedStyle(el).overflowX);
  const cutInline = [];
  for (const eq of document.querySelectorAll('mjx-container:not([display="true"])')) {
    if (eq.closest('mjx-assistive-mml') || !shown(eq)) continue;
    const math = eq.querySelector(':scope > mjx-math') || eq;
    const r = math.getBoundingClientRect();
    const line = eq.closest('p, li, dd, dt, td, th, div, section') || document.body;
    for (let a = eq; a && a !== line; a = a.parentElement) {
      const box = a.getBoundingClientRect();
      if (hides(a) && (r.right > box.right + 1 || r.left < box.left - 1)) {
        cutInline.push(label(eq));
        break;
      }
    }
  }
  // A display formula wider than the text column (checked at desktop width): its block
  // scrolls (reader.css) or it reaches past the column, and its equation number, MathJax's
  // mjx-labels, is out of view. Every part of it, the number included, lies inside the
  // content box of its column (the article) and inside its own block.
  const wideDisplays = [];
  for (const eq of document.querySelectorAll('mjx-container[display="true"]')) {
    if (!shown(eq)) continue;
    const column = eq.closest('article') || document.querySelector('main') || document.body;
    const box = column.getBoundingClientRect();
    const pad = getComputedStyle(column);
    const left = box.left + parseFloat(pad.paddingLeft);
    const right = box.right - parseFloat(pad.paddingRight);
    const parts = [eq, ...eq.querySelectorAll('mjx-math, mjx-labels, mjx-mtd, mjx-mlabeledtr')];
    const past = parts.some((el) => {
      const r = el.getBoundingClientRect();
      return r.width > 0 && (r.left < left - 1 || r.right > right + 1);
    });
    if (past || eq.scrollWidth > eq.clientWidth + 1) wideDisplays.push(label(eq));
  }
  // Anything else of the page that reaches past an edge, outermost only.
  const cut = [];
  const main = document.querySelector('main') || document.body;
  for (const el of main.querySelectorAll('*')) {
    if (el.closest('mjx-assistive-mml') || !shown(el)) continue;
    if (!outside(el) || inScroller(el)) continue;
    if (cut.some((outer) => outer.contains(el))) continue;
    cut.push(el);
  }
  const images = [...document.images];
  for (const img of images) {
    img.loading = 'eager';
    try { await img.decode(); } catch (e) { /* reported below */ }
  }
  return {
    merrors, numbers, cutEquations, cutInline, wideDisplays,
    cut: cut.filter((el) => !el.matches('mjx-container[display="true"]')).map(
      (el) => el.tagName.toLowerCase() + '.' + [...el.classList].join('.') + ': '
        + (el.textContent || '').trim().slice(0, 60)),
    pageWidth: document.documentElement.scrollWidth, width,
    brokenImages: images.filter((i) => !(i.naturalWidth > 0)).map((i) => i.src),
    images: images.length,
    typeset: document.querySelectorAll('mjx-container').length,
    height: document.documentElement.scrollHeight,
  };
})()
"""


# Run in the page after LOOK (MathJax done) and after axe.min.js: the elements that violate
# each rule, as "selector | start of the element's HTML", and the rules that ran.
AXE_RUN = """
(async () => {
  // The whole page, MathJax's glyph boxes included. (Leaving them out, {exclude:
  // [['mjx-container > mjx-math']]}, made axe slower with this axe-core, not faster: it
  // tests every element against each of the hundreds of formulas left out, which took
  // longer than the rules take on the boxes, which hold no text.)
  const result = await axe.run(document, {
    runOnly: RULES ? {type: 'rule', values: RULES} : {type: 'tag', values: TAGS},
    resultTypes: ['violations'],
    // axe preloads the page's media and its style sheets (the "cssom"). A page opened from
    // file:// is an opaque origin whose style sheets' rules a script may not read, so axe
    // asks for each sheet again by XMLHttpRequest, which Chromium refuses for file:// URLs
    // (a Network.loadingFailed per sheet, net::ERR_FAILED). Only css-orientation-lock reads
    // that preload, and it is not among the rules run (test_no_accessibility_violations
    // checks): the media only, then.
    preload: {assets: ['media']},
  });
  const found = {};
  for (const rule of result.violations) {
    found[rule.id] = rule.nodes.map(
      (n) => n.target.join(' ') + ' | ' + n.html.replace(/\\s+/g, ' ').slice(0, 160));
  }
  const ran = ['violations', 'passes', 'incomplete', 'inapplicable'].flatMap(
    (kind) => result[kind].map((rule) => rule.id));
  return {version: axe.version, violations: found, ran};
})()
""".replace("TAGS", json.dumps(AXE_TAGS))


def run_axe(browser: Browser, script: str, rules: list[str] | None = None) -> dict:
    """axe-core's verdict on the page open in ``browser``: ``script`` (axe.min.js) is
    evaluated in it, from the file, over the DevTools pipe (nothing is fetched), then run
    with every WCAG 2.1 A and AA rule, or only ``rules``."""
    browser.evaluate(script + "\n;true")
    return browser.evaluate(AXE_RUN.replace("RULES", json.dumps(rules)), timeout=900_000)


# Run in in_motion.html: each control of the animation's player takes the keyboard's focus and
# has a name a screen reader says (axe's own rules check the names, this the focus).
PLAYER_KEYS = r"""
(() => {
  const player = document.querySelector('.ep-player .animation');
  if (!player) return null;
  const controls = [...player.querySelectorAll('button, input')];
  return controls.map((el) => {
    el.focus();
    const name = el.getAttribute('aria-label') || el.labels && [...el.labels].map(
      (l) => l.textContent).join(' ') || el.textContent;
    return {tag: el.tagName.toLowerCase(), type: el.type, name: (name || '').trim(),
            focused: document.activeElement === el, tabIndex: el.tabIndex};
  });
})()
"""


def pages(html_dir: Path, *besides: str) -> list[Path]:
    """Every page of a build, its own _static, the screenshots and the folders ``besides``
    aside (the book's ``reference``: the docs build, looked at on its own)."""
    skip = {"_static", "_sources", "_screenshots", "_images", ".doctrees", *besides}
    found = []
    # Walked without entering the folders left aside: another build (the student site in
    # student/) may be writing there while the survey starts.
    for root, dirs, files in os.walk(html_dir):
        dirs[:] = [d for d in dirs if d not in skip]
        found += [Path(root) / f for f in files if f.endswith(".html")]
    return sorted(found)


# The book site holds the reference in reference/ (`make book`); it is looked at as "docs".
# The student site is the book's pages without the solutions, from the same sources,
# templates and style sheets: not looked at a second time (that would double the survey).
# The Japanese edition, in the book's ja/ folder, is looked at as "ja". The student site
# inside the published folder (student/, `make book-student`) is left out with it.
BESIDES = {"book": ("reference", "ja", "student"), "ja": (), "docs": ()}
SITES = ("book", "ja", "docs")


def _metrics(browser: Browser, width: int) -> None:
    browser.call("Emulation.setDeviceMetricsOverride", session=True, width=width,
                 height=HEIGHT, deviceScaleFactor=1, mobile=width < 600)


# After a resize: the theme's own response to it, which pydata-sphinx-theme debounces by
# 300 ms (its scripts' addTabStopsToScrollableElements: a box that now scrolls sideways gets
# its tab stop then, as it does at load), then two animation frames to lay the page out.
RELAID = ("new Promise(r => setTimeout(() => requestAnimationFrame(() =>"
          " requestAnimationFrame(() => r(true))), 450))")


def look_at(
    browser: Browser, html_dir: Path, width: int, besides: tuple[str, ...] = (),
    axe: str = "", narrower: tuple[int, ...] = (),
) -> Iterator[tuple[int, str, dict]]:
    """(width, page, what the browser saw) for every page of ``html_dir``, opened at
    ``width``, then looked at again at each of the ``narrower`` desktop widths.

    A desktop width below the first is the same page in a narrower window: the theme lays it
    out by CSS alone (1200 and 1280 px fall in the same breakpoint of its grid), and MathJax
    does not typeset again on a resize. So the page is not loaded and typeset again for it:
    the window is narrowed, the page laid out again, and looked at (LOOK), axe-core's layout
    rules run and a screenshot taken at that width. Loads, requests and script errors are
    the page's, from its one load.
    """
    _metrics(browser, width)
    shots = html_dir / "_screenshots"
    shots.mkdir(exist_ok=True)

    def shoot(name: str, seen: dict, at: int) -> None:
        # The whole page, as a reader scrolls it (capped: the API page is long).
        shot = browser.call(
            "Page.captureScreenshot",
            session=True,
            format="jpeg",
            quality=70,
            captureBeyondViewport=True,
            clip={"x": 0, "y": 0, "width": at, "height": min(seen["height"], 12000), "scale": 1},
        )
        target = shots / f"{name.replace('/', '_').removesuffix('.html')}-{at}.jpg"
        target.write_bytes(base64.b64decode(shot["data"]))
        seen["screenshot"] = str(target)

    def check(seen: dict, at: int) -> None:
        if axe:
            start = time.perf_counter()
            seen["axe"] = run_axe(browser, axe, LAYOUT_RULES.get(at))
            seen["axe"]["seconds"] = time.perf_counter() - start

    for page in pages(html_dir, *besides):
        name = str(page.relative_to(html_dir))
        browser.events()
        browser.call("Page.navigate", session=True, url=page.as_uri())
        browser.wait_for("Page.loadEventFired")
        seen = browser.evaluate(LOOK)
        check(seen, width)
        if name == "in_motion.html":
            seen["player"] = browser.evaluate(PLAYER_KEYS)
        events = browser.events()
        seen["network"] = sorted(
            {
                e["params"]["request"]["url"]
                for e in events
                if e.get("method") == "Network.requestWillBeSent"
                and not e["params"]["request"]["url"].startswith(("file:", "data:", "blob:"))
            }
        )
        # A failed load names the request it ends by its id only: its URL is in the request.
        urls = {
            e["params"]["requestId"]: e["params"]["request"]["url"]
            for e in events
            if e.get("method") == "Network.requestWillBeSent"
        }
        seen["failed"] = sorted(
            {
                f"{urls.get(e['params']['requestId'], '?')}: {e['params'].get('errorText')}"
                f" ({e['params'].get('type')})"
                for e in events
                if e.get("method") == "Network.loadingFailed"
            }
        )
        seen["exceptions"] = [
            e["params"]["exceptionDetails"].get("text", "")
            + " "
            + str(e["params"]["exceptionDetails"].get("exception", {}).get("description", ""))[:200]
            for e in events
            if e.get("method") == "Runtime.exceptionThrown"
        ]
        shoot(name, seen, width)
        yield width, name, seen
        for at in narrower:
            _metrics(browser, at)
            browser.evaluate(RELAID)
            again = browser.evaluate(LOOK)
            check(again, at)
            later = browser.events()  # a resize loads nothing and throws nothing new
            again["network"] = seen["network"] + sorted(
                {e["params"]["request"]["url"] for e in later
                 if e.get("method") == "Network.requestWillBeSent"})
            again["failed"] = seen["failed"] + sorted(
                {str(e["params"].get("errorText")) for e in later
                 if e.get("method") == "Network.loadingFailed"})
            again["exceptions"] = seen["exceptions"] + [
                e["params"]["exceptionDetails"].get("text", "") for e in later
                if e.get("method") == "Runtime.exceptionThrown"]
            shoot(name, again, at)
            yield at, name, again
        if narrower:
            _metrics(browser, width)


@pytest.fixture(scope="module")
def folders(built_book: Path, built_docs: Path, book_ja_build, pdf_job,
            nbgrader_job, bundle_job) -> dict[str, Path]:
    # The PDFs, nbgrader's run and the bundles' venv are made while the browsers survey
    # (tests/book/conftest.py).
    if book_ja_build.returncode != 0:
        pytest.fail("the Japanese edition did not build; see test_japanese", pytrace=False)
    return {"book": built_book, "ja": book_ja_build.outdir, "docs": built_docs}


# Two browsers at once, one (site, width) each: the survey is most of this tier's time,
# and a browser spends much of it waiting (page loads, MathJax), so the two cores share it.
PARALLEL = 2


@pytest.fixture(scope="module")
def survey(
    folders: dict[str, Path], chromium: str, axe_script: str, tmp_path_factory, request
) -> dict:
    """(site, width) -> {page: what the browser saw}, for every page of the three sites."""

    def visit(site: str, widths: tuple[int, ...]) -> dict[tuple[str, int], tuple[dict, float]]:
        browser = Browser(chromium, tmp_path_factory.mktemp("chromium-profile"))
        seen: dict[int, dict] = {width: {} for width in widths}
        spent = dict.fromkeys(widths, 0.0)
        start = time.perf_counter()
        try:
            for width, page, what in look_at(browser, folders[site], widths[0], BESIDES[site],
                                             axe_script, widths[1:]):
                seen[width][page] = what
                spent[width] += time.perf_counter() - start
                start = time.perf_counter()
        finally:
            browser.close()
        return {(site, width): (seen[width], spent[width]) for width in widths}

    # One visit per site and VISITS entry: the desktop widths share their page loads.
    visits = [(site, widths) for site in SITES for widths in VISITS]
    results: dict[tuple[str, int], tuple[dict, float]] = {}
    with ThreadPoolExecutor(max_workers=PARALLEL) as pool:
        for done in pool.map(lambda visit_: visit(*visit_), visits):
            results.update(done)
    keys = [(site, width) for site in SITES for width in WIDTHS]
    found = {key: results[key][0] for key in keys}
    seconds = {key: results[key][1] for key in keys}
    # What the survey costs, per site and width (the CI budget is counted in minutes).
    SUMMARY["accessibility"] = [f"{line}; {seconds[key]:.0f} s"
                                for key, line in zip(found, axe_counts(found), strict=True)]
    # Say where the screenshots are: the builds of a test session live in a temporary folder.
    reporter = request.config.pluginmanager.get_plugin("terminalreporter")
    if reporter is not None:
        for html in folders.values():
            reporter.write_line(f"\nscreenshots: {html / '_screenshots'}")
    return found


def axe_counts(found: dict) -> list[str]:
    """One line per site and width: the pages looked at, and the elements violating each
    axe rule (or none)."""
    lines = []
    for (site, width), seen in found.items():
        rules: dict[str, int] = {}
        for page in seen.values():
            for rule, nodes in page["axe"]["violations"].items():
                rules[rule] = rules.get(rule, 0) + len(nodes)
        counts = ", ".join(f"{rule} {n}" for rule, n in sorted(rules.items())) or "none"
        axe_seconds = sum(page["axe"]["seconds"] for page in seen.values())
        lines.append(f"{site} @{width}: {len(seen)} pages, axe-core violations: {counts}"
                     f" (axe {axe_seconds:.0f} s)")
    return lines


def each(survey: dict, key: str, sites=SITES, widths=WIDTHS) -> dict:
    """{"site page @width": survey value} where that value is not empty."""
    return {
        f"{site} {page} @{width}": seen[key]
        for (site, width), found in survey.items()
        if site in sites and width in widths
        for page, seen in found.items()
        if seen[key]
    }


def test_every_page_was_looked_at(survey: dict, folders: dict[str, Path]) -> None:
    assert {site for site, _ in survey} == set(SITES)
    for (site, _), found in survey.items():
        html = folders[site]
        assert set(found) == {str(p.relative_to(html)) for p in pages(html, *BESIDES[site])}
        assert "index.html" in found
    # MathJax ran: the chapters have typeset formulas
    assert survey[("book", 1280)]["libration.html"]["typeset"] > 50


def test_no_mathjax_errors(survey: dict) -> None:
    assert each(survey, "merrors") == {}


@pytest.mark.parametrize("site", ["book", "ja"])
def test_equation_numbers_are_the_notes_1_to_46(survey: dict, site: str) -> None:
    found: dict[str, list[str]] = {}
    for page, seen in survey[(site, 1280)].items():
        for number in seen["numbers"]:
            found.setdefault(number, []).append(page)
    twice = {n: p for n, p in found.items() if len(p) > 1}
    assert twice == {}, "equation numbers rendered more than once"
    numbers = {int(n) for n in found if n.isdigit()}
    assert sorted(NOTE_EQUATIONS - numbers) == [], "missing equation numbers"
    assert sorted(set(found) - {str(n) for n in NOTE_EQUATIONS}) == [], "unexpected numbers"


def test_no_inline_formula_is_cut_off(survey: dict) -> None:
    assert each(survey, "cutInline") == {}


def test_every_display_formula_fits_the_column_on_a_desktop(survey: dict) -> None:
    assert each(survey, "wideDisplays", widths=(1280,)) == {}
    # The book's column is narrowest at 1200 px, where its margin appears: its formulas fit
    # there too. (The reference site's docstring formulas are held to 1280 px for now.)
    assert each(survey, "wideDisplays", sites=("book", "ja"), widths=DESKTOPS) == {}


def test_no_accessibility_violations(survey: dict, axe_script: str) -> None:
    versions = {seen["axe"]["version"] for found in survey.values() for seen in found.values()}
    # The version package-lock.json pins ran in every page.
    lock = json.loads((ROOT / "package-lock.json").read_text(encoding="utf-8"))
    assert versions == {lock["packages"]["node_modules/axe-core"]["version"]}
    violations = {
        where: found["violations"]
        for where, found in each(survey, "axe").items()
        if found["violations"]
    }
    assert violations == {}
    # No rule ran that reads the style sheets axe is told not to preload (AXE_RUN).
    assert {where: "css-orientation-lock" for where, found in each(survey, "axe").items()
            if "css-orientation-lock" in found["ran"]} == {}
    # At 1200 px the rules that read the layout ran on every page.
    assert {where for where, found in each(survey, "axe", widths=(1200,)).items()
            if not set(LAYOUT_RULES[1200]) <= set(found["ran"])} == set()


# A page with known violations, and the same page mended: the survey's run of axe-core
# reports what is wrong (it is not quietly running nothing) and nothing when it is fixed.
FLAWED_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>A flawed page</title></head>
<body><main><h1>A flawed page</h1>
<p><img src="data:image/gif;base64,R0lGODlhAQABAIAAAAAAAP///yH5BAEAAAAALAAAAAABAAEAAAIBRAA7"
  FIX_ALT></p>
<p style="color: FIX_COLOR; background: #fff">Text the reader must be able to read.</p>
<button type="button" FIX_NAME><span aria-hidden="true">&#9654;</span></button>
</main></body></html>
"""


def test_axe_reports_violations(chromium: str, axe_script: str, tmp_path: Path) -> None:
    flawed = FLAWED_PAGE.replace("FIX_ALT", "").replace("FIX_COLOR", "#aaa").replace(
        "FIX_NAME", "")
    mended = FLAWED_PAGE.replace("FIX_ALT", 'alt="a dot"').replace(
        "FIX_COLOR", "#333").replace("FIX_NAME", 'aria-label="Play"')
    browser = Browser(chromium, tmp_path / "profile")
    found = {}
    try:
        for name, text in (("flawed", flawed), ("mended", mended)):
            page = tmp_path / f"{name}.html"
            page.write_text(text, encoding="utf-8")
            browser.events()
            browser.call("Page.navigate", session=True, url=page.as_uri())
            browser.wait_for("Page.loadEventFired")
            found[name] = run_axe(browser, axe_script)
            found[name]["failed"] = [e for e in browser.events()
                                     if e.get("method") == "Network.loadingFailed"]
    finally:
        browser.close()
    # An image without alt text, grey (#aaa) on white (2.3:1), a button with no name.
    assert set(found["flawed"]["violations"]) == {"image-alt", "color-contrast", "button-name"}
    assert found["flawed"]["violations"]["image-alt"][0].startswith("img | <img")
    assert found["mended"]["violations"] == {}
    assert found["flawed"]["failed"] == found["mended"]["failed"] == []


@pytest.mark.parametrize("site", ["book", "ja"])
def test_the_animation_works_from_the_keyboard(survey: dict, site: str) -> None:
    controls = survey[(site, 1280)]["in_motion.html"]["player"]
    # matplotlib's player: nine buttons, the frame slider, three loop modes, each of which
    # must take the focus (tabIndex 0: reached with Tab) and have a name.
    assert controls is not None and len(controls) >= 10, controls
    assert [c for c in controls if not (c["focused"] and c["tabIndex"] >= 0 and c["name"])] == []
    assert any(c["type"] == "range" for c in controls)


def test_no_display_equation_is_cut_off_on_a_phone(survey: dict) -> None:
    assert each(survey, "cutEquations", widths=(400,)) == {}


def test_nothing_else_is_cut_off_at_any_width(survey: dict) -> None:
    # A check's mark in the margin (book/_ext/checkmarks.py) lies past the column but inside
    # the window: only what passes the window's edge is cut.
    assert each(survey, "cut") == {}


def test_every_image_loads(survey: dict) -> None:
    assert each(survey, "brokenImages") == {}
    assert survey[("book", 1280)]["energy.html"]["images"] > 0


def test_nothing_is_missing_or_fetched(survey: dict) -> None:
    assert each(survey, "network") == {}
    assert each(survey, "failed") == {}


def test_no_script_errors(survey: dict) -> None:
    assert each(survey, "exceptions") == {}


def test_screenshots_are_kept_in_the_builds(survey: dict) -> None:
    for found in survey.values():
        for seen in found.values():
            shot = Path(seen["screenshot"])
            assert shot.is_file() and shot.stat().st_size > 5_000, shot
            assert shot.parent.name == "_screenshots"
