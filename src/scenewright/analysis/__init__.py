"""Scene analysis (paper §3.1): what the text asks for.

``catalogue`` knows the kinds of things (names, sizes, how they rest, which generator builds
them), ``parser`` reads a description into objects, relations, style and ground, ``arrange``
gives the objects first poses (placement priors in ``composition``), and ``offline`` serves all of it as the offline
vision-language backend. Submodules are imported where they are used, so importing the
package stays light.
"""
