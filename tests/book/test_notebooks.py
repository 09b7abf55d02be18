"""The classroom notebooks (tools/classroom) and the bundles a student installs at home.

Two editions in the book's reading order, plain Jupyter Markdown, written from the doctrees
of the session's builds (tools/classroom/doctree.py). Each edition's zip, as the
built sites offer it (the student site's student zip, the instructor site's instructor zip:
the session's builds, tests/conftest.py), is unzipped alone into an empty folder; a fresh
venv holding only ipykernel gets exactly the install command of the bundle's README (parsed
from it), and every notebook of both editions runs there, all cells, in that venv's kernel:
the zip holds all a student needs. Nothing of that venv is cached (a student has nothing
either); pip's download cache makes the install quick on a second run.
"""

from __future__ import annotations

import json
import os
import re
import shlex
import subprocess
import sys
import textwrap
import time
import zipfile
from concurrent.futures import Future
from pathlib import Path

import jupytext
import nbformat
import pytest

from elliptic_pendulum import selfcheck
from tests.book._buildcheck import BookIndex, toctree_entries
from tests.conftest import BOOK, ROOT, SUMMARY, Build
from tools.classroom import bundle
from tools.classroom import export as ex

# Markup that Jupyter would show raw.
MYST_LEFTOVERS = re.compile(r"\{[\w:+-]+\}`|^\s*(:::|```)\{|^\s*\([\w:.-]+\)=\s*$", re.M)
# A MyST role ({eq}`...`, {numref}`...`, {math}`...`) anywhere, e.g. in a JSON dump.
MYST_ROLE = re.compile(r"\{[\w:+-]+\}`")
KERNEL = "bundle-venv"
TIMES = SUMMARY.setdefault("classroom bundles", [])


