"""A picture of a classroom notebook as Jupyter renders it: nbconvert's HTML (the JupyterLab
look), with MathJax served from the local sphinx-mathjax-offline copy (no network), shot by
headless Chromium.

Usage::

    python -m tools.figures.screenshot NOTEBOOK.ipynb OUT.png [--width 1000 --height 2400]

Run the notebook first (its outputs are part of the picture); the HTML is kept next to the PNG.
"""

from __future__ import annotations

import argparse
import importlib.util
import subprocess
import sys
from pathlib import Path

import nbformat
from nbconvert import HTMLExporter

from ..pdf.printer import find_chromium


def local_mathjax() -> str:
    """The file:// address of the MathJax 3 that the book serves (sphinx-mathjax-offline)."""
    spec = importlib.util.find_spec("sphinx-mathjax-offline")
    if spec is None or spec.origin is None:
        raise FileNotFoundError("sphinx-mathjax-offline (the book extra) is not installed")
    return (Path(spec.origin).parent / "static" / "mathjax" / "tex-chtml.js").as_uri()


# nbconvert's template configures MathJax 2; the local copy is MathJax 3, which needs its
# configuration (the $...$ delimiters JupyterLab uses) before it loads.
MATHJAX3 = """<script>window.MathJax = {tex: {inlineMath: [["$", "$"], ["\\\\(", "\\\\)"]],
  processEscapes: true, processEnvironments: true, tags: "ams"}};</script>
"""


def screenshot(notebook: Path, png: Path, width: int = 1000, height: int = 2400) -> Path:
    nb = nbformat.read(notebook, as_version=4)
    for cell in nb.cells:  # folded as JupyterLab folds them (jupyter.source_hidden)
        hidden = cell.metadata.get("jupyter", {})
        cell.metadata["transient"] = {"remove_source": bool(hidden.get("source_hidden"))}
        if hidden.get("outputs_hidden"):
            cell.outputs = []
    url = local_mathjax()
    body, _ = HTMLExporter(template_name="lab", mathjax_url=url).from_notebook_node(nb)
    body = body.replace(f'<script src="{url}">', MATHJAX3 + f'<script src="{url}">', 1)
    png.parent.mkdir(parents=True, exist_ok=True)
    html = png.with_suffix(".html")
    html.write_text(body, encoding="utf-8")
    subprocess.run(
        [find_chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
         "--allow-file-access-from-files", "--virtual-time-budget=20000",
         f"--window-size={width},{height}", f"--screenshot={png.resolve()}",
         html.resolve().as_uri()],
        check=True, capture_output=True, timeout=180,
    )
    return png


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("notebook", type=Path)
    parser.add_argument("png", type=Path)
    parser.add_argument("--width", type=int, default=1000)
    parser.add_argument("--height", type=int, default=2400)
    args = parser.parse_args(argv)
    print(f"wrote {screenshot(args.notebook, args.png, args.width, args.height)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
