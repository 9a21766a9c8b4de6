"""The language server (optional extra `lsp`): the only package that imports pygls."""
