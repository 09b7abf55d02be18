"""The book as PDF (tools/pdf, `make pdf`): a single-page build of each edition, English and
Japanese, printed by headless Chromium after MathJax. The PDFs are read back with pypdf:
every chapter title (the Japanese ones from book/locale's catalogs) and every equation number
of the note is there as text, the figures and formulas were drawn, the instructor's copy has
every solution open and the student's none; the Japanese body is set in a Mincho and its
headings in a Gothic.

And they are fit to print and to navigate (the PDF issue): a title page with the edition,
version, date and licences; an outline and tags; page numbers at the foot and in the table
of contents, which match; no screen controls, no link to a file of the build machine, no
number broken after its "e-", and no page left nearly empty.
"""

from __future__ import annotations

import importlib.metadata
import importlib.util
import os
import re
import shutil
import subprocess
from collections import Counter
from concurrent.futures import Future
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest
from babel.messages.pofile import read_po

from tests.book._buildcheck import BookIndex
from tests.conftest import BOOK, Build
from tools.pdf import build as build_pdf

pytestmark = pytest.mark.slow
REQUIRED = os.environ.get("CI") == "true"


def _need(what: str, ok: bool) -> None:
    if not ok:
        if REQUIRED:
            pytest.fail(f"{what} is required under CI=true", pytrace=False)
        pytest.skip(f"{what} is not installed")


@dataclass(frozen=True)
class Edition:
    """What a PDF of one language must say, from the sources: the chapter titles (the
    English pages' headings, or their translations in book/locale/ja), and the labels that
    Sphinx, sphinx-exercise and our catalogs print."""

    language: str
    chapters: list[str]
    figure: str  # "Fig. {}"
    exercise: str
    solution: str  # a pattern: the heading of a solution
    contents: str
    edition: dict[str, str] = field(default_factory=dict)
    licence: str = ""
    controls: tuple[str, ...] = ()

    def key(self, text: str) -> str:
        """Text as compared: English with its runs of space as one, Japanese (whose lines
        break anywhere, and where pypdf may read a space between two glyph runs) with none."""
        return re.sub(r"\s+", "" if self.language == "ja" else " ", text).strip()


def _translated(page: str, text: str) -> str:
    with (BOOK / "locale" / "ja" / "LC_MESSAGES" / f"{page}.po").open("rb") as po:
        message = read_po(po).get(text)
    assert message is not None and message.string, (page, text)  # make i18n-status holds it
    return str(message.string)


def _editions(titles: dict[str, str]) -> dict[str, Edition]:
    english = Edition(
        "en", [t for doc, t in titles.items() if doc != "index"], "Fig. {}", "Exercise {}",
        r"Solution to\s*Exercise \d+", "Contents",
        {"book": "Instructor edition", "book-student": "Student edition"},
        "Text and figures: CC BY 4.0; code: MIT",
        # What the screen shows to click on: myst-nb's toggles of folded cells, the
        # animation's hint in its caption, sphinx-copybutton's tooltip.
        ("Show code cell source", "Hide code cell source", "Show code cell content",
         "Hide code cell content", "press \u25b6 to play", "Copy to clipboard", "Copied!"))
    # The Japanese labels: book/_ext/i18n.py (the exercise's and the solution's titles, the
    # code cells' toggles), Sphinx's own catalog (図, 目次), tools/pdf/build.py (the title page).
    japanese = Edition(
        "ja", [_translated(doc, t) for doc, t in titles.items() if doc != "index"],
        "図 {}", "演習 {}", r"演習\s*\d+\s*(\([^)]*\)\s*)?の解答", "目次",
        {"book-ja": "教員用（解答付き）", "book-student-ja": "学生用"},
        "本文と図：CC BY 4.0、コード：MIT",
        ("コードを表示", "コードを隠す", "\u25b6 を押すと再生", "クリップボードにコピー"))
    return {"book": english, "book-student": english, "book-ja": japanese,
            "book-student-ja": japanese}


EDITION_NAMES = ("book", "book-student", "book-ja", "book-student-ja")


@pytest.fixture(scope="module")
def editions(index: BookIndex) -> dict[str, Edition]:
    """What each PDF must say, from the chapter titles of the session's English build."""
    return _editions(index.titles)


