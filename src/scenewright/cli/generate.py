"""Placeholder: filled by the generate work (see the issue)."""