def unzip_bundles(built_book: Path, student_site: Path,
                  tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """edition -> the folder its zip unpacks to, each zip alone in an empty folder."""
    sites = {"student": student_site, "instructor": built_book}
    folders = {}
    for edition, site in sites.items():
        archive = site / "classroom" / f"{bundle.bundle_name(edition)}.zip"
        empty = tmp_path_factory.mktemp(f"unzipped-{edition}")
        assert list(empty.iterdir()) == []
        with zipfile.ZipFile(archive) as z:
            z.extractall(empty)
        (folders[edition],) = empty.iterdir()  # one folder, the one the README names
        assert folders[edition].name == bundle.bundle_name(edition)
    return folders


def readme_install(folder: Path) -> list[str]:
    """The README's install command for a laptop (the only ``python -m pip install`` line
    of its laptop section), as argv."""
    text = (folder / bundle.README).read_text(encoding="utf-8")
    heading = "\n## ノートパソコンで" if "\n## ノートパソコンで" in text else "\n## On a laptop"
    laptop = text.split(heading, 1)[1].split("\n## ", 1)[0]
    lines = [line.strip() for line in laptop.splitlines()
             if line.strip().startswith("python -m pip install")]
    assert len(lines) == 1, lines
    return shlex.split(lines[0])


def make_bundle_venv(bundles: dict[str, Path], tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A fresh venv with ipykernel, then each README's install command run in its bundle
    (the student's first; the instructor's then finds all installed), and its kernel spec."""
    start = time.perf_counter()
    venv = tmp_path_factory.mktemp("bundle-venv") / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    python = venv / "bin" / "python"
    steps = [([str(python), "-m", "pip", "install", "--quiet", "ipykernel"], venv)]
    for edition in ("student", "instructor"):
        argv = readme_install(bundles[edition])
        assert argv[:4] == ["python", "-m", "pip", "install"], argv
        steps.append(([str(python), *argv[1:]], bundles[edition]))  # python: the venv's
    for argv, cwd in steps:
        proc = subprocess.run(argv, cwd=cwd, capture_output=True, text=True, timeout=1800)
        assert proc.returncode == 0, f"{argv} failed:\n{proc.stdout[-3000:]}{proc.stderr[-3000:]}"
    subprocess.run([str(python), "-m", "ipykernel", "install", "--prefix", str(venv),
                    "--name", KERNEL], check=True, capture_output=True)
    TIMES.append(f"fresh venv, ipykernel and the READMEs' install: "
                 f"{time.perf_counter() - start:.1f} s")
    return venv


@pytest.fixture(scope="session")
def bundles(bundle_job: Future) -> dict[str, Path]:
    """edition -> its unzipped bundle (made beside the browser survey: tests/book/conftest.py)."""
    return dict(bundle_job.result()[0])


@pytest.fixture(scope="session")
def bundle_venv(bundle_job: Future) -> Path:
    """The fresh venv the bundles' READMEs installed into (see bundles)."""
    return Path(bundle_job.result()[1])


def _kernel_dirs(venv: Path) -> list[str]:
    return [str(venv / "share" / "jupyter" / "kernels")]


def test_the_bundle_kernel_is_the_bundle_venv(bundle_venv: Path, tmp_path: Path) -> None:
    probe = textwrap.dedent("""\
        import importlib.metadata, importlib.util, json, sys
        import elliptic_pendulum
        print(json.dumps({
            "executable": sys.executable,
            "package": elliptic_pendulum.__file__,
            "version": importlib.metadata.version("elliptic-pendulum"),
            "present": [m for m in ("ipywidgets", "jupyterlab", "sympy", "mpmath")
                        if importlib.util.find_spec(m) is not None],
            "missing": [m for m in ("sphinx", "myst_nb", "jupytext", "docutils")
                        if importlib.util.find_spec(m) is None],
        }))
    """)
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(probe)])
    ex.execute(nb, tmp_path, KERNEL, 120, _kernel_dirs(bundle_venv))
    seen = json.loads(nb.cells[0].outputs[0]["text"])
    assert Path(seen["executable"]) == bundle_venv / "bin" / "python"
    # Installed from the wheel into the venv, not the editable src/ of the project.
    assert Path(seen["package"]).is_relative_to(bundle_venv), seen["package"]
    assert seen["version"] == bundle.project()["version"]  # pyproject.toml's
    # requirements.txt brought the sliders and a front end; the book's tools stayed out.
    assert seen["present"] == ["ipywidgets", "jupyterlab", "sympy", "mpmath"]
    assert seen["missing"] == ["sphinx", "myst_nb", "jupytext", "docutils"]


def test_the_installed_wheels_doctests_pass_bare(bundle_venv: Path, tmp_path: Path) -> None:
    # "Doctest runs" as a user makes them: the wheel a bundle installs, pytest and nothing
    # else of the project (none of its doctest flags), from an empty folder.
    python = str(bundle_venv / "bin" / "python")
    pip = subprocess.run([python, "-m", "pip", "install", "--quiet", "pytest"],
                         capture_output=True, text=True, timeout=900)
    assert pip.returncode == 0, pip.stdout[-2000:] + pip.stderr[-2000:]
    proc = subprocess.run(
        [python, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-c", os.devnull,
         "--rootdir", str(tmp_path), "--doctest-modules", "--pyargs", "elliptic_pendulum"],
        cwd=tmp_path, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stdout[-5000:]
    passed = int(re.search(r"(\d+) passed", proc.stdout)[1])
    assert passed >= 75, proc.stdout[-500:]  # every module's examples, not an empty run
    TIMES.append(f"the wheel's doctests, bare: {passed} passed")


def _markdown(nb: nbformat.NotebookNode) -> str:
    return "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")


def _run(folder: Path, name: str, venv: Path) -> tuple[nbformat.NotebookNode, float]:
    nb = nbformat.read(folder / name, as_version=4)
    start = time.perf_counter()
    ex.execute(nb, folder, KERNEL, 600, _kernel_dirs(venv))  # in its folder, as Jupyter
    return nb, time.perf_counter() - start


