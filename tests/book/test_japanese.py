"""The Japanese edition (book/_ext/i18n.py, book/locale/ja): built strictly from the same
pages and the same execution as the English, complete, and linked with it page by page.

The browser checks (MathJax, the 46 equation numbers, nothing cut off, axe-core) look at it
in test_browser.py, the link check and the search in test_site.py.
"""

from __future__ import annotations

import re
import subprocess
import sys
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path

import pytest

from tests.book._buildcheck import BookIndex
from tests.conftest import BOOK, ROOT, Build

JAPANESE_CHAR = re.compile(r"[\u3040-\u30ff\u4e00-\u9fff]")
LETTER = re.compile(r"[A-Za-z\u3040-\u30ff\u4e00-\u9fff]")


def _ok(build: Build) -> Path:
    if build.returncode != 0:
        pytest.fail("the Japanese edition did not build:\n" + build.output[-3000:],
                    pytrace=False)
    return build.outdir


# Pages that Sphinx and its extensions generate, with little or no prose of ours.
GENERATED = {"genindex.html", "search.html", "prf-prf.html"}
# Typography that docutils applies to English text only (its smart quotes: Sphinx leaves
# them out for Japanese), undone before outputs are compared.
TYPOGRAPHY = str.maketrans({"\u2019": "'", "\u2018": "'", "\u201c": '"', "\u201d": '"'})


def book_pages(site: Path) -> list[str]:
    """The English book's pages (the reference, the Japanese edition and the student site
    inside the published folder aside)."""
    skip = {"_static", "_sources", "_images", "_screenshots", "reference", "ja", "classroom",
            "student", "pdf"}
    return [str(p.relative_to(site)) for p in sorted(site.rglob("*.html"))
            if not skip & set(p.relative_to(site).parts)]


def plain(texts: list[str]) -> Counter[str]:
    return Counter(t.translate(TYPOGRAPHY).replace("\u2026", "...") for t in texts)


SIZE_UNIT = re.compile(r"\s*[kM]B\b")


class _Text(HTMLParser):
    """The text of a page's article, with what is the same in every language apart: math,
    code, cell outputs; and the glued values and the outputs on their own."""

    SAME = {"pre", "code", "script", "style", "mjx-container"}

    def __init__(self) -> None:
        super().__init__()
        self.prose: list[str] = []
        self.pasted: list[str] = []
        self.outputs: list[str] = []
        self.sizes: list[str] = []
        self._stack: list[tuple[str, str]] = []
        self._after_pasted = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag in {"br", "img", "meta", "link", "input", "hr"}:
            return
        classes = dict(attrs).get("class") or ""
        self._stack.append((tag, classes))

    def handle_endtag(self, tag: str) -> None:
        while self._stack:
            if self._stack.pop()[0] == tag:
                break

    def handle_data(self, data: str) -> None:
        classes = " ".join(c for _, c in self._stack)
        tags = {t for t, _ in self._stack}
        if "bd-article" not in classes and "article" not in tags:
            return
        if "pasted-text" in classes:
            self.pasted.append(data.strip())
        elif "cell_output" in classes and not tags & {"script", "style"}:
            # Captions are translated, and so are the titles of the pages an output links to
            # and the animation player's controls (interface, book/_ext/i18n.py).
            if data.strip() and not tags & {"figcaption", "caption", "a"} and (
                    "anim-state" not in classes):
                self.outputs.append(data.strip())
        elif not (tags & self.SAME or "math" in classes.split()):
            # A glued size ("3.0 MB") is the edition's own: the pages embed their own images.
            if self.pasted and self._after_pasted and SIZE_UNIT.match(data):
                self.sizes.append(self.pasted.pop())
            self.prose.append(data)
        self._after_pasted = "pasted-text" in classes


def read(path: Path) -> _Text:
    parser = _Text()
    parser.feed(path.read_text(encoding="utf-8"))
    return parser


def test_the_japanese_edition_builds_strictly_and_runs_its_cells_in_japanese(
        book_ja_build: Build) -> None:
    _ok(book_ja_build)
    assert book_ja_build.warnings == []
    # Its own execution, into its own cache (book/_ext/kernels.py): on the fresh copy every
    # page ran, in Japanese.
    assert book_ja_build.output.count("Executing notebook") >= 19


