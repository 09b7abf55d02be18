"""Each published site is one self-contained folder, and the student site holds no solution.

The two sites are what `make book` and `make book-student` build: ``html`` with the reference
in ``html/reference`` (tests/conftest.py builds them that way). Each is copied alone to
another temporary folder, as a reader gets it from a web server or a zip, and checked there:

* every page (parsed with html.parser): each ``href`` and ``src`` is relative and resolves to
  a file inside the copy, and each ``#fragment`` names an ``id`` (or ``name``) of its page;
  the copy is served by ``python -m http.server`` on 127.0.0.1 and every file the pages
  link is fetched from it;
* nothing refers to a local path: no ``file:`` URL, no absolute path, neither the build
  folder nor the repository's path in any text file;
* nothing is loaded from the network: an http(s) URL may only be the ``href`` of a plain
  ``<a>`` link to a work the book cites or a licence (``outward_urls``);
* in Chromium, over http, the search pages of the book and of its reference find a word and
  show snippets of the pages (Sphinx's search reads ``searchindex.js`` and fetches the pages
  for the snippets, which works over http, not from file://).

The pages, links and anchors checked per site go to the terminal summary ("site check").

The student site holds no solution in any file: the text of each solution, taken from the
book's sources (every ``{solution-start}`` .. ``{solution-end}`` block), is searched for in
every file of the student build (pages, ``_sources``, the search index, notebooks, the zips
opened) and must not be there; the same search finds it in the instructor build.
"""

from __future__ import annotations

import html
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.parse
import urllib.request
import zipfile
from collections.abc import Iterator
from html.parser import HTMLParser
from pathlib import Path

import pytest

from tests.book.test_browser import Browser
from tests.conftest import BOOK, DOCS, ROOT, SUMMARY, Build

# Plain <a href> links out of the site (never a src, a <link> or a <script>): where a reader
# goes to read more, nothing that a page needs in order to work. Only these are allowed:
# the works the book cites (the url and doi fields of book/references.bib, on the
# references page and where a page cites them) and the licences' legal codes (about.md).
LICENCES = {
    "https://creativecommons.org/licenses/by/4.0/",
    "https://creativecommons.org/licenses/by/4.0/legalcode",
    "https://opensource.org/license/mit",
}


def outward_urls() -> set[str]:
    """The URLs a page may link to: the references' and the licences'."""
    bib = (BOOK / "references.bib").read_text(encoding="utf-8")
    urls = set(re.findall(r"^\s*url\s*=\s*\{([^}]+)\}", bib, re.M))
    urls |= {f"https://doi.org/{d}" for d in re.findall(r"^\s*doi\s*=\s*\{([^}]+)\}", bib, re.M)}
    return urls | LICENCES


# Attributes that hold a URL the browser loads or follows.
URL_ATTRIBUTES = {"href", "src", "poster", "data"}


