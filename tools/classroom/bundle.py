"""The classroom bundle: what a student needs beside the notebooks to run them at home.

The package is not on a package index, so each edition's folder (and its zip) carries it as a
wheel built from this repository, with ``requirements.txt`` (what the notebooks import: the
package's own dependencies, ipywidgets for the sliders, a Jupyter front end) and a README
that says how to install them on a laptop and on a JupyterHub, and under which licences the
notebooks are. The README's install command, the notebooks' first cell and the test that
installs a bundle into a fresh venv (tests/book/test_notebooks.py) share ``install_args``.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tempfile
import tomllib
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PYPROJECT = ROOT / "pyproject.toml"
TITLE = "The simple pendulum and elliptic functions"
# The book's title in the Japanese edition (its html_title, book/_ext/i18n.py).
TITLE_JA = "単振り子と楕円関数"
CC_BY = "https://creativecommons.org/licenses/by/4.0/"
# Beside the package's own dependencies: the sliders of "The pendulum in motion" need
# ipywidgets 8 (the version JupyterLab 4 renders), and a student on a laptop needs a Jupyter
# front end with its Python kernel. A JupyterHub has those already, and pip skips them there.
NOTEBOOK_REQUIREMENTS = [
    ("ipywidgets>=8", "the sliders of the chapter on the pendulum in motion"),
    ("jupyterlab>=4", "a Jupyter front end (a JupyterHub has one: pip leaves it as it is)"),
    ("ipykernel>=6", "its Python kernel"),
]
# The zip of an edition unpacks to one folder of this name plus "-<edition>".
ZIP_NAME = "elliptic-pendulum-notebooks"
# The files beside the notebooks.
README = "README.md"
REQUIREMENTS = "requirements.txt"
BUNDLE_FILES = (README, REQUIREMENTS)
# A translated edition's catalog of the texts its cells pass to the library (a fact's
# sentence, a figure's label), which its notebooks' language cell names (export.py).
CATALOG = "cells.po"


def catalog_source(language: str) -> Path:
    """The book's catalog of its cells' texts in ``language`` (book/_ext/kernels.py)."""
    return ROOT / "book" / "locale" / language / "LC_MESSAGES" / CATALOG
def bundle_name(edition: str) -> str:
    return f"{ZIP_NAME}-{edition}"


def project() -> dict:
    with PYPROJECT.open("rb") as f:
        return tomllib.load(f)["project"]


def wheel_name(version: str | None = None) -> str:
    """The wheel's file name (PEP 427: the name with "_", pure Python)."""
    meta = project()
    name = re.sub(r"[-_.]+", "_", meta["name"]).lower()
    return f"{name}-{version or meta['version']}-py3-none-any.whl"


def install_args(user: bool = False) -> list[str]:
    """The arguments of ``pip install`` in the bundle's folder (the README's command)."""
    return [*(["--user"] if user else []), "-r", REQUIREMENTS, wheel_name()]


def install_command(user: bool = False) -> str:
    return " ".join(["python", "-m", "pip", "install", *install_args(user)])


def pip_magic() -> str:
    """The same install from a notebook's cell (into the kernel's own environment)."""
    return " ".join(["%pip", "install", *install_args()])


def requirements() -> str:
    """requirements.txt: the package's dependencies (the bounds of pyproject.toml) and
    what the notebooks need beside it."""
    lines = [
        "# What the classroom notebooks import. The package itself, elliptic_pendulum, is the",
        f"# wheel beside this file: {install_command()}",
        "# The package's dependencies, with the lower bounds it is tested with:",
        *project()["dependencies"],
    ]
    for requirement, why in NOTEBOOK_REQUIREMENTS:
        lines += [f"# {why[0].upper()}{why[1:]}:", requirement]
    return "\n".join(lines) + "\n"


