"""Pictures made at build time: the README's phase portrait, screenshots of notebooks."""