def test_the_japanese_doctrees_hold_no_message_documents(book_ja_build: Build) -> None:
    # Sphinx parses each translated message as a document of its own, whose settings hold the
    # build environment; text nodes kept a reference to it, and every pickled page carried
    # the environment (10 MB a page, a second to load for each later build and the PDFs).
    # book/_ext/i18n.py drops the references: here, none is left, and a page weighs about
    # what the English one does.
    import pickle

    from docutils import nodes

    doctrees = _ok(book_ja_build).parents[1] / "doctrees"
    pages = sorted((doctrees / "book-ja").glob("*.doctree"))
    assert len(pages) > 20
    for page in pages:
        tree = pickle.loads(page.read_bytes())
        foreign = [node for node in tree.findall()
                   if isinstance(vars(node).get("_document"), nodes.document)
                   and node._document is not tree]
        assert foreign == [], (page.name, foreign[:3])
        english = doctrees / "book" / page.name
        assert page.stat().st_size < 3 * english.stat().st_size + 100_000, page.name


def test_the_student_edition_in_japanese_builds_strictly(student_ja_build: Build) -> None:
    site = _ok(student_ja_build)
    assert student_ja_build.warnings == []
    # The Japanese edition's cache served it: each edition runs each page once.
    assert "Executing notebook" not in student_ja_build.output
    assert "の解答" not in (site / "energy.html").read_text(encoding="utf-8")


def test_every_page_has_its_japanese_page_and_they_link_each_other(
    built_book: Path, book_ja_build: Build
) -> None:
    ja = _ok(book_ja_build)
    pages = book_pages(built_book)
    assert len(pages) >= 20
    for page in pages:
        english = (built_book / page).read_text(encoding="utf-8")
        japanese = (ja / page).read_text(encoding="utf-8")
        assert '<html lang="ja"' in japanese and '<html lang="en"' in english, page
        up = "../" * page.count("/")
        for html, lang, href in ((english, "ja", f"{up}ja/{page}"),
                                 (japanese, "en", f"{up}../{page}")):
            assert f'<link rel="alternate" hreflang="{lang}" href="{href}"' in html, page
            assert re.search(rf'class="[^"]*language-switch__link[^"]*" href="{re.escape(href)}"'
                             rf' hreflang="{lang}"', html), page


# A number as the outputs write it: 2.1e-16, 0.847213, 1234, 10^-9 aside; one-digit integers
# are left out, as the Japanese writes some the English spells ("1 周期" for "one period").
NUMBER = re.compile(r"(?<![\w.])-?(?:\d+\.\d+(?:e[-+]?\d+)?|\d+e[-+]?\d+|\d{2,})(?!\w|\.\d)")


# What a page embeds is its edition's own size (the animation's frames carry their labels).
SIZE = re.compile(r"\d+(?:\.\d+)? [kM]B\b")


def numbers(texts: list[str]) -> Counter[str]:
    return Counter(NUMBER.findall(SIZE.sub("", " ".join(texts).replace("\u2212", "-"))))


def test_both_editions_show_the_same_numbers(built_book: Path, book_ja_build: Build) -> None:
    # Each edition runs its own cells (in its own language), so its numbers are computed
    # twice: the glued values of the text must be exactly the English build's, and the
    # numbers in the cell outputs (verdicts, tables, printed values) the same ones, page by
    # page (their order may differ with the sentences).
    ja = _ok(book_ja_build)
    pasted = compared = 0
    for page in book_pages(built_book):
        english, japanese = read(built_book / page), read(ja / page)
        assert plain(japanese.pasted) == plain(english.pasted), page
        assert numbers(japanese.outputs) == numbers(english.outputs), page
        pasted += len(english.pasted)
        compared += sum(numbers(english.outputs).values())
    assert pasted > 100  # 121 glued values in the text when this was written
    assert compared > 500


