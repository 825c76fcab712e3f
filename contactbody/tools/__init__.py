"""Repository tooling, run from a checkout and not part of the user's API: the quotes and
generated tables of the docs (quotes, doc_tables), the release folder and wheel (release), the
platform table (platforms) and the Mach-O checks (macho). The wheel leaves this package out
(pyproject.toml lists its packages)."""
