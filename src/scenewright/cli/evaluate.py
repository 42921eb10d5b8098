"""Placeholder: filled by the evaluate work (see the issue)."""
