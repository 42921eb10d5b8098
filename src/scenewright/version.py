"""The package version, in the one place every module that stamps files reads it from."""

__version__ = "0.1.0"
