"""The book as PDF: a single-page build of each edition, printed by headless Chromium."""
