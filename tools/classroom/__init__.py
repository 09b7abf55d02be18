"""The classroom: the book's pages as Jupyter notebooks, the bundles a student installs, the
nbgrader course.

:mod:`.doctree` writes a page's resolved doctree as notebook cells; :mod:`.export` makes the
student and instructor notebooks of one build (the Sphinx extension book/_ext/classroom.py
calls it); :mod:`.words` holds the notebooks' own words in each language; :mod:`.bundle`
adds the wheel, requirements.txt and a README and zips an edition; :mod:`.nbgrader` turns the
instructor notebooks into an nbgrader course.
"""
