"""The Japanese classroom notebooks, without a build (tools/classroom/translation.py).

The exporter translates each Markdown cell through its page's catalog before it converts the
MyST. The catalogs were made by Sphinx's gettext builder from the same pages, so they are
the independent reference for what a message is: every text the exporter looks up must be
one of them, and every message of a page must be used by its notebook, unless the book alone
shows it. The English notebooks are the reference for everything that is not prose: the same
cells, the same code, the same anchors, links and display formulas.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import jupytext
import nbformat
import pytest

from elliptic_pendulum import selfcheck
from tools.classroom import export as ex
from tools.classroom import translation
from tools.classroom.labels import scan
from tools.i18n import status

ROOT = Path(__file__).resolve().parents[2]
BOOK = ROOT / "book"
LOCALE = BOOK / "locale"
BOOK_INDEX = scan(BOOK)
PAGES = BOOK_INDEX.exported
JAPANESE = re.compile(r"[\u3040-\u30ff\u4e00-\u9fff]")
# Messages of the site alone: the dropdown that book/_ext/classroom.py puts under each
# exercise ("Hint", and the sentence naming the results the notebook checks: a notebook
# has the self-check cell itself instead).
SITE_ONLY = re.compile(r"^(Hint|In this chapter's notebook, the cell under the exercise .*)$")


def _notebook_messages(page: str) -> tuple[set[str], list[str]]:
    """(what the exporter looked up for page, what it did not find), the exporter's way."""
    catalog = translation.load(LOCALE, "ja", page)
    looked: set[str] = set()
    get = catalog.get

    def spy(msgid: str) -> str | None:
        looked.add(msgid)
        return get(msgid)

    catalog.get = spy  # type: ignore[method-assign]
    nb = jupytext.read(BOOK / f"{page}.md", fmt="md:myst")
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            translation.translate(cell.source, catalog)
        caption = cell.metadata.get("mystnb", {}).get("figure", {}).get("caption")
        if caption:
            translation.translate(str(caption), catalog)
    for label, target in BOOK_INDEX.targets.items():
        exercise = selfcheck.EXERCISES.get(label)
        if target.page == page and exercise is not None and exercise.written is not None:
            translation.translate(exercise.written, catalog)
    return looked, catalog.missing


@pytest.mark.parametrize("page", PAGES)
def test_the_notebook_uses_exactly_its_pages_messages(page: str) -> None:
    looked, missing = _notebook_messages(page)
    assert missing == []  # every text the exporter took for a message is one
    catalog = translation.load(LOCALE, "ja", page)
    # A figure drawn by a code cell has its alt text in the page; the notebook has no image
    # until the cell runs, and Jupyter reads no alt text from the cell.
    nb = jupytext.read(BOOK / f"{page}.md", fmt="md:myst")
    alts = {str(c.metadata.get("mystnb", {}).get(k, {}).get("alt", "")).strip()
            for c in nb.cells if c.cell_type == "code" for k in ("figure", "image")}
    unused = {m for m in catalog.messages if m not in looked and not SITE_ONLY.match(m)
              and m not in alts
              and not any(f"Proof. {x}" == m or f"({x})" == m for x in looked)}
    assert unused == set()  # and it finds every message of the page


def _export(tmp: Path, language: str) -> dict[str, list[nbformat.NotebookNode]]:
    ex.export(BOOK, tmp / language, language=language)
    return {e: [nbformat.read(p, as_version=4)
                for p in sorted((tmp / language / e).glob("*.ipynb"))] for e in ex.EDITIONS}


@pytest.fixture(scope="module")
def editions(tmp_path_factory: pytest.TempPathFactory) -> dict[str, dict]:
    tmp = tmp_path_factory.mktemp("classroom-ja")
    return {language: _export(tmp, language) for language in ("en", "ja")}


ANCHOR = re.compile(r'<a id="([^"]+)"></a>')
LINK = re.compile(r"\]\(([^)\s]*)\)")
DISPLAY = re.compile(r"\$\$(.+?)\$\$", re.S)
PLACEHOLDER = re.compile(r"^\w+ = \.\.\.  # .*$", re.M)


