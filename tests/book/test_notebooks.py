"""The classroom notebooks (tools/classroom): two editions in the book's reading
order, plain Jupyter Markdown, and code that runs where students are: a fresh kernel of a
plain venv holding only ``pip install .`` (not editable) and ipykernel. That venv is cached
in .cache/plain-venv/<hash of pyproject.toml>; the package is reinstalled when src/ changes.
"""

from __future__ import annotations

import hashlib
import json
import re
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import nbformat
import pytest

from tests.conftest import BOOK, ROOT
from tools.classroom import export as ex
from tools.classroom.labels import scan

BOOK_INDEX = scan(BOOK)
PAGES = BOOK_INDEX.exported
# Markup that Jupyter would show raw.
MYST_LEFTOVERS = re.compile(r"\{[\w:+-]+\}`|^\s*(:::|```)\{|^\s*\([\w:.-]+\)=\s*$", re.M)
KERNEL = "plain-venv"


def _digest(*paths: Path) -> str:
    h = hashlib.sha256()
    for path in paths:
        files = sorted(p for p in path.rglob("*") if p.is_file() and "__pycache__" not in p.parts)
        for f in files if path.is_dir() else [path]:
            h.update(str(f.relative_to(ROOT)).encode() + b"\0" + f.read_bytes())
    return h.hexdigest()[:16]


@pytest.fixture(scope="session")
def plain_venv() -> Path:
    """A venv with only the package (non-editable) and ipykernel, and its kernel spec."""
    venv = ROOT / ".cache" / "plain-venv" / _digest(ROOT / "pyproject.toml")
    python = venv / "bin" / "python"
    pip = [str(python), "-m", "pip", "install", "--quiet"]
    if not (venv / "ready").exists():
        subprocess.run([sys.executable, "-m", "venv", "--clear", str(venv)], check=True)
        subprocess.run([*pip, str(ROOT), "ipykernel"], check=True, cwd=venv)
        (venv / "installed-src").write_text(_digest(ROOT / "src", ROOT / "pyproject.toml"))
        subprocess.run([str(python), "-m", "ipykernel", "install", "--prefix", str(venv),
                        "--name", KERNEL], check=True, capture_output=True)
        (venv / "ready").write_text("")
    src = _digest(ROOT / "src", ROOT / "pyproject.toml")
    if (venv / "installed-src").read_text() != src:  # the same dependencies, a new library
        subprocess.run([*pip, "--no-deps", "--force-reinstall", str(ROOT)], check=True, cwd=venv)
        (venv / "installed-src").write_text(src)
    return venv


def _kernel_dirs(venv: Path) -> list[str]:
    return [str(venv / "share" / "jupyter" / "kernels")]


def test_the_plain_kernel_is_the_plain_venv(plain_venv: Path, tmp_path: Path) -> None:
    probe = textwrap.dedent("""\
        import importlib.util, json, sys
        import elliptic_pendulum
        print(json.dumps({
            "executable": sys.executable,
            "package": elliptic_pendulum.__file__,
            "missing": [m for m in ("sphinx", "myst_nb", "jupytext", "docutils")
                        if importlib.util.find_spec(m) is None],
        }))
    """)
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(probe)])
    ex.execute(nb, tmp_path, KERNEL, 120, _kernel_dirs(plain_venv))
    seen = json.loads(nb.cells[0].outputs[0]["text"])
    assert Path(seen["executable"]) == plain_venv / "bin" / "python"
    # Installed into the venv, not the editable src/ of the project.
    assert Path(seen["package"]).is_relative_to(plain_venv), seen["package"]
    assert seen["missing"] == ["sphinx", "myst_nb", "jupytext", "docutils"]


def _markdown(nb: nbformat.NotebookNode) -> str:
    return "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")


