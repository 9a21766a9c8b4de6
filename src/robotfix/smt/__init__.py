"""The SMT layer: the only package that imports z3."""