def readme(edition: str, notebooks: list[str]) -> str:
    """The bundle's README: how to install and open the notebooks, and their licences."""
    folder = bundle_name(edition)
    zip_name = folder + ".zip"
    first = notebooks[0] if notebooks else "the first notebook"
    content = ("every chapter with its exercises (under each one, cells for your answer and "
               "a self-check that says whether a result is right)" if edition == "student" else
               "every chapter with its exercises and their worked solutions")
    wheel = wheel_name()
    return f"""\
# {TITLE}: classroom notebooks ({edition} edition)

This folder holds the book *{TITLE}* as Jupyter notebooks, {content}; `{first}` lists
the chapters. The notebooks use the Python package `elliptic_pendulum`, which is not on a
package index: it is the file `{wheel}` in this folder. The package also holds the
exercises' self-checks (`elliptic_pendulum.selfcheck`), so a notebook checks its answers
wherever the package is installed. `{REQUIREMENTS}` lists the other
packages the notebooks import (NumPy, SciPy, SymPy, Matplotlib, mpmath, ipywidgets for the
sliders) and JupyterLab to open them.

## On a laptop (Windows, macOS, Linux)

You need Python 3.11 or newer (from python.org; on Windows, tick "Add python.exe to PATH"
in the installer). Unzip `{zip_name}`, open a terminal in the folder `{folder}` (Windows:
PowerShell, or right-click the folder and choose "Open in Terminal"), and:

1. Make a virtual environment for the course and activate it.

   macOS and Linux:

   ```
   python3 -m venv .venv
   source .venv/bin/activate
   ```

   Windows (PowerShell; in the older Command Prompt, `.venv\\Scripts\\activate.bat`):

   ```
   py -m venv .venv
   .venv\\Scripts\\Activate.ps1
   ```

   If PowerShell refuses to run the script, first run
   `Set-ExecutionPolicy -Scope CurrentUser RemoteSigned`.

2. Install the package and what the notebooks need (the same command on every system):

   ```
   {install_command()}
   ```

3. Open Jupyter, and in it `{first}`:

   ```
   jupyter lab
   ```

Next time, activate the environment again (the second line of step 1) and run `jupyter lab`.

## On a JupyterHub

1. Upload `{zip_name}` (the upload button of the file browser).
2. Open a terminal (File > New > Terminal) and unpack and install it:

   ```
   python -m zipfile -e {zip_name} .
   cd {folder}
   {install_command(user=True)}
   ```

   Or, with no terminal: make a notebook beside the zip and unpack it with the cell
   `!python -m zipfile -e {zip_name} .`; then open `{first}` in the folder `{folder}`
   and run this in a new cell:

   ```
   {pip_magic()}
   ```

3. Restart the kernel (Kernel > Restart Kernel) of any notebook that was open, so that it
   sees the new packages.

If `import elliptic_pendulum` fails in a notebook, the install has not reached that
notebook's kernel: run the `%pip` line above in that notebook and restart its kernel.

## Licence

The text and the figures of the notebooks are from the book *{TITLE}*,
© 2024-2026 elliptic-pendulum contributors, licensed under the Creative Commons Attribution
4.0 International licence (CC BY 4.0, {CC_BY}): you may share and adapt them, crediting the
book and its contributors, linking to the licence and saying what you changed. The book
follows S. Takeno's note *The simple pendulum and elliptic functions* (Niigata Institute of
Technology, 2024), which is its author's work and not covered by these licences.

The code (the package `elliptic_pendulum` in the wheel and the notebooks' code cells) is
under the MIT licence, whose text is in the wheel (`elliptic_pendulum-*.dist-info/licenses/`).
"""


_CJK = "\u3000-\u30ff\u4e00-\u9fff\uff00-\uffef"
# A break inside a paragraph: not before a blank line, a heading, a list item or a fence.
_BREAK = re.compile(r"(?<=\S)\n(?=[^\s#\d-]|`[^`])(?!```)")


def readme_ja(edition: str, notebooks: list[str]) -> str:
    """The Japanese bundle's README (the same steps as :func:`readme`).

    The source wraps its lines; a line break inside a Japanese paragraph would read as a
    space once the README is rendered, so the paragraphs are joined back.
    """
    def join(m: re.Match[str]) -> str:  # nothing between two Japanese characters
        before, after = m.string[m.start() - 1], m.string[m.end()]
        both = all(re.match(f"[{_CJK}]", c) for c in (before, after))
        return "" if both else " "

    return _BREAK.sub(join, _readme_ja(edition, notebooks))


