"""The book's checks as its build sees them: every ``verify`` call in the pages' sources."""
