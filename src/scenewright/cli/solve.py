"""Placeholder: filled by the solve work (see the issue)."""