def test_every_page_reads_in_japanese(built_book: Path, book_ja_build: Build) -> None:
    # The prose of each page (math, code, outputs aside): mostly Japanese characters, and
    # no English paragraph left (an untranslated or fuzzy message shows the English).
    ja = _ok(book_ja_build)
    shares = {}
    for page in sorted(set(book_pages(built_book)) - GENERATED):
        text = "".join(read(ja / page).prose)
        letters = LETTER.findall(text)
        shares[page] = len(JAPANESE_CHAR.findall(text)) / max(len(letters), 1)
    print({page: round(share, 2) for page, share in shares.items()})
    # The glossary's English column and the reference list are English by design.
    low = {page: share for page, share in shares.items() if share < 0.6
           and page not in {"glossary.html", "references.html"}}
    assert low == {}


class _Visible(HTMLParser):
    """The text a reader sees in a page's article, code and math aside (they are the same in
    every language): the prose, the cell outputs and the figures' captions; and the images."""

    SKIP_TAGS = {"code", "script", "style", "mjx-container", "svg"}
    SKIP_CLASSES = {"cell_input", "math", "highlight"}
    VOID = {"br", "img", "meta", "link", "input", "hr", "source", "wbr"}

    def __init__(self) -> None:
        super().__init__()
        self.texts: list[str] = []
        self.images: list[str] = []
        self._stack: list[tuple[str, set[str]]] = []

    def _in_article(self) -> bool:
        return any(t == "article" or "bd-article" in c for t, c in self._stack)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "img" and self._in_article():
            self.images.append(dict(attrs).get("src") or "")
        if tag in self.VOID:
            return
        self._stack.append((tag, set((dict(attrs).get("class") or "").split())))

    def handle_endtag(self, tag: str) -> None:
        while self._stack:
            if self._stack.pop()[0] == tag:
                break

    def handle_data(self, data: str) -> None:
        if not data.strip() or not self._in_article():
            return
        if any(t in self.SKIP_TAGS or c & self.SKIP_CLASSES for t, c in self._stack):
            return
        self.texts.append(data)


def visible(path: Path) -> _Visible:
    parser = _Visible()
    parser.feed(path.read_text(encoding="utf-8"))
    return parser


# The chapters a Japanese student reads (the glossary's English column and the list of
# references are English by design).
NOT_CHAPTERS = GENERATED | {"glossary.html", "references.html"}
# A run of three or more English words (tests/ja_text.py) that a chapter may keep: names
# written in Latin letters ("Abramowitz and Stegun", "On-Line Encyclopedia of Integer
# Sequences") and nbgrader's own marker. The bar: at most this many per chapter.
MOST_ENGLISH_RUNS = 20


def test_a_japanese_chapter_reads_in_japanese_outputs_included(
        built_book: Path, book_ja_build: Build) -> None:
    from tests.ja_text import english_runs

    ja = _ok(book_ja_build)
    counts, english = {}, {}
    for page in sorted(set(book_pages(built_book)) - NOT_CHAPTERS):
        runs = [r for text in visible(ja / page).texts for r in english_runs(text)]
        counts[page] = runs
        english[page] = sum(len(english_runs(t)) for t in visible(built_book / page).texts)
    print("runs of English words per Japanese chapter:",
          {page: len(runs) for page, runs in counts.items() if runs},
          f"(total {sum(map(len, counts.values()))}; the English chapters: "
          f"{sum(english.values())})")
    # The count sees what it should: the English chapters, outputs included, are all runs.
    assert sum(english.values()) > 2000
    assert {page: runs for page, runs in counts.items() if len(runs) > MOST_ENGLISH_RUNS} == {}


def test_no_japanese_figure_is_the_english_one(built_book: Path, book_ja_build: Build) -> None:
    # Every figure of a Japanese chapter is its own image (Japanese labels, legends, titles:
    # the library drew it in the edition's language), never the English file.
    import hashlib

    ja = _ok(book_ja_build)

    def digests(site: Path, page: str) -> dict[str, str]:
        return {hashlib.sha256((site / page).parent.joinpath(src).read_bytes()).hexdigest(): src
                for src in visible(site / page).images if "_images/" in src}

    same, figures = {}, 0
    for page in sorted(set(book_pages(built_book)) - NOT_CHAPTERS):
        english, japanese = digests(built_book, page), digests(ja, page)
        assert len(japanese) == len(english), page
        figures += len(japanese)
        if english.keys() & japanese.keys():
            same[page] = sorted(japanese[d] for d in english.keys() & japanese.keys())
    print(f"figures of the Japanese chapters: {figures}, the English image: {len(same)} pages")
    assert figures >= 10  # 14 when this was written
    assert same == {}


