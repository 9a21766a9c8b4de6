"""A second module with a function of the same name, but no refinement."""


def scale(x: float) -> float:
    return 2.0 * x