@pytest.fixture(scope="session")
def executed(bundle_job: Future) -> dict[tuple[str, str], object]:
    """Every notebook of both editions run in the bundle's venv (see run_all), beside the
    browser survey (tests/book/conftest.py)."""
    return dict(bundle_job.result()[2])


def run_all(bundles: dict[str, Path], bundle_venv: Path) -> dict[tuple[str, str], object]:
    """Every notebook of both editions run in the bundle's venv, two at a time (each has its
    own kernel, a process of its own: the machine's two cores run two): (page, edition) ->
    the executed notebook, or the exception its run raised."""
    from concurrent.futures import ThreadPoolExecutor

    jobs = {(path.name[3:-6], edition): (bundles[edition], path.name)
            for edition in ex.EDITIONS for path in sorted(bundles[edition].glob("*.ipynb"))}
    results: dict[tuple[str, str], object] = {}
    start = time.perf_counter()
    with ThreadPoolExecutor(max_workers=2) as pool:
        futures = {key: pool.submit(_run, folder, name, bundle_venv)
                   for key, (folder, name) in jobs.items()}
        for key, future in futures.items():
            try:
                results[key], seconds = future.result()
                TIMES.append(f"{key[1]} {jobs[key][1]}: {seconds:.1f} s")
            except Exception as err:  # reported by the test of that notebook
                results[key] = err
    TIMES.append(f"all {len(jobs)} notebooks, two at a time: {time.perf_counter() - start:.1f} s")
    return results


def _self_check_outputs(nb: nbformat.NotebookNode) -> dict[str, str]:
    said = {}
    for cell in nb.cells:
        label = cell.metadata.get("classroom", {}).get("self_check")
        if label:
            said[label] = "".join(
                o.get("text", "") + str(o.get("data", {}).get("text/markdown", ""))
                for o in cell.get("outputs", []))
    return said


def test_every_notebook_of_the_bundle_runs_in_its_venv(
    executed: dict, bundles: dict[str, Path], index: BookIndex
) -> None:
    assert sorted(executed) == sorted((page, e) for page in index.exported
                                      for e in ex.EDITIONS)
    failed = {key: nb for key, nb in executed.items() if isinstance(nb, BaseException)}
    assert failed == {}, failed
    for key, nb in executed.items():
        errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
                  if o.output_type == "error"]
        assert errors == [], key  # nbclient raises on the first error; the belt to it
    _screenshot(executed[SCREENSHOT_PAGE, "student"], bundles["student"])


# The pages with an exercise whose results a self-check reads (each chapter's self-checks
# are the module of elliptic_pendulum.selfcheck named after its page).
def _page_of(label: str) -> str:
    reference = selfcheck.EXERCISES[label].reference
    assert reference is not None
    return reference.__module__.rsplit(".", 1)[1]


CHECKED_PAGES = sorted({_page_of(label) for label, exercise in selfcheck.EXERCISES.items()
                        if exercise.values})


@pytest.mark.parametrize("page", CHECKED_PAGES)
def test_self_checks_pass_the_solutions_and_answer_an_empty_cell(page: str, executed: dict) -> None:
    # Right answers: the instructor's worked solution, checked against the self-check's
    # independent reference (elliptic_pendulum.selfcheck). Wrong ones: the student's answer
    # cell as handed out, still "...", which the check must call unanswered, not right.
    instructor, student = executed[page, "instructor"], executed[page, "student"]
    if isinstance(instructor, BaseException) or isinstance(student, BaseException):
        pytest.fail("the notebook did not run: see test_every_notebook_of_the_bundle_runs")
    said = _self_check_outputs(instructor)
    wanted = {lab for lab, e in selfcheck.EXERCISES.items()
              if e.values and _page_of(lab) == page}
    assert wanted and set(said) == wanted, (page, sorted(wanted ^ set(said)))
    for label, text in said.items():
        assert "\u2718" not in text and "All right." in text, (label, text)
    for label, text in _self_check_outputs(student).items():
        assert "\u2714" not in text and "is still `...`" in text, (label, text)


