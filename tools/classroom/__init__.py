"""The book's MyST pages as plain Jupyter notebooks, a student and an instructor edition.

:mod:`.export` writes the notebooks; :mod:`.markdown` turns MyST into plain Markdown;
:mod:`.labels` numbers the exercises as the book does; :mod:`.bib` writes the references.
The Sphinx extension ``book/_ext/classroom.py`` uses the same modules.
"""