def _readme_ja(edition: str, notebooks: list[str]) -> str:
    folder = bundle_name(edition)
    zip_name = folder + ".zip"
    first = notebooks[0] if notebooks else "最初のノートブック"
    content = ("全章とその演習（各演習の下に、答えを書くセルと、結果が正しいかどうかを教える"
               "自己チェックがある）" if edition == "student" else "全章とその演習、演習の解答")
    kind = "学生用" if edition == "student" else "教員用"
    wheel = wheel_name()
    return f"""\
# {TITLE_JA}：授業用ノートブック（{kind}）

このフォルダには、本書『{TITLE_JA}』を Jupyter ノートブックにしたもの、すなわち{content}が
入っている。`{first}` が章の一覧である。ノートブックは Python パッケージ `elliptic_pendulum`
を使う。このパッケージはパッケージインデックスにはなく、このフォルダのファイル `{wheel}` が
それである。演習の自己チェック（`elliptic_pendulum.selfcheck`）もこのパッケージに含まれているので、
パッケージを入れた環境ならどこでも、ノートブックは答えを確かめられる。`{REQUIREMENTS}` には、
ノートブックが使うそのほかのパッケージ（NumPy、SciPy、SymPy、Matplotlib、mpmath、スライダー用の
ipywidgets）と、ノートブックを開くための JupyterLab が並んでいる。

## ノートパソコンで（Windows、macOS、Linux）

Python 3.11 以降が必要である（python.org から入手する。Windows では、インストーラーで
「Add python.exe to PATH」にチェックを入れる）。`{zip_name}` を展開し、フォルダ `{folder}` で
ターミナルを開いて（Windows では PowerShell。フォルダを右クリックして「ターミナルで開く」を
選んでもよい）、次のようにする。

1. 授業用の仮想環境を作り、有効にする。

   macOS と Linux：

   ```
   python3 -m venv .venv
   source .venv/bin/activate
   ```

   Windows（PowerShell。古いコマンドプロンプトでは `.venv\\Scripts\\activate.bat`）：

   ```
   py -m venv .venv
   .venv\\Scripts\\Activate.ps1
   ```

   PowerShell がスクリプトの実行を拒むときは、先に
   `Set-ExecutionPolicy -Scope CurrentUser RemoteSigned` を実行する。

2. パッケージと、ノートブックに必要なものをインストールする（どのシステムでも同じコマンド）。

   ```
   {install_command()}
   ```

3. Jupyter を開き、その中で `{first}` を開く。

   ```
   jupyter lab
   ```

次回からは、仮想環境をもう一度有効にして（手順 1 の 2 行目）`jupyter lab` を実行すればよい。

## JupyterHub で

1. `{zip_name}` をアップロードする（ファイルブラウザーのアップロードボタン）。
2. ターミナルを開き（File > New > Terminal）、展開してインストールする。

   ```
   python -m zipfile -e {zip_name} .
   cd {folder}
   {install_command(user=True)}
   ```

   ターミナルが使えないときは、zip と同じ場所にノートブックを作り、セル
   `!python -m zipfile -e {zip_name} .` で展開する。続いてフォルダ `{folder}` の
   `{first}` を開き、新しいセルで次を実行する。

   ```
   {pip_magic()}
   ```

3. 新しいパッケージが見えるように、開いていたノートブックのカーネルを再起動する（Kernel >
   Restart Kernel）。

ノートブックで `import elliptic_pendulum` が失敗するときは、インストールがそのノートブックの
カーネルに届いていない。そのノートブックで上の `%pip` の行を実行し、カーネルを再起動すること。

## ライセンス

ノートブックの本文と図は本書『{TITLE_JA}』のものであり、© 2024-2026 elliptic-pendulum
contributors、クリエイティブ・コモンズ 表示 4.0 国際（CC BY 4.0、{CC_BY}）の下で利用できる。
本書と著作者を表示し、ライセンスへのリンクを示し、変更した点を明記すれば、共有も改変も自由である。
本書は竹野茂治氏のノート『単振り子と楕円関数』（新潟工科大学、2024 年）に沿っているが、
このノートはその著者の著作物であり、これらのライセンスの対象ではない。

コード（wheel の中のパッケージ `elliptic_pendulum` とノートブックのコードセル）は MIT ライセンス
であり、その条文は wheel の中（`elliptic_pendulum-*.dist-info/licenses/`）にある。
"""