def test_interface_strings_are_japanese(book_ja_build: Build) -> None:
    html = (_ok(book_ja_build) / "energy.html").read_text(encoding="utf-8")
    assert "の解答" in html and "Solution to" not in html  # sphinx-exercise's, reordered
    assert "コードを表示" in html  # myst-nb's code-cell toggle
    assert "本書を検索" in html  # the theme's search box
    assert ">図 " in html and ">演習 " in html
    # Sphinx's permalinks, the theme's sidebar toggles and colour switch, from our catalogs
    # (book/locale/ja/LC_MESSAGES/sphinx.po, book/locale/packages).
    for japanese in ("この見出しへのリンク", "目次の表示を切り替える", "システム設定に従う"):
        assert japanese in html, japanese
    for english in ("Link to this heading", "Toggle primary sidebar", "System Settings",
                    "Color mode"):
        assert english not in html, english
    player = (_ok(book_ja_build) / "in_motion.html").read_text(encoding="utf-8")
    assert 'title="再生"' in player and ">往復</label>" in player
    assert 'title="Play"' not in player and ">Reflect<" not in player


def test_every_message_is_translated_and_whole(gettext_build: Build) -> None:
    # `make i18n-status`: the gettext builder's templates of the current pages against the
    # catalogs (tools/i18n/status.py), built on this session's execution cache.
    build = gettext_build
    assert build.returncode == 0 and build.warnings == [], build.output[-3000:]
    assert "Executing notebook" not in build.output
    status = subprocess.run(
        [sys.executable, "-m", "tools.i18n.status", str(build.outdir), str(BOOK / "locale"),
         "ja"], cwd=ROOT, capture_output=True, text=True)
    print(status.stdout[-3000:])
    assert status.returncode == 0, status.stdout[-5000:]


@pytest.mark.parametrize("site", ["instructor", "student"])
def test_the_japanese_sites_offer_japanese_notebooks(
    site: str, book_ja_build: Build, student_ja_build: Build, index: BookIndex
) -> None:
    # Each chapter's download menu points into the edition's own classroom/ folder, at a
    # file that is there; the notebooks and the README there are in Japanese, with the
    # English edition's code (compared cell by cell below).
    import nbformat

    from tools.classroom import bundle

    ja = _ok(book_ja_build if site == "instructor" else student_ja_build)
    files = index.files
    editions = ("student", "instructor") if site == "instructor" else ("student",)
    for page, name in files.items():
        html = (ja / f"{page}.html").read_text(encoding="utf-8")
        links = set(re.findall(r'href="([^"]*classroom/[^"]+)"', html))
        wanted = {f"classroom/{e}/{name}" for e in editions} | {
            f"classroom/{bundle.bundle_name(e)}.zip" for e in editions}
        assert links == wanted, page
        for link in links:
            assert (ja / link).is_file(), (page, link)
    for edition in editions:
        folder = ja / "classroom" / edition
        notebooks = sorted(folder.glob("*.ipynb"))
        assert [p.name for p in notebooks] == list(files.values())
        for path in notebooks:
            text = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells
                             if c.cell_type == "markdown")
            # The prose: link targets and anchors (the English slugs of both editions) aside.
            text = re.sub(r'\]\([^)]*\)|<a id="[^"]*"></a>', "", text)
            assert len(JAPANESE_CHAR.findall(text)) > 0.3 * len(LETTER.findall(text)), path
        readme = (folder / bundle.README).read_text(encoding="utf-8")
        assert readme.startswith("# 単振り子と楕円関数") and "## ノートパソコンで" in readme
        # Its self-checks ask for Japanese, whatever the student's environment says.
        checks = [c.source for path in notebooks
                  for c in nbformat.read(path, as_version=4).cells
                  if c.metadata.get("classroom", {}).get("self_check")]
        assert checks and all("language='ja', " in source for source in checks)
    if site == "student":  # no solution reached the student's Japanese notebooks
        for path in (ja / "classroom" / "student").glob("*.ipynb"):
            text = path.read_text(encoding="utf-8")
            assert re.search(r"#+ 演習 \d+ の解答", text) is None, path
        assert not (ja / "classroom" / "instructor").exists()