TEACHERS = {"book": "book-student", "book-ja": "book-student-ja"}


@pytest.fixture(scope="session")
def pdfs(pdf_job: Future, docs_build: Build) -> dict:
    _need("chromium", shutil.which("chromium") is not None or "CHROMIUM" in os.environ)
    _need("pypdf", importlib.util.find_spec("pypdf") is not None)
    # The Japanese PDFs' faces (Debian's fonts-ipafont-mincho and -gothic, .ci/run).
    faces = subprocess.run(["fc-list", ":", "family"], capture_output=True, text=True,
                           check=False).stdout if shutil.which("fc-list") else ""
    _need("fonts-ipafont-mincho and -gothic", "IPAPMincho" in faces and "IPAPGothic" in faces)
    if docs_build.returncode != 0:
        pytest.fail("the docs did not build (the book links to them)", pytrace=False)
    # Made beside the browser survey (tests/book/conftest.py), or now if it did not run.
    # Their text was read there too (read_pdf), as soon as they were printed.
    out, report, read = pdf_job.result()
    print({k: {n: round(v, 1) if isinstance(v, float) else v for n, v in r.items()}
           for k, r in report.items()})
    from pypdf import PdfReader

    return {"report": report, "texts": {name: read[name][0] for name in report},
            "fonts": {name: read[name][1] for name in report},
            "readers": {name: PdfReader(out / "pdf" / f"{name}.pdf") for name in report}}


def read_pdf(path: Path) -> tuple[list[str], dict[str, str]]:
    """The text of each page of a PDF, and the text drawn in each font (its base name
    without the subset tag), from one reading of each page by pypdf (the slowest part of
    this module's checks: the conftest's pdf_job runs it in processes of its own)."""
    from pypdf import PdfReader

    drawn: dict[str, list[str]] = {}

    def visit(text: str, cm: Any, tm: Any, font: Any, size: Any) -> None:
        if font is not None and text.strip():
            name = str(font.get("/BaseFont", "")).lstrip("/").split("+")[-1]
            drawn.setdefault(name, []).append(text)

    pages = [page.extract_text(visitor_text=visit) for page in PdfReader(path).pages]
    # Ligatures back to letters, so "ﬁrst" reads "first".
    return ([p.replace("\ufb01", "fi").replace("\ufb02", "fl") for p in pages],
            {name: "".join(texts) for name, texts in drawn.items()})


def test_every_edition_is_printed(pdfs: dict) -> None:
    # The four of `make pdf`: this module's expectations cover each of them.
    assert sorted(pdfs["texts"]) == sorted(build_pdf.EDITIONS) == sorted(EDITION_NAMES)


def test_the_pdfs_have_a_plausible_length(pdfs: dict, index: BookIndex) -> None:
    chapters = len(index.pages)
    for name, student in TEACHERS.items():
        teacher, pupil = pdfs["texts"][name], pdfs["texts"][student]
        # Every chapter starts on a new page and runs over several; the solutions add pages.
        assert 3 * chapters < len(pupil) < len(teacher) < 1000, name


def test_chapter_titles_are_text(pdfs: dict, editions: dict[str, Edition]) -> None:
    for name, pages in pdfs["texts"].items():
        edition = editions[name]
        text = edition.key(" ".join(pages))
        missing = [t for t in edition.chapters if edition.key(t) not in text]
        assert missing == [], (name, missing)


def test_japanese_body_is_mincho_and_headings_gothic(
    pdfs: dict, editions: dict[str, Edition],
) -> None:
    # The print stylesheet (book/_ext/static/classroom_print.css): IPA P Mincho for the
    # body, IPA P Gothic for the headings. Without it Chromium sets Japanese in its
    # default sans-serif (the Gothic, or a Noto face) and there is no Mincho at all.
    for name in ("book-ja", "book-student-ja"):
        edition = editions[name]
        fonts = {f: edition.key(text) for f, text in pdfs["fonts"][name].items()}
        sizes = Counter({f: len(text) for f, text in fonts.items()})
        mincho = sum(n for f, n in sizes.items() if "Mincho" in f)
        assert mincho > 0.5 * sum(sizes.values()), (name, sizes.most_common(8))
        gothic = "".join(text for f, text in fonts.items() if "Gothic" in f)
        plain = [t for t in edition.chapters if edition.key(t) not in gothic]
        assert plain == [], (name, plain, sizes.most_common(8))
    for name in ("book", "book-student"):  # (the note's Japanese title is in a Gothic)
        fonts = pdfs["fonts"][name]
        assert not any("Mincho" in f for f in fonts), (name, list(fonts))