@pytest.mark.parametrize("edition", ex.EDITIONS)
def test_the_japanese_notebook_is_the_english_one_in_japanese(
        editions: dict[str, dict], edition: str) -> None:
    english, japanese = editions["en"][edition], editions["ja"][edition]
    assert len(japanese) == len(english) == len(PAGES)
    for page, en, ja in zip(PAGES, english, japanese, strict=True):
        assert [c.cell_type for c in ja.cells] == [c.cell_type for c in en.cells], page
        for c_en, c_ja in zip(en.cells, ja.cells, strict=True):
            if c_en.cell_type == "code":  # the same code; only the answer cell's comment
                # The Japanese self-checks ask for their language (language='ja').
                assert (PLACEHOLDER.sub("", c_ja.source).replace("language='ja', ", "")
                        == PLACEHOLDER.sub("", c_en.source))
                assert c_ja.metadata == c_en.metadata
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
                assert JAPANESE.search(c_ja.source), (page, c_ja.source[:200])


def test_the_exporters_own_words_are_japanese(editions: dict[str, dict]) -> None:
    # The headings the Japanese edition of the book gives the same things
    # (book/_ext/i18n.py: 演習 3 の解答; sphinx-proof and our catalogs: 補題, 証明, 図).
    student = "\n".join(c.source for nb in editions["ja"]["student"] for c in nb.cells
                        if c.cell_type == "markdown")
    teacher = "\n".join(c.source for nb in editions["ja"]["instructor"] for c in nb.cells
                        if c.cell_type == "markdown")
    assert re.search(r"^### 演習 \d+$", student, re.M)
    assert re.search(r"^#### 演習 \d+ の解答$", teacher, re.M)
    assert "> **補題 2（" in teacher and "> **証明**" in teacher and "**図 1**" in teacher
    assert "**あなたの結果**" in student and "<b>ヒント</b>" in student
    for english in ("Exercise", "Solution to", "Your results", "Your answer", "Fig. ",
                    "Proof", "(in the book)", "classroom notebook", "## References"):
        assert english not in student + teacher, english


def test_a_missing_translation_stops_the_export(tmp_path: Path) -> None:
    # A copy of the book whose energy catalog lost one entry: the exporter must refuse,
    # naming the page, rather than ship an English paragraph in a Japanese notebook.
    book = tmp_path / "book"
    shutil.copytree(BOOK, book, ignore=shutil.ignore_patterns("_build", "*.mo", "__pycache__"))
    po = book / "locale" / "ja" / "LC_MESSAGES" / "energy.po"
    text = po.read_text(encoding="utf-8")
    entry = re.search(r'\nmsgid "A first integral"\nmsgstr "[^"]+"\n', text)
    assert entry is not None
    po.write_text(text.replace(entry[0], '\nmsgid "A first integral"\nmsgstr ""\n'),
                  encoding="utf-8")
    with pytest.raises(translation.Untranslated, match="energy.*A first integral"):
        ex.export(book, tmp_path / "out", language="ja", pages=["energy"])


def test_translate_places_each_kind_of_message() -> None:
    # A synthetic page with one message of each kind Sphinx extracts; the catalog is
    # written by hand from what Sphinx's gettext builder extracts for such blocks.
    source = "\n".join([
        "# A title", "", "A paragraph on", "two lines.", "", "1. An item", "   that goes on.",
        "", "| a cell | another |", "|---|---|", "| x | y |", "",
        ":::{prf:lemma} Its title", ":label: lem", "", "The statement.", ":::", "",
        ":::{prf:proof}", "First words.", "", "Then more.", ":::", "",
        "```{figure} f.png", ":alt: An alt", ":name: fig", "", "A caption.", "```", "",
        "$$", "x = 1", "$$",
    ])
    messages = {"A title": "題", "A paragraph on two lines.": "段落。", "An item that goes on.":
                "項目。", "a cell": "セル", "another": "別", "x": "x", "y": "y",
                "(Its title)": "（表題）", "The statement.": "主張。",
                "Proof. First words.": "証明。最初。", "Then more.": "続き。",
                "An alt": "代替", "A caption.": "説明。"}
    catalog = translation.Catalog("synthetic", dict(messages))
    out = translation.translate(source, catalog)
    assert catalog.missing == []
    expected = ["# 題", "段落。", "1. 項目。", "| セル | 別 |", ":::{prf:lemma} 表題",
                ":label: lem", "主張。", "最初。", "続き。", ":alt: 代替", ":name: fig",
                "説明。", "$$\nx = 1\n$$"]
    for piece in expected:
        assert piece in out, piece
    assert not re.search(r"paragraph|item|statement|First|caption|Proof", out)
    catalog = translation.Catalog("synthetic", {})
    translation.translate(source, catalog)
    assert "A paragraph on two lines." in catalog.missing and "x = 1" not in catalog.missing