@pytest.mark.slow
@pytest.mark.parametrize("page", PAGES)
def test_both_editions_run_in_the_plain_venv(page: str, plain_venv: Path, tmp_path: Path) -> None:
    # The instructor edition runs once to learn the glued values (and must not fail) ...
    start = time.perf_counter()
    (tmp_path / "instructor").mkdir()
    run = ex.export_page(BOOK, BOOK_INDEX, page, "instructor", None)
    glue = ex.harvest(run, tmp_path / "instructor", KERNEL, 600, _kernel_dirs(plain_venv))
    seconds = {"instructor": time.perf_counter() - start}
    editions = {e: ex.export_page(BOOK, BOOK_INDEX, page, e, glue) for e in ex.EDITIONS}
    # ... and the shipped instructor notebook has exactly the code that ran.
    code = [c.source for c in editions["instructor"].cells if c.cell_type == "code"]
    assert code == [c.source for c in run.cells if c.cell_type == "code"]
    (tmp_path / "student").mkdir()
    start = time.perf_counter()
    ex.execute(editions["student"], tmp_path / "student", KERNEL, 600, _kernel_dirs(plain_venv))
    seconds["student"] = time.perf_counter() - start
    print(f"{page}: " + ", ".join(f"{e} {s:.1f} s" for e, s in seconds.items()))
    if page == SCREENSHOT_PAGE:
        _screenshot(editions["student"], tmp_path / "student")
    for edition, nb in editions.items():
        text = _markdown(nb)
        assert MYST_LEFTOVERS.findall(text) == [], (edition, MYST_LEFTOVERS.findall(text))
        for name in glue:  # every glued value was pasted, none left as its name
            assert f"`{name}`" not in text, (edition, name)


# One student notebook, as it ran in the plain venv, pictured as JupyterLab renders it
# (tools/figures/screenshot.py: nbconvert's lab template, local MathJax, headless Chromium),
# kept in the build for a person to look at.
SCREENSHOT_PAGE = "energy"
SCREENSHOTS = BOOK / "_build" / "classroom-screenshot"


def _screenshot(nb: nbformat.NotebookNode, cwd: Path) -> None:
    from tools.pdf.printer import find_chromium

    try:
        find_chromium()
    except FileNotFoundError:  # no browser: only the browser tests insist (under CI=true)
        return
    from tools.figures.screenshot import screenshot

    number = PAGES.index(SCREENSHOT_PAGE)  # 00-index, 01-intro, ... as make notebooks names them
    executed = cwd / f"{number:02d}-{SCREENSHOT_PAGE}-student.ipynb"
    nbformat.write(nb, executed)
    png = screenshot(executed, SCREENSHOTS / executed.with_suffix(".png").name)
    # A blank page or a failed shot would be a few kB; the rendered notebook is far more.
    assert png.stat().st_size > 50_000, png
    print(f"screenshot of a student notebook: {png}")


def _editions(out: Path) -> dict[str, list[Path]]:
    ex.export(BOOK, out)
    return {e: sorted((out / e).glob("*.ipynb")) for e in ex.EDITIONS}


def test_editions_follow_the_reading_order(tmp_path: Path) -> None:
    files = _editions(tmp_path)
    names = [p.name for p in files["student"]]
    assert names == [p.name for p in files["instructor"]]
    assert names == [f"{i:02d}-{page}.ipynb" for i, page in enumerate(PAGES)]
    first = _markdown(nbformat.read(files["student"][0], as_version=4))
    for i, page in enumerate(PAGES[1:], 1):  # the first notebook links every chapter
        assert f"{i}. [{BOOK_INDEX.titles[page]}]({i:02d}-{page}.ipynb)" in first