def _tags() -> set[str]:
    tags: set[str] = set()
    for page in BOOK.glob("*.md"):
        tags |= set(re.findall(r"\\tag\{([^}]*)\}", page.read_text(encoding="utf-8")))
    return tags


def test_equation_numbers_are_text(pdfs: dict) -> None:
    tags = _tags()
    assert len(tags) >= 40  # the note numbers (1)-(46)
    for name, pages in pdfs["texts"].items():
        lines = [line.strip() for page in pages for line in page.splitlines()]
        # A typeset tag ends a line of formula (or stands alone), right of the equation;
        # a raw "\tag{9}" (MathJax not run) or a verdict line "✔ (9) ..." does not count.
        found = {
            n for n in tags for line in lines
            if line.endswith(f"({n})") and not line.startswith("\u2714")
            and (line == f"({n})" or re.search(r"[=<>\u2264\u2265\u221a\u222b]|\S\s+\S", line))
        }
        assert tags - found == set(), (name, sorted(tags - found, key=int))


def test_formulas_and_figures_were_drawn(
    pdfs: dict, editions: dict[str, Edition], index: BookIndex,
) -> None:
    for name, seen in pdfs["report"].items():
        assert seen["formulas"] > 500, (name, seen)  # MathJax typeset the whole book
        assert seen["images"] > 5, (name, seen)  # and print_pdf refuses an image not loaded
    figures = set(index.figure_numbers.values())
    for name in TEACHERS:
        edition = editions[name]
        text = edition.key("\n".join(pdfs["texts"][name]))
        labels = {n for n in figures if edition.key(edition.figure.format(n)) in text}
        assert labels == figures, name


def test_solutions_open_for_instructors_absent_for_students(
    pdfs: dict, editions: dict[str, Edition], index: BookIndex,
) -> None:
    exercises = len(index.exercise_numbers)
    for name, pupil in TEACHERS.items():
        edition = editions[name]
        teacher = "\n".join(pdfs["texts"][name])
        student = edition.key("\n".join(pdfs["texts"][pupil]))
        assert pdfs["report"][name]["solutions"] == exercises, name
        assert len(re.findall(edition.solution, teacher)) == exercises, name
        if edition.language == "en":
            assert "Solution" not in re.sub(r"Solutions? of", "", student)
        else:  # 解答 is also in the teacher's guide's title and the intro's prose
            assert not re.search(edition.solution, student), pupil
        for number in index.exercise_numbers.values():  # the exercises, same numbers
            assert edition.key(edition.exercise.format(number)) in student, (pupil, number)


def test_every_exercise_prints_its_hint_open(pdfs: dict, index: BookIndex) -> None:
    # One hint per exercise (book/_ext/classroom.py), opened by the printer in both editions;
    # the text of the first written hint of the registry is on paper.
    from elliptic_pendulum import selfcheck

    exercises = len(index.exercise_numbers)
    # The longest stretch of a hint without math or roles: plain text on paper too.
    plain = max((re.split(r"[${`*]", e.written)[0] for e in selfcheck.EXERCISES.values()
                 if e.written), key=len)
    words = " ".join(plain.split()[:6])
    assert len(words.split()) >= 4, words
    for name in pdfs["texts"]:
        assert pdfs["report"][name]["hints"] == exercises, name
    for name in ("book", "book-student"):  # the hint's words in English
        text = re.sub(r"\s+", " ", " ".join(pdfs["texts"][name]))
        assert words in text, (name, words)


# --- Fit to print and to navigate -----------------------------------------------------------
# The chapters, as the book's toctree lists them (Edition.chapters): every one starts on a
# new page, has an entry in the outline and a line with its page in the contents.


def _squash(text: str) -> str:
    return re.sub(r"\s+", " ", text).strip()


