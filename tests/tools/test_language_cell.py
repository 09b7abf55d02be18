"""A translated edition's notebooks set their language for the library (tools/classroom):
the code cell under the first, and the catalog of the cells' texts shipped beside them.

The expectation is the library's rule (elliptic_pendulum._i18n): the language from LANGUAGE,
the caller's texts from the catalogs ELLIPTIC_PENDULUM_MESSAGES names. The cell runs in a
fresh interpreter, as in a student's kernel, in a folder with and without the catalog.
"""

from __future__ import annotations

import json
import subprocess
import sys
import zipfile
from pathlib import Path

from tools.classroom import bundle, export
from tools.classroom.words import words

RUN = """
{cell}
import json
from elliptic_pendulum.checks import verify as checks
print(json.dumps([os.environ.get("LANGUAGE"), os.environ.get("ELLIPTIC_PENDULUM_MESSAGES"),
                  str(checks.fact("(9)", True, "the energy is conserved"))]))
"""


def _run_cell(source: str, folder: Path) -> list:
    env = {"PATH": "/usr/bin:/bin", "LANGUAGE": "en", "PYTHONPATH": str(Path(export.__file__)
                                                                       .parents[2] / "src")}
    proc = subprocess.run([sys.executable, "-c", RUN.format(cell=source)], cwd=folder,
                          env=env, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return json.loads(proc.stdout)


def test_english_notebooks_have_no_language_cell() -> None:
    assert export.language_cells(words("en")) == []


def test_the_japanese_cell_sets_the_language_and_the_catalog_beside_it(tmp_path: Path) -> None:
    (cell,) = export.language_cells(words("ja"))
    assert cell.cell_type == "code" and cell.metadata["classroom"] == {"language": "ja"}
    (tmp_path / bundle.CATALOG).write_text(
        'msgid ""\nmsgstr ""\n"Language: ja\\n"\n\nmsgid "the energy is conserved"\n'
        'msgstr "エネルギーは保存される"\n', encoding="utf-8")
    language, catalog, verdict = _run_cell(cell.source, tmp_path)
    assert language == "ja" and Path(catalog) == tmp_path / bundle.CATALOG
    assert verdict == "✔ (9) エネルギーは保存される。"
    # A notebook downloaded alone, without the catalog: Japanese still, the text as given.
    alone = tmp_path / "alone"
    alone.mkdir()
    language, catalog, verdict = _run_cell(cell.source, alone)
    assert (language, catalog) == ("ja", None)
    assert verdict == "✔ (9) the energy is conserved。"


def test_the_japanese_bundle_ships_the_catalog_of_its_own_notebooks(tmp_path: Path) -> None:
    # The book's catalog holds the texts of every cell, the solutions' too; a folder gets
    # those its notebooks pass, and nothing else (a student's must hold no solution).
    import nbformat
    from babel.messages.pofile import read_po

    with bundle.catalog_source("ja").open("rb") as f:
        book = {m.id: m.string for m in read_po(f) if m.id}
    shown, hidden = sorted(book)[:2]
    cell = nbformat.v4.new_code_cell(f"verify.fact('(9)', True, {shown!r})")
    wheel = tmp_path / bundle.wheel_name()
    wheel.write_bytes(b"")
    for language in ("en", "ja"):
        folder = tmp_path / language
        folder.mkdir()
        nbformat.write(nbformat.v4.new_notebook(cells=[cell]), folder / "01-intro.ipynb")
        written = bundle.write(folder, "student", wheel, language)
        assert ((folder / bundle.CATALOG) in written) == (language == "ja")
        archive = bundle.zip_edition(folder, "student", folder)
        names = zipfile.ZipFile(archive).namelist()
        assert any(n.endswith("/" + bundle.CATALOG) for n in names) == (language == "ja")
    with (tmp_path / "ja" / bundle.CATALOG).open("rb") as f:
        shipped = {m.id: m.string for m in read_po(f) if m.id}
    assert shipped == {shown: book[shown]} and hidden not in shipped
