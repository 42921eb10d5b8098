"""The benchmarks behind ``scenewright bench ...`` (``make bench``), one module per benchmark.

Each ``run_*`` function returns one JSON-ready dict; the command group in
:mod:`scenewright.cli.bench` prints it. Speed is measured here, never asserted in tests.
"""