# One student notebook, as it ran from its bundle, pictured as JupyterLab renders it
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

    executed = SCREENSHOTS / f"{SCREENSHOT_PAGE}-student.ipynb"
    executed.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, executed)
    png = screenshot(executed, executed.with_suffix(".png"))
    # A blank page or a failed shot would be a few kB; the rendered notebook is far more.
    assert png.stat().st_size > 50_000, png
    print(f"screenshot of a student notebook: {png}")


def test_each_zip_holds_the_notebooks_the_wheel_and_how_to_install(
    bundles: dict[str, Path], index: BookIndex,
) -> None:
    for edition, folder in bundles.items():
        names = sorted(p.name for p in folder.iterdir())
        expected = [*index.files.values(), bundle.README, bundle.REQUIREMENTS,
                    bundle.wheel_name()]
        assert names == sorted(expected), edition
        readme = (folder / bundle.README).read_text(encoding="utf-8")
        # The JupyterHub's commands are the laptop's, with --user, and as a %pip cell.
        laptop = " ".join(readme_install(folder))
        assert laptop.replace("install", "install --user", 1) in readme
        assert laptop.replace("python -m pip", "%pip", 1) in readme
        for words in ("Windows", "macOS", "Linux", "python3 -m venv .venv",
                      r".venv\Scripts\Activate.ps1", "jupyter lab", "JupyterHub",
                      "Restart Kernel", "CC BY 4.0", "MIT licence", bundle.CC_BY):
            assert words in readme, (edition, words)
        # Every dependency of pyproject.toml with its lower bound, and what only the
        # notebooks need (the sliders, a front end).
        wanted = [*bundle.project()["dependencies"], "ipywidgets>=8", "jupyterlab>=4"]
        lines = (folder / bundle.REQUIREMENTS).read_text(encoding="utf-8").splitlines()
        assert set(wanted) <= {line for line in lines if not line.startswith("#")}


def _html_figure_numbers(site: Path, page: str) -> dict[str, str]:
    """The figures of a built page as Sphinx numbered them: {name: number}."""
    text = (site / f"{page}.html").read_text(encoding="utf-8")
    numbers = {}
    # Figures do not nest, so a figure's number is the first after its opening tag (an
    # animation's player holds ids of its own in between).
    for m in re.finditer(r'<figure\b[^>]*\bid="(?P<name>[^"]+)"', text):
        number = re.compile(r'<span class="caption-number">Fig\. (\d+)').search(text, m.end())
        if number:
            numbers[m["name"]] = number[1]
    return numbers


# The captioned figures that a solution draws: the student notebooks have none of them.
SOLUTION_FIGURES = {"fig-problems-poincare"}