# --- The Japanese notebooks against the English ones ---------------------------------------
# Both are written from their build's doctrees (tools/classroom/doctree.py); the English
# notebooks are the reference for everything that is not prose: the same cells, the same
# code, the same anchors, links and display formulas.
ANCHOR = re.compile(r'<a id="([^"]+)"></a>')
LINK = re.compile(r"\]\(([^)\s]*)\)")
DISPLAY = re.compile(r"\$\$(.+?)\$\$", re.S)
PLACEHOLDER = re.compile(r"^\w+ = \.\.\.  # .*$", re.M)


@pytest.mark.parametrize("edition", ["student", "instructor"])
def test_the_japanese_notebook_is_the_english_one_in_japanese(
        edition: str, built_book: Path, book_ja_build: Build) -> None:
    import nbformat

    from tools.i18n import status

    ja_site = _ok(book_ja_build)
    english = sorted((built_book / "classroom" / edition).glob("*.ipynb"))
    japanese = sorted((ja_site / "classroom" / edition).glob("*.ipynb"))
    assert [p.name for p in japanese] == [p.name for p in english] and english
    for path_en, path_ja in zip(english, japanese, strict=True):
        en, ja = (nbformat.read(p, as_version=4) for p in (path_en, path_ja))
        page = path_en.name
        # The Japanese notebook asks for its language in a code cell under the first
        # (tools/classroom/export.py: language_cells); the rest is the English one's.
        language = [c for c in ja.cells if c.metadata.get("classroom", {}).get("language")]
        assert [ja.cells.index(c) for c in language] == [1], page
        assert 'os.environ["LANGUAGE"] = "ja"' in language[0].source, page
        ja.cells.remove(language[0])
        assert [c.cell_type for c in ja.cells] == [c.cell_type for c in en.cells], page
        for c_en, c_ja in zip(en.cells, ja.cells, strict=True):
            if c_en.cell_type == "code":  # the same code; only the answer cell's comment
                # The Japanese self-checks ask for their language (language='ja').
                assert (PLACEHOLDER.sub("", c_ja.source).replace("language='ja', ", "")
                        == PLACEHOLDER.sub("", c_en.source)), page
                assert c_ja.metadata == c_en.metadata, page
                continue
            assert ANCHOR.findall(c_ja.source) == ANCHOR.findall(c_en.source), page
            assert sorted(LINK.findall(c_ja.source)) == sorted(LINK.findall(c_en.source)), page
            assert DISPLAY.findall(c_ja.source) == DISPLAY.findall(c_en.source), page
            # Emphasis that CommonMark reads as such next to Japanese brackets (the
            # catalogs' checker, tools/i18n/status.py, finds asterisks left as text).
            assert status._stray_asterisks(c_ja.source) <= status._stray_asterisks(
                c_en.source), (page, c_ja.source[:200])
            prose = DISPLAY.sub("", ANCHOR.sub("", c_en.source))
            if re.search(r"[A-Za-z]{4,} [a-z]{3,} [a-z]{3,}", prose):  # a sentence
                assert JAPANESE_CHAR.search(c_ja.source), (page, c_ja.source[:200])


def test_the_notebooks_own_words_are_japanese(book_ja_build: Build) -> None:
    # The headings the Japanese edition of the book gives the same things
    # (book/_ext/i18n.py: 演習 3 の解答; sphinx-proof and our catalogs: 補題, 証明, 図).
    import nbformat

    ja_site = _ok(book_ja_build)

    def text(edition: str) -> str:
        return "\n".join(c.source for p in sorted((ja_site / "classroom" / edition).glob(
            "*.ipynb")) for c in nbformat.read(p, as_version=4).cells
            if c.cell_type == "markdown")

    student, teacher = text("student"), text("instructor")
    assert re.search(r"^#### 演習 \d+$", student, re.M)
    assert re.search(r"^#### 演習 \d+ の解答$", teacher, re.M)
    assert "**補題 2（" in teacher and "**証明**" in teacher and "**図 1**" in teacher
    assert "**あなたの結果**" in student and "<b>ヒント</b>" in student
    assert "## 参考文献" in teacher
    for english in ("Exercise", "Solution to", "Your results", "Your answer", "Fig. ",
                    "Proof", "classroom notebook", "## References"):
        assert english not in student + teacher, english