def _outline(reader: Any, items: Any = None, depth: int = 0) -> list[tuple[str, int, int]]:
    """Every entry of the outline (bookmarks), depth first: (title, page from 1, depth).
    The book's title (the cover's heading) is at depth 0, the chapters at depth 1."""
    entries: list[tuple[str, int, int]] = []
    for item in reader.outline if items is None else items:
        if isinstance(item, list):
            entries += _outline(reader, item, depth + 1)
        else:
            entries.append((_squash(item.title), reader.get_destination_page_number(item) + 1,
                            depth))
    return entries


def _body(page: str) -> str:
    """A page's text without its footer (the page number, the last line)."""
    lines = page.rstrip().splitlines()
    return "\n".join(lines[:-1]) if lines and lines[-1].strip().isdigit() else page


def _contents(pages: list[str], edition: Edition) -> dict[str, int]:
    """The table of contents as printed: chapter title -> the page number it gives."""
    start = next(i for i, p in enumerate(pages) if edition.contents in p.splitlines()[:3])
    chapters = {edition.key(t): t for t in edition.chapters}
    found: dict[str, int] = {}
    for page in pages[start:start + 3]:
        for line in _body(page).splitlines():
            m = re.fullmatch(r"(.+?)\s*?(\d+)", line.strip())
            if m and edition.key(m[1]) in chapters:
                found.setdefault(chapters[edition.key(m[1])], int(m[2]))
    return found


def test_outline_lists_every_chapter_on_its_page(pdfs: dict, editions: dict[str, Edition]) -> None:
    # printToPDF(generateDocumentOutline) makes the outline from the headings; without it
    # (or without the tags it is built from) reader.outline is empty.
    for name, reader in pdfs["readers"].items():
        outline = _outline(reader)
        pages = pdfs["texts"][name]
        edition = editions[name]
        for title in edition.chapters:
            # Chromium writes a heading at the top of a page twice into its entry
            # ("ConventionsConventions"): the title is in it.
            # A title on two lines loses its space there ("andelliptic functions").
            at = [page for entry, page, _ in outline
                  if entry.replace(" ", "").startswith(title.replace(" ", ""))]
            assert at, (name, title, [e for e, _, _ in outline][:20])
            assert edition.key(title) in edition.key(pages[at[0] - 1]), (name, title, at[0])


def test_pdf_is_tagged(pdfs: dict) -> None:
    # printToPDF(generateTaggedPDF): a structure tree a screen reader follows. Chromium 156
    # (Debian's, here) tags by default, so this fails only with a Chromium that does not
    # and a printer that does not ask; the outline test above fails without the flag.
    for name, reader in pdfs["readers"].items():
        root = reader.trailer["/Root"]
        assert "/StructTreeRoot" in root, name
        assert root["/MarkInfo"]["/Marked"], name


def test_every_page_has_its_number_in_the_footer(pdfs: dict) -> None:
    # tools/pdf/printer.py's footer template: the page number, centred, as the last line.
    for name, pages in pdfs["texts"].items():
        wrong = [n for n, page in enumerate(pages, 1)
                 if page.rstrip().splitlines()[-1].strip() != str(n)]
        assert wrong == [], (name, wrong[:10])


def test_contents_give_the_page_of_each_chapter(pdfs: dict, editions: dict[str, Edition]) -> None:
    # The printer reads where each chapter landed and writes it into the contents: the
    # number printed beside a title is the page on which that title starts its chapter.
    for name, pages in pdfs["texts"].items():
        edition = editions[name]
        contents = _contents(pages, edition)
        chapters = edition.chapters
        assert sorted(contents) == sorted(chapters), (name, set(chapters) - set(contents))
        for title, number in contents.items():
            # The page starts with the title (on one line or two).
            first = edition.key(" ".join(_body(pages[number - 1]).splitlines()[:3]))
            assert first.startswith(edition.key(title)), (name, title, number, first)
        # One heading "Contents" (the theme printed its own and the list's caption).
        assert sum(p.splitlines().count(edition.contents) for p in pages) == 1, name


