"""Sphinx extension: numbered references resolved without unpickling a page per reference.

Sphinx's standard domain resolves each ``{numref}`` by loading its target's whole doctree
from disk (``env.get_doctree(docname).ids.get(labelid)``), only to read the target node. The
book's pages are large (the animation of in_motion alone is megabytes of frames), and with
over a hundred numbered references a single-page build spent most of its time unpickling the
same doctrees again (90 s of 130 for the Japanese PDF's page). Here that one lookup reads
from a cache of the doctrees it has loaded: they are only read there, never changed, and the
cache is dropped when the build ends. Every other use of ``get_doctree`` is Sphinx's own.
"""

from __future__ import annotations

from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.domains.std import StandardDomain

_CACHE: dict[tuple[int, str], nodes.document] = {}
_RESOLVE = StandardDomain._resolve_numref_xref


def _cached(env: Any, get_doctree: Any) -> Any:
    def get(docname: str) -> nodes.document:
        key = (id(env), docname)
        if key not in _CACHE:
            _CACHE[key] = get_doctree(docname)
        return _CACHE[key]

    return get


def _resolve_numref_xref(self: StandardDomain, env: Any, *args: Any, **kwargs: Any) -> Any:
    env.get_doctree = _cached(env, type(env).get_doctree.__get__(env))
    try:
        return _RESOLVE(self, env, *args, **kwargs)
    finally:
        del env.get_doctree  # the method of the class again, for everyone else


def _drop(app: Sphinx, exception: BaseException | None) -> None:
    _CACHE.clear()


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the cache (one process builds one book at a time)."""
    StandardDomain._resolve_numref_xref = _resolve_numref_xref  # type: ignore[method-assign]
    app.connect("build-finished", _drop)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
