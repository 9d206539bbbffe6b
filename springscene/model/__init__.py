"""The physics: state, forces, integrators, lattices and the timeline. numpy only.

Nothing here draws, reads a file or knows a config: :mod:`springscene.build` turns a
config into a :class:`~springscene.model.physics.System`, and everything above reads it.
"""
