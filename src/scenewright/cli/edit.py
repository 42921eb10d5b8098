"""Placeholder: filled by the edit work (see the issue)."""
