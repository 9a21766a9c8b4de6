"""The refinement language: grammar, AST, units, and where annotations sit in Python."""
