"""Renderers: diagnostics -> text or JSON. They know nothing of the analysis."""
