"""Placeholder: filled by the parse work (see the issue)."""
