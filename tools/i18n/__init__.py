"""The book's translations: the catalogs kept in step with the English pages (status.py)."""