def test_the_bundled_notebooks_are_plain_jupyter(
    bundles: dict[str, Path], built_book: Path, index: BookIndex
) -> None:
    figures = 0
    for page in index.exported:
        numbers = _html_figure_numbers(built_book, page)  # the independent numbering
        book_nb = jupytext.read(BOOK / f"{page}.md", fmt="md:myst")
        captioned = [c for c in book_nb.cells if c.cell_type == "code"
                     and c.metadata.get("mystnb", {}).get("figure", {}).get("caption")]
        for edition, folder in bundles.items():
            nb = nbformat.read(folder / index.files[page], as_version=4)
            where = (edition, page)
            # The first cell: how to install if the import fails, the licence, nothing
            # that tells a student to leave the file alone.
            first = nb.cells[0].source
            assert nb.cells[0].cell_type == "markdown", where
            assert bundle.pip_magic() in first and bundle.README in first, where
            assert "CC BY 4.0" in first and bundle.CC_BY in first, where
            for forbidden in ("edit the book page", "not this file", "generated from"):
                assert forbidden not in first.lower(), where
            # No MyST: neither in the Markdown nor in any metadata (the book's figure
            # options held roles in their captions).
            assert MYST_LEFTOVERS.findall(_markdown(nb)) == [], where
            meta = json.dumps([nb.metadata, *(c.metadata for c in nb.cells)])
            assert MYST_ROLE.findall(meta) == [] and "mystnb" not in meta, where
            # Every captioned figure of the page: its code cell, then its caption as
            # Markdown, numbered as the HTML book numbers it.
            sources = [c.source for c in nb.cells]
            for cell in captioned:
                name = cell.metadata["mystnb"]["figure"]["name"]
                if edition == "student" and cell.source not in sources:
                    # A figure drawn in a solution (problems' Poincare section) goes with it.
                    assert name in SOLUTION_FIGURES, (where, name)
                    continue
                i = sources.index(cell.source)
                caption = nb.cells[i + 1]
                assert caption.cell_type == "markdown", (where, name)
                assert caption.source.startswith(
                    f'<a id="{name}"></a>\n\n**Fig. {numbers[name]}.** '), (where, name)
                figures += 1
    # Every captioned figure of the exported pages, counted in their sources, in both
    # editions; the student's lacks those its solutions draw.
    captions = sum(len(re.findall(r"^  figure:\n    caption:", (BOOK / f"{p}.md").read_text(
        encoding="utf-8"), re.M)) for p in index.exported)
    assert captions >= 30 and figures == 2 * captions - len(SOLUTION_FIGURES)


def _editions(site: Path) -> dict[str, list[Path]]:
    return {e: sorted((site / "classroom" / e).glob("*.ipynb")) for e in ex.EDITIONS}


def test_editions_follow_the_reading_order(built_book: Path, index: BookIndex) -> None:
    files = _editions(built_book)
    names = [p.name for p in files["student"]]
    assert names == [p.name for p in files["instructor"]]
    # The index's toctree, read from its source here (the independent order); the registry
    # of checks keeps its number but has no notebook.
    order = ["index", *toctree_entries(BOOK)]
    order = [page for page in order if page in index.pages]
    assert names == [f"{i:02d}-{page}.ipynb" for i, page in enumerate(order)
                     if page != "checks"]
    first = _markdown(nbformat.read(files["student"][0], as_version=4))
    for i, page in enumerate(order[1:], 1):  # the first notebook lists every chapter
        link = f"[{index.titles[page]}]({i:02d}-{page}.ipynb)"
        assert (link if page != "checks" else index.titles[page]) in first, page


def test_student_has_answer_cells_and_no_solutions(built_book: Path, index: BookIndex) -> None:
    files = _editions(built_book)
    total = 0
    for student, teacher in zip(files["student"], files["instructor"], strict=True):
        s = nbformat.read(student, as_version=4).cells
        t = nbformat.read(teacher, as_version=4).cells
        s_text = _markdown(nbformat.v4.new_notebook(cells=s))
        assert re.search(r"^#+ Solution|Solution to Exercise", s_text, re.M) is None
        s_code = [c.source for c in s if c.cell_type == "code" and c.source]
        t_code = [c.source for c in t if c.cell_type == "code"]
        # Beyond the instructor's code, only the answer cells: "name = ..." for each result
        # the self-check reads, nothing of a solution.
        for extra in set(s_code) - set(t_code):
            for line in extra.splitlines():
                assert re.fullmatch(r"\w+ = \.\.\.  # replace \.\.\. by your result", line), line
        s_ex = [i for i, c in enumerate(s) if c.cell_type == "markdown" and
                re.search(r"^#+ Exercise \d+", c.source, re.M)]
        for i in s_ex:  # the student's cells right after each exercise: results, or a hint
            after = s[i + 1]
            assert (after.cell_type == "code" and after.source == "") or (
                after.source.startswith("**Your results.**")) or (
                after.metadata.get("classroom", {}).get("written")
            ), (student.name, after.source[:80])
            assert "<details><summary><b>Hint</b>" in s[i].source, student.name
        t_ex = [re.findall(r"^#+ Exercise (\d+)", c.source, re.M) for c in t]
        s_numbers = [re.findall(r"^#+ Exercise (\d+)", c.source, re.M) for c in s]
        assert sum(t_ex, []) == sum(s_numbers, []), student.name
        solutions = [i for i, c in enumerate(t) if c.cell_type == "markdown"
                     and re.search(r"^#+ Solution to Exercise \d+", c.source, re.M)]
        assert len(solutions) == len(s_ex), teacher.name
        total += len(s_ex)
    numbers = [n for page in index.pages for lab, n in index.exercise_numbers.items()
               if index.exercise_pages[lab] == page]
    assert numbers == [str(i) for i in range(1, total + 1)]  # one count through the book


