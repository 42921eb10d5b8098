"""Placement priors: what a designer does with the things a text names but does not place.

One small module per kind of rule, applied in order by :func:`scenewright.analysis.arrange.compose`:

- ``relational`` — where the text's relations put things, one related group at a time;
- ``groups`` — functional groups (desk + chair, table + chairs, lounge, bed, lamp by a seat,
  rug under its group);
- ``outdoor`` — stalls around a square or along a street, vehicles by a road, natural things
  scattered (Poisson disc), ways in kept free;
- ``packing`` — groups set out compactly, repeated groups in a grid;
- ``edges`` — tall storage along the edges, backs outward;
- ``anchors`` — a group the text anchors in the room moved there as one, once the room is known;
- ``lines`` — never a line of unrelated things (``spread`` measures it).
"""
