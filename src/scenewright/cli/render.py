"""Placeholder: filled by the render work (see the issue)."""