def test_code_needs_only_the_package(built_book: Path) -> None:
    for files in _editions(built_book).values():
        for path in files:
            nb = nbformat.read(path, as_version=4)
            code = "\n".join(c.source for c in nb.cells if c.cell_type == "code")
            assert ex.BOOK_ONLY.search(code) is None, path.name
            assert "myst_nb" not in code, path.name


def test_folded_cells_stay_folded(built_book: Path) -> None:
    files = _editions(built_book)
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
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
bibtex_bibfiles = ["references.bib"]
numfig = True
html_theme = "sphinx_book_theme"
""",
    "references.bib": "@book{k1,\n  author = {Doe, Jane and Roe, Rick},\n"
    "  title = {A Title},\n  publisher = {P},\n  year = {1999}\n}\n",
}


def test_synthetic_book(tiny_sites: dict) -> None:
    # The small book above, built by Sphinx with the book's extensions (tests/book/conftest.py):
    # its notebooks must say what its pages say, resolved as the HTML resolves it.
    site = tiny_sites["full"]
    teacher = nbformat.read(site / "classroom" / "instructor" / "02-alpha.ipynb", 4)
    student = nbformat.read(site / "classroom" / "student" / "02-alpha.ipynb", 4)
    assert sorted(p.name for p in (site / "classroom" / "student").glob("*.ipynb")) == [
        "00-index.ipynb", "01-zeta.ipynb", "02-alpha.ipynb"]  # the toctree's order
    text = _markdown(teacher)
    assert MYST_LEFTOVERS.findall(text) == []
    for expected in [
        "[(7)](01-zeta.ipynb#eq-7)", "[Zeta first](01-zeta.ipynb#zeta)",
        "[Zeta first](01-zeta.ipynb)", "[Fig. 1](#fig-line)", "**Fig. 1.** A line.",
        "`ep.solve`", "[Proposition 1](#prop-a)", "300 states with 0.12 error",
        "**Proposition 1 (Name).**", "> **Numerical note**", "**sympy identity**: both "
        "sides agree.", "#### Exercise 2", "#### Solution to Exercise 2",
    ]:
        assert expected in text, expected
    # The citation, as sphinxcontrib-bibtex resolved it: a link to the entry in the notebook
    # of the page that holds the bibliography (here the index), where its anchor is.
    cite = re.search(r"\[DR99\]\(00-index\.ipynb#([\w-]+)\)", text)
    assert cite, text
    index = _markdown(nbformat.read(site / "classroom" / "instructor" / "00-index.ipynb", 4))
    assert f'<a id="{cite[1]}"></a>' in index and "A Title" in index
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
    zeta = _markdown(nbformat.read(site / "classroom" / "student" / "01-zeta.ipynb", 4))
    assert '<a id="eq-7"></a>' in zeta and "#### Exercise 1" in zeta


# The Japanese bundles: the same code as the English ones (tests/book/test_japanese.py
# compares them cell by cell, and every English notebook ran above), so two chapters of
# each run here, for what differs: the Japanese README's install command, the notebook's
# language cell (its verdicts and figures in Japanese, from the catalog beside it), and the
# self-checks answering in Japanese, as their cells ask (language='ja').
JA_PAGES = ("energy", "libration")
# The bar of the Japanese chapters (test_japanese.py), for a notebook's outputs.
MOST_ENGLISH_RUNS = 20


def _outputs(nb: nbformat.NotebookNode) -> tuple[list[str], set[str]]:
    """What a notebook's code cells showed: the texts (HTML without its tags) and the
    images (their digests)."""
    import base64
    import hashlib

    texts, images = [], set()
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            texts.append(str(out.get("text", "")))
            data = out.get("data", {})
            for kind in ("text/markdown", "text/plain"):
                texts.append(str(data.get(kind, "")))
            texts.append(re.sub(r"<script.*?</script>|<[^>]+>", " ",
                                str(data.get("text/html", "")), flags=re.S))
            if "image/png" in data:
                images.add(hashlib.sha256(base64.b64decode(data["image/png"])).hexdigest())
            if "image/svg+xml" in data:
                images.add(hashlib.sha256(str(data["image/svg+xml"]).encode()).hexdigest())
    return texts, images


@pytest.fixture(scope="session")
def ja_bundles(book_ja_build: Build, student_ja_build: Build,
               tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """edition -> the folder the Japanese site's zip unpacks to, alone in an empty folder."""
    for build in (book_ja_build, student_ja_build):
        if build.returncode != 0:
            pytest.fail("a Japanese site did not build; see test_japanese", pytrace=False)
    sites = {"student": student_ja_build.outdir, "instructor": book_ja_build.outdir}
    folders = {}
    for edition, site in sites.items():
        empty = tmp_path_factory.mktemp(f"unzipped-ja-{edition}")
        with zipfile.ZipFile(site / "classroom" / f"{bundle.bundle_name(edition)}.zip") as z:
            z.extractall(empty)
        (folders[edition],) = empty.iterdir()
    return folders