def test_student_has_answer_cells_and_no_solutions(tmp_path: Path) -> None:
    files = _editions(tmp_path)
    total = 0
    for student, teacher in zip(files["student"], files["instructor"], strict=True):
        s = nbformat.read(student, as_version=4).cells
        t = nbformat.read(teacher, as_version=4).cells
        s_text = _markdown(nbformat.v4.new_notebook(cells=s))
        assert re.search(r"^#+ Solution|Solution to Exercise", s_text, re.M) is None
        s_code = [c.source for c in s if c.cell_type == "code" and c.source]
        t_code = [c.source for c in t if c.cell_type == "code"]
        assert set(s_code) <= set(t_code)
        s_ex = [i for i, c in enumerate(s) if c.cell_type == "markdown" and
                re.search(r"^### Exercise \d+", c.source, re.M)]
        for i in s_ex:  # an empty code cell right after each exercise
            assert s[i + 1].cell_type == "code" and s[i + 1].source == "", student.name
        t_ex = [re.findall(r"^### Exercise (\d+)", c.source, re.M) for c in t]
        s_numbers = [re.findall(r"^### Exercise (\d+)", c.source, re.M) for c in s]
        assert sum(t_ex, []) == sum(s_numbers, []), student.name
        solutions = [i for i, c in enumerate(t) if c.cell_type == "markdown"
                     and re.match(r"#+ Solution to Exercise \d+", c.source)]
        assert len(solutions) == len(s_ex), teacher.name
        total += len(s_ex)
    numbers = [n for page in BOOK_INDEX.pages for lab, n in BOOK_INDEX.exercise_numbers.items()
               if BOOK_INDEX.targets[lab].page == page]
    assert numbers == [str(i) for i in range(1, total + 1)]  # one count through the book


def test_code_needs_only_the_package(tmp_path: Path) -> None:
    for files in _editions(tmp_path).values():
        for path in files:
            nb = nbformat.read(path, as_version=4)
            code = "\n".join(c.source for c in nb.cells if c.cell_type == "code")
            assert ex.BOOK_ONLY.search(code) is None, path.name
            assert "myst_nb" not in code, path.name


def test_folded_cells_stay_folded(tmp_path: Path) -> None:
    files = _editions(tmp_path)
    tagged = hidden = 0
    for path in files["instructor"]:
        for cell in nbformat.read(path, as_version=4).cells:
            tags = set(cell.metadata.get("tags", []))
            if tags & {"hide-input", "hide-cell"}:
                tagged += 1
                hidden += cell.metadata.get("jupyter", {}).get("source_hidden", False)
    assert tagged > 0 and hidden == tagged


# --- A small synthetic book: every construct the exporter must turn into plain Jupyter ------

HEADER = "---\njupytext:\n  text_representation:\n    format_name: myst\n---\n\n"
SYNTHETIC = {
    "index.md": HEADER + """# Tiny book

```{toctree}
:caption: Parts

zeta
alpha
```

```{bibliography}
```
""",
    "zeta.md": HEADER + """(zeta)=
# Zeta first

(eq-7)=
$$
x = 1 \\tag{7}
$$

:::{exercise}
:label: ex-z

Do it.
:::
""",
    "alpha.md": HEADER + """# Alpha second

```{code-cell} ipython3
:tags: [hide-cell]

from myst_nb import glue
```

```{code-cell} ipython3
---
tags: [hide-input]
mystnb:
  figure:
    caption: A line. Look at it.
    name: fig-line
---
import matplotlib.pyplot as plt

plt.plot([0, 1])
glue("n", 300, display=False)
glue("x", 0.123456, display=False)
```

See {ref}`(7) <eq-7>`, {ref}`zeta`, {doc}`zeta`, {numref}`fig-line`, {cite:p}`k1`,
{cite:t}`k1`, {py:func}`ep.solve <elliptic_pendulum.motion.solve>`, {prf:ref}`prop-a`
and {glue:text}`n` states with {glue:text}`x:.2f` error.

:::{prf:proposition} Name
:label: prop-a

True.
:::

:::{admonition} Numerical note
:class: numerical-note

Careful.
:::

sympy identity
: both sides agree.

:::{exercise}
:label: ex-a

Compute.
:::

:::{solution-start} ex-a
:class: dropdown
:::

Worked.

```{code-cell} ipython3
answer = 42
assert answer == 42
```

:::{solution-end}
:::
""",
    "conf.py": f"""import sys
sys.path[:0] = [{str(ROOT / 'book' / '_ext')!r}, {str(ROOT)!r}]
extensions = ["myst_nb", "sphinx_proof", "sphinx_exercise", "sphinxcontrib.bibtex",
              "sphinx_book_theme", "classroom"]
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence"]
bibtex_bibfiles = ["references.bib"]
numfig = True
html_theme = "sphinx_book_theme"
""",
    "references.bib": "@book{k1,\n  author = {Doe, Jane and Roe, Rick},\n"
    "  title = {A Title},\n  publisher = {P},\n  year = {1999}\n}\n",
}