def build_wheel(dest: Path, root: Path = ROOT) -> Path:
    """Build the package's wheel into dest, offline, from a clean copy of the sources.

    A copy, because setuptools builds in the source tree: a ``build/`` folder left there by
    an earlier build would put modules deleted since into the wheel. No build isolation, so
    no index is needed: the build backend (setuptools>=77, the ``book`` extra) is the
    running interpreter's.
    """
    dest.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        tree = Path(tmp) / "src-tree"
        shutil.copytree(root / "src", tree / "src",
                        ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
        for name in ("pyproject.toml", "README.md", "LICENSE"):
            shutil.copy2(root / name, tree / name)
        out = Path(tmp) / "wheel"
        proc = subprocess.run(
            [sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "--no-index",
             "--no-build-isolation", "--wheel-dir", str(out), str(tree)],
            capture_output=True, text=True, timeout=600,
        )
        wheels = list(out.glob("*.whl"))
        if proc.returncode != 0 or len(wheels) != 1:
            raise RuntimeError(f"the wheel did not build (setuptools>=77 is needed, the book "
                               f"extra):\n{proc.stdout}{proc.stderr}")
        if wheels[0].name != wheel_name():
            raise RuntimeError(f"built {wheels[0].name}, expected {wheel_name()}")
        target = dest / wheels[0].name
        shutil.copy2(wheels[0], target)
    return target


def write(folder: Path, edition: str, wheel: Path, language: str = "en") -> list[Path]:
    """Add the wheel, requirements.txt and the README to an edition's folder of notebooks
    (the README and the self-checks' answers in ``language``)."""
    notebooks = sorted(p.name for p in folder.glob("*.ipynb"))
    shutil.copy2(wheel, folder / wheel.name)
    (folder / REQUIREMENTS).write_text(requirements(), encoding="utf-8")
    text = readme_ja(edition, notebooks) if language == "ja" else readme(edition, notebooks)
    (folder / README).write_text(text, encoding="utf-8")
    written = [folder / wheel.name, folder / REQUIREMENTS, folder / README]
    if language != "en":
        write_catalog(folder, language)
        written.append(folder / CATALOG)
    return written


def write_catalog(folder: Path, language: str) -> Path:
    """Write the catalog of the texts that the folder's notebooks pass to the library.

    Only their own: the book's catalog holds the texts of every cell, the solutions'
    included, and a student's folder must not hold a solution in any file.
    """
    import nbformat
    from babel.messages.pofile import read_po, write_po

    from tools.i18n.library_texts import code_texts

    wanted = {t.text for path in sorted(folder.glob("*.ipynb"))
              for cell in nbformat.read(path, as_version=4).cells if cell.cell_type == "code"
              for t in code_texts(cell.source) if t.literal}
    with catalog_source(language).open("rb") as f:
        book = read_po(f, locale=language)
    for message in list(book):
        if message.id and message.id not in wanted:
            del book[message.id]
        elif message.id:
            message.locations = []  # the pages' lines mean nothing beside the notebooks
    target = folder / CATALOG
    with target.open("wb") as f:
        write_po(f, book, width=0, omit_header=False)
    return target


def zip_edition(folder: Path, edition: str, zip_dir: Path) -> Path:
    """zip_dir/<name>-<edition>.zip: the folder's notebooks and bundle files under one
    top folder, so that unzipping makes one folder, the README's."""
    name = bundle_name(edition)
    archive = zip_dir / f"{name}.zip"
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_DEFLATED) as z:
        files = [*sorted(folder.glob("*.ipynb")), *(folder / f for f in BUNDLE_FILES)]
        files.append(folder / wheel_name())
        if (folder / CATALOG).is_file():
            files.append(folder / CATALOG)
        for path in files:
            z.write(path, f"{name}/{path.name}")
    return archive


def bundle_editions(out: Path, editions: tuple[str, ...], language: str = "en") -> list[Path]:
    """For each edition folder out/<edition> of exported notebooks: add the bundle files
    and zip it as out/<name>-<edition>.zip (the wheel is built once). Returns the zips."""
    if language not in ("en", "ja"):
        raise ValueError(f"language must be 'en' or 'ja', not {language!r}")
    with tempfile.TemporaryDirectory() as tmp:
        wheel = build_wheel(Path(tmp))
        zips = []
        for edition in editions:
            write(out / edition, edition, wheel, language)
            zips.append(zip_edition(out / edition, edition, out))
    return zips