@pytest.mark.parametrize("edition", ex.EDITIONS)
def test_the_japanese_bundle_installs_and_answers_in_japanese(
    edition: str, ja_bundles: dict[str, Path], bundles: dict[str, Path], bundle_venv: Path,
    executed: dict,
) -> None:
    from elliptic_pendulum.selfcheck import _ja
    from tests.ja_text import english_runs

    folder = ja_bundles[edition]
    argv = readme_install(folder)
    assert argv == readme_install(bundles[edition])  # the README's command, in Japanese
    proc = subprocess.run([str(bundle_venv / "bin" / "python"), *argv[1:]], cwd=folder,
                          capture_output=True, text=True, timeout=1800)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    all_right = _ja.TEMPLATES["all_right"]
    still = _ja.TEMPLATES["still"].split("{what}")[0].format(name="")
    for page in JA_PAGES:
        (name,) = (p.name for p in folder.glob(f"[0-9][0-9]-{page}.ipynb"))
        nb, _ = _run(folder, name, bundle_venv)
        said = _self_check_outputs(nb)
        assert said, page
        for label, text in said.items():
            if edition == "instructor":  # the worked solution, judged in Japanese
                assert "\u2718" not in text and all_right in text, (label, text)
            else:  # the answer cell as handed out
                assert "\u2714" not in text and still.strip() in text, (label, text)
            assert "All right" not in text and "is still" not in text, (label, text)
        # Everything else it showed is Japanese too: the verdicts, the figures (not the
        # English notebook's images, which ran above in the same venv).
        texts, images = _outputs(nb)
        runs = [r for text in texts for r in english_runs(text)]
        english_images = _outputs(executed[page, edition])[1]
        TIMES.append(f"Japanese {edition} {name}: {len(runs)} runs of English words in its "
                     f"outputs, {len(images & english_images)} of {len(images)} images the "
                     f"English notebook's")
        assert len(runs) <= MOST_ENGLISH_RUNS, (name, runs)
        assert images and not images & english_images, name