@pytest.fixture()
def tiny_book(tmp_path: Path) -> Path:
    book = tmp_path / "book"
    book.mkdir()
    for name, text in SYNTHETIC.items():
        (book / name).write_text(text, encoding="utf-8")
    return book


def test_synthetic_book(tiny_book: Path, tmp_path: Path) -> None:
    index = scan(tiny_book)
    assert index.pages == ["index", "zeta", "alpha"]  # the toctree's order, not the alphabet
    assert index.exercise_numbers == {"ex-z": "1", "ex-a": "2"}
    glue = {"n": "300", "x": "0.123456"}
    student = ex.export_page(tiny_book, index, "alpha", "student", glue)
    teacher = ex.export_page(tiny_book, index, "alpha", "instructor", glue)
    text = _markdown(teacher)
    assert MYST_LEFTOVERS.findall(text) == []
    for expected in [
        "[(7)](01-zeta.ipynb#eq-7)", "[Zeta first](01-zeta.ipynb#zeta)",
        "[Zeta first](01-zeta.ipynb)", "[Fig. 1](#fig-line)", "**Fig. 1.** A line.",
        "\\[[Doe and Roe, 1999](#ref-k1)\\]", "[Doe and Roe [1999]](#ref-k1)", "`ep.solve`",
        "[Proposition 1](#prop-a)", "300 states with 0.12 error", "**Proposition 1 (Name).**",
        "**Numerical note.**", "**sympy identity**: both sides agree.",
        '<a id="ref-k1"></a>**[Doe and Roe, 1999]**',
        "### Exercise 2", "#### Solution to Exercise 2",
    ]:
        assert expected in text, expected
    cells = teacher.cells
    sol = next(i for i, c in enumerate(cells) if "Solution to Exercise 2" in c.source)
    assert cells[sol + 1].cell_type == "code" and "answer = 42" in cells[sol + 1].source
    code = "\n".join(c.source for c in cells if c.cell_type == "code")
    assert "myst_nb" not in code and "def glue(" in code
    setup, figure = [c for c in cells if c.cell_type == "code"][:2]
    assert setup.metadata["jupyter"] == {"outputs_hidden": True, "source_hidden": True}
    assert figure.metadata["jupyter"] == {"source_hidden": True}
    s_text = _markdown(student)
    assert "Solution" not in s_text and "Worked." not in s_text
    s_code = [c.source for c in student.cells if c.cell_type == "code"]
    assert "" in s_code and not any("answer = 42" in c for c in s_code)
    zeta = _markdown(ex.export_page(tiny_book, index, "zeta", "student", glue))
    assert '<a id="eq-7"></a>' in zeta and "### Exercise 1" in zeta
    with pytest.raises(ValueError, match="pastes 'x'"):  # a pasted value nothing glued
        ex.export_page(tiny_book, index, "alpha", "student", {"n": "1"})


def test_glue_is_formatted_as_the_book_formats_it() -> None:
    assert ex.format_glue("300", "s") == "300"
    assert ex.format_glue("300", "") == "300"
    assert ex.format_glue("0.000123456", ".1e") == "1.2e-04"
    assert ex.format_glue("0.5", ".0%") == "50%"
    assert ex.format_glue("'text'", "s") == "text"
