"""Stand-ins for the services scenewright talks to, and problem generators, for tests and benchmarks.

What :mod:`numpy.testing` is to numpy: :mod:`.fake_openai` is a scripted OpenAI-compatible
server, :mod:`.hunyuan3d_standin` a Hunyuan3D-2 API server with a chosen model and delay, and
:mod:`.problems` layout problems with a planted solution. Servers bind 127.0.0.1 only. Nothing
in the product imports this package (docs/architecture.md).
"""