def test_title_page_states_edition_version_date_and_licence(
    pdfs: dict, editions: dict[str, Edition], index: BookIndex,
) -> None:
    # tools/pdf/build.py's title_page; the licences of book/about.md.
    version = importlib.metadata.version("elliptic-pendulum")
    title = index.titles["index"]
    titles = {"en": title, "ja": _translated("index", title)}
    for name, pages in pdfs["texts"].items():
        edition = editions[name]
        first = edition.key(pages[0])
        assert edition.key(titles[edition.language]) in first, name
        assert edition.key(edition.edition[name]) in first, (name, first)
        assert edition.key(f"elliptic-pendulum {version}") in first, (name, first)
        assert re.search(r"\d{4}-\d{2}-\d{2}", first), (name, first)
        assert edition.key(edition.licence) in first, (name, first)


def test_no_screen_controls_are_printed(pdfs: dict, editions: dict[str, Edition]) -> None:
    for name, pages in pdfs["texts"].items():
        edition = editions[name]
        # The introduction names the toggle in quotes, as text ("the code under “Show
        # code cell source”", 「コードを表示」): a quoted name is no control.
        text = re.sub(r"\u201c[^\u201d]*\u201d|\u300c[^\u300d]*\u300d", "",
                      _squash(" ".join(pages)))
        assert [c for c in edition.controls if edition.key(c) in edition.key(text)] == [], name
        lines = {line.strip() for page in pages for line in page.splitlines()}
        # The animation player's repetition modes, in either language (book/_ext/i18n.py).
        assert not lines & {"Copy", "Once", "Loop", "Reflect", "Once Loop Reflect",
                            "1 回", "ループ", "往復", "1 回 ループ 往復"}, name


def test_links_go_to_the_web_or_into_the_document(pdfs: dict) -> None:
    # Before, 101 links of each PDF read file:///<build machine>/docs/... (the reference
    # site beside the build). An internal link must land on a destination that exists
    # (the single-page build wrote "#document-<page>#<id>", which none has).
    for name, reader in pdfs["readers"].items():
        names = set(reader.named_destinations)
        uris, dests = [], []
        for page in reader.pages:
            for annotation in page.get("/Annots") or []:
                link = annotation.get_object()
                if link.get("/Subtype") != "/Link":
                    continue
                if "/Dest" in link:
                    dests.append(link["/Dest"])
                elif "/A" in link and "/URI" in link["/A"]:
                    uris.append(str(link["/A"]["/URI"]))
        # http: the note's own address (nalab.mind.meiji.ac.jp) has no https.
        bad = [u for u in uris if not re.match(r"https?://[^/\s]+\.[^/\s]+", u)]
        assert bad == [], (name, len(bad), bad[:5])
        assert len(dests) > 100, (name, len(dests))  # cross-references and the contents
        missing = [d for d in dests if not isinstance(d, str) or d not in names]
        assert missing == [], (name, len(missing), missing[:5])


def _has_figure(page: Any) -> bool:
    """An image, or a vector drawing (the book's figures are SVG: many path operators)."""
    if page.images:
        return True
    contents = page.get_contents()
    return contents is not None and len(contents.get_data()) > 20_000


def test_no_page_is_left_nearly_empty(pdfs: dict) -> None:
    # A page with under 150 characters and no figure is one a box or a table pushed its
    # content away from (break-inside: avoid on something taller than the space left):
    # before the fix, the registry of "What is checked, and how" left four. Only the title
    # page, and the last page of a chapter (the next one starts on a new page), may be short.
    for name, reader in pdfs["readers"].items():
        pages = pdfs["texts"][name]
        starts = {page for _, page, depth in _outline(reader) if depth == 1}
        short = [n for n, page in enumerate(pages, 1)
                 if len(_body(page).strip()) < 150 and not _has_figure(reader.pages[n - 1])]
        allowed = {1} | {n - 1 for n in starts} | {len(pages)}
        assert [n for n in short if n not in allowed] == [], (name, short)


def test_no_number_is_broken_after_its_e(pdfs: dict) -> None:
    # "1e-" at the end of a line and "12" on the next: the print stylesheet wrapped code
    # and outputs anywhere, and tools/verify had to keep a verdict's number whole.
    for name, pages in pdfs["texts"].items():
        broken = [line for page in pages for line in page.splitlines()
                  if re.search(r"\d[eE][-+]?$", line.rstrip())]
        assert broken == [], (name, broken[:5])