class _Page(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.urls: list[tuple[str, str, str]] = []  # (tag, attribute, value)
        self.ids: set[str] = set()
        self.text: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        for key, value in attrs:
            if value is None:
                continue
            if key in ("id", "name") and (key == "id" or tag == "a"):
                self.ids.add(value)
            if key in URL_ATTRIBUTES:
                self.urls.append((tag, key, value.strip()))
            if key == "srcset":
                for part in value.split(","):
                    if part.strip():
                        self.urls.append((tag, key, part.split()[0]))

    def handle_data(self, data: str) -> None:
        self.text.append(data)


def _parse(page: Path) -> _Page:
    parser = _Page()
    parser.feed(page.read_text(encoding="utf-8"))
    parser.close()
    return parser


def _pages(site: Path) -> list[Path]:
    """The pages of a site (the theme's templates in _static are not pages)."""
    return [p for p in sorted(site.rglob("*.html")) if "_static" not in p.relative_to(site).parts]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Served:
    """A folder served by ``python -m http.server`` on 127.0.0.1 while the object lives."""

    def __init__(self, folder: Path) -> None:
        self.port = _free_port()
        self.url = f"http://127.0.0.1:{self.port}/"
        self.process = subprocess.Popen(
            [sys.executable, "-m", "http.server", str(self.port), "--bind", "127.0.0.1",
             "--directory", str(folder)],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        )
        for _ in range(100):
            try:
                urllib.request.urlopen(self.url, timeout=2).close()
                return
            except OSError:
                time.sleep(0.1)
        self.close()
        raise RuntimeError("python -m http.server did not answer")

    def status(self, path: str) -> int:
        request = urllib.request.Request(self.url + path, method="HEAD")
        try:
            with urllib.request.urlopen(request, timeout=10) as reply:
                return reply.status
        except urllib.error.HTTPError as err:
            return err.code

    def close(self) -> None:
        self.process.terminate()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()


def _site(build: Build) -> Path:
    if build.returncode != 0:
        pytest.fail(f"{build.outdir} did not build; see the build tests", pytrace=False)
    return build.outdir


@pytest.fixture(scope="module")
def copies(book_build: Build, student_book: Build, book_ja_build: Build,
           student_ja_build: Build, readme_runs, tmp_path_factory) -> dict[str, tuple]:
    """site -> (the copy, the folder it was built in): the published folder that `make site`
    put together, and the student site inside it, each copied alone (the student site can be
    served alone), with its Japanese edition in ja/ (the language switch links the two)."""
    assert readme_runs.result("make site").returncode == 0, "make site failed: test_readme"
    found = {}
    for name, build in (("book", book_build), ("student", student_book)):
        built = _site(build)
        _site(book_ja_build if name == "book" else student_ja_build)
        copy = tmp_path_factory.mktemp(f"copied-{name}") / "site"
        # The browser test leaves its screenshots in the build: not part of the site.
        shutil.copytree(built, copy, ignore=shutil.ignore_patterns("_screenshots"))
        found[name] = (copy, built)
    return found


@pytest.fixture(scope="module")
def checked(copies: dict) -> dict[str, dict]:
    """site -> what the link check found: the problems, and how much was checked."""
    result = {}
    for name, (copy, built) in copies.items():
        result[name] = _check_links(copy, built)
    SUMMARY["site check"] = [
        f"{name}: {r['pages']} pages, {r['links']} links ({r['files']} files fetched over "
        f"http), {r['anchors']} anchors, {r['outward']} outward <a> links to "
        f"{len(r['hosts'])} hosts ({', '.join(sorted(r['hosts']))})"
        for name, r in result.items()
    ]
    return result


def _check_links(copy: Path, built: Path) -> dict:
    problems: list[str] = []
    parsed = {page: _parse(page) for page in _pages(copy)}
    links = anchors = outward = 0
    hosts: set[str] = set()
    allowed = outward_urls()
    targets: set[str] = set()
    for page, found in parsed.items():
        name = page.relative_to(copy).as_posix()
        for tag, key, url in found.urls:
            links += 1
            parts = urllib.parse.urlsplit(url)
            if parts.scheme in ("http", "https") or url.startswith("//"):
                if tag == "a" and key == "href" and url in allowed:
                    outward += 1
                    hosts.add(parts.hostname)
                else:
                    problems.append(f"{name}: <{tag} {key}={url}> from the network")
                continue
            if parts.scheme in ("mailto", "data"):
                continue
            if parts.scheme or parts.netloc or parts.path.startswith("/"):
                problems.append(f"{name}: <{tag} {key}={url}> not relative")
                continue
            path = urllib.parse.unquote(parts.path)
            target = page if not path else (page.parent / path)
            if path.endswith("/") or (target.is_dir() and path):
                target = target / "index.html"
            target = Path(_normalise(target))
            if copy not in target.parents:
                problems.append(f"{name}: {url} leaves the site")
                continue
            if not target.is_file():
                problems.append(f"{name}: {url} is missing")
                continue
            targets.add(target.relative_to(copy).as_posix())
            if parts.fragment and target.suffix == ".html":
                anchors += 1
                fragment = urllib.parse.unquote(parts.fragment)
                if fragment not in parsed[target].ids:
                    problems.append(f"{name}: {url} has no anchor #{fragment}")
    # The same files, over http: what a web server serves from the copied folder.
    served = Served(copy)
    try:
        for target in sorted(targets):
            status = served.status(urllib.parse.quote(target))
            if status != 200:
                problems.append(f"{target}: HTTP {status}")
    finally:
        served.close()
    problems += _local_paths(copy, built)
    return {"problems": problems, "pages": len(parsed), "links": links, "anchors": anchors,
            "outward": outward, "hosts": hosts, "files": len(targets)}


def _normalise(path: Path) -> str:
    return os.path.normpath(path)


TEXT_SUFFIXES = {".html", ".js", ".css", ".txt", ".md", ".ipynb", ".json", ".inv", ".xml"}


def _local_paths(copy: Path, built: Path) -> list[str]:
    """Text files that name the build folder, the repository or a file: URL."""
    machine = {str(built), str(built.parent), str(ROOT), str(Path.home())}
    problems = []
    for path in sorted(copy.rglob("*")):
        if not path.is_file() or path.suffix not in TEXT_SUFFIXES:
            continue
        if "mathjax" in path.relative_to(copy).parts:
            continue  # MathJax's own code, untouched by the build
        text = path.read_text(encoding="utf-8", errors="replace")
        name = path.relative_to(copy).as_posix()
        for local in machine:
            if local in text:
                problems.append(f"{name}: names {local}")
        if path.suffix == ".html" and "file://" in text:
            problems.append(f"{name}: a file:// URL")
    return problems


@pytest.mark.parametrize("site", ["book", "student"])
def test_every_link_and_anchor_resolves_inside_the_copied_site(checked: dict, site: str) -> None:
    found = checked[site]
    assert found["pages"] > 20 and found["links"] > 1000 and found["anchors"] > 100
    assert found["problems"] == []


@pytest.mark.parametrize("site", ["book", "student"])
def test_the_site_holds_its_reference(copies: dict, site: str) -> None:
    copy, _ = copies[site]
    assert (copy / "reference" / "api.html").is_file()
    assert (copy / "reference" / "objects.inv").is_file()
    # The doctrees (pickles holding the build machine's paths) are kept out of the site.
    assert not list(copy.rglob(".doctrees"))
    pages = {p: (copy / p).read_text(encoding="utf-8") for p in ("index.html", "energy.html")}
    assert any('href="reference/api.html#elliptic_pendulum.' in t for t in pages.values())


# Wait until Sphinx's search has listed its results and made their snippets: it fetches every
# page it lists, one after another, which took more than 30 s on a loaded 2-core CI machine;
# the wait ends as soon as the snippets are there, or after 3 minutes.
SEARCH = r"""
(async () => {
  const deadline = Date.now() + 180000;
  while (Date.now() < deadline) {
    const items = document.querySelectorAll('#search-results li');
    const snippets = [...document.querySelectorAll('#search-results li p.context')]
      .filter((p) => p.textContent.trim().length > 20);
    // Finished when searchtools.js says so in its status line (its _pulse_status can go back
    // to counting after the search stops: a pulse timer that fires late restarts it).
    // The line is in the page's language (the Japanese edition's too): ask for it the way
    // searchtools.js writes it.
    const done = typeof Search !== 'undefined' && Search.status && items.length > 0 &&
      Search.status.innerText === Documentation.ngettext(
        'Search finished, found one page matching the search query.',
        'Search finished, found ${resultCount} pages matching the search query.',
        items.length).replace('${resultCount}', items.length);
    if (done && snippets.length > 0) {
      return {items: items.length, snippets: snippets.length,
              highlighted: document.querySelectorAll('#search-results p.context .highlighted')
                .length,
              first: snippets[0].textContent.trim().slice(0, 120),
              links: [...document.querySelectorAll('#search-results li a')].map((a) => a.href)};
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  return {items: document.querySelectorAll('#search-results li').length, snippets: 0,
          text: (document.querySelector('#search-results') || document.body).textContent
            .slice(0, 300)};
})()
"""


@pytest.mark.parametrize("site", ["book", "student"])
def test_search_finds_a_word_with_snippets_over_http(
    copies: dict, site: str, chromium: str, tmp_path: Path
) -> None:
    copy, _ = copies[site]
    served = Served(copy)
    browser = Browser(chromium, tmp_path / "profile", serving="127.0.0.1")
    try:
        # The Japanese edition's search splits a query as its index is split (ja_search):
        # 楕円関数 is two words there, 楕円 and 関数.
        for page, word in (("search.html", "separatrix"), ("reference/search.html", "modulus"),
                           ("ja/search.html", "楕円関数")):
            browser.events()
            browser.call("Page.navigate", session=True,
                         url=f"{served.url}{page}?q={urllib.parse.quote(word)}")
            browser.wait_for("Page.loadEventFired")
            seen = browser.evaluate(SEARCH)
            elsewhere = sorted({
                e["params"]["request"]["url"] for e in browser.events()
                if e.get("method") == "Network.requestWillBeSent"
                and not e["params"]["request"]["url"].startswith((served.url, "data:"))
            })
            assert seen["items"] > 0 and seen["snippets"] > 0, (page, seen)
            assert seen["highlighted"] > 0, (page, seen)  # the word, shown in its context
            assert all(link.startswith(served.url) for link in seen["links"]), seen["links"]
            assert elsewhere == [], page
    finally:
        browser.close()
        served.close()


# --- No solution in the student site ---------------------------------------------------

# Markup that the HTML, the notebooks and the search index render differently from the
# source: math, roles, inline code, emphasis, list and table marks. The plain text between
# them is what a reader sees, and what the search looks for.
MARKUP = re.compile(r"\$\$?[^$]*\$\$?|\{[\w:+-]+\}`[^`]*`|`[^`]*`|[*_|\\]{1,2}|^\s*(\d+\.|[-+])\s")
MIN_LENGTH = 24


# A MyST directive's opening line: its fence and its name.
DIRECTIVE_OPEN = re.compile(r"^(?P<fence>`{3,}|:{3,})\{(?P<name>[^}]+)\}\s*(?P<arg>.*)$")


def solutions(text: str, keep: list[str] | None = None) -> list[list[str]]:
    """The source lines of each solution of a page: ``{solution-start}`` .. ``{solution-end}``
    blocks and ``{solution}`` directives, their directive lines and options left out. The
    lines outside every solution go to ``keep``, if given."""
    found: list[list[str]] = []
    lines = text.splitlines()
    i, current = 0, None
    while i < len(lines):
        opened = DIRECTIVE_OPEN.match(lines[i].strip())
        name = opened["name"].strip() if opened else ""
        if opened and name in {"solution", "solution-start", "solution-end"}:
            closing = re.compile(r"^\s*" + re.escape(opened["fence"][0]) + "{3,}\\s*$")
            body = []
            i += 1
            while i < len(lines) and not closing.match(lines[i]):
                body.append(lines[i])
                i += 1
            i += 1
            if name == "solution":
                found.append(body)
            elif name == "solution-start":
                current = []
                found.append(current)
            else:
                current = None
            continue
        if current is not None:
            current.append(lines[i])
        elif keep is not None:
            keep.append(lines[i])
        i += 1
    return found


def without_solutions(text: str) -> str:
    """A page's source with every solution left out."""
    kept: list[str] = []
    solutions(text, kept)
    return "\n".join(kept)


def _squash(text: str) -> str:
    # The same as re.sub(r"\s+", " ", text).strip() (str.split and re's \s split at the same
    # Unicode whitespace), several times faster on a site's megabytes.
    return " ".join(text.split())


def snippets(lines: list[str]) -> set[str]:
    """Distinctive pieces of a solution: its code lines, and the plain text of its prose
    between the markup, each at least MIN_LENGTH characters long."""
    found = set()
    in_code = False
    for line in lines:
        stripped = line.strip()
        if re.match(r"^(`{3,}|~{3,})", stripped):
            in_code = not in_code
            continue
        if not stripped or re.match(r"^(:[\w-]+:|---$|tags:|mystnb:)", stripped):
            continue
        pieces = [stripped] if in_code else MARKUP.split(stripped)
        for piece in pieces:
            piece = _squash(piece or "").strip(" ,.;:()")
            if len(piece) >= MIN_LENGTH and len(piece.split()) >= 3:
                found.add(piece)
    return found


def solution_snippets() -> dict[str, set[str]]:
    """``page:n`` -> the snippets of the n-th solution of the page, less those that the
    published text holds anyway (the book without solutions, the reference's sources and
    the package's docstrings), which would prove nothing."""
    public = [without_solutions(p.read_text(encoding="utf-8")) for p in sorted(BOOK.glob("*.md"))]
    public += [p.read_text(encoding="utf-8") for p in sorted(DOCS.glob("*.md"))]
    public += [p.read_text(encoding="utf-8") for p in sorted((ROOT / "src").rglob("*.py"))]
    public_text = _squash("\n".join(public))
    found = {}
    for page in sorted(BOOK.glob("*.md")):
        for n, lines in enumerate(solutions(page.read_text(encoding="utf-8")), 1):
            found[f"{page.stem}:{n}"] = {s for s in snippets(lines) if s not in public_text}
    return found


def _texts(path: Path, name: str, data: bytes) -> Iterator[tuple[str, str]]:
    """The readable text of one file (a zip's members one by one), as a reader or a search
    engine sees it: HTML without tags and entities, notebooks and JSON as their strings."""
    if name.endswith(".zip"):
        import io

        with zipfile.ZipFile(io.BytesIO(data)) as z:
            for member in z.namelist():
                yield from _texts(path, f"{name}!{member}", z.read(member))
        return
    text = data.decode("utf-8", errors="replace")
    if name.endswith((".html", ".htm")):
        yield name, html.unescape(re.sub(r"<[^>]+>", "", text))
    elif name.endswith((".ipynb", ".json")):
        try:
            yield name, "\n".join(_strings(json.loads(text)))
        except ValueError:
            yield name, text
    else:
        yield name, text
    yield name + " (raw)", text


def _strings(value) -> Iterator[str]:
    if isinstance(value, str):
        yield value
    elif isinstance(value, list):
        if all(isinstance(v, str) for v in value):  # a notebook cell's source lines
            yield "".join(value)
        else:
            for v in value:
                yield from _strings(v)
    elif isinstance(value, dict):
        for v in value.values():
            yield from _strings(v)


def scan_site(site: Path, wanted: dict[str, set[str]]) -> tuple[dict[str, list[str]], int]:
    """(solution -> the files in which one of its snippets appears, files scanned).

    Every snippet is looked for in every text, but through a word index: a snippet is
    squashed text of three words or more, so each of its inner words (the first and the
    last may be the ends of longer words of the text) is a whole word of a squashed text
    that holds it. A snippet is searched for in a text only when its inner words are all
    words of the text: the others cannot hold it (a thousand snippets searched in every
    file took minutes)."""
    by_word: dict[str, list[tuple[str, str, list[str]]]] = {}
    for solution, pieces in wanted.items():
        for piece in pieces:
            inner = piece.split(" ")[1:-1]
            assert inner, f"a snippet of fewer than three words: {piece!r}"
            by_word.setdefault(max(inner, key=len), []).append((solution, piece, inner))
    hits: dict[str, list[str]] = {}
    files = 0
    for path in sorted(site.rglob("*")):
        if not path.is_file():
            continue
        files += 1
        name = path.relative_to(site).as_posix()
        for where, text in _texts(path, name, path.read_bytes()):
            text = _squash(text)
            words = set(text.split(" "))
            found = {solution for word in by_word.keys() & words
                     for solution, piece, inner in by_word[word]
                     if all(w in words for w in inner) and piece in text}
            for solution in wanted:
                if solution in found:
                    hits.setdefault(solution, []).append(where)
    return hits, files


def test_the_student_site_holds_no_solution_in_any_file(copies: dict) -> None:
    wanted = solution_snippets()
    # Every solution of the book: one per exercise, counted from the pages' directives.
    exercises = sum(len(re.findall(r"^:{3,}\{exercise\}", p.read_text(encoding="utf-8"), re.M))
                    for p in BOOK.glob("*.md"))
    assert len(wanted) == exercises > 40, sorted(wanted)
    empty = [s for s, pieces in wanted.items() if not pieces]
    assert empty == [], "solutions without a distinctive snippet"
    student, instructor = copies["student"][0], copies["book"][0]
    leaks, scanned = scan_site(student, wanted)
    found, scanned_instructor = scan_site(instructor, wanted)
    count = sum(len(p) for p in wanted.values())
    SUMMARY["solution search"] = [
        f"{count} snippets of {len(wanted)} solutions; student site: {scanned} files scanned "
        f"(zips opened), {len(leaks)} solutions found; instructor site: {scanned_instructor} "
        f"files scanned, {len(found)} solutions found"
    ]
    assert leaks == {}
    # The same search finds every solution in the instructor site: the check can fail.
    assert sorted(found) == sorted(wanted)
    pages = {s for s, where in found.items() if any(w.endswith(".html") for w in where)}
    assert pages == set(wanted), "solutions not found in the instructor site's pages"


def test_the_student_site_offers_only_the_student_bundle(copies: dict) -> None:
    student, instructor = copies["student"][0], copies["book"][0]
    assert sorted(p.name for p in (student / "classroom").glob("*.zip")) == [
        "elliptic-pendulum-notebooks-student.zip"]
    for page in _pages(student):
        assert "instructor" not in " ".join(u for _, _, u in _parse(page).urls), page
    index = (instructor / "energy.html").read_text(encoding="utf-8")
    assert 'href="classroom/elliptic-pendulum-notebooks-instructor.zip"' in index
