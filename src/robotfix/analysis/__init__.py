"""Abstract interpretation of Python: values, states, statements, expressions, VCs."""
