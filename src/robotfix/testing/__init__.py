"""Helpers for RobotFix's own data-driven tests (shipped so plugins can reuse them)."""
